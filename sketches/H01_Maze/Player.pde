// Where the player is: the cell size that fits the window, and the player's box in pixels.

float cellSize(int cols, int rows) {
  return min(mapWidth / cols, mapHeight / rows);
}

// The pixel box, centred on the player's cell.
void placeBox() {
  float size = grid.cellWidth() * 0.6;
  box = new Rect(grid.cellCenterX(playerCol) - size / 2, grid.cellCenterY(playerRow) - size / 2, size, size);
}

float playerX() {
  return box.x() + box.w() / 2;
}

float playerY() {
  return box.y() + box.h() / 2;
}
