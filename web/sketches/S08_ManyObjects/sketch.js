// Many objects (tutorial section 8): a list of rectangles and a loop that tests the mouse's
// circle against each (Hitbox's Collide.rectCircle); each one hit turns red. A click adds one.
const obstacles = [];
const r = 30;

function setup() {
  createCanvas(600, 400);
  randomSeed(8);
  for (let i = 0; i < 12; i++) {
    obstacles.push({ x: random(width - 80), y: random(height - 60), w: random(30, 80), h: random(20, 60) });
  }
}

function draw() {
  background(32);
  noStroke();
  let hits = 0;
  for (const o of obstacles) {
    const hit = hitbox.Collide.rectCircle(o.x, o.y, o.w, o.h, mouseX, mouseY, r);
    if (hit) hits++;
    fill(hit ? '#E8504A' : '#4C7CC3');
    rect(o.x, o.y, o.w, o.h);
  }
  fill(255, 160);
  circle(mouseX, mouseY, r * 2);
  fill(255);
  text(hits + ' of ' + obstacles.length + ' hit', 10, 20);
}

function mousePressed() {
  obstacles.push({ x: mouseX - 25, y: mouseY - 15, w: 50, h: 30 });
}
