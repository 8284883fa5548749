/**
 * Grids: a maze of cells
 * Tutorial section 9: Grids
 *
 * The tutorial's program: the grid is a 2D boolean array, grid[row][column], true where a cell
 * is an obstacle, each cell given a 20% chance; the player is a column and a row in it,
 * starting at 10, 10; and each arrow key has its own if: not in the edge row or column, and
 * the cell it would step into not an obstacle? No geometry at all. That code runs here.
 *
 * Where Hitbox differs: press l for its Grid instead (Hitbox.pde). It differs twice: outside the map counts as
 * solid, so one call, maze.canMove(column, row, dColumn, dRow), does the edge checks too; and
 * fillRandom makes exactly 20% of the cells solid and keeps the player's cell free, because
 * the tutorial's coin flip per cell gives a different count every time and can put an
 * obstacle right under the player. Its cells are copied into grid, so the tutorial's drawing
 * loop draws them.
 *
 * Try this: press r for new mazes, in both modes, until the tutorial's drops an obstacle on
 * the player; change the .2 to .4 and see how quickly the maze closes.
 * Keys: arrows move, l Hitbox's Grid / the tutorial's array, r a new maze, d shows the maths
 * (the mouse's cell too).
 */
import hitbox.*;
import hitbox.processing.*;

//build a grid
int rows = 20;
int columns = 20;
//if a cell is true it's an obstacle
boolean[][] grid = new boolean[rows][columns];
//where the player is in the grid
int playerIndexX = 10;
int playerIndexY = 10;

float cellWidth;
float cellHeight;
long seed = 1;          // the same seed makes the same mazes (r: the next seed)
boolean hitboxDecides;  // l: Hitbox's Grid fills the maze and checks the moves

void setup() {
  size(600, 420);  // the 400 x 400 grid, a panel on the right, the key hint below
  newMaze();
}

void newMaze() {
  if (hitboxDecides) {
    hitboxMaze();   // Hitbox.pde
    return;
  }
  randomSeed(seed);
  //randomly place obstacles in the grid
  for (int row = 0; row < grid.length; row++) {
    for (int column = 0; column < grid[row].length; column++) {
      grid[row][column] = false;
      //each cell has a 20% chance of being an obstacle
      if (random(1) < .2) {
        grid[row][column] = true;
      }
    }
  }
}

void draw() {
  background(Palette.BACKGROUND);
  cellWidth = 400 / columns;   // the tutorial's width / columns: here the grid is 400 wide
  cellHeight = 400 / rows;
  stroke(Palette.LINE);
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      float cellX = cellWidth * column;
      float cellY = cellHeight * row;
      //fill the obstacles in with red
      if (grid[row][column]) {
        fill(Palette.OBSTACLE);
      } else {
        noFill();
      }
      rect(cellX, cellY, cellWidth, cellHeight);
    }
  }
  drawPlayer();       // the rest is in Maths.pde
  drawPanel();
}

void keyPressed() {
  int wasX = playerIndexX;
  int wasY = playerIndexY;
  if (hitboxDecides && key == CODED) {
    hitboxStep();   // Hitbox.pde
  } else if (keyCode == UP) {
    //if we aren't in the top row and the cell above us doesn't contain an obstacle
    if (playerIndexY > 0 && !grid[playerIndexY - 1][playerIndexX]) {
      playerIndexY--;
    }
  } else if (keyCode == DOWN) {
    //if we aren't in the bottom row and the cell below us doesn't contain an obstacle
    if (playerIndexY < rows - 1 && !grid[playerIndexY + 1][playerIndexX]) {
      playerIndexY++;
    }
  } else if (keyCode == LEFT) {
    //if we aren't in the left-most column and the cell to our left doesn't contain an obstacle
    if (playerIndexX > 0 && !grid[playerIndexY][playerIndexX - 1]) {
      playerIndexX--;
    }
  } else if (keyCode == RIGHT) {
    //if we aren't in the right-most column and the cell to our right doesn't contain an obstacle
    if (playerIndexX < columns - 1 && !grid[playerIndexY][playerIndexX + 1]) {
      playerIndexX++;
    }
  } else {
    otherKeys();
  }
  describeStep(wasX, wasY);
}
