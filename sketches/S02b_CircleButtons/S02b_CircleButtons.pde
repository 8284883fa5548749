/**
 * Circular buttons
 * Tutorial section 2: Circle/Point
 *
 * The tutorial says the circle/point test is useful for circular buttons. Here are four:
 * a button is under the mouse when the mouse is inside its circle, Collide.circlePoint
 * (the tutorial's dist(mouseX, mouseY, x, y) < r, compared squared). The button under the
 * mouse gets a white ring, and a click on it lights the lamp in its colour. A click in a
 * corner of a button's square misses it: that is why a round button needs the circle test.
 *
 * Try this: give each button its own radius; make a ring-shaped button (inside the outer
 * circle and not inside the inner one); count the clicks on each button.
 * Keys: d shows the maths (each button's square, the distance to the nearest, dist < r).
 */
import hitbox.*;
import hitbox.processing.*;

// The buttons: centres along a row, one radius, one colour each.
float[] buttonX = {120, 240, 360, 480};
float buttonY = 300;
float buttonRadius = 42;
color[] buttonColour = {Palette.HIT, Palette.ACCENT, Palette.MISS, Palette.PLAYER};

int picked = 3;      // the button clicked last: the lamp shows its colour
boolean showMaths;   // d

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
    // Is the mouse on this button? Inside its circle: dist < r.
    boolean over = Collide.circlePoint(buttonX[i], buttonY, buttonRadius, mouseX, mouseY);
    if (over) {
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
  Overlay.hint(g, "move over a button, click it to light the lamp     d: show the maths");
}

void mousePressed() {
  // The same test as the ring: a click counts only inside a button's circle.
  for (int i = 0; i < buttonX.length; i++) {
    if (Collide.circlePoint(buttonX[i], buttonY, buttonRadius, mouseX, mouseY)) {
      picked = i;
    }
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
