// The panel, the "show the maths" overlay (d), and the other keys.

boolean showMaths = false;
String lastMove = "use the arrow keys";

// The player's cell, and a red ring if the grid has an obstacle under it (only the
// tutorial's fill lets that happen).
void drawPlayer() {
  //fill the player's cell with green
  float px = playerIndexX * cellWidth;
  float py = playerIndexY * cellHeight;
  noStroke();
  fill(Palette.PLAYER);
  rect(px + 3, py + 3, cellWidth - 6, cellHeight - 6, 4);
  if (grid[playerIndexY][playerIndexX]) {
    noFill();
    stroke(Palette.HIT);
    strokeWeight(3);
    rect(px + 1, py + 1, cellWidth - 2, cellHeight - 2);
    strokeWeight(1);
  }
}

int countObstacles() {
  int n = 0;
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      n += grid[row][column] ? 1 : 0;
    }
  }
  return n;
}

void drawPanel() {
  float px = columns * cellWidth + 12;
  float pw = width - px - 8;
  textAlign(LEFT, TOP);
  textSize(14);
  fill(Palette.NEUTRAL);
  text(hitboxDecides ? "Hitbox's Grid" : "the tutorial's\nboolean[][] grid", px, 12);
  textSize(12);
  fill(Palette.OBSTACLE);
  String fill = hitboxDecides ? "exactly 20%, never\nthe player's cell" : "each cell a 20% chance";
  text("seed " + seed + ": " + countObstacles() + " obstacles\n" + fill, px, 52);
  fill(Palette.PLAYER);
  text("player: column " + playerIndexX + ", row " + playerIndexY, px, 100);
  if (grid[playerIndexY][playerIndexX]) {
    fill(Palette.HIT);
    text("an obstacle is under the player!", px, 116, pw, 40);
  }
  fill(lastMove.startsWith("blocked") ? Palette.HIT : Palette.NEUTRAL);
  text(lastMove, px, 150, pw, 70);
  Overlay.hint(g, "arrows: move   l: Hitbox's Grid / the tutorial's array   r: new maze   d: show the maths");
  if (showMaths) {
    drawMaths();
  }
}

// After an arrow key: where the player tried to go, and why it did or did not.
void describeStep(int wasX, int wasY) {
  if (key != CODED || (keyCode != UP && keyCode != DOWN && keyCode != LEFT && keyCode != RIGHT)) {
    return;
  }
  int dx = keyCode == LEFT ? -1 : keyCode == RIGHT ? 1 : 0;
  int dy = keyCode == UP ? -1 : keyCode == DOWN ? 1 : 0;
  boolean free = playerIndexX != wasX || playerIndexY != wasY;
  int x = wasX + dx;
  int y = wasY + dy;
  String name = dy < 0 ? "UP" : dy > 0 ? "DOWN" : dx < 0 ? "LEFT" : "RIGHT";
  boolean inGrid = x >= 0 && x < columns && y >= 0 && y < rows;
  String why;
  if (!hitboxDecides) {
    why = inGrid ? "grid[" + y + "][" + x + "] is " + grid[y][x] : "past the " + edgeName(dx, dy) + " edge";
  } else {
    why = "maze.canMove(" + wasX + ", " + wasY + ", " + dx + ", " + dy + ")\n= " + free;
  }
  lastMove = (free ? name + ": moved\n" : "blocked " + name + ":\n") + why;
}

String edgeName(int dx, int dy) {
  return dy < 0 ? "top" : dy > 0 ? "bottom" : dx < 0 ? "left" : "right";
}

// Where the numbers live: the mouse's cell with the division that finds it, the player's
// cell with the multiplication that places it, and the four cells it could step into.
void drawMaths() {
  float px = playerIndexX * cellWidth;
  float py = playerIndexY * cellHeight;
  neighbour(0, -1, px + cellWidth / 2, py - 4, 0, -1);
  neighbour(0, 1, px + cellWidth / 2, py + cellHeight + 4, 0, 1);
  neighbour(-1, 0, px - 4, py + cellHeight / 2, -1, 0);
  neighbour(1, 0, px + cellWidth + 4, py + cellHeight / 2, 1, 0);

  Overlay.label(g, columns * cellWidth + 12, 226, "the player's cell in pixels:\nplayerPixelX = " + playerIndexX + " * "
      + (int) cellWidth + " = " + (int) px + "\nplayerPixelY = " + playerIndexY + " * " + (int) cellHeight + " = " + (int) py,
      Palette.PLAYER);

  int column = floor(mouseX / cellWidth);
  int row = floor(mouseY / cellHeight);
  if (column >= 0 && column < columns && row >= 0 && row < rows) {
    pushStyle();
    noFill();
    stroke(Overlay.GUIDE);
    strokeWeight(2);
    rect(column * cellWidth, row * cellHeight, cellWidth, cellHeight);
    strokeWeight(1);
    line(mouseX - 5, mouseY, mouseX + 5, mouseY);  // the mouse itself
    line(mouseX, mouseY - 5, mouseX, mouseY + 5);
    popStyle();
    boolean solid = grid[row][column];
    String cell = hitboxDecides ? "maze.isSolid(" + column + ", " + row + ") = " + solid
        : "grid[" + row + "][" + column + "] = " + solid;
    String text = "mouseX " + mouseX + " / " + (int) cellWidth + " = " + Overlay.number(mouseX / cellWidth) + " -> column " + column
        + "\nmouseY " + mouseY + " / " + (int) cellHeight + " = " + Overlay.number(mouseY / cellHeight) + " -> row " + row
        + "\n" + cell;
    float lx = mouseX + 14 > columns * cellWidth - 200 ? mouseX - 210 : mouseX + 14;
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
  boolean free = !grid[y][x];
  color colour = free ? Overlay.MISS : Overlay.HIT;
  pushStyle();
  noFill();
  stroke(colour);
  strokeWeight(2);
  rect(x * cellWidth, y * cellHeight, cellWidth, cellHeight);
  popStyle();
  String text = hitboxDecides ? (free ? "free" : "solid") : "" + grid[y][x];
  Overlay.labelBeside(g, lx + sideX * cellWidth, ly + sideY * cellHeight, sideX, sideY, text, colour);
}

void otherKeys() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
    newMaze();   // the same seed: the tutorial's maze comes back as it was
    lastMove = hitboxDecides ? "Hitbox's Grid" : "the tutorial's boolean[][]";
  } else if (key == 'r') {
    seed++;
    newMaze();
    lastMove = "new maze, seed " + seed;
  }
}
