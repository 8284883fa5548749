// Circle/Point (tutorial section 2): the mouse in a circle.
// The tutorial's if, dist(mouseX, mouseY, cx, cy) < r, beside Hitbox's Collide.circlePoint
// (the same question, squared: no square root to round). Try this: a second circle.
const cx = 300, cy = 200, r = 100;

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  const tutorialsIf = dist(mouseX, mouseY, cx, cy) < r;
  const hit = hitbox.Collide.circlePoint(cx, cy, r, mouseX, mouseY);
  fill(hit ? '#E8504A' : '#4CC36A');
  noStroke();
  circle(cx, cy, r * 2);
  fill(255);
  text('dist() < r: ' + tutorialsIf + '    Collide.circlePoint: ' + hit, 10, 20);
}
