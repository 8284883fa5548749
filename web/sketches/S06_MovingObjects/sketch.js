// Moving objects (tutorial section 6): a ball bounces off a rectangle by checking where it will
// be next frame, before it moves. The tutorial's if on the next position beside Hitbox's
// Collide.circleRect for the same question. Try this: make the ball faster than the rectangle
// is wide, and see the next-position check miss (the swept test never does).
let x = 80, y = 200, xSpeed = 4, ySpeed = 2.5;
const r = 20, rx = 250, ry = 120, rw = 100, rh = 160;

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  // the tutorial: would the next position overlap? then turn round instead of moving
  const nextX = x + xSpeed;
  if (hitbox.Collide.circleRect(nextX, y, r, rx, ry, rw, rh)) {
    xSpeed *= -1;
  }
  const nextY = y + ySpeed;
  if (hitbox.Collide.circleRect(x, nextY, r, rx, ry, rw, rh)) {
    ySpeed *= -1;
  }
  x += xSpeed;
  y += ySpeed;
  if (x < r || x > width - r) xSpeed *= -1;
  if (y < r || y > height - r) ySpeed *= -1;
  noStroke();
  fill('#4C7CC3');
  rect(rx, ry, rw, rh);
  fill('#4CC36A');
  circle(x, y, r * 2);
}
