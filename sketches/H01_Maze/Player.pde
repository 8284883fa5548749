// Loading the town, the cell size that fits the window, where the player is, and its box in
// pixels.

float cellSize(int cols, int rows) {
  return min(mapWidth / cols, mapHeight / rows);
}

// The pixel box, centred on the player's cell.
void placeBox() {
  float size = grid.cellWidth() * 0.6;
  box = new Rect(grid.cellCenterX(playerIndexX) - size / 2, grid.cellCenterY(playerIndexY) - size / 2, size, size);
}

float playerX() {
  return box.x() + box.w() / 2;
}

float playerY() {
  return box.y() + box.h() / 2;
}

// Reads the town from the picture or the text, with cells as big as fit the map area.
void loadTown() {
  if (fromPicture) {
    PImage picture = loadImage("town.png");
    float cell = cellSize(picture.width / PIXELS_PER_CELL, picture.height / PIXELS_PER_CELL);
    grid = Maps.fromImage(picture, PIXELS_PER_CELL, townColours, cell);
  } else {
    String text = join(loadStrings("town.txt"), "\n");
    Grid sized = Grid.parse(text);
    grid = Grid.parse(text, cellSize(sized.cols(), sized.rows()));
  }
  grid.passable(PARK, RIVER);
  playerIndexX = constrain(playerIndexX, 0, grid.cols() - 1);
  playerIndexY = constrain(playerIndexY, 0, grid.rows() - 1);
  placeBox();
  guards.clear();
  for (int[][] beat : guardBeats) {
    guards.add(new Guard(beat));
  }
}

// Pixel mode: the arrows held move the box, and Grid.move keeps it out of the buildings.
void moveBox() {
  float vx = ((rightDown ? 1 : 0) - (leftDown ? 1 : 0)) * boxSpeed;
  float vy = ((downDown ? 1 : 0) - (upDown ? 1 : 0)) * boxSpeed;
  Sweep.Move m = grid.move(box, vx, vy);
  box = new Rect(m.x(), m.y(), box.w(), box.h());
  playerIndexX = grid.colAt(playerX());
  playerIndexY = grid.rowAt(playerY());
}
