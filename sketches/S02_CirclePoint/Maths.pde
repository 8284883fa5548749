// How close the mouse is, the answers, and the "show the maths" overlay (key d).

/**
 * Both answers, each in its colour, the one that picks the colour marked, and whether they
 * agree (on the second line): "the tutorial's if: inside  (picks the colour)".
 */
void answers(String tutorials, boolean tutorialSays, String hitboxs, boolean hitboxSays, boolean hitboxDecides) {
  Overlay.label(g, 8, 8, tutorials + ": " + (tutorialSays ? "inside" : "outside") + (hitboxDecides ? "" : "  (picks the colour)"),
      tutorialSays ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, 8, 30, hitboxs + ": " + (hitboxSays ? "inside" : "outside") + (hitboxDecides ? "  (picks the colour)" : "")
      + (tutorialSays == hitboxSays ? ";  they agree" : ";  they DISAGREE"), hitboxSays ? Overlay.HIT : Overlay.MISS);
}

/**
 * The mouse is close: the ring closeDistance out from the outline, a line from the mouse to
 * the nearest point of the outline, and how far that is, dist(...) - circleRadius.
 */
void drawHowClose() {
  float d = dist(mouseX, mouseY, circleCenterX, circleCenterY);
  float nearestX = circleCenterX + (mouseX - circleCenterX) * circleRadius / d;
  float nearestY = circleCenterY + (mouseY - circleCenterY) * circleRadius / d;
  noFill();
  stroke(Palette.ACCENT, 90);
  strokeWeight(1);
  ellipse(circleCenterX, circleCenterY, (circleRadius + closeDistance) * 2, (circleRadius + closeDistance) * 2);
  stroke(Palette.ACCENT);
  strokeWeight(2);
  line(mouseX, mouseY, nearestX, nearestY);
  Overlay.labelBeside(g, mouseX + (mouseX - circleCenterX) / d * 10, mouseY + (mouseY - circleCenterY) / d * 10,
      (mouseX - circleCenterX) / d, (mouseY - circleCenterY) / d,
      "close: " + Overlay.number(d - circleRadius) + " px from the circle", Palette.ACCENT);
}

/** The distance from the centre to the mouse, the radius beside it, and dist < r written out. */
void drawMaths(boolean inside) {
  float d = dist(circleCenterX, circleCenterY, mouseX, mouseY);
  // The direction from the centre to the mouse (to the right when the mouse is on the centre).
  float ux = d > 0.5 ? (mouseX - circleCenterX) / d : 1;
  float uy = d > 0.5 ? (mouseY - circleCenterY) / d : 0;
  // The radius, along the same direction, set to one side (-uy, ux) of the distance line.
  Overlay.radius(g, circleCenterX, circleCenterY, ux, uy, circleRadius, "r");

  // The distance: a dashed line from the centre to the mouse, its length written beside it
  // on the other side.
  Overlay.guide(g, circleCenterX, circleCenterY, mouseX, mouseY);
  Overlay.labelBeside(g, (circleCenterX + mouseX) / 2, (circleCenterY + mouseY) / 2, uy, -ux,
      "dist = " + Overlay.number(d), Overlay.GUIDE);

  // The centre, where both lines start.
  noStroke();
  fill(Overlay.GUIDE);
  circle(circleCenterX, circleCenterY, 6);

  // The test written out: the tutorial's way, with dist(), and Collide.circlePoint's, squared.
  float dx = mouseX - circleCenterX;
  float dy = mouseY - circleCenterY;
  String squared = "dx * dx + dy * dy < r * r:  " + int(dx * dx + dy * dy) + " < " + int(circleRadius * circleRadius);
  color colour = inside ? Overlay.HIT : Overlay.MISS;
  Overlay.labelCentered(g, width / 2, 8, "dist < r:  " + Overlay.verdict(d, "<", circleRadius, inside)
      + "\n" + squared + "  (Collide.circlePoint)", colour);
}
