/**
 * Edges: a ball bouncing off the window
 * Tutorial section 1: Edges
 *
 * Move the ball, then ask: has it gone past an edge? If so, reverse its speed. This runs the
 * tutorial's code: the ball's centre tested against 0, width, 0 and height, and the speed
 * multiplied by -1. Press l for Hitbox's way: it tests the ball's edge (x - r < left) and sets
 * the speed's sign (pointing back inside), because a flipped speed only brings the ball back
 * if one step is enough: a ball that starts past an edge flips every frame and stays stuck in
 * the wall, flickering. The ball is red on the frames an edge test fires.
 *
 * Try this: press e to move the edges in to a box (the tutorial: "just change the numbers in
 * the if statements"; boxIfs in Box.pde are its ifs with the box's numbers), then click beside
 * the box to drop the ball in the wall; then press l and do it again.
 * Keys: l Hitbox's Edges / the tutorial's code, e the window's edges / a box's, click puts the
 * ball at the mouse, d shows the maths.
 */
import hitbox.*;
import java.util.Set;
import hitbox.processing.*;

// The ball: position, radius and speed (pixels a frame).
float x = 300;
float y = 140;
float r = 24;
float xSpeed = 4.5;
float ySpeed = 3.2;

// The edges it bounces off. e swaps the window's for a box's.
float left = 0;
float right = 600;
float top = 0;
float bottom = 400;

boolean hitboxDecides;  // l: Hitbox's Edges instead of the tutorial's if statements
boolean bounced;        // an edge test fired this frame: the ball is drawn red
boolean showMaths;      // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  x += xSpeed;
  y += ySpeed;

  bounced = false;
  if (!hitboxDecides && right == width) {
    // The tutorial's code: the centre against the window's edges, then flip the speed.
    if (x < 0 || x > width) {
      xSpeed *= -1;
      bounced = true;
    }
    if (y < 0 || y > height) {
      ySpeed *= -1;
      bounced = true;
    }
  } else if (!hitboxDecides) {
    boxIfs();  // the same ifs with the box's numbers in them (Box.pde)
  } else {
    // Hitbox's: the ball's edge against the edges (x - r < left, x + r > right, the same
    // down the page); Edges measures from (0, 0), so it gets the ball's place in the box.
    // Then the speed is set to point back inside: abs(xSpeed) past the left edge,
    // -abs(xSpeed) past the right. Set, not flipped: a second frame in the wall keeps it.
    Set<Side> crossed = Edges.crossed(new Circle(x - left, y - top, r), right - left, bottom - top);
    bounced = !crossed.isEmpty();
    xSpeed = Edges.bounceX(crossed, xSpeed);
    ySpeed = Edges.bounceY(crossed, ySpeed);
  }

  drawWalls();
  noStroke();
  fill(bounced ? Palette.HIT : Palette.PLAYER);
  circle(x, y, 2 * r);

  Overlay.label(g, 8, 8, hitboxDecides ? "Hitbox's code: the ball's edge, speed's sign set"
      : "the tutorial's code: the centre, speed *= -1");
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "l: Hitbox's code / the tutorial's   e: window / box edges   click: drop the ball   d: show the maths");
}

void mousePressed() {
  x = mouseX;
  y = mouseY;
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
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
