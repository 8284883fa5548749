/**
 * As drawn: test shapes where translate() and rotate() put them
 * Beyond the tutorial: shapes that turn and follow the drawing matrix
 *
 * Every shape here is drawn the plain Processing way, at the origin, then moved and turned
 * with pushMatrix(), translate(), rotate() and scale(). Drawn.shape(g, shape) gives the same
 * shape where the current matrix puts it on screen, so mouseX and mouseY can be tested against
 * what you see: a turned rect comes back as a polygon, a circle squashed by scale() as a turned
 * ellipse. The shape under the mouse turns red.
 *
 * Try this: add a scale(2) before the paddle's rect; give the windmill a fifth blade; nest a
 * second rotate() inside a blade.
 * Keys: the mouse points, space stops and starts the turning, d shows the maths (each shape as
 * the library returns it, with its kind).
 */
import hitbox.*;
import hitbox.processing.*;

float angle = 0.6;        // how far the paddle and the windmill have turned, radians
boolean turning = true;
boolean showMaths;

// The shapes as the library returns them, this frame: for the drawing, the overlay and the tests.
Shape paddle, ball;
Shape[] blades = new Shape[4];
boolean overPaddle, overBall;
int overBlade = -1;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  if (turning) {
    angle += 0.01;
  }
  noStroke();

  // A paddle: rect(-80, -30, 160, 60) turned about its centre.
  pushMatrix();
  translate(170, 200);
  rotate(angle);
  paddle = Drawn.shape(g, new Rect(-80, -30, 160, 60));
  overPaddle = paddle.contains(mouseX, mouseY);
  fill(overPaddle ? Palette.HIT : Palette.PLAYER);
  rect(-80, -30, 160, 60);
  popMatrix();

  // A ball squashed by scale(): the circle comes back as a turned ellipse.
  pushMatrix();
  translate(440, 120);
  rotate(-0.5);
  scale(1.8, 0.7);
  ball = Drawn.shape(g, new Circle(0, 0, 40));
  overBall = ball.contains(mouseX, mouseY);
  fill(overBall ? Palette.HIT : Palette.ACCENT);
  circle(0, 0, 80);
  popMatrix();

  // A windmill: each blade is the same triangle, turned a quarter more than the last.
  pushMatrix();
  translate(440, 290);
  rotate(-1.5 * angle);
  overBlade = -1;
  for (int i = 0; i < 4; i++) {
    rotate(HALF_PI);
    blades[i] = Drawn.shape(g, Polygon.of(12, -8, 90, -22, 90, 8));
    if (blades[i].contains(mouseX, mouseY)) {
      overBlade = i;
    }
    fill(overBlade == i ? Palette.HIT : Palette.OBSTACLE);
    triangle(12, -8, 90, -22, 90, 8);
  }
  popMatrix();
  fill(Palette.NEUTRAL);
  circle(440, 290, 16);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "point at a shape     space: " + (turning ? "stop" : "start") + " turning     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ') {
    turning = !turning;
  }
}
