/**
 * Polygon/Point, and a ball against the same polygon
 * Tutorial section 10: More advanced collision detection
 *
 * Is the mouse inside this concave polygon? The tutorial leaves shapes beyond points,
 * rectangles and circles to the maths you find; the rectangle video names this trick among
 * those for convex and concave polygons: project a line from the point and check whether the
 * number of edges it crosses is odd or even. It does not say which is which: odd means
 * inside, even outside. Here the line is a ray to the right, and crosses() below
 * decides for one edge: the edge must reach the ray's level, one end below it and the other
 * at or above it, and meet it right of the point. Only one end may count as "at", because a
 * ray through a corner would otherwise count that corner twice (once per edge): a corner the
 * outline just touches counts 0 or 2 times, one it passes through once. The count decides the
 * crown's colour. Collide.polygonPoint, the whole count in one call (Collide.rayCrossesEdge
 * the rule for one edge), runs beside it; press l and it decides. Yellow dots are the
 * crossings; hollow rings are corners touched, not crossed.
 *
 * Press b and the mouse carries a ball: a shape against the concave polygon, which the video
 * says becomes more complex. They overlap when an edge of the crown cuts into the ball, or
 * when the ball's centre is inside (the crossing count again), for a ball wholly inside
 * touches no edge; crown.overlaps(ball) is the library's answer.
 *
 * Where Hitbox differs: neither source writes the count out; the code here is ours.
 * Collide.polygonPoint counts as crosses() does, but first asks whether the point is on the
 * outline: there it is not inside, whatever the count, and a ball that only touches an edge
 * does not overlap, because touching is not colliding for every pair. The count alone cannot
 * see the outline: put the mouse on an edge and the two can disagree.
 *
 * Try this: put the mouse level with a corner of the crown (y = 140 or y = 70); put it in
 * the notch at the bottom; with the ball, slide it into the notch until it touches both
 * sides; make your own polygon with Polygon.of(x0, y0, x1, y1, ...).
 * Keys: b a ball instead of a point, l Collide.polygonPoint decides / the count, d shows the maths (each edge's number, which ones
 * count and why).
 */
import hitbox.*;
import hitbox.processing.*;

// A crown: concave, with corners level with each other (y = 70, 140) for the ray to meet.
Polygon crown = Polygon.of(
    120, 70,  220, 140,  300, 60,  380, 140,  480, 70,  520, 210,
    430, 310,  330, 230,  250, 310,  140, 270,  90, 190);

float px, py;         // the point: the mouse
int crossings;        // edges the ray to the right crosses: written out below the crown
boolean inside;       // the crown is red while the point is inside
boolean hitboxSays;   // Collide.polygonPoint, beside the count
boolean hitboxDecides;  // l
boolean showMaths;    // d
boolean ballMode;     // b: the mouse carries a ball
float ballRadius = 28;
boolean ballHits;     // the ball overlaps the crown

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  px = mouseX;
  py = mouseY;

  // Count the edges a ray from the point to the right crosses: odd means inside.
  crossings = 0;
  for (int i = 0; i < crown.size(); i++) {
    Segment e = crown.edge(i);
    if (crosses(e.x1(), e.y1(), e.x2(), e.y2())) {   // Collide.rayCrossesEdge(..., px, py)
      crossings++;
    }
  }
  // Collide.polygonPoint is that count in one call (a point on an edge is not inside).
  hitboxSays = Collide.polygonPoint(crown.coordinates(), px, py);
  inside = hitboxDecides ? hitboxSays : crossings % 2 == 1;

  // The ball: an edge cutting into it, or its centre inside.
  ballHits = false;
  for (int i = 0; i < crown.size(); i++) {
    Segment e = crown.edge(i);
    if (Collide.lineCircle(e.x1(), e.y1(), e.x2(), e.y2(), px, py, ballRadius)) {
      ballHits = true;
    }
  }
  ballHits = ballHits || crossings % 2 == 1;   // crown.overlaps(new Circle(px, py, ballRadius))

  noStroke();
  fill((ballMode ? ballHits : inside) ? Palette.HIT : Palette.MISS);
  Draw.shape(g, crown);

  // The ray, to the window's edge.
  stroke(Palette.ACCENT);
  strokeWeight(2);
  line(px, py, width, py);

  findCrossings();
  if (showMaths) {
    drawMaths();
  }
  if (ballMode) {
    noStroke();
    fill(Palette.PLAYER, 150);
    circle(px, py, 2 * ballRadius);
  }
  noStroke();
  fill(Palette.PLAYER);
  circle(px, py, 10);
  drawCrossings();

  String verdict = onOutline ? "on the outline: the count says " + (crossings % 2 == 1 ? "inside" : "outside")
      + ", Collide.polygonPoint not inside (touching does not count)"
      : crossings + (crossings == 1 ? " crossing: " : " crossings: ") + (crossings % 2 == 1 ? "odd, inside" : "even, outside");
  if (ballMode) {
    verdict = "the ball: " + (ballHits ? "overlaps the crown" : "apart") + ";  its centre: " + verdict;
  }
  boolean red = ballMode ? ballHits : inside;
  Overlay.labelCentered(g, width / 2, py < 60 ? height - 40 : 22, verdict, red ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "move the mouse in and out of the crown   b: " + (ballMode ? "a point" : "a ball") + "   l: "
      + (hitboxDecides ? "the count" : "Collide.polygonPoint") + " decides   d: show the maths");
}

// Does the ray from the point (px, py) to the right cross the edge from (ax, ay) to (bx, by)?
boolean crosses(float ax, float ay, float bx, float by) {
  // The edge must reach the ray's level: one end below it, the other at or above (y grows down).
  if ((ay > py) == (by > py)) {
    return false;
  }
  // It meets that level at x = ax + (py - ay) / (by - ay) * (bx - ax); is that right of the
  // point? The same question multiplied out, which stays exact for whole pixels:
  float side = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  return by > ay ? side > 0 : side < 0;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'b') {
    ballMode = !ballMode;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  }
}
