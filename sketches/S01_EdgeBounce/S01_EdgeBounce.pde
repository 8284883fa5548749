/**
 * Edges: a ball bouncing off the window
 * Tutorial section 1: Edges
 *
 * Move the ball, then ask: has it gone past an edge? If so, reverse its speed. The tutorial
 * tests the ball's centre against 0 and width and multiplies the speed by -1; press t to run
 * its code. Hitbox tests the ball's edge (x - r < left) and sets the speed's sign (pointing
 * back inside), because a flipped speed only brings the ball back if one step is enough: a
 * ball that starts past an edge flips every frame and stays stuck in the wall, flickering.
 *
 * Try this: with the tutorial's code, press e to move the edges in while the ball is outside
 * the box (the tutorial: "just change the numbers in the if statements"), or click beside the
 * box to drop the ball in the wall; then press t and do it again.
 * Keys: t the tutorial's code / Hitbox's, e the window's edges / a box's, click puts the ball
 * at the mouse, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

// The ball: position, radius and speed (pixels a frame).
float x = 300;
float y = 140;
float r = 24;
float xSpeed = 4.5;
float ySpeed = 3.2;

// The edges it bounces off: the numbers in the if statements. e swaps the window's for a box's.
float left = 0;
float right = 600;
float top = 0;
float bottom = 400;

boolean tutorialsCode = false;  // t: the tutorial's if statements, or Hitbox's Edges
boolean bounced;                // an edge test fired this frame: the ball is drawn red
boolean showMaths;              // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  x += xSpeed;
  y += ySpeed;

  if (tutorialsCode) {
    // The tutorial's code: the centre against the edges, then flip the speed.
    bounced = false;
    if (x < left || x > right) {
      xSpeed *= -1;
      bounced = true;
    }
    if (y < top || y > bottom) {
      ySpeed *= -1;
      bounced = true;
    }
  } else {
    // Hitbox's: the ball's edge against the edges (x - r < left, x + r > right, the same
    // down the page); Edges measures from (0, 0), so it gets the ball's place in the box.
    // Then the speed is set to point back inside: abs(xSpeed) past the left edge,
    // -abs(xSpeed) past the right. Set, not flipped: a second frame in the wall keeps it.
    int crossed = Edges.circleCrossed(x - left, y - top, r, right - left, bottom - top);
    bounced = crossed != Edges.NONE;
    xSpeed = Edges.bounceX(crossed, xSpeed);
    ySpeed = Edges.bounceY(crossed, ySpeed);
  }

  drawWalls();
  noStroke();
  fill(bounced ? Palette.HIT : Palette.PLAYER);
  circle(x, y, 2 * r);

  Overlay.label(g, 8, 8, tutorialsCode ? "the tutorial's code: the centre, speed *= -1"
      : "Hitbox's code: the ball's edge, speed's sign set");
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "t: tutorial's code / Hitbox's   e: window / box edges   click: drop the ball   d: show the maths");
}

void mousePressed() {
  x = mouseX;
  y = mouseY;
}

void keyPressed() {
  if (key == 't') {
    tutorialsCode = !tutorialsCode;
  } else if (key == 'e') {
    boolean window = right == width;
    left = window ? 150 : 0;
    right = window ? 450 : width;
    top = window ? 100 : 0;
    bottom = window ? 300 : height;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
