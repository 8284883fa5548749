/**
 * Rectangle/Point
 * Tutorial section 4: Rectangle/Point
 *
 * A button: the mouse is over it when it is right of the left edge, left of the right edge,
 * below the top edge and above the bottom edge, Collide.rectPoint(rx, ry, rw, rh, mouseX,
 * mouseY). The button turns red while hovered, and counts only the clicks that land inside
 * it. A click exactly on an edge is not inside.
 *
 * Try this: make several buttons from an array of rectangles; make the button move away
 * when hovered; change rectMode to CENTER and see which numbers have to change.
 * Keys: d shows the maths (the four comparisons at their edges). Click the button.
 */
import hitbox.*;
import hitbox.processing.*;

// The button: top-left corner and size, Processing's rectMode(CORNER).
float rx = 200;
float ry = 150;
float rw = 200;
float rh = 100;

boolean hovered;      // the answer for this frame, kept for the tests
int clicks;           // presses that landed on the button
float lastClickX = -100;
float lastClickY = -100;
boolean lastCounted;
int lastClickFrame = -1000;
boolean showMaths;    // the 'd' overlay

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  // The whole idea in one line: is the mouse inside the button?
  hovered = Collide.rectPoint(rx, ry, rw, rh, mouseX, mouseY);

  noStroke();
  fill(hovered ? Palette.HIT : Palette.MISS);
  rect(rx, ry, rw, rh, 0);

  fill(Palette.BACKGROUND);
  textAlign(CENTER, CENTER);
  textSize(24);
  text(clicks == 1 ? "1 click" : clicks + " clicks", rx + rw / 2, ry + rh / 2 - 3);

  drawLastClick();

  // The point: the mouse.
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "hover over the button and click it     d: show the maths");
}

/** A ring where the last click landed, fading out: white if it counted, grey if it missed. */
void drawLastClick() {
  int age = frameCount - lastClickFrame;
  if (age > 60) {
    return;
  }
  noFill();
  stroke(lastCounted ? Palette.NEUTRAL : Palette.OBSTACLE, 255 - age * 4);
  strokeWeight(2);
  circle(lastClickX, lastClickY, 14 + age / 2);
}

/** Each of the four comparisons written at its edge, coloured by whether it holds. */
void drawMaths() {
  float px = mouseX;
  float py = mouseY;
  boolean left = px > rx;
  boolean right = px < rx + rw;
  boolean top = py > ry;
  boolean bottom = py < ry + rh;

  // Each edge, extended across the window as a faint line: the comparison is about the whole
  // line, the four together cut out the rectangle.
  edge(rx, ry, rx, ry + rh, true, left);
  edge(rx + rw, ry, rx + rw, ry + rh, true, right);
  edge(rx, ry, rx + rw, ry, false, top);
  edge(rx, ry + rh, rx + rw, ry + rh, false, bottom);

  // Where the mouse is: across, between the left and right edge lines, and down, between
  // the top and bottom edge lines.
  Overlay.guide(g, min(px, rx), py, max(px, rx + rw), py);
  Overlay.guide(g, px, min(py, ry), px, max(py, ry + rh));

  Overlay.labelBeside(g, rx - 8, ry + rh / 2, -1, 0, "px > rx\n" + Overlay.comparison(px, ">", rx, left), colour(left));
  Overlay.labelBeside(g, rx + rw + 8, ry + rh / 2, 1, 0, "px < rx + rw\n" + Overlay.comparison(px, "<", rx + rw, right), colour(right));
  Overlay.labelBeside(g, rx + rw / 2, ry - 8, 0, -1, "py > ry\n" + Overlay.comparison(py, ">", ry, top), colour(top));
  Overlay.labelBeside(g, rx + rw / 2, ry + rh + 8, 0, 1, "py < ry + rh\n" + Overlay.comparison(py, "<", ry + rh, bottom), colour(bottom));

  int holding = (left ? 1 : 0) + (right ? 1 : 0) + (top ? 1 : 0) + (bottom ? 1 : 0);
  String verdict = (holding == 4 ? "all four hold" : holding + " of 4 hold") + ": " + (hovered ? "colliding" : "not colliding");
  Overlay.labelCentered(g, width / 2, 28, "px > rx && px < rx + rw && py > ry && py < ry + rh\n" + verdict, colour(hovered));
}

/** An edge drawn thick in its comparison's colour, and extended across the window, thin. */
void edge(float x1, float y1, float x2, float y2, boolean vertical, boolean holds) {
  stroke(colour(holds), 90);
  strokeWeight(1);
  if (vertical) {
    line(x1, 0, x2, height);
  } else {
    line(0, y1, width, y2);
  }
  stroke(colour(holds));
  strokeWeight(4);
  line(x1, y1, x2, y2);
}

/** A comparison that holds pushes towards a collision: the colliding colour. */
color colour(boolean holds) {
  return holds ? Overlay.HIT : Overlay.MISS;
}

void mousePressed() {
  // A click counts only if it lands inside the button: the same test as the hover.
  lastCounted = Collide.rectPoint(rx, ry, rw, rh, mouseX, mouseY);
  if (lastCounted) {
    clicks++;
  }
  lastClickX = mouseX;
  lastClickY = mouseY;
  lastClickFrame = frameCount;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
