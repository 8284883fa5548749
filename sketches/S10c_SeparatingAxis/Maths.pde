// The axes panel, the axis drawn beside the shapes, and the "show the maths" details (key d).

int panelX = 566;             // the axes panel, right of the shapes

/** The axis where the shadows overlap least: the shortest way out. */
int leastOverlap() {
  int least = 0;
  for (int i = 1; i < axes.size(); i++) {
    if (axes.get(i).overlap() < axes.get(least).overlap()) {
      least = i;
    }
  }
  return least;
}

/** Which edge an axis belongs to: the rectangle's edges come first, then the triangle's. */
String owner(int i) {
  return i < box.size() ? "rect edge " + i : shapeName() + " edge " + (i - box.size());
}

String shapeName() {
  return sides == 3 ? "triangle" : sides + "-gon";
}

/**
 * One axis drawn beside the shapes: a line along the axis, just clear of both shapes, with
 * each shape's shadow on it. A point whose shadow is at s along the axis lands at
 * s - (centre . axis) from the line's middle.
 */
void drawAxisInPlace(int i) {
  SeparatingAxis.Axis a = axes.get(i);
  float nx = a.nx(), ny = a.ny();
  float base = cx * nx + cy * ny;
  float aLo = a.minA() - base, aHi = a.maxA() - base;
  float bLo = a.minB() - base, bHi = a.maxB() - base;
  float lo = min(aLo, bLo) - 30, hi = max(aHi, bHi) + 30;
  // Across the axis: the line goes on the side where it stays in view, clear of the
  // rectangle's corners (97 from its centre) and of the mouse shape's (52 from the mouse).
  float px = -ny, py = nx;
  float across = (mouseX - cx) * px + (mouseY - cy) * py;
  float plus = max(97, across + 52) + 18;
  float minus = max(97, -across + 52) + 18;
  float outPlus = outOfView(cx + px * plus, cy + py * plus, nx, ny, lo, hi);
  float outMinus = outOfView(cx - px * minus, cy - py * minus, nx, ny, lo, hi);
  boolean flip = outMinus < outPlus || (outMinus == outPlus && minus < plus);
  if (flip) {
    px = -px;
    py = -py;
  }
  float d = flip ? minus : plus;
  float ox = cx + px * d, oy = cy + py * d;
  boolean separates = a.separates();
  color colour = separates ? Palette.MISS : Palette.HIT;

  if (showMaths) {
    // The light that casts the shadows: from each shadow's ends straight back across the
    // axis, grazing the shapes' outermost corners.
    for (float t : new float[] {aLo, aHi, bLo, bHi}) {
      Overlay.guide(g, ox + nx * t, oy + ny * t, ox + nx * t - px * (d + 110), oy + ny * t - py * (d + 110));
    }
  } else if (separates) {
    // A line through the middle of the gap fits between the shapes.
    float mid = (min(aHi, bHi) + max(aLo, bLo)) / 2;
    Overlay.guide(g, ox + nx * mid, oy + ny * mid, ox + nx * mid - px * (d + 110), oy + ny * mid - py * (d + 110));
  }

  stroke(colour);
  strokeWeight(1.5);
  line(ox + nx * lo, oy + ny * lo, ox + nx * hi, oy + ny * hi);
  strokeCap(SQUARE);
  strokeWeight(6);
  stroke(overlapping ? Palette.HIT : Palette.MISS);
  line(ox + nx * aLo + px * 3, oy + ny * aLo + py * 3, ox + nx * aHi + px * 3, oy + ny * aHi + py * 3);
  stroke(Palette.PLAYER);
  line(ox + nx * bLo - px * 3, oy + ny * bLo - py * 3, ox + nx * bHi - px * 3, oy + ny * bHi - py * 3);
  strokeCap(ROUND);

  String text = "axis " + (i + 1) + (separates ? ": gap " + Overlay.number(-a.overlap()) : ": overlap " + Overlay.number(a.overlap()));
  // At the line's end that leaves the label most room inside the shapes' area.
  float hx = ox + nx * hi, hy = oy + ny * hi, lx = ox + nx * lo, ly = oy + ny * lo;
  if (room(hx, hy) >= room(lx, ly)) {
    Overlay.labelBeside(g, hx, hy, nx + px, ny + py, text, separates ? Overlay.MISS : Overlay.HIT);
  } else {
    Overlay.labelBeside(g, lx, ly, -nx + px, -ny + py, text, separates ? Overlay.MISS : Overlay.HIT);
  }
}

/** How far a point is from the shapes' area's nearest edge (the right one counts a label's width). */
float room(float x, float y) {
  return min(min(x, panelX - 130 - x), min(y - 20, height - 60 - y));
}

/** How far the ends of a line from (ox, oy) + n * lo to (ox, oy) + n * hi are outside the shapes' area. */
float outOfView(float ox, float oy, float nx, float ny, float lo, float hi) {
  float out = 0;
  for (float t : new float[] {lo, hi}) {
    float x = ox + nx * t, y = oy + ny * t;
    out += max(0, 12 - x) + max(0, x - (panelX - 12)) + max(0, 12 - y) + max(0, y - (height - 48));
  }
  return out;
}

/** Every axis as a row: its direction, both shadows to scale, and whether it separates. */
void drawPanel() {
  noStroke();
  fill(#171A20);
  rect(panelX, 0, width - panelX, height);
  fill(Palette.NEUTRAL);
  textAlign(LEFT, TOP);
  textSize(13);
  text("shadows on each axis (" + axes.size() + ")", panelX + 12, 10);
  int rowH = min(38, (height - 60) / axes.size());
  for (int i = 0; i < axes.size(); i++) {
    drawRow(i, 32 + i * rowH, rowH);
  }
}

void drawRow(int i, float y, int rowH) {
  SeparatingAxis.Axis a = axes.get(i);
  boolean separates = a.separates();
  if (i == shown) {
    noStroke();
    fill(separates ? Palette.MISS : Palette.HIT, 45);
    rect(panelX + 4, y - 2, width - panelX - 8, rowH - 2, 4);
  }
  // The direction, as a little arrow in a circle.
  float gx = panelX + 20, gy = y + rowH / 2.0 - 1;
  noFill();
  stroke(Palette.LINE);
  strokeWeight(1);
  circle(gx, gy, 24);
  stroke(Palette.NEUTRAL);
  strokeWeight(1.5);
  Draw.arrow(g, gx - a.nx() * 9, gy - a.ny() * 9, a.nx() * 18, a.ny() * 18);

  // The name and the verdict.
  fill(separates ? Palette.MISS : #AAB0BC);
  textAlign(LEFT, TOP);
  textSize(11);
  text((i + 1) + "  " + owner(i), panelX + 38, y);
  textAlign(RIGHT, TOP);
  text(separates ? "gap " + Overlay.number(-a.overlap()) : "overlap " + Overlay.number(a.overlap()), width - 10, y);

  // Both shadows, scaled to fit the row.
  float lo = min(a.minA(), a.minB()), hi = max(a.maxA(), a.maxB());
  float x0 = panelX + 38, x1 = width - 12;
  float barY = y + 16;
  strokeCap(SQUARE);
  strokeWeight(5);
  stroke(overlapping ? Palette.HIT : Palette.MISS);
  line(map(a.minA(), lo, hi, x0, x1), barY, map(a.maxA(), lo, hi, x0, x1), barY);
  stroke(Palette.PLAYER);
  line(map(a.minB(), lo, hi, x0, x1), barY + 6, map(a.maxB(), lo, hi, x0, x1), barY + 6);
  strokeCap(ROUND);
  float gapLo = min(a.maxA(), a.maxB()), gapHi = max(a.minA(), a.minB());
  if (separates) {
    stroke(Palette.ACCENT);
    strokeWeight(1.5);
    float gx0 = map(gapLo, lo, hi, x0, x1), gx1 = map(gapHi, lo, hi, x0, x1);
    line(gx0, barY - 4, gx0, barY + 10);
    line(gx1, barY - 4, gx1, barY + 10);
  }
  if (showMaths && rowH >= 30) {
    fill(#AAB0BC);
    textSize(10);
    textAlign(LEFT, TOP);
    text("[" + Overlay.number(a.minA()) + ", " + Overlay.number(a.maxA()) + "]  ["
        + Overlay.number(a.minB()) + ", " + Overlay.number(a.maxB()) + "]", x0, barY + 9);
  }
}

