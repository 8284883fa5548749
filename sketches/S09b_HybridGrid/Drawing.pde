// The level: its obstacle cells, filled.

void drawLevel() {
  noStroke();
  for (int r = 0; r < grid.rows(); r++) {
    for (int c = 0; c < grid.cols(); c++) {
      if (grid.isSolid(c, r)) {
        fill(Palette.OBSTACLE);
        Draw.shape(g, grid.cellRect(c, r));
      }
    }
  }
}
