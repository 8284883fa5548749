// Grids (tutorial section 9): a map of cells, '#' solid. Hitbox's Grid answers which cell a
// point is in (colAt, rowAt) and whether a circle overlaps any solid cell
// (circleOverlapsSolid), without a loop over every cell. Try this: edit the map.
let grid;
const map = [
  '............',
  '..##....##..',
  '..#......#..',
  '.....##.....',
  '..#......#..',
  '..##....##..',
  '............',
  '............',
].join('\n');

function setup() {
  createCanvas(600, 400);
  grid = hitbox.Grid.parse(map, 50);
}

function draw() {
  background(32);
  const hit = grid.circleOverlapsSolid(mouseX, mouseY, 20);
  noStroke();
  for (let row = 0; row < grid.rows; row++) {
    for (let col = 0; col < grid.cols; col++) {
      if (grid.isSolid(col, row)) {
        fill('#4C7CC3');
        rect(col * 50, row * 50, 50, 50);
      }
    }
  }
  const col = grid.colAt(mouseX), row = grid.rowAt(mouseY);
  noFill();
  stroke(255, 120);
  rect(col * 50, row * 50, 50, 50);
  noStroke();
  fill(hit ? '#E8504A' : '#4CC36A');
  circle(mouseX, mouseY, 40);
  fill(255);
  text('cell ' + col + ', ' + row + (hit ? ': touching a wall' : ''), 10, 20);
}
