/**
 * Circle/Point
 * Tutorial section 2: Circle/Point
 *
 * The tutorial's program: the mouse is a point, inside the circle when its distance to the
 * centre is less than the radius, dist(mouseX, mouseY, circleCenterX, circleCenterY) <
 * circleRadius. The tutorial's if picks the colour: red while the mouse is inside, green
 * otherwise. Hitbox's Collide.circlePoint asks the same question beside it, squared (dx * dx
 * + dy * dy < r * r, in double: no square root to round, so exactly on the outline is never
 * inside); both answers are written at the top, and whether they agree. Press l and Hitbox's
 * answer picks the colour instead.
 *
 * The tutorial says the test is also useful "for detecting when a point gets close to an
 * object". Here (our way of doing it) close is the same if with closeDistance added to the
 * radius: the mouse then gets a line to the circle and how far it is, dist(...) - circleRadius.
 *
 * Try this: change the < in the tutorial's if to > and watch the colours swap; make the
 * radius 0 (a circle of radius 0 contains no point); make circular buttons (the tutorial's
 * idea; S02b has some).
 * Keys: l the library picks the colour / the tutorial's if, d shows the maths (the distance
 * line, the radius, dist < r written out).
 */
import hitbox.*;
import hitbox.processing.*;

float circleCenterX;
float circleCenterY;
float circleRadius;
float closeDistance = 70;  // "close": this near the outline, or nearer

boolean hitboxDecides;  // l: Collide.circlePoint picks the colour instead of the tutorial's if
boolean showMaths;      // d

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
  boolean tutorialSays = dist(mouseX, mouseY, circleCenterX, circleCenterY) < circleRadius;
  //Hitbox's call, beside it: the same question, compared squared
  boolean hitboxSays = Collide.circlePoint(circleCenterX, circleCenterY, circleRadius, mouseX, mouseY);
  boolean inside = hitboxDecides ? hitboxSays : tutorialSays;
  //close to the circle: the same if, with closeDistance added to the radius
  boolean close = dist(mouseX, mouseY, circleCenterX, circleCenterY) < circleRadius + closeDistance;

  //red inside, green outside
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
    answers("the tutorial's if, dist() < circleRadius", tutorialSays, "Collide.circlePoint", hitboxSays, hitboxDecides);
  }
  Overlay.hint(g, "move the mouse in and out of the circle     l: " + (hitboxDecides ? "the tutorial's if" : "Hitbox")
      + " picks the colour     d: show the maths");
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
