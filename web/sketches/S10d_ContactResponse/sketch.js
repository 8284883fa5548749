// Beyond the tutorial: contact data. A circle at the mouse is pushed out of the rectangle by
// the contact's normal and depth (hitbox's shape.contact(other)): where it would be drawn
// without overlapping. Try this: a polygon instead of the rectangle.
let box;

function setup() {
  createCanvas(600, 400);
  box = hitbox.rect(200, 150, 200, 100);
}

function draw() {
  background(32);
  noStroke();
  fill('#4C7CC3');
  rect(200, 150, 200, 100);
  const ball = hitbox.circle(mouseX, mouseY, 40);
  const c = ball.contact(box);
  let x = mouseX, y = mouseY;
  if (c) {
    // the normal points from the ball into the box: move back along it by the depth
    x -= c.nx * c.depth;
    y -= c.ny * c.depth;
    noFill();
    stroke(255, 120);
    circle(mouseX, mouseY, 80);
  }
  noStroke();
  fill(c ? '#E8504A' : '#4CC36A');
  circle(x, y, 80);
  fill(255);
  text(c ? 'contact: normal (' + c.nx.toFixed(2) + ', ' + c.ny.toFixed(2) + '), depth ' + c.depth.toFixed(1) : 'apart', 10, 20);
}
