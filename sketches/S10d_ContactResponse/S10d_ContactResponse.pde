/**
 * Contact and response: push out, bounce, slide
 * Tutorial section 10: Contact and response
 *
 * Knowing that two shapes overlap is not enough to make them behave: you need to know which
 * way, and how far, to move them apart. Contact.between(ball, shape) gives that: a unit
 * normal pointing from the ball into the shape and the depth of the overlap. Then Response
 * does the rest: separate moves the ball back by the depth so the two just touch; bounce
 * reverses the part of the velocity along the normal (a ball off a wall); slide removes it
 * and keeps the part along the surface (a character walking along a wall).
 *
 * 1 push out: the ball goes where the mouse is, but never into a shape.
 * 2 bounce: the ball flies on its own and bounces off everything (click to throw it at the mouse).
 * 3 slide: the ball chases the mouse and slides along whatever is in the way.
 *
 * Try this: in push out, drag the ball deep into the rectangle and see which edge it leaves
 * by; in slide, put the mouse behind the pentagon; give bounce a restitution below 1.
 * Keys: 1 push out, 2 bounce, 3 slide, click throws (bounce), d shows the maths (normal,
 * depth, and the velocity split into its normal and surface parts).
 */
import hitbox.*;
import hitbox.processing.*;

int PUSH = 1, BOUNCE = 2, SLIDE = 3;
String[] modeNames = {"", "push out", "bounce", "slide"};
int mode = PUSH;

float r = 18;              // the ball
float x = 300, y = 340;
float vx = 3.1, vy = -2.3;

Shape[] shapes = {
    new Circle(160, 230, 55),
    new Rect(340, 80, 150, 60),
    Polygon.regular(430, 275, 62, 5, -HALF_PI),
};
String[] shapeNames = {"circle", "rect", "pentagon"};
Shape[] walls;             // the window's edges, as rectangles just outside it
int[] flash = new int[3];  // frames left to show a shape red after a hit

// This frame's contacts, for drawing and the tests: which shape, the contact, and the
// velocity just before and just after the response.
ArrayList<Integer> hitShapes = new ArrayList<Integer>();
ArrayList<Contact> contacts = new ArrayList<Contact>();
ArrayList<Vec> before = new ArrayList<Vec>();
ArrayList<Vec> after = new ArrayList<Vec>();
float ghostX, ghostY;      // where the ball was before the push out
int movedIn;               // the mode this frame's contacts were answered in

// The last hit, kept on screen for a moment so it can be read.
Contact shownContact;
float shownX, shownY;      // the ball's centre after the push out
float shownBx, shownBy, shownAx, shownAy;   // velocity before and after
float shownGhostX, shownGhostY;
int shownShape = -1;
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
  background(Palette.BACKGROUND);
  move();

  for (int i = 0; i < shapes.length; i++) {
    noStroke();
    fill(flash[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    Draw.shape(g, shapes[i]);
    if (flash[i] > 0) {
      flash[i]--;
    }
  }

  Overlay.label(g, 8, 8, "mode: " + mode + " " + modeNames[mode] + "   (1 push out, 2 bounce, 3 slide)");

  if (mode == PUSH && (ghostX != x || ghostY != y)) {
    // Where the mouse would put the ball: inside a shape.
    noFill();
    stroke(Palette.PLAYER, 160);
    strokeWeight(1.5);
    circle(ghostX, ghostY, 2 * r);
  }
  noStroke();
  fill(Palette.PLAYER);
  circle(x, y, 2 * r);
  if (mode != PUSH) {
    stroke(Palette.NEUTRAL);
    strokeWeight(2);
    Draw.arrow(g, x, y, vx * 8, vy * 8);   // the velocity, 8 frames' worth
  }

  if (shownFor > 0) {
    drawContact();
    shownFor--;
  }
  Overlay.hint(g, mode == BOUNCE ? "click: throw the ball at the mouse     d: show the maths"
      : mode == SLIDE ? "the ball chases the mouse     d: show the maths"
      : "move the mouse into the shapes     d: show the maths");
}

/** One frame: move the ball, then answer each contact as the mode says. */
void move() {
  movedIn = mode;
  hitShapes.clear();
  contacts.clear();
  before.clear();
  after.clear();
  if (mode == PUSH) {
    x = mouseX;
    y = mouseY;
  } else {
    if (mode == SLIDE) {
      // Head for the mouse, at most 4 pixels a frame.
      float dx = mouseX - x, dy = mouseY - y;
      float d = dist(0, 0, dx, dy);
      float speed = min(d, 4);
      vx = d > 0 ? dx / d * speed : 0;
      vy = d > 0 ? dy / d * speed : 0;
    }
    x += vx;
    y += vy;
  }
  ghostX = x;
  ghostY = y;
  // Pushed out of one shape, the ball can land in another (in a corner, say): a few passes
  // over all of them settle it.
  for (int pass = 0; pass < 4; pass++) {
    int before = contacts.size();
    respond();
    if (contacts.size() == before) {
      break;
    }
  }
}

/** One pass: every shape the ball overlaps, answered in turn. */
void respond() {
  for (int i = 0; i < shapes.length + walls.length; i++) {
    Shape s = i < shapes.length ? shapes[i] : walls[i - shapes.length];
    Circle ball = new Circle(x, y, r);
    Contact c = Contact.between(ball, s);
    if (c == null) {
      continue;
    }
    Vec v0 = new Vec(vx, vy);
    if (mode == BOUNCE) {
      Vec v = Response.bounce(vx, vy, c);
      vx = v.x();
      vy = v.y();
    } else if (mode == SLIDE) {
      Vec v = Response.slide(vx, vy, c);
      vx = v.x();
      vy = v.y();
    }
    // Out along the normal by the depth, and exactly out: overlaps() is false afterwards.
    Circle out = Response.separate(ball, s);
    x = out.x();
    y = out.y();
    hitShapes.add(i);
    contacts.add(c);
    before.add(v0);
    after.add(new Vec(vx, vy));
    if (i < shapes.length) {
      flash[i] = mode == PUSH ? 1 : 12;
    }
    // Keep it on screen for a moment (a bounce lasts one frame).
    shownContact = c;
    shownShape = i;
    shownX = x;
    shownY = y;
    shownGhostX = ghostX;
    shownGhostY = ghostY;
    shownBx = v0.x();
    shownBy = v0.y();
    shownAx = vx;
    shownAy = vy;
    shownFor = mode == PUSH ? 1 : 45;
  }
}

/**
 * The last contact: the normal where the ball touches the shape, and with the maths on, the
 * depth it was pushed out by and the velocity's two parts before and after.
 */
void drawContact() {
  Contact c = shownContact;
  float nx = c.nx(), ny = c.ny();
  float sx = -ny, sy = nx;   // along the surface
  boolean stale = shownX != x || shownY != y;
  if (stale) {
    // The ball has moved on: where it was when it touched.
    noFill();
    stroke(Palette.PLAYER, 140);
    strokeWeight(1.5);
    circle(shownX, shownY, 2 * r);
  }
  if (mode != PUSH) {
    // The velocity coming in (ending at the ball) and going out (starting from it).
    stroke(Palette.PLAYER, 200);
    strokeWeight(2);
    Draw.arrow(g, shownX - shownBx * 8, shownY - shownBy * 8, shownBx * 8, shownBy * 8);
    stroke(Palette.NEUTRAL);
    Draw.arrow(g, shownX, shownY, shownAx * 8, shownAy * 8);
  }
  // The contact point, on the ball's outline towards the shape, and the normal: from the
  // ball (a) into the shape (b).
  float tx = shownX + nx * r, ty = shownY + ny * r;
  stroke(Palette.ACCENT);
  strokeWeight(2.5);
  Draw.arrow(g, tx, ty, nx * 34, ny * 34);
  noStroke();
  fill(Palette.ACCENT);
  circle(tx, ty, 7);
  String name = shownShape < shapes.length ? shapeNames[shownShape] : "window edge";
  Overlay.labelBeside(g, tx + nx * 38, ty + ny * 38, nx, ny, "normal", Overlay.GUIDE);
  if (!showMaths) {
    return;
  }
  String text = "Contact.between(ball, " + name + "): normal (" + Overlay.number(nx) + ", "
      + Overlay.number(ny) + "), depth " + Overlay.number(c.depth());
  if (mode == PUSH) {
    // The push, as a dimension line beside the ball: from where the mouse put it, back
    // against the normal by the depth.
    float side = sy > 0 || (sy == 0 && sx < 0) ? -1 : 1;   // on the upper side
    float off = side * (r + 10);
    float ax = shownGhostX + sx * off, ay = shownGhostY + sy * off;
    float bx = shownX + sx * off, by = shownY + sy * off;
    Overlay.guide(g, ax, ay, bx, by);
    stroke(Overlay.GUIDE);
    strokeWeight(1.5);
    line(ax - sx * 5, ay - sy * 5, ax + sx * 5, ay + sy * 5);
    line(bx - sx * 5, by - sy * 5, bx + sx * 5, by + sy * 5);
    Overlay.labelBeside(g, (ax + bx) / 2 + sx * side * 6, (ay + by) / 2 + sy * side * 6, sx * side, sy * side,
        "depth = " + Overlay.number(c.depth()), Overlay.GUIDE);
    text += "\nResponse.separate: moved " + Overlay.number(c.depth()) + " against the normal, now just touching";
  } else {
    // The velocity's part along the normal, and along the surface, before and after.
    Vec surface = new Vec(sx, sy);
    float inB = new Vec(shownBx, shownBy).dot(c.normal());
    float inA = new Vec(shownAx, shownAy).dot(c.normal());
    float alongB = new Vec(shownBx, shownBy).dot(surface);
    float alongA = new Vec(shownAx, shownAy).dot(surface);
    text += "\nvelocity before: " + Overlay.number(inB) + " along the normal, " + Overlay.number(alongB) + " along the surface"
        + "\nResponse." + (mode == BOUNCE ? "bounce" : "slide") + ": " + Overlay.number(inA) + " along the normal, "
        + Overlay.number(alongA) + " along the surface"
        + (inB <= 0 ? "\n(it was moving away already: unchanged)"
            : mode == BOUNCE ? "\n(the normal part turned round, the surface part kept)"
            : "\n(the normal part removed, the surface part kept)");
  }
  // At the bottom, or at the top while the ball is down there.
  int lines = text.split("\n").length;
  float ly = max(y, shownY) > height - 40 - 15 * lines - 30 ? 34 : height - 24 - 15 * lines - 6;
  Overlay.label(g, 8, ly, text, Overlay.GUIDE);
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
