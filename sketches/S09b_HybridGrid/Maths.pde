// The maths (d): what the last move looked at, and the fields only this overlay needs.

boolean showMaths = false;
Rect before;          // where the player was before the last move
float movedX = 0;     // and the motion it was given
float movedY = 0;

// Called before each move.
void remember(Rect from, float speedX, float speedY) {
  before = from;
  movedX = speedX;
  movedY = speedY;
}

// Hitbox's grid.move: the box the move swept, turned into cells by dividing by the cell size;
// the obstacle cells among them, the only ones the move checked; and the sides it hit. The
// default, cellsMove: the cells under the two next positions it looked at.
void drawMaths() {
  if (!hitboxDecides) {
    drawCellsMaths();
    return;
  }
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
  int solid = 0;
  for (int r = r0; r <= r1; r++) {
    for (int c = c0; c <= c1; c++) {
      if (grid.isSolid(c, r)) {   // beyond the map's edge counts as solid too
        Draw.shape(g, grid.cellRect(c, r));
        solid++;
      }
    }
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
      + "\ncols " + Overlay.number(left) + " / " + (int) cellWidth + " -> " + c0 + " to " + Overlay.number(right) + " / " + (int) cellWidth + " -> " + c1
      + "\nrows " + Overlay.number(top) + " / " + (int) cellWidth + " -> " + r0 + " to " + Overlay.number(bottom) + " / " + (int) cellWidth + " -> " + r1
      + "\n" + (c1 - c0 + 1) * (r1 - r0 + 1) + " cells under it, " + solid + " solid: the only ones checked"
      + "\nhit: " + (sides.length() > 0 ? sides : "nothing");
  Overlay.label(g, 8, 30, text, last.hitAnything() ? Overlay.HIT : Overlay.MISS);
}

// cellsMove's look: the box one step across, then one step down, and the cells under each
// (floor of its corners divided by the cell size); an obstacle cell among them is red.
void drawCellsMaths() {
  float nextX = before.x() + movedX;
  float nextY = before.y() + movedY;
  pushStyle();
  noFill();
  strokeWeight(2);
  cellsUnder(nextX, before.y());
  cellsUnder(player.x(), nextY);
  stroke(Palette.NEUTRAL);
  strokeWeight(1);
  rect(nextX, before.y(), player.w(), player.h());
  rect(player.x(), nextY, player.w(), player.h());
  popStyle();
  String text = "next x: columns floor(" + Overlay.number(nextX) + " / " + (int) cellWidth + ") = " + columnAt(nextX)
      + " to " + (ceil((nextX + player.w()) / cellWidth) - 1)
      + (obstacleUnder(nextX, before.y(), player.w(), player.h()) ? ": an obstacle, snap" : ": free, move")
      + "\nnext y: rows floor(" + Overlay.number(nextY) + " / " + (int) cellHeight + ") = " + rowAt(nextY)
      + " to " + (ceil((nextY + player.h()) / cellHeight) - 1)
      + (obstacleUnder(player.x(), nextY, player.w(), player.h()) ? ": an obstacle, snap" : ": free, move");
  Overlay.label(g, 8, 30, text, last.hitAnything() ? Overlay.HIT : Overlay.MISS);
}

// Outlines the cells under a box at (x, y), the player's size: red for an obstacle.
void cellsUnder(float x, float y) {
  for (int row = rowAt(y); row < ceil((y + player.h()) / cellHeight); row++) {
    for (int column = columnAt(x); column < ceil((x + player.w()) / cellWidth); column++) {
      stroke(obstacleAt(column, row) ? Overlay.HIT : Overlay.GUIDE);
      rect(column * cellWidth, row * cellHeight, cellWidth, cellHeight);
    }
  }
}
