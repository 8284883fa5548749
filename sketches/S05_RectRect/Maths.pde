// The "show the maths" overlay (key d) and the drawing helpers.

/** The two rectangles' names, as the maths calls them. */
void names() {
  fill(Palette.BACKGROUND);
  textAlign(LEFT, TOP);
  textSize(13);
  text("r2", r2x + 6, r2y + 4);
  fill(Palette.NEUTRAL);
  text("r1", r1x + 6, r1y + 4);
}

/** One answer, written in its colour: "the tutorial's if: colliding". */
void answer(float x, float y, String who, boolean colliding) {
  Overlay.label(g, x, y, who + ": " + (colliding ? "colliding" : "not colliding"), colour(colliding));
}

/** The four comparisons, each drawn at the two edges it compares, and the verdict. */
void drawMaths(boolean colliding) {
  boolean a = r1x + r1w > r2x;   // r1's right edge is past r2's left edge
  boolean b = r1x < r2x + r2w;   // r1's left edge is before r2's right edge
  boolean c = r1y + r1h > r2y;   // r1's bottom edge is below r2's top edge
  boolean d = r1y < r2y + r2h;   // r1's top edge is above r2's bottom edge

  // r2's edges, extended across the window: each comparison asks on which side of one of
  // these lines r1's opposite edge is.
  edgeLine(r2x, true, a);
  edgeLine(r2x + r2w, true, b);
  edgeLine(r2y, false, c);
  edgeLine(r2y + r2h, false, d);
  // The edges each comparison compares, in its colour.
  edge(r1x + r1w, r1y, r1x + r1w, r1y + r1h, a);
  edge(r1x, r1y, r1x, r1y + r1h, b);
  edge(r1x, r1y + r1h, r1x + r1w, r1y + r1h, c);
  edge(r1x, r1y, r1x + r1w, r1y, d);
  edge(r2x, r2y, r2x, r2y + r2h, a);
  edge(r2x + r2w, r2y, r2x + r2w, r2y + r2h, b);
  edge(r2x, r2y, r2x + r2w, r2y, c);
  edge(r2x, r2y + r2h, r2x + r2w, r2y + r2h, d);

  // Each comparison written at r2's edge, outside it.
  Overlay.labelBeside(g, r2x - 8, r2y + r2h / 2, -1, 0,
      "r1 right > r2 left\n" + Overlay.comparison(r1x + r1w, ">", r2x, a), colour(a));
  Overlay.labelBeside(g, r2x + r2w + 8, r2y + r2h / 2, 1, 0,
      "r1 left < r2 right\n" + Overlay.comparison(r1x, "<", r2x + r2w, b), colour(b));
  Overlay.labelBeside(g, r2x + r2w / 2, r2y - 8, 0, -1,
      "r1 bottom > r2 top\n" + Overlay.comparison(r1y + r1h, ">", r2y, c), colour(c));
  Overlay.labelBeside(g, r2x + r2w / 2, r2y + r2h + 8, 0, 1,
      "r1 top < r2 bottom\n" + Overlay.comparison(r1y, "<", r2y + r2h, d), colour(d));

  // The verdict, at the top, or at the bottom while r1 is up there.
  int holding = (a ? 1 : 0) + (b ? 1 : 0) + (c ? 1 : 0) + (d ? 1 : 0);
  String verdict = (holding == 4 ? "all four hold" : holding + " of 4 hold") + ": " + (colliding ? "colliding" : "not colliding");
  float verdictY = r1y < 50 ? height - 46 : 28;
  Overlay.labelCentered(g, width / 2, verdictY,
      "r1x + r1w > r2x && r1x < r2x + r2w && r1y + r1h > r2y && r1y < r2y + r2h\n" + verdict, colour(colliding));
}

/** An edge, drawn thick in its comparison's colour. */
void edge(float x1, float y1, float x2, float y2, boolean holds) {
  stroke(colour(holds));
  strokeWeight(4);
  line(x1, y1, x2, y2);
}

/** One of r2's edges extended across the window, thin. */
void edgeLine(float at, boolean vertical, boolean holds) {
  stroke(colour(holds), 90);
  strokeWeight(1);
  if (vertical) {
    line(at, 0, at, height);
  } else {
    line(0, at, width, at);
  }
}

/** A comparison that holds pushes towards a collision: the colliding colour. */
color colour(boolean holds) {
  return holds ? Overlay.HIT : Overlay.MISS;
}
