/**
 * Hybrid grid: a pixel player on a tile map
 * Tutorial section 9: Grids
 *
 * The section's hybrid approach: "store your obstacles in a grid, but your player's position
 * in terms of pixels. Then to check whether the player is colliding with an obstacle, you
 * convert the pixel position into a grid cell", as the original Super Mario Bros. did. The
 * level is a grid of 24-pixel cells read from a text map; the player is a box that moves
 * any number of pixels a frame, with gravity and a jump.
 *
 * The conversion is one division: the column under a pixel x is floor(x / cellWidth), the
 * row under y is floor(y / cellHeight), and then a look in the grid says whether that cell
 * is an obstacle (columnAt, rowAt and obstacleAt below; Hitbox's grid.colAt, grid.rowAt and
 * grid.isSolid do the same). Press t for the tutorial's way with them: section 6's look at
 * the next position, one axis at a time, in the cells under the box there, and section 7's
 * snap to the edge of the cell it would enter.
 *
 * Where Hitbox differs: its way (the default) is one call, grid.move(player, vx, vy): it
 * sweeps the box from where it is to where the motion would take it, through the cells under
 * that path, stops it touching the first obstacle and slides it along with the rest of the
 * motion. The tutorial's way looks at one next position, so a move longer than a platform is
 * thick can step right over it; the sweep never tunnels. Touching is not colliding in both,
 * so running along a floor never catches on the seams between cells. The map's edge counts
 * as solid.
 *
 * Try this: raise maxFall to 60 (more than two cells a frame), fall onto a thin platform in
 * both ways; make the player wider than a cell, or draw your own level in the map below.
 * Keys: LEFT / RIGHT run, UP or SPACE jumps (on the ground only), t the tutorial's way /
 * Hitbox's, d shows the maths.
 */
import hitbox.*;
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
Grid grid = Grid.parse(join(level, "\n"), cellWidth, cellHeight);  // Hitbox's copy of the map

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
boolean tutorialWay = false;   // t: the tutorial's cells-at-the-next-position way
Sweep.Move last;               // where the last move ended, and the sides it hit

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
  String way = tutorialWay ? "the tutorial's cells (t: grid.move)" : "grid.move (t: the tutorial's cells)";
  Overlay.label(g, 8, 8, way + ",  " + (onGround ? "on the ground: UP or SPACE jumps" : "in the air"));
  Overlay.hint(g, "t: tutorial's way / Hitbox's   d: show the maths   LEFT / RIGHT: run   UP or SPACE: jump");
}

void step() {
  vx = (rightDown ? runSpeed : 0) - (leftDown ? runSpeed : 0);
  if (jumpPressed && onGround) {
    vy = -jumpSpeed;
  }
  jumpPressed = false;
  vy = min(vy + gravity, maxFall);
  remember(player, vx, vy);   // for the maths (Maths.pde)

  if (tutorialWay) {
    last = tutorialMove(player, vx, vy);
  } else {
    // Hitbox: sweep the box through the grid's obstacle cells, in one call.
    last = grid.move(player, vx, vy);
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

// Is any cell under a box at (x, y) an obstacle? Every cell from its top-left corner's to
// its bottom-right corner's; an edge exactly on a cell line does not reach into the next.
boolean obstacleUnder(float x, float y, float w, float h) {
  for (int row = rowAt(y); row < ceil((y + h) / cellHeight); row++) {
    for (int column = columnAt(x); column < ceil((x + w) / cellWidth); column++) {
      if (obstacleAt(column, row)) {
        return true;
      }
    }
  }
  return false;
}

// The tutorial's way: look at the next position, across then down (section 6); if an
// obstacle is there, snap to the edge of the cell it would enter (section 7).
Sweep.Move tutorialMove(Rect p, float speedX, float speedY) {
  float x = p.x();
  float y = p.y();
  int sides = 0;
  if (obstacleUnder(x + speedX, y, p.w(), p.h())) {
    if (speedX > 0) {
      x = columnAt(x + p.w() + speedX) * cellWidth - p.w();   // against the cell's left side
      sides |= Side.LEFT.bit();
    } else {
      x = (columnAt(x + speedX) + 1) * cellWidth;             // against its right side
      sides |= Side.RIGHT.bit();
    }
    speedX = 0;
  }
  x += speedX;
  if (obstacleUnder(x, y + speedY, p.w(), p.h())) {
    if (speedY > 0) {
      y = rowAt(y + p.h() + speedY) * cellHeight - p.h();     // on the cell's top: landed
      sides |= Side.TOP.bit();
    } else {
      y = (rowAt(y + speedY) + 1) * cellHeight;               // head against its bottom
      sides |= Side.BOTTOM.bit();
    }
    speedY = 0;
  }
  y += speedY;
  return new Sweep.Move(x, y, speedX, speedY, sides);
}
