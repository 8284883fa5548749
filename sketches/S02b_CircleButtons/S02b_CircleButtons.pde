/**
 * Circular buttons
 * Tutorial section 2: Circle/Point
 *
 * The tutorial says the circle/point test is useful for circular buttons. Here are four:
 * a button is under the mouse when the mouse is inside its circle, the tutorial's if,
 * dist(mouseX, mouseY, buttonX[i], buttonY) < buttonRadius (overButton below; the tutorial
 * gives no code for buttons, so the rest is ours). The button under the mouse gets a white
 * ring, and a click on it lights the lamp in its colour. A click in a corner of a button's
 * square misses it: that is why a round button needs the circle test. Hitbox's
 * Collide.circlePoint (the same test, compared squared) runs beside it; press l and it
 * decides instead. The top line says whether they have ever disagreed.
 *
 * Try this: give each button its own radius; make a ring-shaped button (inside the outer
 * circle and not inside the inner one); count the clicks on each button.
 * Keys: l Collide.circlePoint decides / the tutorial's if, d shows the maths (each button's
 * square, the distance to the nearest, dist < r).
 */
import hitbox.*;
import hitbox.processing.*;

// The buttons: centres along a row, one radius, one colour each.
float[] buttonX = {120, 240, 360, 480};
float buttonY = 300;
float buttonRadius = 42;
color[] buttonColour = {Palette.HIT, Palette.ACCENT, Palette.MISS, Palette.PLAYER};

int picked = 3;         // the button clicked last: the lamp shows its colour
int disagreements = 0;  // tests where the tutorial's if and Collide.circlePoint differed
boolean hitboxDecides;  // l: Collide.circlePoint decides instead of the tutorial's if
boolean showMaths;      // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // The lamp, in the colour of the button clicked last.
  noStroke();
  fill(buttonColour[picked]);
  circle(300, 120, 150);

  for (int i = 0; i < buttonX.length; i++) {
    if (overButton(i)) {
      stroke(Palette.NEUTRAL);
      strokeWeight(5);
    } else {
      stroke(Palette.LINE);
      strokeWeight(2);
    }
    fill(buttonColour[i]);
    circle(buttonX[i], buttonY, 2 * buttonRadius);
  }

  // The point: the mouse.
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  if (showMaths) {
    drawMaths();
  }
  Overlay.label(g, 8, 8, (hitboxDecides ? "Collide.circlePoint decides (l: the tutorial's if)" : "the tutorial's if decides (l: Collide.circlePoint)")
      + ";  they have disagreed " + disagreements + " times");
  Overlay.hint(g, "move over a button, click it to light the lamp     l: who decides     d: show the maths");
}

// Is the mouse on button i? The tutorial's if: inside its circle, dist() < radius.
boolean overButton(int i) {
  boolean tutorialSays = dist(mouseX, mouseY, buttonX[i], buttonY) < buttonRadius;
  boolean hitboxSays = Collide.circlePoint(buttonX[i], buttonY, buttonRadius, mouseX, mouseY);
  if (tutorialSays != hitboxSays) {
    disagreements++;
  }
  return hitboxDecides ? hitboxSays : tutorialSays;
}

void mousePressed() {
  // The same test as the ring: a click counts only inside a button's circle.
  for (int i = 0; i < buttonX.length; i++) {
    if (overButton(i)) {
      picked = i;
    }
  }
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
