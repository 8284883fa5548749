/**
 * Polygon/Point
 * Tutorial section 10: More advanced collision detection
 *
 * Is the mouse inside this concave polygon? The tutorial leaves shapes beyond points,
 * rectangles and circles to the maths you find; the rectangle video names this trick:
 * send a line from the point and count how many edges it crosses, odd means inside, even
 * outside. Here the line is a ray to the right, and Collide.rayCrossesEdge says whether it
 * crosses one edge; Collide.polygonPoint does the whole count. Hitbox counts an edge only
 * if one end is below the ray and the other at or above it, because a ray through a corner
 * would otherwise count that corner twice (once per edge): a corner the outline just
 * touches counts 0 or 2 times, one it passes through once. A point on the outline is not
 * inside. Yellow dots are the crossings; hollow rings are corners touched, not crossed.
 *
 * Try this: put the mouse level with a corner of the crown (y = 140 or y = 70); put it in
 * the notch at the bottom; make your own polygon with Polygon.of(x0, y0, x1, y1, ...).
 * Keys: d shows the maths (each edge's number, which ones count and why).
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
boolean showMaths;    // d

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
  for (int i = 0; i < crown.edgeCount(); i++) {
    Segment e = crown.edge(i);
    if (Collide.rayCrossesEdge(e.x1(), e.y1(), e.x2(), e.y2(), px, py)) {
      crossings++;
    }
  }
  // Collide.polygonPoint is that count in one call (a point on an edge is not inside).
  inside = Collide.polygonPoint(crown.coordinates(), px, py);

  noStroke();
  fill(inside ? Palette.HIT : Palette.MISS);
  Draw.shape(g, crown);

  // The ray, to the window's edge.
  stroke(Palette.ACCENT);
  strokeWeight(2);
  line(px, py, width, py);

  findCrossings();
  if (showMaths) {
    drawMaths();
  }
  noStroke();
  fill(Palette.PLAYER);
  circle(px, py, 10);
  drawCrossings();

  String verdict = onOutline ? "on the outline: not inside (touching does not count)"
      : crossings + (crossings == 1 ? " crossing: " : " crossings: ") + (crossings % 2 == 1 ? "odd, inside" : "even, outside");
  Overlay.labelCentered(g, width / 2, py < 60 ? height - 40 : 22, verdict, inside ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "move the mouse in and out of the crown     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
