/**
 * A maze of your town
 * Homework 1: a maze based on a map of your town
 *
 * "Create a maze application. Try basing it off a map of your town. What would the obstacles
 * be?" Here the obstacles are buildings, and the town is a picture: data/town.png, 8 x 8
 * pixels a cell, read with Maps.fromImage through a colour key (townColours). Buildings are
 * solid; parks and the river are terrain you can cross, at a price. Walk the streets with the
 * arrow keys, one cell a step, by section 9's four ifs (keyPressed below: not at the edge, and
 * the next cell not solid; l hands the step to Grid.canMove, the same question in one call),
 * or press p to move in pixels (Grid.move slides the player along the walls; section 9 only
 * names that hybrid, S09b writes it out). Click to set a goal: the cheapest route there is drawn (Grid.path with
 * PathCosts: a street costs 1, a park 2, the river 10, so the route takes a bridge). Two
 * guards walk their beats; a guard sees you when you are near and no building is in the
 * way (Grid.lineOfSight: touching a building's corner does not block the view).
 *
 * Your own town: draw it in any paint program in four colours, street #D8D2C4, building
 * #6B4F3F, park #6DB35A, river #4A86D0, each cell an 8 x 8 block (the picture's width and
 * height a whole number of blocks; turn anti-aliasing off), and save it over data/town.png.
 * Or write it as text in data/town.txt, one character a cell ('.' street, '#' building,
 * '2' park, '3' river), and press m to read that instead. Any size works: the cells shrink
 * to fit the window. Then move the guards' beats (guardBeats) onto your streets.
 *
 * Try this: stand behind a corner and let a guard pass; make the river cheaper than the
 * detour to a bridge; give the guards a longer view.
 * Keys: arrows move, click sets the goal, l Grid.canMove / section 9's ifs, p toggles cells /
 * pixels, m toggles the picture / text map, d shows the maths (the guards' view).
 */
import hitbox.*;
import hitbox.processing.*;

int STREET = 0;
int BUILDING = Grid.SOLID;
int PARK = 2;
int RIVER = 3;
int PIXELS_PER_CELL = 8;
TerrainColors townColours = new TerrainColors()
    .put(#D8D2C4, STREET)
    .put(#6B4F3F, BUILDING)
    .put(#6DB35A, PARK)
    .put(#4A86D0, RIVER);
PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 2, 10);

float mapWidth = 640;
float mapHeight = 416;
Grid grid;
boolean fromPicture = true;

// The player: a cell when walking cell by cell, a box when moving in pixels.
int playerIndexX = 0;
int playerIndexY = 25;
boolean hitboxDecides = false;  // l: Grid.canMove checks the steps instead of section 9's ifs
boolean pixelMode = false;
Rect box;
float boxSpeed = 2;
boolean leftDown = false;
boolean rightDown = false;
boolean upDown = false;
boolean downDown = false;

int goalCol = 39;
int goalRow = 0;
int[] route = new int[0];

// Each guard walks from corner to corner of its beat, round and round.
int[][][] guardBeats = {
  {{0, 0}, {12, 0}, {12, 10}, {0, 10}},
  {{13, 13}, {24, 13}, {24, 25}, {13, 25}},
};
ArrayList<Guard> guards = new ArrayList<Guard>();
float guardView = 120;  // how far a guard sees, in pixels
boolean seen = false;
int sightings = 0;
boolean showMaths = false;

void setup() {
  size(820, 440);  // the town on the left, a panel on the right, the key hint below
  loadTown();
}

void draw() {
  background(Palette.BACKGROUND);
  if (pixelMode) {
    moveBox();
  }
  for (Guard guard : guards) {
    guard.walk();
  }
  boolean seenNow = false;
  for (Guard guard : guards) {
    seenNow |= guard.sees(playerX(), playerY());
  }
  if (seenNow && !seen) {
    sightings++;
  }
  seen = seenNow;
  route = grid.path(playerIndexX, playerIndexY, goalCol, goalRow, costs);

  drawTown();
  drawRoute();
  for (Guard guard : guards) {
    guard.draw();
  }
  noStroke();
  fill(seen ? Palette.HIT : Palette.PLAYER);
  if (pixelMode) {
    Draw.shape(g, box);
  } else {
    circle(playerX(), playerY(), grid.cellWidth() * 0.75);
  }
  if (showMaths) {
    drawMaths();
  }
  drawPanel();
  Overlay.hint(g, "d: the guards' view   arrows: move   click: goal   l: " + (hitboxDecides ? "the ifs" : "canMove") + "   p: " + (pixelMode ? "cells" : "pixels")
      + "   m: " + (fromPicture ? "text map" : "picture map"));
}

void keyPressed() {
  if (key != CODED || pixelMode || hitboxDecides) {
    otherKeys();   // Keys.pde
    return;
  }
  //section 9's moves: not at the edge of the map, and the cell next door not solid
  if (keyCode == UP) {
    if (playerIndexY > 0 && !grid.isSolid(playerIndexX, playerIndexY - 1)) {
      playerIndexY--;
    }
  } else if (keyCode == DOWN) {
    if (playerIndexY < grid.rows() - 1 && !grid.isSolid(playerIndexX, playerIndexY + 1)) {
      playerIndexY++;
    }
  } else if (keyCode == LEFT) {
    if (playerIndexX > 0 && !grid.isSolid(playerIndexX - 1, playerIndexY)) {
      playerIndexX--;
    }
  } else if (keyCode == RIGHT) {
    if (playerIndexX < grid.cols() - 1 && !grid.isSolid(playerIndexX + 1, playerIndexY)) {
      playerIndexX++;
    }
  }
  placeBox();   // the player's box follows its cell (Player.pde)
}
