// The panel, the "show the maths" overlay (d), and the other keys.

boolean showMaths = false;
String lastMove = "use the arrow keys";

// The player's cell, and a red ring if the grid has an obstacle under it (only the
// tutorial's fill lets that happen).
void drawPlayer() {
  float px = playerIndexX * cellSize;
  float py = playerIndexY * cellSize;
  noStroke();
  fill(Palette.PLAYER);
  rect(px + 3, py + 3, cellSize - 6, cellSize - 6, 4);
  if (obstacle(playerIndexX, playerIndexY)) {
    noFill();
    stroke(Palette.HIT);
    strokeWeight(3);
    rect(px + 1, py + 1, cellSize - 2, cellSize - 2);
    strokeWeight(1);
  }
}

int countObstacles() {
  int n = 0;
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      n += obstacle(column, row) ? 1 : 0;
    }
  }
  return n;
}

void drawPanel() {
  float px = columns * cellSize + 12;
  float pw = width - px - 8;
  textAlign(LEFT, TOP);
  textSize(14);
  fill(Palette.NEUTRAL);
  text(tutorialGrid ? "the tutorial's\nboolean[][] grid" : "Hitbox's Grid", px, 12);
  textSize(12);
  fill(Palette.OBSTACLE);
  String fill = tutorialGrid ? "each cell a 20% chance" : "exactly 20%, never\nthe player's cell";
  text("seed " + seed + ": " + countObstacles() + " obstacles\n" + fill, px, 52);
  fill(Palette.PLAYER);
  text("player: column " + playerIndexX + ", row " + playerIndexY, px, 100);
  if (obstacle(playerIndexX, playerIndexY)) {
    fill(Palette.HIT);
    text("an obstacle is under the player!", px, 116, pw, 40);
  }
  fill(lastMove.startsWith("blocked") ? Palette.HIT : Palette.NEUTRAL);
  text(lastMove, px, 150, pw, 70);
  Overlay.hint(g, "arrows: move   t: the tutorial's array / Hitbox's Grid   r: new maze   d: show the maths");
}

void describeStep(int dx, int dy, boolean free) {
  int x = playerIndexX + (free ? 0 : dx);
  int y = playerIndexY + (free ? 0 : dy);
  String name = dy < 0 ? "UP" : dy > 0 ? "DOWN" : dx < 0 ? "LEFT" : "RIGHT";
  boolean inGrid = x >= 0 && x < columns && y >= 0 && y < rows;
  String why;
  if (tutorialGrid) {
    why = inGrid ? "grid[" + y + "][" + x + "] is " + grid[y][x] : "past the " + edgeName(dx, dy) + " edge";
  } else {
    int fromX = free ? playerIndexX - dx : playerIndexX;
    int fromY = free ? playerIndexY - dy : playerIndexY;
    why = "maze.canMove(" + fromX + ", " + fromY + ", " + dx + ", " + dy + ")\n= " + free;
  }
  lastMove = (free ? name + ": moved\n" : "blocked " + name + ":\n") + why;
}

String edgeName(int dx, int dy) {
  return dy < 0 ? "top" : dy > 0 ? "bottom" : dx < 0 ? "left" : "right";
}

// Where the numbers live: the mouse's cell with the division that finds it, the player's
// cell with the multiplication that places it, and the four cells it could step into.
void drawMaths() {
  float px = playerIndexX * cellSize;
  float py = playerIndexY * cellSize;
  neighbour(0, -1, px + cellSize / 2, py - 4, 0, -1);
  neighbour(0, 1, px + cellSize / 2, py + cellSize + 4, 0, 1);
  neighbour(-1, 0, px - 4, py + cellSize / 2, -1, 0);
  neighbour(1, 0, px + cellSize + 4, py + cellSize / 2, 1, 0);

  Overlay.label(g, columns * cellSize + 12, 226, "the player's cell in pixels:\nx = " + playerIndexX + " * "
      + (int) cellSize + " = " + (int) px + "\ny = " + playerIndexY + " * " + (int) cellSize + " = " + (int) py,
      Palette.PLAYER);

  int column = floor(mouseX / cellSize);
  int row = floor(mouseY / cellSize);
  if (column >= 0 && column < columns && row >= 0 && row < rows) {
    pushStyle();
    noFill();
    stroke(Overlay.GUIDE);
    strokeWeight(2);
    rect(column * cellSize, row * cellSize, cellSize, cellSize);
    strokeWeight(1);
    line(mouseX - 5, mouseY, mouseX + 5, mouseY);  // the mouse itself
    line(mouseX, mouseY - 5, mouseX, mouseY + 5);
    popStyle();
    boolean solid = obstacle(column, row);
    String cell = tutorialGrid ? "grid[" + row + "][" + column + "] = " + solid
        : "maze.isSolid(" + column + ", " + row + ") = " + solid;
    String text = "mouseX " + mouseX + " / " + (int) cellSize + " = " + Overlay.number(mouseX / cellSize) + " -> column " + column
        + "\nmouseY " + mouseY + " / " + (int) cellSize + " = " + Overlay.number(mouseY / cellSize) + " -> row " + row
        + "\n" + cell;
    float lx = mouseX + 14 > columns * cellSize - 200 ? mouseX - 210 : mouseX + 14;
    Overlay.label(g, lx, mouseY + 14, text, solid ? Overlay.HIT : Overlay.MISS);
  }
}

// One of the player's four neighbours in the grid, outlined free (green) or blocked (red), with
// what the grid holds there: the array's true or false, or the Grid's word.
void neighbour(int dx, int dy, float lx, float ly, float sideX, float sideY) {
  int x = playerIndexX + dx;
  int y = playerIndexY + dy;
  boolean inGrid = x >= 0 && x < columns && y >= 0 && y < rows;
  if (!inGrid) {
    return;   // past the edge: nothing to show there (the panel says why a step is refused)
  }
  boolean free = !obstacle(x, y);
  color colour = free ? Overlay.MISS : Overlay.HIT;
  pushStyle();
  noFill();
  stroke(colour);
  strokeWeight(2);
  rect(x * cellSize, y * cellSize, cellSize, cellSize);
  popStyle();
  String text = tutorialGrid ? "" + grid[y][x] : free ? "free" : "solid";
  Overlay.labelBeside(g, lx + sideX * cellSize, ly + sideY * cellSize, sideX, sideY, text, colour);
}

void otherKeys() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 't') {
    tutorialGrid = !tutorialGrid;
    newMaze();   // the same seed: the tutorial's maze comes back as it was
    lastMove = tutorialGrid ? "the tutorial's boolean[][]" : "Hitbox's Grid";
  } else if (key == 'r') {
    seed++;
    newMaze();
    lastMove = "new maze, seed " + seed;
  }
}
