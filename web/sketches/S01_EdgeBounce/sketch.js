// Edges (tutorial section 1): a ball bouncing off the window's edges.
// The tutorial's ifs (x < r, x > width - r) beside Hitbox's Collide.rectContainsCircle, which
// asks whether the ball is still wholly inside the window. Try this: change the speeds.
let x = 100, y = 80, r = 25, xSpeed = 5, ySpeed = 3;

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  x += xSpeed;
  y += ySpeed;
  // the tutorial's ifs: past an edge, turn round
  if (x < r || x > width - r) xSpeed *= -1;
  if (y < r || y > height - r) ySpeed *= -1;
  // Hitbox's call: is the ball wholly inside the window?
  const inside = hitbox.Collide.rectContainsCircle(0, 0, width, height, x, y, r);
  fill(inside ? '#4CC36A' : '#E8504A');
  noStroke();
  circle(x, y, r * 2);
}
