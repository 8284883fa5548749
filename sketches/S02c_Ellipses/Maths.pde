// The 'd' overlay: the nearest ellipse's radii, and its test written out with the mouse's
// numbers: (dx / rx)^2 + (dy / ry)^2 < 1 for a point.

void drawMaths() {
  // The ellipse whose centre is nearest the mouse.
  int n = 0;
  for (int i = 1; i < ellipses.length; i++) {
    if (dist(mouseX, mouseY, ellipses[i].x(), ellipses[i].y()) < dist(mouseX, mouseY, ellipses[n].x(), ellipses[n].y())) {
      n = i;
    }
  }
  Ellipse e = ellipses[n];
  Overlay.radius(g, e.x(), e.y(), 1, 0, e.rx(), "rx");
  Overlay.radius(g, e.x(), e.y(), 0, -1, e.ry(), "ry");
  Overlay.guide(g, e.x(), e.y(), mouseX, mouseY);
  noStroke();
  fill(Overlay.GUIDE);
  circle(e.x(), e.y(), 6);

  float u = (mouseX - e.x()) / e.rx();
  float v = (mouseY - e.y()) / e.ry();
  color colour = hit[n] ? Overlay.HIT : Overlay.MISS;
  String test;
  if (circleMode) {
    test = "Collide.ellipseCircle: the circle's centre inside, or its distance\nto the outline < r = "
        + Overlay.number(mouseR) + "  ->  " + (hit[n] ? "overlap" : "apart");
  } else {
    test = "(dx / rx)^2 + (dy / ry)^2 < 1\n" + Overlay.verdict(u * u + v * v, "<", 1, hit[n]);
  }
  Overlay.labelCentered(g, width / 2, 28, test, colour);
}
