// The "show the maths" overlay (d): what the world sees (the grid's cells, every body's box,
// this frame's contacts with their normals), the player's collisions written out, and what
// it stands on.

boolean showMaths = false;

void drawMaths() {
  if (showMaths) {
    WorldDraw.debug(g, world);
  }
  Overlay.label(g, 8, 8, "coins: " + collected + (demo ? "   (demo: press an arrow key to play)" : ""));
  Overlay.hint(g, "LEFT RIGHT run   UP or SPACE jumps   d: show the maths (boxes, cells, contacts and their normals)");
  if (!showMaths) {
    return;
  }
  String text = "the player's move this frame met:";
  if (met.isEmpty()) {
    text += "\n  nothing (in the air)";
  }
  for (Collision c : met) {
    text += "\n  " + name(c.other()) + ": " + c.reaction() + ", normal (" + Overlay.number(c.nx()) + ", "
        + Overlay.number(c.ny()) + ")" + (c.landed() ? ", landed" : "");
  }
  text += "\non the ground: " + player.onGround();
  if (player.onGround()) {
    Vec n = player.groundNormal();
    text += ", on " + name(player.ground()) + ", its normal (" + Overlay.number(n.x() + 0) + ", " + Overlay.number(n.y() + 0) + ")";   // + 0: no -0.0
  }
  text += "\n" + world;
  Overlay.label(g, 8, 34, text, Overlay.GUIDE);
}

String name(Body b) {
  if (b == slope) {
    return "the slope";
  } else if (tiles.indexOf(b) > tiles.indexOf(slope)) {
    return "step " + (tiles.indexOf(b) - tiles.indexOf(slope));
  } else if (tiles.contains(b)) {
    return "tile " + tiles.indexOf(b);
  } else if (platforms.contains(b)) {
    return "one-way platform " + platforms.indexOf(b);
  } else if (b == lift) {
    return "moving platform";
  } else if (coins.contains(b) || b.isSensor()) {
    return "coin (a sensor)";
  }
  return "window side";
}
