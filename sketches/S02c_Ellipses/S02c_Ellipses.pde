/**
 * Ellipses: when ellipse() is given two sizes
 * Tutorial section 2: Circle/Point, for ellipses (beyond the tutorial)
 *
 * The tutorial draws its ball and its circles with ellipse(), always as wide as they are
 * tall, so they are circles and its distance tests fit them (section 1 tests only the ball's
 * centre). Give ellipse() a different width and height and the shape is an ellipse, which
 * no distance test fits; the tutorial has no test for it, so this sketch goes beyond it.
 *
 * ellipse(x, y, w, h) draws an ellipse with radii w / 2 and h / 2: new Ellipse(x, y, rx, ry)
 * holds the same centre and radii. A point is inside when (dx / rx)^2 + (dy / ry)^2 < 1:
 * e.contains(mouseX, mouseY). A circle against an ellipse is e.overlaps(circle), with the
 * circle a new Circle(x, y, r); two ellipses, or an ellipse and any other shape, the same
 * e.overlaps(other). Each ellipse turns red while the mouse (a point, or a circle) is inside
 * it, green otherwise.
 *
 * The fourth ellipse is turned: new Ellipse(x, y, rx, ry, angle) takes the angle as rotate()
 * does (radians, clockwise on screen). The same two calls answer for it, by turning the mouse
 * into the ellipse's own frame, where the same formula holds, and Draw.shape(g, e) draws it
 * turned.
 *
 * Try this: make an ellipse flat (a radius of 0: it has no inside any more); give the mouse
 * circle radius 0 and see it act as a point; squash an ellipse by changing its radii.
 * Keys: space switches the mouse between a point and a circle, t turns the fourth ellipse,
 * d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

// The ellipses, as ellipse(x, y, w, h) draws them: centre and radii (w / 2, h / 2).
Ellipse[] ellipses = {
    new Ellipse(150, 200, 110, 45),
    new Ellipse(380, 140, 40, 90),
    new Ellipse(460, 310, 90, 60),
    new Ellipse(255, 325, 65, 22, 0.5),   // turned by 0.5 radians
};
boolean[] hit = new boolean[4];   // this frame's answers, for the drawing and the tests
boolean turning;                  // t: the fourth ellipse keeps turning
float mouseR = 30;                // the mouse circle's radius
boolean circleMode;               // space: the mouse is a circle, not a point
boolean showMaths;                // the 'd' overlay

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  if (turning) {
    Ellipse e = ellipses[3];
    ellipses[3] = new Ellipse(e.x(), e.y(), e.rx(), e.ry(), e.angle() + 0.02);
  }
  for (int i = 0; i < ellipses.length; i++) {
    Ellipse e = ellipses[i];
    // The whole idea: is the mouse (a point, or a circle) inside this ellipse?
    if (circleMode) {
      Circle mouseCircle = new Circle(mouseX, mouseY, mouseR);
      hit[i] = e.overlaps(mouseCircle);
    } else {
      hit[i] = e.contains(mouseX, mouseY);
    }
    noStroke();
    fill(hit[i] ? Palette.HIT : Palette.MISS);
    if (e.angle() != 0) {
      // Turned: the library draws it turned about its centre, as rotate() turns it.
      Draw.shape(g, e);
    } else {
      // As the tutorial draws: ellipse() takes the width and height, twice the radii.
      ellipse(e.x(), e.y(), 2 * e.rx(), 2 * e.ry());
    }
  }

  // The mouse: a point, or a circle drawn as its outline.
  if (circleMode) {
    noFill();
    stroke(Palette.NEUTRAL);
    strokeWeight(2);
    circle(mouseX, mouseY, 2 * mouseR);
  }
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move the mouse over the ellipses     space: point / circle     t: turn     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ') {
    circleMode = !circleMode;
  } else if (key == 't') {
    turning = !turning;
  }
}
