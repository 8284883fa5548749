/**
 * Hybrid grid: a pixel player on a tile map
 * Tutorial section 9: Grids
 *
 * The section's hybrid approach: "store your obstacles in a grid, but your player's position
 * in terms of pixels. Then to check whether the player is colliding with an obstacle, you
 * convert the pixel position into a grid cell", as the original Super Mario Bros. did. The
 * section gives no code for it; the code here is ours. The level is a grid of 24-pixel cells
 * read from a text map; the player is a box that moves any number of pixels a frame, with
 * gravity and a jump.
 *
 * The conversion is one division: the column under a pixel x is floor(x / cellWidth), the row
 * under y is floor(y / cellHeight), then a look in the grid says whether that cell is an
 * obstacle (columnAt, rowAt, obstacleAt below). That runs by default: cellsMove (Move.pde)
 * looks at the cells under the box's next position, one axis at a time (section 6), and snaps
 * to the edge of the cell it would enter (section 7).
 *
 * Where Hitbox differs: press l for its grid.move(player, vx, vy): it sweeps the box through the cells under
 * its whole path, stops it touching the first obstacle and slides it along. A look at one next
 * position lets a move longer than a platform is thick step right over it; the sweep never
 * tunnels. In both, touching is not colliding (running along a floor never catches on the
 * seams between cells) and the map's edge counts as solid.
 *
 * Try this: raise maxFall to 60 (more than two cells a frame) and fall onto a thin platform,
 * then press l and do it again; make the player wider than a cell, or draw your own level.
 * Keys: LEFT / RIGHT run, UP or SPACE jumps (on the ground only), l Hitbox's grid.move / the
 * cells, d shows the maths.
 */
import hitbox.*;
import java.util.EnumSet;
import java.util.Set;
import hitbox.processing.*;

float cellWidth = 24;
float cellHeight = 24;
String[] level = {
  ".........................",
  ".........................",
  "..................####...",
  ".........................",
  "..........###............",
  "..................#......",
  "....###...........#......",
  "..................#..###.",
  "..#.........######.......",
  "..#......................",
  "..#....####..............",
  ".......#.........###.....",
  ".......#............##...",
  "...######.......#######..",
  "............##...........",
  "#########################",
};
Grid grid = Grid.parse(join(level, "\n"), cellWidth);  // Hitbox's copy of the map (square cells)

float gravity = 0.55;
float jumpSpeed = 10.5;
float runSpeed = 3.5;
float maxFall = 16;

Rect player = new Rect(40, 40, 18, 28);
float vx = 0;
float vy = 0;
boolean onGround = false;
boolean leftDown = false;
boolean rightDown = false;
boolean jumpPressed = false;
boolean hitboxDecides;  // l: Hitbox's grid.move instead of the cells under the next position
Sweep.Move last;        // where the last move ended, and the sides it hit

void setup() {
  size(600, 420);  // the 600 x 384 level, the key hint below
}

void draw() {
  background(Palette.BACKGROUND);
  step();
  drawLevel();
  noStroke();
  fill(Palette.PLAYER);
  Draw.shape(g, player);
  if (showMaths) {
    drawMaths();
  }
  String way = hitboxDecides ? "Hitbox's grid.move (l: the cells)" : "the cells under the next position (l: grid.move)";
  Overlay.label(g, 8, 8, way + ",  " + (onGround ? "on the ground: UP or SPACE jumps" : "in the air"));
  Overlay.hint(g, "l: Hitbox's grid.move / the cells   d: show the maths   LEFT / RIGHT: run   UP or SPACE: jump");
}

void step() {
  vx = (rightDown ? runSpeed : 0) - (leftDown ? runSpeed : 0);
  if (jumpPressed && onGround) {
    vy = -jumpSpeed;
  }
  jumpPressed = false;
  vy = min(vy + gravity, maxFall);
  remember(player, vx, vy);   // for the maths (Maths.pde)

  if (hitboxDecides) {
    // Hitbox: sweep the box through the grid's obstacle cells, in one call.
    last = grid.move(player, vx, vy);
  } else {
    last = cellsMove(player, vx, vy);   // Move.pde
  }
  player = new Rect(last.x(), last.y(), player.w(), player.h());
  vy = last.vy();  // 0 if it landed or bumped its head
  onGround = last.landed();
}

// The section's point: the cell under a pixel. Divide by the cell's size and round down.
int columnAt(float x) {
  return floor(x / cellWidth);    // Hitbox: grid.colAt(x)
}

int rowAt(float y) {
  return floor(y / cellHeight);   // Hitbox: grid.rowAt(y)
}

// Then a look in the grid: is that cell an obstacle? Outside the map counts as one.
boolean obstacleAt(int column, int row) {
  if (row < 0 || row >= level.length || column < 0 || column >= level[row].length()) {
    return true;
  }
  return level[row].charAt(column) == '#';   // Hitbox: grid.isSolid(column, row)
}
