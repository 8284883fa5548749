/**
 * Grids: a maze of cells
 * Tutorial section 9: Grids
 *
 * A 20 x 20 grid of 20-pixel cells, a fifth of them solid, filled at random from a seed (the
 * same seed always gives the same maze; the player's cell is always kept free). The player
 * moves one cell at a time, and the collision test is no geometry at all: is the cell it
 * would step into free? Grid.canMove answers, and the map's edge counts as solid.
 *
 * Pixels and cells convert by dividing: the cell under pixel (x, y) is column x / 20 and row
 * y / 20, rounded down (Grid.colAt, Grid.rowAt), and a cell's corner is at col * 20, row * 20
 * (Grid.cellX, Grid.cellY). With the maths on, move the mouse over the grid to see it.
 *
 * Try this: press r for new mazes until the player is walled in; change the 0.2 to 0.4 and
 * see how quickly the maze closes up.
 * Keys: arrows move, r makes a new maze, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

int cols = 20;
int rows = 20;
float cell = 20;
float solidShare = 0.2;
long seed = 1;
Grid grid = new Grid(cols, rows, cell).fillRandom(solidShare, seed, 0, 0);
int col = 0;
int row = 0;
String lastMove = "use the arrow keys";
boolean showMaths = false;

void setup() {
  size(600, 420);  // the 400 x 400 grid, a panel on the right, the key hint below
}

void draw() {
  background(Palette.BACKGROUND);
  drawGrid();
  fill(Palette.PLAYER);
  noStroke();
  Rect p = grid.cellRect(col, row);
  rect(p.x() + 3, p.y() + 3, p.w() - 6, p.h() - 6, 4);
  drawPanel();
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "d: show the maths   arrows: move one cell   r: new maze");
}

void drawGrid() {
  stroke(Palette.LINE);
  strokeWeight(1);
  for (int c = 0; c < grid.cols(); c++) {
    for (int r = 0; r < grid.rows(); r++) {
      fill(grid.isSolid(c, r) ? Palette.OBSTACLE : Palette.BACKGROUND);
      Draw.shape(g, grid.cellRect(c, r));
    }
  }
}

void drawPanel() {
  float px = grid.width() + 12;
  fill(Palette.NEUTRAL);
  textSize(14);
  textAlign(LEFT, TOP);
  text("Grid " + grid.cols() + " x " + grid.rows() + ", cells " + (int) cell + " px", px, 12);
  textSize(12);
  fill(Palette.OBSTACLE);
  text("seed " + seed + ": " + grid.countSolid() + " solid cells\n(" + round(solidShare * 100) + "% of "
      + grid.cols() * grid.rows() + ")", px, 36);
  fill(Palette.PLAYER);
  text("player: col " + col + ", row " + row, px, 80);
  fill(lastMove.startsWith("blocked") ? Palette.HIT : Palette.NEUTRAL);
  text(lastMove, px, 100, width - px - 8, 60);
}

// Where the numbers live: the mouse's cell with the division that finds it, the player's
// cell with the multiplication that places it, and the four cells it could step into.
void drawMaths() {
  Rect p = grid.cellRect(col, row);
  neighbour(0, -1, "up", p.x(), p.y() - 40);
  neighbour(0, 1, "down", p.x(), p.bottom() + 22);
  neighbour(-1, 0, "left", p.x() - 60, p.y());
  neighbour(1, 0, "right", p.right() + 22, p.y());

  float px = grid.width() + 12;
  Overlay.label(g, px, 170, "player's cell in pixels:\ncellX(" + col + ") = " + col + " * " + (int) cell + " = "
      + (int) grid.cellX(col) + "\ncellY(" + row + ") = " + row + " * " + (int) cell + " = " + (int) grid.cellY(row),
      Palette.PLAYER);

  int mc = grid.colAt(mouseX);
  int mr = grid.rowAt(mouseY);
  if (grid.inGrid(mc, mr)) {
    pushStyle();
    noFill();
    stroke(Overlay.GUIDE);
    strokeWeight(2);
    Draw.shape(g, grid.cellRect(mc, mr));
    strokeWeight(1);
    line(mouseX - 5, mouseY, mouseX + 5, mouseY);  // the mouse itself
    line(mouseX, mouseY - 5, mouseX, mouseY + 5);
    popStyle();
    boolean solid = grid.isSolid(mc, mr);
    String text = "mouseX " + mouseX + " / " + (int) cell + " = " + Overlay.number(mouseX / cell) + " -> col " + mc
        + "\nmouseY " + mouseY + " / " + (int) cell + " = " + Overlay.number(mouseY / cell) + " -> row " + mr
        + "\ncell (" + mc + ", " + mr + "): " + (solid ? "solid" : "free");
    float lx = mouseX + 14 > grid.width() - 190 ? mouseX - 200 : mouseX + 14;
    Overlay.label(g, lx, mouseY + 14, text, solid ? Overlay.HIT : Overlay.MISS);
  }
}

// One of the player's four neighbours: outlined and labelled free or solid, as canMove says.
void neighbour(int dc, int dr, String name, float lx, float ly) {
  boolean free = grid.canMove(col, row, dc, dr);
  color colour = free ? Overlay.MISS : Overlay.HIT;
  pushStyle();
  noFill();
  stroke(colour);
  strokeWeight(2);
  Draw.shape(g, grid.cellRect(col + dc, row + dr));
  popStyle();
  boolean outside = !grid.inGrid(col + dc, row + dr);
  Overlay.label(g, lx, ly, free ? "free" : outside ? "edge" : "solid", colour);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'r') {
    seed++;
    grid.fillRandom(solidShare, seed, col, row);  // a new maze, keeping the player's cell free
    lastMove = "new maze, seed " + seed;
  } else if (key == CODED) {
    if (keyCode == UP) {
      step(0, -1, "UP");
    } else if (keyCode == DOWN) {
      step(0, 1, "DOWN");
    } else if (keyCode == LEFT) {
      step(-1, 0, "LEFT");
    } else if (keyCode == RIGHT) {
      step(1, 0, "RIGHT");
    }
  }
}

void step(int dc, int dr, String name) {
  if (grid.canMove(col, row, dc, dr)) {
    col += dc;
    row += dr;
    lastMove = name + ": moved\ncanMove(" + (col - dc) + ", " + (row - dr) + ", " + dc + ", " + dr + ") = true";
  } else {
    lastMove = "blocked " + name + ": " + (grid.inGrid(col + dc, row + dr) ? "solid cell" : "edge of the map")
        + "\ncanMove(" + col + ", " + row + ", " + dc + ", " + dr + ") = false";
  }
}
