// The default move, built on the first tab's pixel-to-cell step (columnAt, rowAt, obstacleAt).

// Is any cell under a box at (x, y) an obstacle? Every cell from its top-left corner's to
// its bottom-right corner's; an edge exactly on a cell line does not reach into the next.
boolean obstacleUnder(float x, float y, float w, float h) {
  for (int row = rowAt(y); row < ceil((y + h) / cellHeight); row++) {
    for (int column = columnAt(x); column < ceil((x + w) / cellWidth); column++) {
      if (obstacleAt(column, row)) {
        return true;
      }
    }
  }
  return false;
}

// The cells under the next position, across then down (section 6); if an obstacle is there,
// snap to the edge of the cell it would enter (section 7).
Sweep.Move cellsMove(Rect p, float speedX, float speedY) {
  float x = p.x();
  float y = p.y();
  Set<Side> sides = EnumSet.noneOf(Side.class);
  if (obstacleUnder(x + speedX, y, p.w(), p.h())) {
    if (speedX > 0) {
      x = columnAt(x + p.w() + speedX) * cellWidth - p.w();   // against the cell's left side
      sides.add(Side.LEFT);
    } else {
      x = (columnAt(x + speedX) + 1) * cellWidth;             // against its right side
      sides.add(Side.RIGHT);
    }
    speedX = 0;
  }
  x += speedX;
  if (obstacleUnder(x, y + speedY, p.w(), p.h())) {
    if (speedY > 0) {
      y = rowAt(y + p.h() + speedY) * cellHeight - p.h();     // on the cell's top: landed
      sides.add(Side.TOP);
    } else {
      y = (rowAt(y + speedY) + 1) * cellHeight;               // head against its bottom
      sides.add(Side.BOTTOM);
    }
    speedY = 0;
  }
  y += speedY;
  return new Sweep.Move(x, y, speedX, speedY, sides);
}
