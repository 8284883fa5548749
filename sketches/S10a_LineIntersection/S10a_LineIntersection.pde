/**
 * Lines: line/line, line/rectangle, line/circle
 * Tutorial section 10: More advanced collision detection
 *
 * The tutorial stops at points, rectangles and circles: any other shape works too, it says,
 * once you find the right maths (search for "rectangle line intersection"). The video names
 * line/circle, line/square and line/line among the common cases. Neither writes the code, so
 * here it is, written out (Lines.pde) and deciding the colours: a line (a segment) runs from
 * the start point to the mouse; three segments, a rectangle and a circle turn red while it
 * hits them. Two segments meet when each one's ends lie on opposite sides of the other's
 * line, or an end lies on the other segment: which side is the sign of a cross product, so
 * parallel and vertical lines need no special case (the formula such a search usually finds
 * solves for the crossing point and divides by a number that is 0 for parallel lines). A line
 * hits the rectangle when an end is inside it (section 4's if) or it crosses a side; the
 * circle, when the segment's point nearest the centre is closer than the radius (section 2's
 * dist()). Segments are closed, so touching an end counts; shapes with area are open, so a
 * line along the rectangle's edge, or touching the circle's outline, does not hit.
 *
 * Hitbox's Collide.lineLine, lineRect and lineCircle run beside them; the top line counts the
 * targets where they disagree, and l lets them decide. They differ only where the written-out
 * maths is loose: a line through two of the rectangle's corners crosses no side properly and
 * has no end inside, so lineRect below misses it; Collide.lineRect does not.
 *
 * Try this: put the mouse exactly on a segment's end; run the line along the rectangle's
 * bottom edge (it starts level with it); run it through two corners of the rectangle.
 * Keys: click moves the start, l Hitbox's calls decide / the written-out maths, d shows the
 * maths (which side of each line the ends are on).
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
int disagreements;                       // targets where the written-out maths and Hitbox differ now
boolean hitboxDecides;                   // l: Hitbox's calls decide the colours
boolean showMaths;                       // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // Does the line from the start to the mouse hit each target? The maths written out
  // (Lines.pde), and Hitbox's call beside it.
  disagreements = 0;
  for (int i = 0; i < segments.length; i++) {
    Segment s = segments[i];
    segmentHit[i] = decide(lineLine(startX, startY, mouseX, mouseY, s.x1(), s.y1(), s.x2(), s.y2()),
        Collide.lineLine(startX, startY, mouseX, mouseY, s.x1(), s.y1(), s.x2(), s.y2()));
  }
  boxHit = decide(lineRect(startX, startY, mouseX, mouseY, box.x(), box.y(), box.w(), box.h()),
      Collide.lineRect(startX, startY, mouseX, mouseY, box.x(), box.y(), box.w(), box.h()));
  ballHit = decide(lineCircle(startX, startY, mouseX, mouseY, ball.x(), ball.y(), ball.r()),
      Collide.lineCircle(startX, startY, mouseX, mouseY, ball.x(), ball.y(), ball.r()));

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
  if (!showMaths) {
    Overlay.label(g, 8, 8, (hitboxDecides ? "Hitbox's calls decide (l: the maths below)" : "the written-out maths decides (l: Hitbox's calls)")
        + ";  they disagree on " + disagreements + " targets", disagreements > 0 ? Overlay.HIT : Overlay.TEXT);
  }
  Overlay.hint(g, "move the mouse: the line runs from the start to it     click: move the start     l: who decides     d: show the maths");
}

// One target's answer: the written-out maths, or Hitbox's (l); counted if they differ.
boolean decide(boolean writtenOut, boolean hitboxSays) {
  if (writtenOut != hitboxSays) {
    disagreements++;
  }
  return hitboxDecides ? hitboxSays : writtenOut;
}

void mousePressed() {
  startX = mouseX;
  startY = mouseY;
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
