// Circle/Circle (tutorial section 3): a big circle in the middle, a small one on the mouse.
// The tutorial's if, dist() < bigRadius + smallRadius, beside Hitbox's Collide.circleCircle:
// circles that only touch never collide. Try this: give the mouse circle radius 0.
const bigRadius = 100, smallRadius = 75;

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  const tutorialsIf = dist(mouseX, mouseY, width / 2, height / 2) < bigRadius + smallRadius;
  const hit = hitbox.Collide.circleCircle(mouseX, mouseY, smallRadius, width / 2, height / 2, bigRadius);
  noStroke();
  fill(hit ? '#E8504A' : '#4CC36A');
  circle(mouseX, mouseY, smallRadius * 2);
  noFill();
  stroke(255);
  strokeWeight(2);
  circle(width / 2, height / 2, bigRadius * 2);
  noStroke();
  fill(255);
  text('dist() < r1 + r2: ' + tutorialsIf + '    Collide.circleCircle: ' + hit, 10, 20);
}
