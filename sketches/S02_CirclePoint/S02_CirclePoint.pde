/**
 * Circle/Point
 * Tutorial section 2: Circle/Point
 *
 * The tutorial's program: the mouse is a point, inside the circle when its distance to the
 * centre is less than the radius, dist(mouseX, mouseY, circleCenterX, circleCenterY) <
 * circleRadius. The circle turns red while the mouse is inside, green otherwise. Hitbox's
 * Collide.circlePoint asks the same question squared, dx * dx + dy * dy < r * r, in double:
 * the same answers with no square root to round, so exactly on the outline is never inside.
 * Both answers are written at the top, every frame.
 *
 * The tutorial says the test is also useful "for detecting when a point gets close to an
 * object". Here (our way of doing it) close means the same test with a bigger circle: within
 * closeDistance of the outline, the mouse gets a line to the circle and how far it is,
 * dist(...) - circleRadius.
 *
 * Try this: make the radius 0 (a circle of radius 0 contains no point); move the centre
 * to the mouse on click; make circular buttons (the tutorial's idea; S02b has some).
 * Keys: d shows the maths (the distance line, the radius, dist < r written out).
 */
import hitbox.*;
import hitbox.processing.*;

float circleCenterX;
float circleCenterY;
float circleRadius;
float closeDistance = 70;  // "close": this near the outline, or nearer

boolean showMaths;   // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  circleCenterX = width / 2;
  circleCenterY = height / 2;
  circleRadius = 100;
}

void draw() {
  background(Palette.BACKGROUND);

  //the tutorial's if: is the distance from the mouse to the centre less than the radius?
  boolean tutorialsIf = dist(mouseX, mouseY, circleCenterX, circleCenterY) < circleRadius;
  //Hitbox's call: the same question, compared squared
  boolean inside = Collide.circlePoint(circleCenterX, circleCenterY, circleRadius, mouseX, mouseY);
  //close to the circle: the same test, with a circle closeDistance bigger
  boolean close = Collide.circlePoint(circleCenterX, circleCenterY, circleRadius + closeDistance, mouseX, mouseY);

  if (inside) {
    fill(Palette.HIT);
  } else {
    fill(Palette.MISS);
  }
  noStroke();
  ellipse(circleCenterX, circleCenterY, circleRadius * 2, circleRadius * 2);
  if (close && !inside) {
    drawHowClose();
  }

  // The point: the mouse.
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  if (showMaths) {
    drawMaths(inside);
  } else {
    answer(8, 8, "the tutorial's if, dist() < circleRadius", tutorialsIf);
    answer(8, 30, "Collide.circlePoint", inside);
  }
  Overlay.hint(g, "move the mouse in and out of the circle     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
