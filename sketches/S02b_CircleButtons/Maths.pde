// The "show the maths" overlay: each button's square, and the nearest button's test.

void drawMaths() {
  // Each button's square: a rectangle test would call all of it "on the button",
  // its corners too; the circle test does not.
  for (int i = 0; i < buttonX.length; i++) {
    float left = buttonX[i] - buttonRadius;
    float top = buttonY - buttonRadius;
    float right = buttonX[i] + buttonRadius;
    float bottom = buttonY + buttonRadius;
    Overlay.guide(g, left, top, right, top);
    Overlay.guide(g, right, top, right, bottom);
    Overlay.guide(g, right, bottom, left, bottom);
    Overlay.guide(g, left, bottom, left, top);
  }

  // The button nearest the mouse: the distance from its centre, its radius, and dist < r.
  int nearest = 0;
  for (int i = 1; i < buttonX.length; i++) {
    if (dist(mouseX, mouseY, buttonX[i], buttonY) < dist(mouseX, mouseY, buttonX[nearest], buttonY)) {
      nearest = i;
    }
  }
  float bx = buttonX[nearest];
  float d = dist(mouseX, mouseY, bx, buttonY);
  float ux = d > 0.5 ? (mouseX - bx) / d : 1;
  float uy = d > 0.5 ? (mouseY - buttonY) / d : 0;
  Overlay.radius(g, bx, buttonY, ux, uy, buttonRadius, "r");
  Overlay.guide(g, bx, buttonY, mouseX, mouseY);
  noStroke();
  fill(Overlay.GUIDE);
  circle(bx, buttonY, 6);
  // The mouse, again, over the lines.
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  boolean over = Collide.circlePoint(bx, buttonY, buttonRadius, mouseX, mouseY);
  boolean inSquare = abs(mouseX - bx) < buttonRadius && abs(mouseY - buttonY) < buttonRadius;
  String note = over ? "on the button" : inSquare ? "in its square, but not on the button" : "not on the button";
  Overlay.labelCentered(g, width / 2, 226, "nearest button: dist < r:  " + Overlay.verdict(d, "<", buttonRadius, over)
      + "\n" + note, over ? Overlay.HIT : Overlay.MISS);
}
