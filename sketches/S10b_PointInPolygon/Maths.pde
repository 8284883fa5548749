// Where the ray meets the outline (to draw it), and the "show the maths" overlay.

ArrayList<RayHit> counted = new ArrayList<RayHit>();     // crossings, nearest first
ArrayList<Integer> countedEdges = new ArrayList<Integer>();
ArrayList<RayHit> touched = new ArrayList<RayHit>();     // corners met, but not counted
boolean onOutline;                                       // the point is on an edge

/**
 * The crossings, for drawing: the ray from the point to the right, cast at each edge. An
 * edge counts by the same rule as the count in draw(), Collide.rayCrossesEdge; an edge the
 * ray meets only at a corner or along its length does not.
 */
void findCrossings() {
  counted.clear();
  countedEdges.clear();
  touched.clear();
  onOutline = false;
  Ray ray = new Ray(px, py, 1, 0);
  for (int i = 0; i < crown.size(); i++) {
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
    } else if (!sameSpot(touched, hit)) {
      touched.add(hit);
    }
  }
  // A corner on the ray counted by one edge is a crossing, not a touch.
  for (int i = touched.size() - 1; i >= 0; i--) {
    if (sameSpot(counted, touched.get(i))) {
      touched.remove(i);
    }
  }
}

/** Is there already a hit at this spot in the list (the two edges at one corner meet the ray there)? */
boolean sameSpot(ArrayList<RayHit> hits, RayHit hit) {
  for (RayHit h : hits) {
    if (h.x() == hit.x() && h.y() == hit.y()) {
      return true;
    }
  }
  return false;
}

/** Each crossing, numbered along the ray (a corner counted by both its edges gets both numbers), and each touched corner as a ring. */
void drawCrossings() {
  for (RayHit h : touched) {
    noFill();
    stroke(Palette.ACCENT);
    strokeWeight(2);
    circle(h.x(), h.y(), 13);
  }
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
}

/** Each edge's number, the counted ones highlighted, and the rule at the corners the ray meets. */
void drawMaths() {
  for (int i = 0; i < crown.size(); i++) {
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
      + "\nCollide.polygonPoint: " + hitboxSays;
  Overlay.label(g, 8, py > height - 110 ? 46 : height - 72, text, inside ? Overlay.HIT : Overlay.MISS);
  for (RayHit t : touched) {
    Overlay.labelBeside(g, t.x(), t.y() + 8, 0, 1, "corner: not crossed", Overlay.GUIDE);
  }
}
