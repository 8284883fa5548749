/**
 * Circle/Circle
 * Tutorial section 3: Circle/Circle
 *
 * Two circles overlap when the distance between their centres is less than the sum of their
 * radii: Collide.circleCircle(x1, y1, r1, x2, y2, r2). Move the blue circle with the mouse;
 * the centre circle turns red while they overlap. Circles that only touch do not collide.
 *
 * Try this: change the radii; give the mouse circle radius 0 and it behaves as a point
 * (section 2); put circles in an array and test every pair.
 * Keys: d shows the maths (the line between the centres, both radii, dist < r1 + r2).
 */
import hitbox.*;
import hitbox.processing.*;

// Circle 1 follows the mouse; circle 2 stays in the middle of the window.
float r1 = 75;
float x2 = 300;
float y2 = 200;
float r2 = 100;

boolean colliding;    // the answer for this frame, kept for the tests
boolean showMaths;    // the 'd' overlay

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  float x1 = mouseX;
  float y1 = mouseY;

  // The whole idea in one line: do the two circles overlap?
  colliding = Collide.circleCircle(x1, y1, r1, x2, y2, r2);

  noStroke();
  fill(colliding ? Palette.HIT : Palette.MISS);
  circle(x2, y2, 2 * r2);

  // The mouse circle, see-through so the overlap shows.
  stroke(Palette.PLAYER);
  strokeWeight(2);
  fill(Palette.PLAYER, 150);
  circle(x1, y1, 2 * r1);

  if (showMaths) {
    drawMaths(x1, y1);
  }
  Overlay.hint(g, "move the blue circle onto the other one     d: show the maths");
}

/** The line between the centres with its length, each radius along it, and dist < r1 + r2. */
void drawMaths(float x1, float y1) {
  float d = dist(x1, y1, x2, y2);
  // The direction from circle 1 to circle 2 (to the right when the centres coincide).
  float ux = d > 0.5 ? (x2 - x1) / d : 1;
  float uy = d > 0.5 ? (y2 - y1) / d : 0;
  // Sideways: radius 1 is drawn on this side of the line, radius 2 on the other.
  float px = -uy;
  float py = ux;

  Overlay.radius(g, x1, y1, ux, uy, r1, "r1");
  Overlay.radius(g, x2, y2, -ux, -uy, r2, "r2");

  // The distance between the centres: a dashed line.
  Overlay.guide(g, x1, y1, x2, y2);
  noStroke();
  fill(Overlay.GUIDE);
  circle(x1, y1, 6);
  circle(x2, y2, 6);
  // Its label goes beside the middle, outside radius 2's bar, so the place where the bars meet
  // or pass each other stays visible.
  Overlay.labelBeside(g, (x1 + x2) / 2 - px * 18, (y1 + y2) / 2 - py * 18, -px, -py, "dist = " + Overlay.number(d), Overlay.GUIDE);

  // The test itself, written out at the top, or at the bottom while the mouse circle is up there.
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  float verdictY = y1 - r1 < 50 ? height - 46 : 28;
  Overlay.labelCentered(g, width / 2, verdictY, "dist < r1 + r2\n" + Overlay.verdict(d, "<", r1 + r2, colliding), colour);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
