// Hitbox's Grid (key l): the same size, filled with exactly 20% solid cells and never the
// player's, and one call that checks a step, outside the map counting as solid.

Grid maze = new Grid(20, 20, 20);

// Hitbox's fill, copied into the tutorial's array so that its drawing loop draws it.
void hitboxMaze() {
  maze.fillRandom(0.2, seed, playerIndexX, playerIndexY);
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      grid[row][column] = maze.isSolid(column, row);
    }
  }
}

// An arrow key, the step checked by maze.canMove.
void hitboxStep() {
  int dx = keyCode == LEFT ? -1 : keyCode == RIGHT ? 1 : 0;
  int dy = keyCode == UP ? -1 : keyCode == DOWN ? 1 : 0;
  if ((dx != 0 || dy != 0) && maze.canMove(playerIndexX, playerIndexY, dx, dy)) {
    playerIndexX += dx;
    playerIndexY += dy;
  }
}
