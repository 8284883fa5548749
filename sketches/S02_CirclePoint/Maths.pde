// The "show the maths" overlay: the distance, the radius, and the test both ways.

/** The distance from the centre to the mouse, the radius beside it, and dist < r written out. */
void drawMaths() {
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
  Overlay.labelCentered(g, width / 2, 34, "dist < r:  " + Overlay.verdict(d, "<", circleRadius, inside)
      + "\n" + squared + "  (Collide.circlePoint)", colour);
}
