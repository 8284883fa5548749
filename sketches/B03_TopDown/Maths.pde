// The "show the maths" overlay (d): every body's box (it grows and shrinks as the body turns),
// the grid's cells, the ship's contacts with their normals, and the sentry's answer.

boolean showMaths = false;

void drawMaths() {
  if (showMaths) {
    WorldDraw.debug(g, world);
    if (sight != null && !seen) {
      Overlay.guide(g, sight.hit().x(), sight.hit().y(), ship.body().pivotX(), ship.body().pivotY());   // the rest of the way
    }
  }
  Overlay.label(g, 8, 8, (seen ? "the sentry sees the ship" : "the ship is hidden from the sentry")
      + "   contacts with rocks and walls: " + hits + (demo ? "\n(demo: press an arrow key to fly)" : ""),
      seen ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "LEFT RIGHT turn   UP thrusts   d: show the maths (boxes, cells, contacts, the ray)");
  if (!showMaths) {
    return;
  }
  String answer = sight == null ? "null: nothing in the way"
      : sight.body() == ship.body() ? "the ship, at " + Overlay.number(sight.distance()) + " px: seen"
      : name(sight.body()) + ", at " + Overlay.number(sight.distance()) + " px: hidden";
  Body b = ship.body();
  String text = "ship: translate(" + Overlay.number(b.pivotX()) + ", " + Overlay.number(b.pivotY()) + "); rotate("
      + Overlay.number(b.angle()) + ")\nworld.raycastFirst(sentry to ship): " + answer;
  for (Collision c : met) {
    text += "\nthe ship met " + name(c.other()) + ": " + c.reaction() + ", normal ("
        + Overlay.number(c.nx()) + ", " + Overlay.number(c.ny()) + ")"
        + (c.hit().alreadyOverlapping() ? ": turned into it, pushed out" : "");
  }
  Overlay.label(g, 8, 48, text, Overlay.GUIDE);
}

String name(Body b) {
  return rocks.contains(b) ? "rock " + rocks.indexOf(b) : "wall " + walls.indexOf(b);
}
