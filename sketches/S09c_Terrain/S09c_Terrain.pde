/**
 * Terrain: grass, water, forest
 * Tutorial section 9: Grids
 *
 * "Each grid cell could contain an int that represents the type of terrain in that cell: 0
 * for grass, 1 for water, 2 for forest." Here it does: the map below is those numbers, one
 * digit a cell, and each type has its own rule. Water stops the player: 1 is the grid's
 * SOLID, so grid.move never lets the player's box into it. Forest slows it down: the sketch
 * looks up the terrain under the player's centre (grid.get of colAt, rowAt) and moves it 1
 * pixel a frame there instead of 3.
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
Grid grid = Grid.parse(join(map, "\n"), cell).passable(FOREST);

float grassSpeed = 3;
float forestSpeed = 1;
PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 3);  // the time to cross a cell
boolean diagonals = false;

color grassColour = #5FA84F;
color waterColour = #3D78C8;
color forestColour = #2C5E34;

Rect player = new Rect(24, 64, 12, 12);
boolean leftDown = false;
boolean rightDown = false;
boolean upDown = false;
boolean downDown = false;
float speed = grassSpeed;
int goalCol = 28;
int goalRow = 3;
int[] shortest = new int[0];
int[] cheapest = new int[0];
boolean showMaths = false;

void setup() {
  size(600, 440);  // the 600 x 400 map, the routes' legend and the key hint below
}

void draw() {
  background(Palette.BACKGROUND);
  step();
  findRoutes();
  drawMap();
  drawRoute(shortest, -3, Palette.NEUTRAL);
  drawRoute(cheapest, 3, Palette.ACCENT);
  drawGoal();
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

int playerCol() {
  return grid.colAt(player.x() + player.w() / 2);
}

int playerRow() {
  return grid.rowAt(player.y() + player.h() / 2);
}

int terrainUnderPlayer() {
  return grid.get(playerCol(), playerRow());
}

void findRoutes() {
  PathCosts steps = diagonals ? PathCosts.steps().withDiagonals() : PathCosts.steps();
  shortest = grid.path(playerCol(), playerRow(), goalCol, goalRow, steps);
  cheapest = grid.path(playerCol(), playerRow(), goalCol, goalRow, diagonals ? costs.withDiagonals() : costs);
}
