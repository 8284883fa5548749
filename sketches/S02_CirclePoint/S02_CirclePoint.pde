/**
 * Circle/Point
 * Tutorial section 2: Circle/Point
 *
 * The mouse is a point. It is inside the circle when its distance to the centre is less
 * than the radius: Collide.circlePoint(cx, cy, r, mouseX, mouseY). The circle turns red
 * while the mouse is inside, green otherwise. Exactly on the outline is not inside.
 *
 * Try this: make the radius 0 (a circle of radius 0 contains no point); move the centre
 * to the mouse on click; draw many circles and colour the ones under the mouse.
 * Keys: d shows the maths (the distance line, the radius, dist < r written out).
 */
import hitbox.*;
import hitbox.processing.*;

float cx = 300;   // the circle's centre
float cy = 200;
float r = 100;    // its radius (Processing's circle() takes the diameter, 2 * r)

boolean inside;       // the answer for this frame, kept for the tests
boolean showMaths;    // the 'd' overlay

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // The whole idea in one line: is the point (mouseX, mouseY) inside the circle?
  inside = Collide.circlePoint(cx, cy, r, mouseX, mouseY);

  noStroke();
  fill(inside ? Palette.HIT : Palette.MISS);
  circle(cx, cy, 2 * r);

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

/** The distance from the centre to the mouse, the radius beside it, and dist < r. */
void drawMaths() {
  float d = dist(cx, cy, mouseX, mouseY);
  // The direction from the centre to the mouse (to the right when the mouse is on the centre).
  float ux = d > 0.5 ? (mouseX - cx) / d : 1;
  float uy = d > 0.5 ? (mouseY - cy) / d : 0;
  // The radius, along the same direction, set to one side (-uy, ux) of the distance line.
  Overlay.radius(g, cx, cy, ux, uy, r, "r");

  // The distance: a dashed line from the centre to the mouse, its length written beside it
  // on the other side.
  Overlay.guide(g, cx, cy, mouseX, mouseY);
  Overlay.labelBeside(g, (cx + mouseX) / 2, (cy + mouseY) / 2, uy, -ux, "dist = " + Overlay.number(d), Overlay.GUIDE);

  // The centre, where both lines start.
  noStroke();
  fill(Overlay.GUIDE);
  circle(cx, cy, 6);

  // The test itself, written out.
  color colour = inside ? Overlay.HIT : Overlay.MISS;
  Overlay.labelCentered(g, width / 2, 28, "dist < r\n" + Overlay.verdict(d, "<", r, inside), colour);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
