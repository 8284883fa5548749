// The "show the maths" overlay: the distance, both radii, and dist < r + circleRadius.

void drawMaths() {
  float d = dist(x, y, circleCenterX, circleCenterY);
  float ux = d > 0.5 ? (circleCenterX - x) / d : 1;
  float uy = d > 0.5 ? (circleCenterY - y) / d : 0;

  Overlay.radius(g, x, y, ux, uy, r, "r");
  Overlay.radius(g, circleCenterX, circleCenterY, -ux, -uy, circleRadius, "circleRadius");
  Overlay.guide(g, x, y, circleCenterX, circleCenterY);
  noStroke();
  fill(Overlay.GUIDE);
  circle(x, y, 6);
  circle(circleCenterX, circleCenterY, 6);
  Overlay.labelBeside(g, (x + circleCenterX) / 2 + uy * 18, (y + circleCenterY) / 2 - ux * 18, uy, -ux, "dist = " + Overlay.number(d), Overlay.GUIDE);

  color colour = inside ? Overlay.HIT : Overlay.MISS;
  float verdictY = y - r < 60 && abs(x - width / 2) < 150 ? height - 46 : 28;
  Overlay.labelCentered(g, width / 2, verdictY, "dist < r + circleRadius\n" + Overlay.verdict(d, "<", r + circleRadius, inside), colour);
}
