/**
 * Polygon/Point
 * Tutorial section 10: Polygons
 *
 * Is the mouse inside this concave polygon? Send a ray from the point to the right and count
 * the edges it crosses: an odd count means inside, an even count outside. The library's
 * Collide.polygonPoint decides it exactly. Where the ray passes exactly through a corner,
 * each edge counts only if one of its ends is below the ray and the other at or above it, so
 * a corner the outline just touches counts 0 or 2 times, a corner it passes through once.
 * The yellow dots are the crossings (a Ray cast at each edge); hollow rings are corners the
 * ray touches without crossing.
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

float px, py;              // the point: the mouse
boolean inside;            // the answer, kept for the tests
boolean onOutline;         // the point is on an edge (not inside: polygons are open)
int crossings;             // edges the ray crosses, counted by the rule
ArrayList<RayHit> counted = new ArrayList<RayHit>();
ArrayList<Integer> countedEdges = new ArrayList<Integer>();
ArrayList<RayHit> touched = new ArrayList<RayHit>();     // met, but not counted
boolean showMaths;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  px = mouseX;
  py = mouseY;

  // The whole idea in one line: is the point inside?
  inside = Collide.polygonPoint(crown.coordinates(), px, py);

  findCrossings();

  noStroke();
  fill(inside ? Palette.HIT : Palette.MISS);
  Draw.shape(g, crown);

  // The ray, to the window's edge.
  stroke(Palette.ACCENT);
  strokeWeight(2);
  line(px, py, width, py);

  if (showMaths) {
    drawMaths();
  }
  noStroke();
  fill(Palette.PLAYER);
  circle(px, py, 10);
  for (RayHit h : touched) {
    noFill();
    stroke(Palette.ACCENT);
    strokeWeight(2);
    circle(h.x(), h.y(), 13);
  }
  // Each crossing, numbered along the ray; a corner counted by both its edges gets both numbers.
  String number = "";
  for (int i = 0; i < counted.size(); i++) {
    RayHit h = counted.get(i);
    number += (number.isEmpty() ? "" : ",") + (i + 1);
    boolean nextSameSpot = i + 1 < counted.size() && counted.get(i + 1).x() == h.x() && counted.get(i + 1).y() == h.y();
    if (nextSameSpot) {
      continue;
    }
    stroke(Palette.BACKGROUND);
    strokeWeight(2);
    fill(Palette.ACCENT);
    circle(h.x(), h.y(), 12);
    fill(Palette.NEUTRAL);
    textSize(13);
    textAlign(CENTER, BOTTOM);
    text(number, h.x(), h.y() - 9);
    number = "";
  }

  String verdict = onOutline ? "on the outline: not inside (touching does not count)"
      : crossings + (crossings == 1 ? " crossing: " : " crossings: ") + (crossings % 2 == 1 ? "odd, inside" : "even, outside");
  Overlay.labelCentered(g, width / 2, py < 60 ? height - 40 : 22, verdict, inside ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "move the mouse in and out of the crown     d: show the maths");
}

/**
 * The crossings, for drawing: a ray from the point to the right, cast at each edge. Whether
 * an edge counts is the library's rule, Collide.rayCrossesEdge: one end below the ray and
 * the other at or above it; an edge the ray meets only at a corner or along its length does
 * not.
 */
void findCrossings() {
  counted.clear();
  countedEdges.clear();
  touched.clear();
  onOutline = false;
  Ray ray = new Ray(px, py, 1, 0);
  for (int i = 0; i < crown.edgeCount(); i++) {
    Segment e = crown.edge(i);
    RayHit hit = ray.cast(e);
    if (hit == null) {
      continue;
    }
    if (hit.distance() == 0) {
      onOutline = true;
    }
    if (Collide.rayCrossesEdge(e.x1(), e.y1(), e.x2(), e.y2(), px, py)) {
      // In order along the ray, nearest first.
      int k = 0;
      while (k < counted.size() && counted.get(k).distance() <= hit.distance()) {
        k++;
      }
      counted.add(k, hit);
      countedEdges.add(k, i);
    } else if (!sameSpot(hit)) {
      touched.add(hit);
    }
  }
  // A corner on the ray counted by one edge is a crossing, not a touch.
  for (int i = touched.size() - 1; i >= 0; i--) {
    for (RayHit c : counted) {
      if (c.x() == touched.get(i).x() && c.y() == touched.get(i).y()) {
        touched.remove(i);
        break;
      }
    }
  }
  crossings = counted.size();
}

/** Already listed as touched (the two edges at one corner meet the ray at the same spot). */
boolean sameSpot(RayHit hit) {
  for (RayHit t : touched) {
    if (t.x() == hit.x() && t.y() == hit.y()) {
      return true;
    }
  }
  return false;
}

/** Each edge's number, the counted ones highlighted, and the rule at the corners the ray meets. */
void drawMaths() {
  for (int i = 0; i < crown.edgeCount(); i++) {
    Segment e = crown.edge(i);
    boolean counts = countedEdges.contains(i);
    if (counts) {
      stroke(Palette.ACCENT);
      strokeWeight(4);
      line(e.x1(), e.y1(), e.x2(), e.y2());
    }
    // The edge's number, just outside it, a quarter of the way along.
    float mx = lerp(e.x1(), e.x2(), 0.25);
    float my = lerp(e.y1(), e.y2(), 0.25);
    float nx = e.y2() - e.y1();
    float ny = -(e.x2() - e.x1());
    float len = dist(0, 0, nx, ny);
    if (crown.contains(mx + nx / len * 3, my + ny / len * 3)) {
      nx = -nx;
      ny = -ny;
    }
    Overlay.labelBeside(g, mx, my, nx, ny, "e" + i, counts ? Overlay.GUIDE : Overlay.TEXT);
  }
  // The rule, and the edges that count, at the bottom-left.
  String list = "";
  for (int i : countedEdges) {
    list += (list.isEmpty() ? "" : ", ") + "e" + i;
  }
  String text = "an edge counts when one end is below the ray and the other at or above it\n"
      + "the ray crosses: " + (list.isEmpty() ? "none" : list) + "  ->  " + crossings
      + (crossings % 2 == 1 ? ": odd" : ": even")
      + "\nCollide.polygonPoint: " + inside;
  Overlay.label(g, 8, py > height - 110 ? 46 : height - 72, text, inside ? Overlay.HIT : Overlay.MISS);
  for (RayHit t : touched) {
    Overlay.labelBeside(g, t.x(), t.y() + 8, 0, 1, "corner: not crossed", Overlay.GUIDE);
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
