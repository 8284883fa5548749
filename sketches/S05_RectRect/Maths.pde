// The "show the maths" overlay (key d) and the drawing helpers.

/**
 * Both answers, each in its colour, the one that picks the colour marked, and whether they
 * agree (on the second line): "the tutorial's if: colliding  (picks the colour)".
 */
void answers(String tutorials, boolean tutorialSays, String hitboxs, boolean hitboxSays, boolean hitboxDecides) {
  Overlay.label(g, 8, 8, tutorials + ": " + (tutorialSays ? "colliding" : "not colliding") + (hitboxDecides ? "" : "  (picks the colour)"),
      tutorialSays ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, 8, 30, hitboxs + ": " + (hitboxSays ? "colliding" : "not colliding") + (hitboxDecides ? "  (picks the colour)" : "")
      + (tutorialSays == hitboxSays ? ";  they agree" : ";  they DISAGREE"), hitboxSays ? Overlay.HIT : Overlay.MISS);
}

/** The four comparisons, each drawn at the two edges it compares, and the verdict. */
void drawMaths(boolean colliding) {
  float mx = mouseX, my = mouseY, mw = mouseRectWidth, mh = mouseRectHeight;
  float cx = centerRectX, cy = centerRectY, cw = centerRectWidth, ch = centerRectHeight;
  boolean a = mx + mw > cx;   // the mouse rectangle's right edge is past the center one's left edge
  boolean b = mx < cx + cw;   // its left edge is before the center one's right edge
  boolean c = my + mh > cy;   // its bottom edge is below the center one's top edge
  boolean d = my < cy + ch;   // its top edge is above the center one's bottom edge

  // The center rectangle's edges, extended across the window: each comparison asks on which
  // side of one of these lines the mouse rectangle's opposite edge is.
  edgeLine(cx, true, a);
  edgeLine(cx + cw, true, b);
  edgeLine(cy, false, c);
  edgeLine(cy + ch, false, d);
  // The edges each comparison compares, in its colour.
  edge(mx + mw, my, mx + mw, my + mh, a);
  edge(mx, my, mx, my + mh, b);
  edge(mx, my + mh, mx + mw, my + mh, c);
  edge(mx, my, mx + mw, my, d);
  edge(cx, cy, cx, cy + ch, a);
  edge(cx + cw, cy, cx + cw, cy + ch, b);
  edge(cx, cy, cx + cw, cy, c);
  edge(cx, cy + ch, cx + cw, cy + ch, d);

  // Each comparison written at the center rectangle's edge, outside it.
  Overlay.labelBeside(g, cx - 8, cy + ch / 2, -1, 0,
      "mouseX + mouseRectWidth > centerRectX\n" + Overlay.comparison(mx + mw, ">", cx, a), colour(a));
  Overlay.labelBeside(g, cx + cw + 8, cy + ch / 2, 1, 0,
      "mouseX < centerRectX + centerRectWidth\n" + Overlay.comparison(mx, "<", cx + cw, b), colour(b));
  Overlay.labelBeside(g, cx + cw / 2, cy - 8, 0, -1,
      "mouseY + mouseRectHeight > centerRectY\n" + Overlay.comparison(my + mh, ">", cy, c), colour(c));
  Overlay.labelBeside(g, cx + cw / 2, cy + ch + 8, 0, 1,
      "mouseY < centerRectY + centerRectHeight\n" + Overlay.comparison(my, "<", cy + ch, d), colour(d));

  // The verdict, at the top, or at the bottom while the mouse rectangle is up there.
  int holding = (a ? 1 : 0) + (b ? 1 : 0) + (c ? 1 : 0) + (d ? 1 : 0);
  String verdict = (holding == 4 ? "all four hold" : holding + " of 4 hold") + ": " + (colliding ? "colliding" : "not colliding");
  float verdictY = my < 50 ? height - 46 : 8;
  Overlay.labelCentered(g, width / 2, verdictY, verdict, colour(colliding));
}

/** An edge, drawn thick in its comparison's colour. */
void edge(float x1, float y1, float x2, float y2, boolean holds) {
  stroke(colour(holds));
  strokeWeight(4);
  line(x1, y1, x2, y2);
}

/** One of the center rectangle's edges extended across the window, thin. */
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
