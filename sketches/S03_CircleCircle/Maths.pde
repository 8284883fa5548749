// The answers, and the "show the maths" overlay: the line between the centres, both radii, and the test.

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

/** The line between the centres with its length, each radius along it, and dist < r1 + r2. */
void drawMaths(boolean colliding) {
  float x1 = mouseX;                 // circle 1: the small one, on the mouse
  float y1 = mouseY;
  float r1 = smallCircleRadius;
  float x2 = width / 2;              // circle 2: the big one, in the middle
  float y2 = height / 2;
  float r2 = bigCircleRadius;
  float d = dist(x1, y1, x2, y2);
  // The direction from circle 1 to circle 2 (to the right when the centres coincide).
  float ux = d > 0.5 ? (x2 - x1) / d : 1;
  float uy = d > 0.5 ? (y2 - y1) / d : 0;
  // Sideways: radius 1 is drawn on this side of the line, radius 2 on the other.
  float px = -uy;
  float py = ux;

  Overlay.radius(g, x1, y1, ux, uy, r1, "r1");
  Overlay.radius(g, x2, y2, -ux, -uy, r2, "r2");

  // The distance between the centres: a dashed line.
  Overlay.guide(g, x1, y1, x2, y2);
  noStroke();
  fill(Overlay.GUIDE);
  circle(x1, y1, 6);
  circle(x2, y2, 6);
  // Its label goes beside the middle, outside radius 2's bar, so the place where the bars meet
  // or pass each other stays visible.
  Overlay.labelBeside(g, (x1 + x2) / 2 - px * 18, (y1 + y2) / 2 - py * 18, -px, -py, "dist = " + Overlay.number(d), Overlay.GUIDE);

  // The test written out at the top, or at the bottom while the mouse circle is up there:
  // the tutorial's way, with dist(), and Collide.circleCircle's, squared.
  float dx = x1 - x2;
  float dy = y1 - y2;
  String squared = "dx * dx + dy * dy < (r1 + r2) * (r1 + r2):  " + int(dx * dx + dy * dy) + " < " + int((r1 + r2) * (r1 + r2));
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  float verdictY = y1 - r1 < 50 ? height - 52 : 34;
  Overlay.labelCentered(g, width / 2, verdictY, "dist < r1 + r2:  " + Overlay.verdict(d, "<", r1 + r2, colliding)
      + "\n" + squared + "  (Collide.circleCircle)", colour);
}
