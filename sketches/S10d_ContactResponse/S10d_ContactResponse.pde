/**
 * Contact and response: push out, bounce, slide
 * Beyond the tutorial: contact data and response
 *
 * Knowing that two shapes overlap is not enough to make them behave: you need to know which
 * way, and how far, to move them apart. Section 7 snaps a rectangle out along one axis; a
 * ball against a circle or a slanted edge needs a direction too. ball.contact(shape)
 * gives it: a unit normal pointing from the ball into the shape, and the depth of the
 * overlap. Then Response does the rest: separate moves the ball back by the depth so the two
 * just touch; bounce reverses the part of the velocity along the normal (a ball off a wall);
 * slide removes it and keeps the part along the surface (a character walking along a wall).
 *
 * 1 push out: the ball goes where the mouse is, but never into a shape.
 * 2 bounce: the ball flies on its own and bounces off everything (click to throw it at the mouse).
 * 3 slide: the ball chases the mouse and slides along whatever is in the way.
 *
 * Where Hitbox differs: the tutorial's responses work along the window's axes only: sections
 * 1, 6 and 8 bounce by flipping a speed (xSpeed *= -1, bouncingRectSpeedX *= -1), section 7
 * snaps to an edge, and for more it points to physics libraries; the video stops at
 * yes-or-no.
 * Hitbox adds Contact and Response, because a push, a bounce or a slide off a circle or a
 * slanted edge needs the normal and the depth, not just a yes.
 *
 * Try this: in push out, drag the ball deep into the rectangle and see which edge it leaves
 * by; in slide, put the mouse behind the pentagon; give bounce a restitution below 1.
 * Keys: 1 push out, 2 bounce, 3 slide, click throws (bounce), d shows the maths (normal,
 * depth, and the velocity split into its normal and surface parts).
 */
import hitbox.*;
import hitbox.processing.*;

int PUSH = 1, BOUNCE = 2, SLIDE = 3;
int mode = PUSH;

float r = 18;              // the ball
float x = 300, y = 340;
float vx = 3.1, vy = -2.3;

Shape[] shapes = {
    new Circle(160, 230, 55),
    new Rect(340, 80, 150, 60),
    Polygon.regular(430, 275, 62, 5, -HALF_PI),
};
Shape[] walls;             // the window's edges, as rectangles just outside it

// This frame's answers (one per contact), and the last one, kept on screen for a moment.
ArrayList<Answer> answers = new ArrayList<Answer>();
Answer shown;
int shownFor;
boolean showMaths;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  walls = new Shape[] {
      new Rect(-100, -100, width + 200, 100),
      new Rect(-100, height, width + 200, 100),
      new Rect(-100, -100, 100, height + 200),
      new Rect(width, -100, 100, height + 200),
  };
}

void draw() {
  move();
  drawScene();
}

/** One frame: move the ball, then answer every contact as the mode says. */
void move() {
  if (mode == PUSH) {
    x = mouseX;
    y = mouseY;
  } else {
    if (mode == SLIDE) {
      chaseTheMouse();
    }
    x += vx;
    y += vy;
  }
  answers.clear();
  float ghostX = x, ghostY = y;
  // Pushed out of one shape, the ball can land in another (in a corner, say): a few passes
  // over all of them settle it.
  for (int pass = 0; pass < 4; pass++) {
    int before = answers.size();
    for (int i = 0; i < shapes.length + walls.length; i++) {
      Shape s = i < shapes.length ? shapes[i] : walls[i - shapes.length];
      Circle ball = new Circle(x, y, r);
      Contact c = ball.contact(s);   // null when apart
      if (c == null) {
        continue;
      }
      Manifold touch = Contact.manifold(ball, s);   // the same contact, and where they meet
      Vec v0 = new Vec(vx, vy);
      Vec v = mode == BOUNCE ? Response.bounce(vx, vy, c.nx(), c.ny(), 1) : mode == SLIDE ? Response.slide(vx, vy, c.nx(), c.ny()) : v0;
      vx = v.x();
      vy = v.y();
      // Out along the normal by the depth, and exactly out: overlaps() is false afterwards.
      Circle out = Response.separate(ball, s);
      x = out.x();
      y = out.y();
      answered(new Answer(i, c, touch, ghostX, ghostY, x, y, v0, v));
    }
    if (answers.size() == before) {
      break;
    }
  }
}

void mousePressed() {
  if (mode == BOUNCE) {
    float dx = mouseX - x, dy = mouseY - y;
    float d = dist(0, 0, dx, dy);
    if (d > 0) {
      vx = dx / d * 6;
      vy = dy / d * 6;
    }
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key >= '1' && key <= '3') {
    mode = key - '0';
    shownFor = 0;
    if (mode == BOUNCE && vx == 0 && vy == 0) {
      vx = 3.1;
      vy = -2.3;
    }
  }
}
