// The "show the maths" overlay (d): every body's box (it grows and shrinks as the body turns),
// the grid's cells, the ship's contacts with their normals, and the sentry's answer.

boolean showMaths = false;

void drawMaths() {
  if (showMaths) {
    WorldDraw.debug(g, world);
    if (sight != null && !seen) {
      Overlay.guide(g, sight.hit().x(), sight.hit().y(), ship.x(), ship.y());   // the rest of the way
    }
  }
  Overlay.label(g, 8, 8, (seen ? "the sentry sees the ship" : "the ship is hidden from the sentry")
      + "   contacts with rocks: " + hits + (demo ? "\n(demo: press an arrow key to fly)" : ""),
      seen ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "LEFT RIGHT turn   UP thrusts   d: show the maths (boxes, cells, contacts, the ray)");
  if (!showMaths) {
    return;
  }
  String answer = sight == null ? "null: nothing in the way"
      : sight.body() == ship ? "the ship, at " + Overlay.number(sight.distance()) + " px: seen"
      : "rock " + rocks.indexOf(sight.body()) + ", at " + Overlay.number(sight.distance()) + " px: hidden";
  String text = "ship: translate(" + Overlay.number(ship.x()) + ", " + Overlay.number(ship.y()) + "); rotate("
      + Overlay.number(ship.angle()) + ")\nworld.raycastFirst(sentry to ship): " + answer;
  for (Collision c : met) {
    text += "\nthe ship met rock " + rocks.indexOf(c.other()) + ": " + c.reaction() + ", normal ("
        + Overlay.number(c.nx()) + ", " + Overlay.number(c.ny()) + ")";
  }
  Overlay.label(g, 8, 48, text, Overlay.GUIDE);
}
