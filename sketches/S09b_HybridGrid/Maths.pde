// The maths: the box the move swept, turned into cells by dividing by the tile size; the
// solid tiles among them, the only ones the move checked; and the sides it hit.
void drawMaths() {
  float left = min(before.x(), before.x() + movedX);
  float top = min(before.y(), before.y() + movedY);
  float right = max(before.right(), before.right() + movedX);
  float bottom = max(before.bottom(), before.bottom() + movedY);
  int c0 = grid.colAt(left);
  int c1 = grid.colAt(right);
  int r0 = grid.rowAt(top);
  int r1 = grid.rowAt(bottom);

  pushStyle();
  noFill();
  // The cells under the swept box, faint, and the solid ones the move checked, bright.
  stroke(Palette.LINE);
  strokeWeight(1);
  for (int r = r0; r <= r1; r++) {
    for (int c = c0; c <= c1; c++) {
      Draw.shape(g, grid.cellRect(c, r));
    }
  }
  stroke(Overlay.GUIDE);
  strokeWeight(2);
  for (Rect cell : checked) {
    Draw.shape(g, cell);
  }
  // The swept box itself, and the motion.
  stroke(Palette.NEUTRAL);
  strokeWeight(1);
  rect(left, top, right - left, bottom - top);
  Draw.arrow(g, before.x() + before.w() / 2, before.y() + before.h() / 2, movedX * 4, movedY * 4);
  // The sides hit, drawn on the player's edge that met them.
  stroke(Overlay.HIT);
  strokeWeight(3);
  if (last.hit(Side.TOP)) {
    line(player.x(), player.bottom(), player.right(), player.bottom());
  }
  if (last.hit(Side.BOTTOM)) {
    line(player.x(), player.y(), player.right(), player.y());
  }
  if (last.hit(Side.LEFT)) {
    line(player.right(), player.y(), player.right(), player.bottom());
  }
  if (last.hit(Side.RIGHT)) {
    line(player.x(), player.y(), player.x(), player.bottom());
  }
  popStyle();

  String sides = "";
  for (Side s : Side.values()) {
    if (s != Side.NONE && last.hit(s)) {
      sides += (sides.length() > 0 ? ", " : "") + s + (s == Side.TOP ? " (landed)" : s == Side.BOTTOM ? " (head)" : " (wall)");
    }
  }
  String text = "grid.move(player, " + Overlay.number(movedX) + ", " + Overlay.number(movedY) + ")"
      + "\nswept box x " + Overlay.number(left) + " to " + Overlay.number(right)
      + ", y " + Overlay.number(top) + " to " + Overlay.number(bottom)
      + "\ncols " + Overlay.number(left) + " / " + (int) tile + " -> " + c0 + " to " + Overlay.number(right) + " / " + (int) tile + " -> " + c1
      + "\nrows " + Overlay.number(top) + " / " + (int) tile + " -> " + r0 + " to " + Overlay.number(bottom) + " / " + (int) tile + " -> " + r1
      + "\n" + (c1 - c0 + 1) * (r1 - r0 + 1) + " cells under it, " + checked.size() + " solid: the only ones checked"
      + "\nhit: " + (sides.length() > 0 ? sides : "nothing");
  Overlay.label(g, 8, 30, text, last.hitAnything() ? Overlay.HIT : Overlay.MISS);
}
