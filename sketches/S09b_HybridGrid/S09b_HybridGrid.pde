/**
 * Hybrid grid: a pixel player on a tile map
 * Tutorial section 9: Grids
 *
 * The tutorial's hybrid approach, "store your obstacles in a grid, but your player's position
 * in terms of pixels", as the original Super Mario Bros. did: the level is a grid of 24-pixel
 * tiles read from a text map, and the player is a box that moves any number of pixels a
 * frame, with gravity and a jump.
 *
 * Every frame one call moves it: grid.move(player, vx, vy). The box goes until it hits a
 * solid tile, stops touching it and slides along it with the rest of the motion, so it lands
 * on floors, bumps its head and stops at walls, and it never tunnels through a tile however
 * fast it falls. Touching is not colliding, so running along a floor never catches on the
 * seams between tiles. The grid only looks at the tiles under the box the move sweeps (from
 * where the player is to where the motion would take it): pixels become cells by dividing
 * by 24 (Grid.colAt, Grid.rowAt). The map's edge counts as solid.
 *
 * Try this: raise maxFall to 60 (more than two tiles a frame) and fall from the top: it still
 * lands. Make the player wider than a tile, or draw your own level in the map below.
 * Keys: LEFT / RIGHT run, UP or SPACE jumps (on the ground only), d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;
import java.util.List;

float tile = 24;
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
Grid grid = Grid.parse(join(level, "\n"), tile);

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

// What the last move looked at and ran into, for the maths overlay.
Rect before = player;
float movedX = 0;
float movedY = 0;
List<Rect> checked = new ArrayList<Rect>();
Sweep.Move last;
boolean showMaths = false;

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
  Overlay.label(g, 8, 8, onGround ? "on the ground: UP or SPACE jumps" : "in the air");
  Overlay.hint(g, "d: show the maths   LEFT / RIGHT: run   UP or SPACE: jump");
}

void step() {
  vx = (rightDown ? runSpeed : 0) - (leftDown ? runSpeed : 0);
  if (jumpPressed && onGround) {
    vy = -jumpSpeed;
  }
  jumpPressed = false;
  vy = min(vy + gravity, maxFall);

  // The whole collision test: sweep the box through the grid's solid tiles.
  before = player;
  movedX = vx;
  movedY = vy;
  checked = grid.moveObstacles(player, vx, vy);
  last = grid.move(player, vx, vy);
  player = new Rect(last.x(), last.y(), player.w(), player.h());
  vy = last.vy();  // 0 if it landed or bumped its head
  onGround = last.landed();
}

void drawLevel() {
  noStroke();
  for (int r = 0; r < grid.rows(); r++) {
    for (int c = 0; c < grid.cols(); c++) {
      if (grid.isSolid(c, r)) {
        fill(Palette.OBSTACLE);
        Draw.shape(g, grid.cellRect(c, r));
      }
    }
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ') {
    jumpPressed = true;
  } else if (key == CODED) {
    if (keyCode == LEFT) {
      leftDown = true;
    } else if (keyCode == RIGHT) {
      rightDown = true;
    } else if (keyCode == UP) {
      jumpPressed = true;
    }
  }
}

void keyReleased() {
  if (key == CODED) {
    if (keyCode == LEFT) {
      leftDown = false;
    } else if (keyCode == RIGHT) {
      rightDown = false;
    }
  }
}
