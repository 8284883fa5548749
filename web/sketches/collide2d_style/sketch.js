// A sketch written for p5.collide2D, typed from its documentation's examples, run unchanged
// on Hitbox's add-on (p5.hitbox.js): a rectangle and a circle follow the mouse; each shape they
// hit turns red. collideRectRect, collideRectCircle, collideCircleCircle, collidePointPoly and
// collideLineCircle, with p5.collide2D's arguments (circles by diameter, polygons as vectors).
var hit = false;
var poly = [];

function setup() {
  createCanvas(400, 300);
  poly[0] = createVector(300, 40);
  poly[1] = createVector(370, 90);
  poly[2] = createVector(340, 170);
  poly[3] = createVector(260, 150);
}

function draw() {
  background(255);
  noFill();

  // the rectangle at the mouse against a still one
  hit = collideRectRect(40, 40, 100, 80, mouseX, mouseY, 50, 50);
  stroke(hit ? color('red') : 0);
  rect(40, 40, 100, 80);

  // a circle against the rectangle at the mouse
  hit = collideRectCircle(mouseX, mouseY, 50, 50, 200, 220, 100);
  stroke(hit ? color('red') : 0);
  circle(200, 220, 100);

  // a circle against a circle at the mouse
  hit = collideCircleCircle(mouseX, mouseY, 40, 90, 230, 60);
  stroke(hit ? color('red') : 0);
  circle(90, 230, 60);

  // the mouse in a polygon
  hit = collidePointPoly(mouseX, mouseY, poly);
  stroke(hit ? color('red') : 0);
  beginShape();
  for (var i = 0; i < poly.length; i++) {
    vertex(poly[i].x, poly[i].y);
  }
  endShape(CLOSE);

  // a line against the circle at the mouse
  hit = collideLineCircle(180, 30, 380, 280, mouseX, mouseY, 40);
  stroke(hit ? color('red') : 0);
  line(180, 30, 380, 280);

  stroke(0);
  rect(mouseX, mouseY, 50, 50);
  circle(mouseX, mouseY, 40);
}
