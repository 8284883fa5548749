// The drawing, and the "show the maths" overlay (key d): the normal, the depth, and the
// velocity split into its part along the normal and its part along the surface.

String[] modeNames = {"", "push out", "bounce", "slide"};
String[] shapeNames = {"circle", "rect", "pentagon"};
int[] flash = new int[3];  // frames left to show a shape red after a hit

/** Head for the mouse, at most 4 pixels a frame. */
void chaseTheMouse() {
  float dx = mouseX - x, dy = mouseY - y;
  float d = dist(0, 0, dx, dy);
  float speed = min(d, 4);
  vx = d > 0 ? dx / d * speed : 0;
  vy = d > 0 ? dy / d * speed : 0;
}

/** Notes an answer: this frame's list, the shape's flash, and the one kept on screen. */
void answered(Answer a) {
  answers.add(a);
  if (a.shape < shapes.length) {
    flash[a.shape] = mode == PUSH ? 1 : 12;
  }
  shown = a;
  shownFor = mode == PUSH ? 1 : 45;   // a bounce lasts one frame: keep it a moment
}

void drawScene() {
  background(Palette.BACKGROUND);
  for (int i = 0; i < shapes.length; i++) {
    noStroke();
    fill(flash[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    Draw.shape(g, shapes[i]);
    if (flash[i] > 0) {
      flash[i]--;
    }
  }
  Overlay.label(g, 8, 8, "mode: " + mode + " " + modeNames[mode] + "   (1 push out, 2 bounce, 3 slide)");

  if (mode == PUSH && !answers.isEmpty()) {
    // Where the mouse would put the ball: inside a shape.
    noFill();
    stroke(Palette.PLAYER, 160);
    strokeWeight(1.5);
    circle(answers.get(0).ghostX, answers.get(0).ghostY, 2 * r);
  }
  noStroke();
  fill(Palette.PLAYER);
  circle(x, y, 2 * r);
  if (mode != PUSH) {
    stroke(Palette.NEUTRAL);
    strokeWeight(2);
    Draw.arrow(g, x, y, vx * 8, vy * 8);   // the velocity, 8 frames' worth
  }
  // Every other contact of this frame (in a corner, say), as a short normal at the ball.
  for (Answer a : answers) {
    if (a == shown) {
      continue;
    }
    stroke(Palette.ACCENT);
    strokeWeight(1.5);
    Draw.arrow(g, a.x + a.contact.nx() * r, a.y + a.contact.ny() * r, a.contact.nx() * 16, a.contact.ny() * 16);
  }
  if (shownFor > 0) {
    drawContact();
    shownFor--;
  }
  Overlay.hint(g, mode == BOUNCE ? "click: throw the ball at the mouse     d: show the maths"
      : mode == SLIDE ? "the ball chases the mouse     d: show the maths"
      : "move the mouse into the shapes     d: show the maths");
}

/**
 * The last contact: the normal where the ball touches the shape, and with the maths on, the
 * depth it was pushed out by and the velocity's two parts before and after.
 */
void drawContact() {
  Contact c = shown.contact;
  float shownX = shown.x, shownY = shown.y;
  float shownBx = shown.before.x(), shownBy = shown.before.y();
  float shownAx = shown.after.x(), shownAy = shown.after.y();
  float shownGhostX = shown.ghostX, shownGhostY = shown.ghostY;
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
  String name = shown.shape < shapes.length ? shapeNames[shown.shape] : "window edge";
  Overlay.labelBeside(g, tx + nx * 38, ty + ny * 38, nx, ny, "normal", Overlay.GUIDE);
  if (!showMaths) {
    return;
  }
  // Where they met, before the push: Contact.manifold's point, the ball's deepest point in
  // the shape (a ball meets anything at one point; a box lying on a face would give two).
  Manifold touch = shown.touch;
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Overlay.TEXT);
  Draw.manifold(g, touch, 11);
  float across = sx > 0 || (sx == 0 && sy > 0) ? 1 : -1;   // the label to the right of it
  Overlay.labelBeside(g, touch.x(0) + across * sx * 10, touch.y(0) + across * sy * 10, across * sx, across * sy,
      "manifold point", Overlay.TEXT);
  String text = "ball.contact(" + name + "): normal (" + Overlay.number(nx) + ", "
      + Overlay.number(ny) + "), depth " + Overlay.number(c.depth());
  text += "\nContact.manifold: " + touch.pointCount() + " point, (" + Overlay.number(touch.x(0)) + ", "
      + Overlay.number(touch.y(0)) + "), the ball's deepest point in the " + name;
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
    Vec normal = new Vec(c.nx(), c.ny());
    float inB = new Vec(shownBx, shownBy).dot(normal);
    float inA = new Vec(shownAx, shownAy).dot(normal);
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

