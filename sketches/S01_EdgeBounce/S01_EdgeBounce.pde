/**
 * Edges: a ball bouncing off the window
 * Tutorial section 1: Edges
 *
 * The simplest collision: has the ball gone past an edge of the window? The library's
 * Edges.circleCrossed answers with the edges it crossed, and the sketch decides what to do:
 * bounce back (Edges.bounceX/Y turn the speed to point inside), wrap around to the other side
 * like Pac-Man (Edges.circleWrapX/Y), or stop at the edge.
 *
 * Try this: switch modes while the ball moves; make the ball bigger than the window's
 * height and see both top and bottom crossed at once.
 * Keys: b bounce, w wrap, s stop, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

float x = 300;
float y = 140;
float r = 24;
float vx = 4.5;
float vy = 3.2;
String mode = "bounce";
boolean showMaths = false;
int crossedThisFrame = Edges.NONE;

void setup() {
  size(600, 400);
  textSize(14);
}

void draw() {
  background(Palette.BACKGROUND);

  x += vx;
  y += vy;
  crossedThisFrame = Edges.circleCrossed(x, y, r, width, height);

  if (mode.equals("bounce")) {
    vx = Edges.bounceX(crossedThisFrame, vx);
    vy = Edges.bounceY(crossedThisFrame, vy);
    // Put it back inside too, so it never sits past the edge, even for a frame.
    x = Edges.circleClampX(x, r, width);
    y = Edges.circleClampY(y, r, height);
  } else if (mode.equals("wrap")) {
    x = Edges.circleWrapX(x, r, width);
    y = Edges.circleWrapY(y, r, height);
  } else {  // stop: stay at the edge it reached
    if (Edges.has(crossedThisFrame, Edges.LEFT) || Edges.has(crossedThisFrame, Edges.RIGHT)) {
      vx = 0;
    }
    if (Edges.has(crossedThisFrame, Edges.TOP) || Edges.has(crossedThisFrame, Edges.BOTTOM)) {
      vy = 0;
    }
    x = Edges.circleClampX(x, r, width);
    y = Edges.circleClampY(y, r, height);
  }

  noStroke();
  fill(crossedThisFrame == Edges.NONE ? Palette.PLAYER : Palette.HIT);
  circle(x, y, 2 * r);

  Overlay.label(g, 8, 8, "mode: " + mode + "   (b bounce, w wrap, s stop)");
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "d: show the maths   b / w / s: bounce, wrap, stop");
}

// The tutorial's four comparisons, each written next to the edge it tests.
void drawMaths() {
  Overlay.guide(g, x - r, y, 0, y);
  Overlay.guide(g, x + r, y, width, y);
  Overlay.guide(g, x, y - r, x, 0);
  Overlay.guide(g, x, y + r, x, height);
  // Each label sits beside its own guide line, just clear of the ball.
  edgeLabel(10, y + r + 6, "left: x < r", x, "<", r, Edges.LEFT);
  edgeLabel(width, y + r + 6, "right: x > width - r", x, ">", width - r, Edges.RIGHT);
  edgeLabel(x + r + 6, 10, "top: y < r", y, "<", r, Edges.TOP);
  edgeLabel(x + r + 6, height - 62, "bottom: y > height - r", y, ">", height - r, Edges.BOTTOM);
}

void edgeLabel(float lx, float ly, String test, float left, String op, float right, int edge) {
  boolean crossed = Edges.has(crossedThisFrame, edge);
  Overlay.label(g, lx, ly, test + "\n" + Overlay.comparison(left, op, right, crossed),
      crossed ? Overlay.HIT : Overlay.MISS);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'b' || key == 'w') {
    mode = key == 'b' ? "bounce" : "wrap";
    if (vx == 0 && vy == 0) {  // coming back from "stop": give it a push
      vx = 4.5;
      vy = 3.2;
    }
  } else if (key == 's') {
    mode = "stop";
  }
}
