// Rectangle/Point (tutorial section 4): the mouse over a rectangle.
// The tutorial's combined if (mouseX > x && mouseX < x + w && ...) beside Hitbox's
// Collide.rectPoint. Try this: a row of rectangles as buttons.
const rx = 200, ry = 125, rw = 200, rh = 150;

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  const tutorialsIf = mouseX > rx && mouseX < rx + rw && mouseY > ry && mouseY < ry + rh;
  const hit = hitbox.Collide.rectPoint(rx, ry, rw, rh, mouseX, mouseY);
  noStroke();
  fill(hit ? '#E8504A' : '#4CC36A');
  rect(rx, ry, rw, rh);
  fill(255);
  text('the tutorial\'s if: ' + tutorialsIf + '    Collide.rectPoint: ' + hit, 10, 20);
}
