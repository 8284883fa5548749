/**
 * Circle/Circle
 * Tutorial section 3: Circle/Circle
 *
 * The tutorial's program: a big circle in the middle of the window, drawn as an outline, and
 * a small one on the mouse. They collide when the distance between their centres is less
 * than the sum of their radii: dist(mouseX, mouseY, width / 2, height / 2) < bigCircleRadius
 * + smallCircleRadius. The tutorial's if picks the colour: the small circle is red while they
 * collide, green otherwise. Hitbox's Collide.circleCircle asks the same question beside it,
 * squared, in double (no square root to round, so circles that only touch, the distance
 * exactly the sum, never collide); both answers are written at the top, and whether they
 * agree. Press l and Hitbox's answer picks the colour instead.
 *
 * Try this: change the + in the tutorial's if to - and watch the red shrink; change the
 * radii; give the mouse circle radius 0 and it behaves as a point (section 2); put circles in
 * an array and test every pair.
 * Keys: l the library picks the colour / the tutorial's if, d shows the maths (the line
 * between the centres, both radii, dist < r1 + r2).
 */
import hitbox.*;
import hitbox.processing.*;

float bigCircleRadius = 100;   // the tutorial's is 50 in a 300 x 300 window
float smallCircleRadius = 75;  // and 25: here both are bigger, the sum is the 175 of its pictures

boolean hitboxDecides;  // l: Collide.circleCircle picks the colour instead of the tutorial's if
boolean showMaths;      // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  //draw the big circle
  noFill();
  stroke(255);
  strokeWeight(2);
  ellipse(width / 2, height / 2, bigCircleRadius * 2, bigCircleRadius * 2);

  //the tutorial's if: is the distance between the centres less than the sum of the radii?
  boolean tutorialSays = dist(mouseX, mouseY, width / 2, height / 2) < bigCircleRadius + smallCircleRadius;
  //Hitbox's call, beside it: the same question, compared squared
  boolean hitboxSays = Collide.circleCircle(mouseX, mouseY, smallCircleRadius, width / 2, height / 2, bigCircleRadius);
  boolean colliding = hitboxDecides ? hitboxSays : tutorialSays;

  //change color if circles are colliding
  if (colliding) {
    fill(Palette.HIT);
  } else {
    fill(Palette.MISS);
  }
  //draw the small circle
  noStroke();
  ellipse(mouseX, mouseY, smallCircleRadius * 2, smallCircleRadius * 2);
  // The big circle's outline again, over it, so the overlap shows.
  noFill();
  stroke(255);
  ellipse(width / 2, height / 2, bigCircleRadius * 2, bigCircleRadius * 2);

  if (showMaths) {
    drawMaths(colliding);
  } else {
    answers("the tutorial's if, dist() < bigCircleRadius + smallCircleRadius", tutorialSays,
        "Collide.circleCircle", hitboxSays, hitboxDecides);
  }
  Overlay.hint(g, "move the small circle onto the big one     l: " + (hitboxDecides ? "the tutorial's if" : "Hitbox")
      + " picks the colour     d: show the maths");
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
