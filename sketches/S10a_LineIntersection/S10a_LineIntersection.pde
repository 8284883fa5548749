/**
 * Lines: line/line, line/rectangle, line/circle
 * Tutorial section 10: More advanced collision detection
 *
 * The tutorial stops at points, rectangles and circles: any other shape works too, it says,
 * once you find the right maths (search for "rectangle line intersection"). This is that
 * maths for lines (the tutorial writes none, so there is no tutorial's version to switch
 * to). A line (a segment) runs from the start point to the mouse; three segments, a
 * rectangle and a circle turn red while it hits them. Two segments meet when
 * each one's ends lie on opposite sides of the other's line, or an end lies on it:
 * Collide.lineLine. The formula such a search usually finds solves for the crossing point
 * and divides by a number that is 0 for parallel lines; Hitbox only asks which side each end
 * is on (the sign of a cross product), so parallel and vertical lines need no special case.
 * Segments are closed, so touching an end counts; shapes with area are open, so a line
 * along the rectangle's edge, or touching the circle's outline, does not hit.
 *
 * Try this: put the mouse exactly on a segment's end; run the line along the rectangle's
 * bottom edge (it starts level with it); click to move the start inside the rectangle.
 * Keys: click moves the start, d shows the maths (which side of each line the ends are on).
 */
import hitbox.*;
import hitbox.processing.*;

// The line: from the start (click to move it) to the mouse.
float startX = 40;
float startY = 340;

// What it can hit.
Segment[] segments = {
    new Segment(60, 190, 170, 80),
    new Segment(300, 80, 300, 200),      // vertical
    new Segment(430, 110, 570, 170),
};
String[] names = {"s1", "s2", "s3"};
Rect box = new Rect(400, 250, 140, 90);  // its bottom edge is level with the start
Circle ball = new Circle(220, 280, 42);

boolean[] segmentHit = new boolean[3];   // this frame's answers: each target's colour
boolean boxHit, ballHit;
boolean showMaths;                       // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // One library call per target: does the line from the start to the mouse hit it?
  for (int i = 0; i < segments.length; i++) {
    Segment s = segments[i];
    segmentHit[i] = Collide.lineLine(startX, startY, mouseX, mouseY, s.x1(), s.y1(), s.x2(), s.y2());
  }
  boxHit = Collide.lineRect(startX, startY, mouseX, mouseY, box.x(), box.y(), box.w(), box.h());
  ballHit = Collide.lineCircle(startX, startY, mouseX, mouseY, ball.x(), ball.y(), ball.r());

  noStroke();
  fill(boxHit ? Palette.HIT : Palette.MISS);
  Draw.shape(g, box);
  fill(ballHit ? Palette.HIT : Palette.MISS);
  Draw.shape(g, ball);
  strokeCap(ROUND);
  strokeWeight(5);
  textSize(13);
  textAlign(CENTER, CENTER);
  for (int i = 0; i < segments.length; i++) {
    stroke(segmentHit[i] ? Palette.HIT : Palette.MISS);
    Draw.shape(g, segments[i]);
    fill(Palette.NEUTRAL);
    text(names[i], segments[i].x2() + 4, segments[i].y2() - 16);
  }

  // The line.
  stroke(Palette.PLAYER);
  strokeWeight(3);
  line(startX, startY, mouseX, mouseY);
  noStroke();
  fill(Palette.PLAYER);
  circle(startX, startY, 10);
  circle(mouseX, mouseY, 8);

  drawCrossings();
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move the mouse: the line runs from the start to it     click: move the start     d: show the maths");
}

void mousePressed() {
  startX = mouseX;
  startY = mouseY;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
