/**
 * Ball in a Circle
 * Tutorial section 3: Circle/Circle
 *
 * The tutorial's "try this" at the end of the circle sections: a ball that bounces off the
 * edges of the window and turns red inside a circle in the middle. Two tests each frame:
 * section 1's edges, and section 3's circle/circle, Collide.circleCircle(x, y, r, cx, cy, R),
 * the tutorial's dist(x, y, cx, cy) < r + R. Red here means "overlapping": the ball turns
 * red as soon as it reaches in. The edges are Hitbox's way from S01 (the ball's edge
 * tested, the speed's sign set), with the ball put back at the edge.
 *
 * Try this: make it red only when wholly inside (dist + r < R); make the ball bigger than
 * the circle; add a second ball and test the two balls against each other.
 * Keys: d shows the maths (distance, both radii, dist < r + R, the edges crossed). Space
 * pauses. Click to put the ball at the mouse.
 */
import hitbox.*;
import hitbox.processing.*;

// The circle in the middle.
float cx = 300;
float cy = 200;
float R = 90;

// The ball: position, radius and speed (pixels a frame).
float x = 110;
float y = 90;
float r = 22;
float xSpeed = 3.3;
float ySpeed = 2.1;

boolean inside;      // does the ball overlap the circle? It is drawn red while it does
boolean paused;      // space
boolean showMaths;   // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  startTrail();
}

void draw() {
  background(Palette.BACKGROUND);
  if (!paused) {
    x += xSpeed;
    y += ySpeed;
    // Section 1: bounce off the window's edges, Hitbox's way (S01), then put it back at the edge.
    int crossed = Edges.circleCrossed(x, y, r, width, height);
    xSpeed = Edges.bounceX(crossed, xSpeed);
    ySpeed = Edges.bounceY(crossed, ySpeed);
    x = Edges.circleClampX(x, r, width);
    y = Edges.circleClampY(y, r, height);
    addToTrail(crossed);
  }

  // Section 3: does the ball overlap the circle? dist(x, y, cx, cy) < r + R
  inside = Collide.circleCircle(x, y, r, cx, cy, R);

  // The circle: an obstacle the ball passes through.
  stroke(Palette.OBSTACLE);
  strokeWeight(2);
  fill(Palette.OBSTACLE, 50);
  circle(cx, cy, 2 * R);

  color ballColour = inside ? Palette.HIT : Palette.MISS;
  drawTrail(ballColour);
  noStroke();
  fill(ballColour);
  circle(x, y, 2 * r);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "d: show the maths     space: pause     click: put the ball there");
  drawBounce();
}

void mousePressed() {
  x = Edges.circleClampX(mouseX, r, width);
  y = Edges.circleClampY(mouseY, r, height);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ') {
    paused = !paused;
  }
}
