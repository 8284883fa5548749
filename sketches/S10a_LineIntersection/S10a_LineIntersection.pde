/**
 * Lines: line/line, line/rectangle, line/circle
 * Tutorial section 10: Lines
 *
 * A line (a segment) from the start point to the mouse, against three segments, a rectangle
 * and a circle; each turns red while the line hits it. Collide.lineLine asks whether each
 * segment's two ends lie on opposite sides of the other's line: exact, with no division
 * that fails for vertical or parallel lines. Segments are closed, so touching an end counts;
 * shapes with area are open, so a line that only runs along a rectangle's edge, or touches
 * the circle's outline, does not hit (Collide.lineRect, Collide.lineCircle). The yellow dots
 * are where the line crosses each outline (a Ray cast each way).
 *
 * Try this: put the mouse exactly on a segment's end; run the line along the rectangle's
 * bottom edge (it starts level with it); click to move the start inside the rectangle.
 * Keys: click moves the start, d shows the maths (which side of each line the ends are on:
 * opposite sides both ways, or an end on the other, means they meet).
 */
import hitbox.*;
import hitbox.processing.*;

float ax = 40;      // the line's start (click to move it); its end is the mouse
float ay = 340;
float bx, by;

Segment[] segments = {
    new Segment(60, 190, 170, 80),
    new Segment(300, 80, 300, 200),     // vertical: the tutorial's division would fail here
    new Segment(430, 110, 570, 170),
};
String[] names = {"s1", "s2", "s3"};
Rect box = new Rect(400, 250, 140, 90);  // its bottom edge is level with the start
Circle ball = new Circle(220, 280, 42);

boolean[] segmentHit = new boolean[3];  // this frame's answers, kept for the tests
boolean boxHit, ballHit;
boolean showMaths;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  bx = mouseX;
  by = mouseY;

  // The tests, one library call each.
  for (int i = 0; i < segments.length; i++) {
    Segment s = segments[i];
    segmentHit[i] = Collide.lineLine(ax, ay, bx, by, s.x1(), s.y1(), s.x2(), s.y2());
  }
  boxHit = Collide.lineRect(ax, ay, bx, by, box.x(), box.y(), box.w(), box.h());
  ballHit = Collide.lineCircle(ax, ay, bx, by, ball.x(), ball.y(), ball.r());

  noStroke();
  fill(boxHit ? Palette.HIT : Palette.MISS);
  Draw.shape(g, box);
  fill(ballHit ? Palette.HIT : Palette.MISS);
  Draw.shape(g, ball);
  strokeCap(ROUND);
  for (int i = 0; i < segments.length; i++) {
    stroke(segmentHit[i] ? Palette.HIT : Palette.MISS);
    strokeWeight(5);
    Draw.shape(g, segments[i]);
    Segment s = segments[i];
    fill(Palette.NEUTRAL);
    textSize(13);
    textAlign(CENTER, CENTER);
    text(names[i], s.x2() + 4, s.y2() - 16);
  }

  // The mouse line.
  stroke(Palette.PLAYER);
  strokeWeight(3);
  line(ax, ay, bx, by);
  noStroke();
  fill(Palette.PLAYER);
  circle(ax, ay, 10);
  circle(bx, by, 8);

  drawCrossings();
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move the mouse: the line runs from the start to it     click: move the start     d: show the maths");
}

/**
 * Where the line crosses each outline: a ray from the start towards the mouse finds the
 * first crossing, one from the mouse back towards the start the last.
 */
void drawCrossings() {
  if (ax == bx && ay == by) {
    return;  // a point: no direction to cast in
  }
  Ray forward = Ray.between(ax, ay, bx, by);
  Ray back = Ray.between(bx, by, ax, ay);
  for (int i = 0; i < segments.length; i++) {
    if (segmentHit[i]) {
      crossing(forward.cast(segments[i]));
    }
  }
  if (boxHit) {
    crossing(forward.cast(box));
    crossing(back.cast(box));
  }
  if (ballHit) {
    crossing(forward.cast(ball));
    crossing(back.cast(ball));
  }
}

/** A crossing point; a ray that starts inside a shape hits it at its own origin (not drawn). */
void crossing(RayHit hit) {
  if (hit == null || hit.distance() == 0) {
    return;
  }
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.ACCENT);
  circle(hit.x(), hit.y(), 11);
}

/** The maths: for each segment the four orientation tests, for the rectangle and circle their parts. */
void drawMaths() {
  Overlay.labelBeside(g, ax, ay - 8, 0, -1, "A1", Overlay.TEXT);
  Overlay.labelBeside(g, bx + 8, by + 8, 1, 1, "A2", Overlay.TEXT);
  // Each segment's four orientation tests, in a row along the top, above its segment.
  for (int i = 0; i < segments.length; i++) {
    Segment s = segments[i];
    String a1 = side(s.x1(), s.y1(), s.x2(), s.y2(), ax, ay);
    String a2 = side(s.x1(), s.y1(), s.x2(), s.y2(), bx, by);
    String s1 = side(ax, ay, bx, by, s.x1(), s.y1());
    String s2 = side(ax, ay, bx, by, s.x2(), s.y2());
    String text = "lineLine(A, " + names[i] + "): " + segmentHit[i] + "\n"
        + "A1, A2 vs " + names[i] + ": " + a1 + " | " + a2 + "\n"
        + names[i] + "'s ends vs A: " + s1 + " | " + s2;
    Overlay.label(g, 8 + i * 197, 8, text, segmentHit[i] ? Overlay.HIT : Overlay.MISS);
  }

  // The rectangle: the tutorial tests the line against its four edges with lineLine.
  String[] edgeNames = {"top", "right", "bottom", "left"};
  float[][] edges = {
      {box.x(), box.y(), box.right(), box.y()},
      {box.right(), box.y(), box.right(), box.bottom()},
      {box.x(), box.bottom(), box.right(), box.bottom()},
      {box.x(), box.y(), box.x(), box.bottom()},
  };
  String met = "";
  for (int k = 0; k < 4; k++) {
    float[] e = edges[k];
    if (Collide.lineLine(ax, ay, bx, by, e[0], e[1], e[2], e[3])) {
      met += (met.isEmpty() ? "" : ", ") + edgeNames[k];
    }
  }
  Overlay.labelBeside(g, box.centerX(), box.y() - 6, 0, -1,
      "lineRect: " + (boxHit ? "true: A goes inside" : "false: A never goes inside") + "\n"
      + "edges A meets (lineLine): " + (met.isEmpty() ? "none" : met),
      boxHit ? Overlay.HIT : Overlay.MISS);

  // The circle: an end inside it, or the line passing through.
  boolean a1 = Collide.circlePoint(ball.x(), ball.y(), ball.r(), ax, ay);
  boolean a2 = Collide.circlePoint(ball.x(), ball.y(), ball.r(), bx, by);
  Overlay.labelBeside(g, ball.x() - ball.r() - 6, ball.y(), -1, 0,
      "lineCircle: " + ballHit + "\nA1 inside: " + a1 + "\nA2 inside: " + a2,
      ballHit ? Overlay.HIT : Overlay.MISS);
}

/**
 * Which side of the line from (x1, y1) to (x2, y2) the point is on, looking from the first
 * end to the second, in the overlay's words: Collide.lineSide, the orientation test that
 * Collide.lineLine compares.
 */
String side(float x1, float y1, float x2, float y2, float px, float py) {
  int side = Collide.lineSide(x1, y1, x2, y2, px, py);
  return side > 0 ? "right" : side < 0 ? "left" : "on it";
}

void mousePressed() {
  ax = mouseX;
  ay = mouseY;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
