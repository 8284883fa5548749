// The 'd' overlay: each shape as Drawn.shape returns it, drawn again after popMatrix() (so in
// screen coordinates, with no matrix), with its bounding box and what kind it came back as.

void drawMaths() {
  noFill();
  strokeWeight(1);
  Shape[] all = {paddle, ball, blades[0], blades[1], blades[2], blades[3]};
  for (Shape s : all) {
    stroke(Overlay.GUIDE);
    Draw.shape(g, s);
    Rect box = s.bounds();
    stroke(Overlay.GUIDE, 90);
    rect(box.x(), box.y(), box.w(), box.h());
  }
  noStroke();
  Overlay.label(g, 20, 20, "Drawn.shape(g, new Rect(-80, -30, 160, 60))\n  -> " + describe(paddle), overPaddle ? Overlay.HIT : Overlay.TEXT);
  Overlay.label(g, 330, 20, "Drawn.shape(g, new Circle(0, 0, 40))\n  -> " + describe(ball), overBall ? Overlay.HIT : Overlay.TEXT);
  Overlay.label(g, 20, 330, "each blade: Drawn.shape(g, Polygon.of(...))\n  -> " + describe(blades[0]), overBlade >= 0 ? Overlay.HIT : Overlay.TEXT);
  fill(Overlay.HIT);
  circle(mouseX, mouseY, 6);
}

/** The kind the shape came back as, and its size. */
String describe(Shape s) {
  if (s instanceof Polygon) {
    Polygon p = (Polygon) s;
    return "Polygon, " + p.size() + " corners, first (" + Overlay.number(p.x(0)) + ", " + Overlay.number(p.y(0)) + ")";
  }
  if (s instanceof Ellipse) {
    Ellipse e = (Ellipse) s;
    return "Ellipse rx " + Overlay.number(e.rx()) + ", ry " + Overlay.number(e.ry()) + ", angle " + Overlay.number(e.angle());
  }
  return s.toString();
}
