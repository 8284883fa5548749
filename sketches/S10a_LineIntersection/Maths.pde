// Where the line crosses each outline, and the "show the maths" overlay.

/**
 * Where the line crosses each outline: a ray from the start towards the mouse finds the
 * first crossing, one from the mouse back towards the start the last.
 */
void drawCrossings() {
  if (startX == mouseX && startY == mouseY) {
    return;  // a point: no direction to cast in
  }
  Ray forward = Ray.between(startX, startY, mouseX, mouseY);
  Ray back = Ray.between(mouseX, mouseY, startX, startY);
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

/** The maths: for each segment the four side tests, for the rectangle and circle their parts. */
void drawMaths() {
  float ax = startX;  // the line's ends, A1 and A2
  float ay = startY;
  float bx = mouseX;
  float by = mouseY;
  Overlay.labelBeside(g, ax, ay - 8, 0, -1, "A1", Overlay.TEXT);
  Overlay.labelBeside(g, bx + 8, by + 8, 1, 1, "A2", Overlay.TEXT);
  // Each segment's four side tests, in a row along the top, above its segment.
  for (int i = 0; i < segments.length; i++) {
    Segment s = segments[i];
    String a1 = sideWord(s.x1(), s.y1(), s.x2(), s.y2(), ax, ay);
    String a2 = sideWord(s.x1(), s.y1(), s.x2(), s.y2(), bx, by);
    String s1 = sideWord(ax, ay, bx, by, s.x1(), s.y1());
    String s2 = sideWord(ax, ay, bx, by, s.x2(), s.y2());
    String text = "lineLine(A, " + names[i] + "): " + segmentHit[i] + "\n"
        + "A1, A2 vs " + names[i] + ": " + a1 + " | " + a2 + "\n"
        + names[i] + "'s ends vs A: " + s1 + " | " + s2;
    Overlay.label(g, 8 + i * 197, 8, text, segmentHit[i] ? Overlay.HIT : Overlay.MISS);
  }

  // The rectangle: which of its edges the line meets (lineLine on each). Collide.lineRect
  // asks whether the line reaches inside, which a line wholly inside does too, meeting none.
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
 * end to the second, in the overlay's words: Collide.lineSide, the sign that
 * Collide.lineLine compares.
 */
String sideWord(float x1, float y1, float x2, float y2, float px, float py) {
  int side = Collide.lineSide(x1, y1, x2, y2, px, py);
  return side > 0 ? "right" : side < 0 ? "left" : "on it";
}
