// The walls outside a box's edges, and the "show the maths" overlay.

/** With a box's edges, everything outside them is wall: shaded, with the edges drawn. */
void drawWalls() {
  if (right == width && left == 0) {
    return;  // the window's edges: the window is the box
  }
  noStroke();
  fill(Palette.OBSTACLE, 60);
  rect(0, 0, width, top);
  rect(0, bottom, width, height - bottom);
  rect(0, top, left, bottom - top);
  rect(right, top, width - right, bottom - top);
  stroke(Palette.OBSTACLE);
  strokeWeight(2);
  noFill();
  rect(left, top, right - left, bottom - top);
}

/**
 * The four edge tests, written out with this frame's numbers and what each does to the
 * speed when it holds, in a panel on the side away from the ball; guides from the ball to
 * the edges they test.
 */
void drawMaths() {
  Overlay.guide(g, x, y, left, y);
  Overlay.guide(g, x, y, right, y);
  Overlay.guide(g, x, y, x, top);
  Overlay.guide(g, x, y, x, bottom);
  // The ball's centre: the tutorial's point, and where Hitbox's r is measured from.
  noStroke();
  fill(Overlay.GUIDE);
  circle(x, y, 6);

  float px = x < width / 2 ? width - 300 : 10;
  float py = y < height / 2 ? height - 134 : 32;
  if (!hitboxDecides) {
    boolean window = right == width;
    testLine(px, py, "x < " + Overlay.number(left), x, "<", left, "xSpeed *= -1");
    testLine(px, py + 22, "x > " + (window ? "width" : Overlay.number(right)), x, ">", right, "xSpeed *= -1");
    testLine(px, py + 44, "y < " + Overlay.number(top), y, "<", top, "ySpeed *= -1");
    testLine(px, py + 66, "y > " + (window ? "height" : Overlay.number(bottom)), y, ">", bottom, "ySpeed *= -1");
  } else {
    testLine(px, py, "x - r < left", x - r, "<", left, "xSpeed = abs(xSpeed)");
    testLine(px, py + 22, "x + r > right", x + r, ">", right, "xSpeed = -abs(xSpeed)");
    testLine(px, py + 44, "y - r < top", y - r, "<", top, "ySpeed = abs(ySpeed)");
    testLine(px, py + 66, "y + r > bottom", y + r, ">", bottom, "ySpeed = -abs(ySpeed)");
  }
  Overlay.label(g, px, py + 88, "now: xSpeed = " + Overlay.number(xSpeed) + ", ySpeed = " + Overlay.number(ySpeed));
}

/** One edge test: what it compares, with the numbers, and what it did if it held. */
void testLine(float lx, float ly, String test, float a, String op, float b, String action) {
  boolean holds = op.equals("<") ? a < b : a > b;
  Overlay.label(g, lx, ly, test + ":  " + Overlay.comparison(a, op, b, holds) + (holds ? "  ->  " + action : ""),
      holds ? Overlay.HIT : Overlay.MISS);
}
