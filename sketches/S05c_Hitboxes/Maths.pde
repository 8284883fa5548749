// The hit box as a shape, its drawing, and the "show the maths" overlay (key d).

/** The hit box as a library shape: a Rect, a Circle, or a polygon shaped like the rocket. */
Shape hitBox() {
  if (boxShape.equals("circle")) {
    return new Circle(ship.x, ship.y, boxH / 2);
  } else if (boxShape.equals("polygon")) {
    float w = boxW / 2, h = boxH / 2;
    return Polygon.of(0, -h, w, -h / 3, w, h, -w, h, -w, -h / 3).translated(ship.x, ship.y);
  }
  return new Rect(boxX(), boxY(), boxW, boxH);
}

void drawBox() {
  noFill();
  stroke(Palette.NEUTRAL);
  strokeWeight(1.5);
  Draw.shape(g, hitBox());
  String size = boxShape.equals("circle") ? "radius " + (int) (boxH / 2) : (int) boxW + " x " + (int) boxH;
  Overlay.labelBeside(g, boxX() + boxW, boxY(), 1, -1, boxShape + " hit box " + size, Overlay.TEXT);
}

/**
 * Where the mistakes come from: the box's area outside the rocket (a rock there is a false
 * hit) in yellow, the rocket's area outside the box (a rock there is missed) in purple, each
 * measured in pixels by testing every pixel's centre against both.
 */
void drawMaths() {
  // Every pixel near the rocket: in both, the box only (yellow), or the rocket only (purple).
  Shape box = hitBox();
  int shipArea = 0, boxArea = 0, boxOnly = 0, shipOnly = 0;
  for (int py = (int) ship.y - 110; py < ship.y + 110; py++) {
    for (int px = (int) ship.x - 110; px < ship.x + 110; px++) {
      boolean inShip = ship.contains(px + 0.5, py + 0.5);
      boolean inBox = box.contains(px + 0.5, py + 0.5);
      shipArea += inShip ? 1 : 0;
      boxArea += inBox ? 1 : 0;
      boxOnly += inBox && !inShip ? 1 : 0;
      shipOnly += inShip && !inBox ? 1 : 0;
      if (inBox && !inShip) {
        set(px, py, FALSE_HIT_COLOUR);
      } else if (inShip && !inBox) {
        set(px, py, MISS_COLOUR);
      } else if (inShip) {
        set(px, py, #D8DCE4);
      }
    }
  }
  float lx = ship.x + 120;
  Overlay.label(g, lx, ship.y - 70, "rocket: " + shipArea + " px\u00B2\nhit box: " + boxArea + " px\u00B2");
  Overlay.label(g, lx, ship.y - 30, "box outside the rocket: " + boxOnly + " px\u00B2\nrocks here are false hits", FALSE_HIT_COLOUR);
  Overlay.label(g, lx, ship.y + 10, "rocket outside the box: " + shipOnly + " px\u00B2\nrocks here are missed", MISS_COLOUR);
  Overlay.label(g, lx, ship.y + 50, "first the box, then only if it is hit:\nbody, leftFin or rightFin .overlaps(rock)", Overlay.TEXT);
}
