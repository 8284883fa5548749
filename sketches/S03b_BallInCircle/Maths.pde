// The "show the maths" overlay: the distance, both radii, and dist < r + R.

void drawMaths() {
  float d = dist(x, y, cx, cy);
  float ux = d > 0.5 ? (cx - x) / d : 1;
  float uy = d > 0.5 ? (cy - y) / d : 0;

  Overlay.radius(g, x, y, ux, uy, r, "r");
  Overlay.radius(g, cx, cy, -ux, -uy, R, "R");
  Overlay.guide(g, x, y, cx, cy);
  noStroke();
  fill(Overlay.GUIDE);
  circle(x, y, 6);
  circle(cx, cy, 6);
  Overlay.labelBeside(g, (x + cx) / 2 + uy * 18, (y + cy) / 2 - ux * 18, uy, -ux, "dist = " + Overlay.number(d), Overlay.GUIDE);

  color colour = inside ? Overlay.HIT : Overlay.MISS;
  float verdictY = y - r < 60 && abs(x - width / 2) < 150 ? height - 46 : 28;
  Overlay.labelCentered(g, width / 2, verdictY, "dist < r + R\n" + Overlay.verdict(d, "<", r + R, inside), colour);
}
