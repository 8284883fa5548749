/**
 * A maze of your town
 * Homework 1: a maze based on a map of your town
 *
 * "Create a maze application. Try basing it off a map of your town. What would the obstacles
 * be?" Here the obstacles are buildings, and the town is a picture: data/town.png, 8 x 8
 * pixels a cell, read with Maps.fromImage through a colour key (townColours). Buildings are solid; parks
 * and the river are terrain you can cross, at a price. Walk the streets with the arrow keys,
 * one cell a step (Grid.canMove), or press p to move in pixels (Grid.move slides the player
 * along the walls). Click to set a goal: the cheapest route there is drawn (Grid.path with
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
 * Keys: arrows move, click sets the goal, p toggles cells / pixels, m toggles the picture /
 * text map, d shows the maths (the guards' view).
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
int playerCol = 0;
int playerRow = 25;
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

// Reads the town from the picture or the text, with cells as big as fit the map area.
void loadTown() {
  if (fromPicture) {
    PImage picture = loadImage("town.png");
    float cell = cellSize(picture.width / PIXELS_PER_CELL, picture.height / PIXELS_PER_CELL);
    grid = Maps.fromImage(picture, PIXELS_PER_CELL, townColours, cell);
  } else {
    String text = join(loadStrings("town.txt"), "\n");
    Grid sized = Grid.parse(text);
    grid = Grid.parse(text, cellSize(sized.cols(), sized.rows()));
  }
  grid.passable(PARK, RIVER);
  playerCol = constrain(playerCol, 0, grid.cols() - 1);
  playerRow = constrain(playerRow, 0, grid.rows() - 1);
  placeBox();
  guards.clear();
  for (int[][] beat : guardBeats) {
    guards.add(new Guard(beat));
  }
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
  route = grid.path(playerCol, playerRow, goalCol, goalRow, costs);

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
  Overlay.hint(g, "d: the guards' view   arrows: move   click: goal   p: " + (pixelMode ? "cells" : "pixels")
      + "   m: " + (fromPicture ? "text map" : "picture map"));
}

// Pixel mode: the arrows held move the box, and Grid.move keeps it out of the buildings.
void moveBox() {
  float vx = ((rightDown ? 1 : 0) - (leftDown ? 1 : 0)) * boxSpeed;
  float vy = ((downDown ? 1 : 0) - (upDown ? 1 : 0)) * boxSpeed;
  Sweep.Move m = grid.move(box, vx, vy);
  box = new Rect(m.x(), m.y(), box.w(), box.h());
  playerCol = grid.colAt(playerX());
  playerRow = grid.rowAt(playerY());
}
