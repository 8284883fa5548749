/**
 * Circle/Point
 * Tutorial section 2: Circle/Point
 *
 * The mouse is a point. It is inside the circle when its distance to the centre is less
 * than the radius: the tutorial writes dist(mouseX, mouseY, circleCenterX, circleCenterY)
 * < circleRadius. The circle turns red while the mouse is inside, green otherwise. Hitbox's
 * Collide.circlePoint asks the same question squared, dx * dx + dy * dy < r * r, in double:
 * the same answers with no square root to round, so exactly on the outline is never inside.
 *
 * Try this: make the radius 0 (a circle of radius 0 contains no point); move the centre
 * to the mouse on click; make circular buttons (the tutorial's idea; S02b has some).
 * Keys: d shows the maths (the distance line, the radius, dist < r written out).
 */
import hitbox.*;
import hitbox.processing.*;

float circleCenterX = 300;
float circleCenterY = 200;
float circleRadius = 100;  // circle() takes the diameter: 2 * circleRadius

boolean inside;      // is the mouse inside? The colour shows it, the overlay writes it out
boolean showMaths;   // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // The tutorial's test: is the distance from the mouse to the centre less than the radius?
  //   if (dist(mouseX, mouseY, circleCenterX, circleCenterY) < circleRadius)
  // Collide.circlePoint is that test, compared squared:
  inside = Collide.circlePoint(circleCenterX, circleCenterY, circleRadius, mouseX, mouseY);
  if (inside) {
    fill(Palette.HIT);
  } else {
    fill(Palette.MISS);
  }
  noStroke();
  circle(circleCenterX, circleCenterY, 2 * circleRadius);

  // The point: the mouse.
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move the mouse in and out of the circle     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
