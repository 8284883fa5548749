/**
 * Terrain: grass, water, forest
 * Tutorial section 9: Grids
 *
 * Section 9 ends: "each grid cell could contain an int that represents the type of terrain
 * in that cell: 0 for grass, 1 for water, 2 for forest, etc. Or each grid cell could contain
 * an object (or even multiple objects)". Here both: terrain is an int[][], terrain[row][column],
 * read from the map below (one digit a cell), and coins is a grid of lists, the coins lying
 * in each cell, none, one or several. Forest slows the player down: the terrain under its
 * centre (its pixels divided by the cell size, then terrain[row][column]) makes it move 1
 * pixel a frame there instead of 3. Water stops it: Hitbox's Grid, parsed from the same
 * digits, has 1 as its SOLID, so grid.move never lets the player's box into it. A coin is
 * picked up when the player touches it, and only the coins in the cells under the player
 * are looked at, never the rest.
 *
 * Click to set a goal. Two routes lead there from the player, drawn side by side: the
 * shortest, the fewest steps from cell to cell (grid.path), and the cheapest, where a step
 * costs the time it takes to cross the cell it enters, 1 for grass and 3 for forest
 * (grid.path with PathCosts.byTerrain(1, water, 3)). The shortest often cuts through the
 * forest; the cheapest goes round it when that is quicker.
 *
 * Try this: click a goal across the forest, then one near its edge, and watch the routes
 * part and meet; make forest cost 1.5 and see the cheapest route go through again; press 8
 * for diagonal steps (they never cut a corner of water).
 * Collect the coins in a cell that holds several: they go one by one, as the box reaches each.
 * Keys: arrows move, click sets the goal, 8 toggles diagonal steps, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

int GRASS = 0;
int WATER = 1;  // the grid's SOLID: nothing enters it
int FOREST = 2;
String[] map = {
  "000000000002222222200000000000",
  "000000000022222222220000000000",
  "000000000022222222220000000000",
  "000000000022222222220000000000",
  "000000000022222222220000000000",
  "000000000002222222200000000000",
  "000000000000222222000000000000",
  "000000000000000000000000000000",
  "000000000000000000000000000000",
  "000111100000000000000000222000",
  "001111110000000002220002222200",
  "001111111000000022222002222200",
  "000111111100000022222000222000",
  "000011111100000002220000000000",
  "000000111100000000000000000000",
  "000000011110000000000001111111",
  "000000001111000000000011111111",
  "022200000111100000000111111111",
  "222220000011110000001111111111",
  "022200000001111000011111111111",
};
float cell = 20;
int rows = map.length;
int columns = map[0].length();
int[][] terrain = new int[rows][columns];             // 0 grass, 1 water, 2 forest
ArrayList<Coin>[][] coins = new ArrayList[rows][columns];   // the coins lying in each cell
Grid grid = Grid.parse(join(map, "\n"), cell).passable(FOREST);   // Hitbox's copy of the numbers

float grassSpeed = 3;
float forestSpeed = 1;

Rect player = new Rect(24, 64, 12, 12);
boolean leftDown = false;
boolean rightDown = false;
boolean upDown = false;
boolean downDown = false;
float speed = grassSpeed;
boolean showMaths = false;

void setup() {
  size(600, 440);  // the 600 x 400 map, the routes' legend and the key hint below
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      terrain[row][column] = map[row].charAt(column) - '0';   // the digit '2' is the int 2
      coins[row][column] = new ArrayList<Coin>();
    }
  }
  placeCoins();   // in Coins.pde: some cells get one, some several
}

void draw() {
  background(Palette.BACKGROUND);
  step();
  pickUpCoins();
  findRoutes();
  drawMap();
  drawRoute(shortest, -3, Palette.NEUTRAL);
  drawRoute(cheapest, 3, Palette.ACCENT);
  drawGoal();
  drawCoins();
  noStroke();
  fill(Palette.PLAYER);
  Draw.shape(g, player);
  drawLegend();
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "d: show the maths   arrows: move   click: set the goal   8: diagonal steps " + (diagonals ? "on" : "off"));
}

// The terrain under the player's centre sets its speed; grid.move keeps it out of the water.
void step() {
  speed = terrainUnderPlayer() == FOREST ? forestSpeed : grassSpeed;
  float vx = ((rightDown ? 1 : 0) - (leftDown ? 1 : 0)) * speed;
  float vy = ((downDown ? 1 : 0) - (upDown ? 1 : 0)) * speed;
  Sweep.Move m = grid.move(player, vx, vy);
  player = new Rect(m.x(), m.y(), player.w(), player.h());
}

// The cell under the player's centre: its pixels divided by the cell size, rounded down.
int playerCol() {
  return floor((player.x() + player.w() / 2) / cell);   // Hitbox: grid.colAt
}

int playerRow() {
  return floor((player.y() + player.h() / 2) / cell);   // Hitbox: grid.rowAt
}

int terrainUnderPlayer() {
  return terrain[playerRow()][playerCol()];   // Hitbox: grid.get(column, row)
}

// Only the cells under the player can hold a coin it touches: look in those lists, no others.
void pickUpCoins() {
  looked = 0;
  for (int row = floor(player.y() / cell); row <= floor(player.bottom() / cell); row++) {
    for (int column = floor(player.x() / cell); column <= floor(player.right() / cell); column++) {
      if (row < 0 || row >= rows || column < 0 || column >= columns) {
        continue;
      }
      ArrayList<Coin> here = coins[row][column];
      for (int i = here.size() - 1; i >= 0; i--) {
        looked++;
        Coin coin = here.get(i);
        if (Collide.circleRect(coin.x, coin.y, coin.radius, player.x(), player.y(), player.w(), player.h())) {
          here.remove(i);
          collected++;
        }
      }
    }
  }
}
