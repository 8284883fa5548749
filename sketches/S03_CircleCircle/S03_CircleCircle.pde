/**
 * Circle/Circle
 * Tutorial section 3: Circle/Circle
 *
 * Two circles overlap when the distance between their centres is less than the sum of their
 * radii: the tutorial writes dist(mouseX, mouseY, width / 2, height / 2) < bigCircleRadius +
 * smallCircleRadius. Move the blue circle with the mouse; the one in the middle turns red
 * while they overlap. Hitbox's Collide.circleCircle asks the same question squared, in
 * double: the same answers with no square root to round, so circles that only touch (the
 * distance exactly the sum) never collide.
 *
 * Try this: change the radii; give the mouse circle radius 0 and it behaves as a point
 * (section 2); put circles in an array and test every pair.
 * Keys: d shows the maths (the line between the centres, both radii, dist < r1 + r2).
 */
import hitbox.*;
import hitbox.processing.*;

float bigCircleRadius = 100;   // the circle in the middle of the window
float smallCircleRadius = 75;  // the circle on the mouse

boolean colliding;   // do they overlap? The colour shows it, the overlay writes it out
boolean showMaths;   // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // The tutorial's test: is the distance between the centres less than the sum of the radii?
  //   if (dist(mouseX, mouseY, width / 2, height / 2) < bigCircleRadius + smallCircleRadius)
  // Collide.circleCircle is that test, compared squared:
  colliding = Collide.circleCircle(mouseX, mouseY, smallCircleRadius, width / 2, height / 2, bigCircleRadius);
  if (colliding) {
    fill(Palette.HIT);
  } else {
    fill(Palette.MISS);
  }
  noStroke();
  circle(width / 2, height / 2, 2 * bigCircleRadius);

  // The mouse circle, see-through so the overlap shows.
  stroke(Palette.PLAYER);
  strokeWeight(2);
  fill(Palette.PLAYER, 150);
  circle(mouseX, mouseY, 2 * smallCircleRadius);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move the blue circle onto the other one     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
