// Homework 1: "Create a maze application. Try basing it off a map of your town. What would the
// obstacles be?" Here the obstacles are buildings ('#'); parks ('2') and the river ('3') can be
// crossed. The map is text, one character a cell, read by Hitbox's Grid.parse. The arrow keys
// walk the streets one cell a step by section 9's four ifs (keyPressed below, on the tutorial's
// boolean grid[row][column]); Hitbox's Grid answers the rest: the shortest route to the cell
// under the mouse (town.path), and whether the guard sees you: near, and no building in the
// way (town.lineOfSight; touching a building's corner does not block the view).
// Your own town: edit the map below, same width on every line.
const map = [
  '........................................',
  '.####.######.222222222222.####.#####.##.',
  '.####.######.222222222222.####.#####.##.',
  '.####........222222222222.####.......##.',
  '......###.##.222233332222....#######.##.',
  '.####.###.##.222233332222.##.#######.##.',
  '.####.###.##.222233332222.##.#######....',
  '..........##.222222222222.##............',
  '.####.###.##.222222222222.##.####.#####.',
  '.####.###.##.222222222222.##.####.#####.',
  '........................................',
  '3333333..3333333333333333333333..3333333',
  '3333333..3333333333333333333333..3333333',
  '........................................',
  '.#####.######.###.######.#####.#####.##.',
  '.#####.######.###.######.#####.#####.##.',
  '.#####........###........#####.......##.',
  '.......###.##.###.###.##.......#####.##.',
  '.22222.###.##.###.###.##.#####.#####.##.',
  '.22222.###.##.....###.##.#####.#####....',
  '.22222.###.##.#######.##................',
  '.22222.....##.#######.##.#####.########.',
  '.22222.222.##.#######.##.#####.########.',
  '.22222.222...............#####..........',
  '.22222.222...............#####.########.',
  '........................................',
].join('\n');
const cellSize = 15;
const colours = { 0: '#D8D2C4', 1: '#6B4F3F', 2: '#6DB35A', 3: '#4A86D0' };
let town, rows, columns;
//if a cell is true it's an obstacle
let grid;
//where the player is in the grid
let playerIndexX = 0;
let playerIndexY = 25;
// the guard walks round its beat, corner to corner
const beat = [[13, 13], [24, 13], [24, 25], [13, 25]];
let guardX = 13 * cellSize + cellSize / 2, guardY = 13 * cellSize + cellSize / 2, leg = 0;
const guardView = 120;
let sightings = 0;

function setup() {
  createCanvas(600, 400);
  town = hitbox.Grid.parse(map, cellSize);
  rows = town.rows;
  columns = town.cols;
  grid = [];
  for (let row = 0; row < rows; row++) {
    grid.push([]);
    for (let column = 0; column < columns; column++) grid[row].push(town.isSolid(column, row));
  }
}

function draw() {
  background(32);
  noStroke();
  for (let row = 0; row < rows; row++) {
    for (let column = 0; column < columns; column++) {
      fill(colours[town.get(column, row)] || '#D8D2C4');
      rect(column * cellSize, row * cellSize, cellSize, cellSize);
    }
  }
  // the route to the cell under the mouse: Hitbox's town.path, cells as row * columns + column
  const goalX = constrain(town.colAt(mouseX), 0, columns - 1), goalY = constrain(town.rowAt(mouseY), 0, rows - 1);
  const route = town.path(playerIndexX, playerIndexY, goalX, goalY);
  fill('#F2C14E');
  for (const cell of route) circle((cell % columns + 0.5) * cellSize, (Math.floor(cell / columns) + 0.5) * cellSize, 5);
  // under test: walk the route, a step every 6 frames, through the same four ifs as the keys
  if (window.scriptedRun && route.length > 1 && frameCount % 6 === 0) {
    const next = route[1], dx = next % columns - playerIndexX, dy = Math.floor(next / columns) - playerIndexY;
    walk(dx > 0 ? RIGHT_ARROW : dx < 0 ? LEFT_ARROW : dy > 0 ? DOWN_ARROW : UP_ARROW);
  }
  moveGuard();
  const px = (playerIndexX + 0.5) * cellSize, py = (playerIndexY + 0.5) * cellSize;
  const seen = dist(px, py, guardX, guardY) < guardView && town.lineOfSight(guardX, guardY, px, py);
  if (seen) sightings++;
  if (seen) {
    stroke('#E8504A');
    strokeWeight(2);
    line(guardX, guardY, px, py);
    noStroke();
  }
  fill(seen ? '#E8504A' : '#3A3A8C');
  circle(guardX, guardY, cellSize);
  //fill the player's cell with green
  fill('#4CC36A');
  rect(playerIndexX * cellSize, playerIndexY * cellSize, cellSize, cellSize);
  fill(0, 160);
  rect(0, 390, width, 10);
  fill(255);
  textSize(10);
  text('route ' + Math.max(0, route.length - 1) + ' steps' + (seen ? ';  the guard sees you' : '') + ';  seen for ' + sightings + ' frames', 4, 399);
}

function moveGuard() {
  const [col, row] = beat[(leg + 1) % beat.length];
  const tx = (col + 0.5) * cellSize, ty = (row + 0.5) * cellSize;
  const d = dist(guardX, guardY, tx, ty);
  if (d < 1) {
    leg = (leg + 1) % beat.length;
  } else {
    guardX += (tx - guardX) / d;
    guardY += (ty - guardY) / d;
  }
}

function keyPressed() {
  walk(keyCode);
}

// Section 9's four ifs: not at the edge, and the next cell not an obstacle.
function walk(keyCode) {
  if (keyCode === UP_ARROW) {
    //if we aren't in the top row and the cell above us doesn't contain an obstacle
    //then we can move up
    if (playerIndexY > 0 && !grid[playerIndexY - 1][playerIndexX]) {
      playerIndexY--;
    }
  } else if (keyCode === DOWN_ARROW) {
    if (playerIndexY < rows - 1 && !grid[playerIndexY + 1][playerIndexX]) {
      playerIndexY++;
    }
  } else if (keyCode === LEFT_ARROW) {
    if (playerIndexX > 0 && !grid[playerIndexY][playerIndexX - 1]) {
      playerIndexX--;
    }
  } else if (keyCode === RIGHT_ARROW) {
    if (playerIndexX < columns - 1 && !grid[playerIndexY][playerIndexX + 1]) {
      playerIndexX++;
    }
  }
}
