/**
 * Grids: a maze of cells
 * Tutorial section 9: Grids
 *
 * The tutorial's grid is a 2D boolean array, grid[row][column], true where a cell is an
 * obstacle. The player is a column and a row in it, and before each step it checks the cell
 * it would step into: inside the grid, and not an obstacle? No geometry at all.
 *
 * Press t to switch between the tutorial's array and Hitbox's Grid. Hitbox differs twice:
 * outside the map counts as solid, so one call, maze.canMove(col, row, dCol, dRow), does the
 * edge checks too; and fillRandom makes exactly 20% of the cells solid and keeps the
 * player's cell free, because the tutorial's coin flip per cell (random(1) < 0.2) gives a
 * different count every time and can put an obstacle right under the player.
 *
 * Try this: walk somewhere and press r for new mazes, in both modes, until the tutorial's
 * drops an obstacle on the player; change the 0.2 to 0.4 and see how quickly the maze closes.
 * Keys: arrows move, t the tutorial's array / Hitbox's Grid, r a new maze, d shows the maths
 * (the mouse's cell too).
 */
import hitbox.*;
import hitbox.processing.*;

int rows = 20;
int columns = 20;
float cellSize = 20;
// The tutorial's grid: if a cell is true it's an obstacle.
boolean[][] grid = new boolean[rows][columns];
// Hitbox's grid of the same size.
Grid maze = new Grid(columns, rows, cellSize);
boolean tutorialGrid = false;   // t switches
int playerIndexX = 0;           // the player's column...
int playerIndexY = 0;           // ...and row
long seed = 1;                  // the same seed makes the same mazes

void setup() {
  size(600, 420);  // the 400 x 400 grid, a panel on the right, the key hint below
  newMaze();
}

void newMaze() {
  // The tutorial's fill: each cell has a 20% chance of being an obstacle (seeded here, so
  // a seed always makes the same maze).
  randomSeed(seed);
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      grid[row][column] = random(1) < 0.2;
    }
  }
  // Hitbox's fill: exactly 20% of the cells, never the player's.
  maze.fillRandom(0.2, seed, playerIndexX, playerIndexY);
}

// Is this cell an obstacle, in the grid shown now?
boolean obstacle(int column, int row) {
  return tutorialGrid ? grid[row][column] : maze.isSolid(column, row);
}

void draw() {
  background(Palette.BACKGROUND);
  stroke(Palette.LINE);
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      fill(obstacle(column, row) ? Palette.OBSTACLE : Palette.BACKGROUND);
      rect(column * cellSize, row * cellSize, cellSize, cellSize);
    }
  }
  drawPlayer();       // the rest is in Maths.pde
  drawPanel();
  if (showMaths) {
    drawMaths();
  }
}

void keyPressed() {
  if (keyCode == UP) {
    step(0, -1);
  } else if (keyCode == DOWN) {
    step(0, 1);
  } else if (keyCode == LEFT) {
    step(-1, 0);
  } else if (keyCode == RIGHT) {
    step(1, 0);
  } else {
    otherKeys();
  }
}

// Before the player steps by (dx, dy): is the cell it would step into free?
void step(int dx, int dy) {
  int x = playerIndexX + dx;
  int y = playerIndexY + dy;
  boolean free;
  if (tutorialGrid) {
    // The tutorial's check, which it writes once per arrow key: not past that edge of the
    // grid, and not an obstacle.
    free = x >= 0 && x < columns && y >= 0 && y < rows && !grid[y][x];
  } else {
    // Hitbox's: outside the grid counts as solid, so one call checks both.
    free = maze.canMove(playerIndexX, playerIndexY, dx, dy);
  }
  if (free) {
    playerIndexX = x;
    playerIndexY = y;
  }
  describeStep(dx, dy, free);
}
