// Rectangle/Rectangle (tutorial section 5): a rectangle at the mouse against one in the centre.
// The tutorial's if (r1x + r1w > r2x && r1x < r2x + r2w && ...) beside Hitbox's
// Collide.rectRect: rectangles that only share an edge do not collide.
const w = 150, h = 100;

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  const cx = width / 2 - w / 2, cy = height / 2 - h / 2;
  const tutorialsIf = mouseX + w > cx && mouseX < cx + w && mouseY + h > cy && mouseY < cy + h;
  const hit = hitbox.Collide.rectRect(mouseX, mouseY, w, h, cx, cy, w, h);
  noStroke();
  fill(hit ? '#E8504A' : '#4CC36A');
  rect(cx, cy, w, h);
  fill(255, 180);
  rect(mouseX, mouseY, w, h);
  fill(255);
  text('the tutorial\'s if: ' + tutorialsIf + '    Collide.rectRect: ' + hit, 10, 20);
}
