// The 'd' overlay: the nearest ellipse's radii, and its test written out with the mouse's
// numbers: (dx / rx)^2 + (dy / ry)^2 < 1 for a point (for the turned ellipse, dx and dy
// measured along its own turned axes: u = dx cos + dy sin, v = -dx sin + dy cos).

void drawMaths() {
  // The ellipse whose centre is nearest the mouse.
  int n = 0;
  for (int i = 1; i < ellipses.length; i++) {
    if (dist(mouseX, mouseY, ellipses[i].x(), ellipses[i].y()) < dist(mouseX, mouseY, ellipses[n].x(), ellipses[n].y())) {
      n = i;
    }
  }
  Ellipse e = ellipses[n];
  float c = cos(e.angle());
  float s = sin(e.angle());
  Overlay.radius(g, e.x(), e.y(), c, s, e.rx(), "rx");
  // ry drawn down its axis (-s, c): its label goes above the centre, rx's to the left, apart.
  Overlay.radius(g, e.x(), e.y(), -s, c, e.ry(), "ry");
  Overlay.guide(g, e.x(), e.y(), mouseX, mouseY);
  noStroke();
  fill(Overlay.GUIDE);
  circle(e.x(), e.y(), 6);

  float dx = mouseX - e.x();
  float dy = mouseY - e.y();
  float u = (dx * c + dy * s) / e.rx();
  float v = (-dx * s + dy * c) / e.ry();
  color colour = hit[n] ? Overlay.HIT : Overlay.MISS;
  String test;
  if (circleMode) {
    test = "e.overlaps(mouseCircle): the circle's centre inside, or its distance\nto the outline < r = "
        + Overlay.number(mouseR) + "  ->  " + (hit[n] ? "overlap" : "apart");
  } else {
    String formula = e.angle() != 0 ? "(u / rx)^2 + (v / ry)^2 < 1, u and v along the turned axes" : "(dx / rx)^2 + (dy / ry)^2 < 1";
    test = formula + "\n" + Overlay.verdict(u * u + v * v, "<", 1, hit[n]);
  }
  Overlay.labelCentered(g, width / 2, 28, test, colour);
}
