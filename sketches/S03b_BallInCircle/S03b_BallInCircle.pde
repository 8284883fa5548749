/**
 * Ball in a Circle
 * Tutorial section 3: Circle/Circle
 *
 * The "try this" from the circle sections: a ball bounces around the window and turns red
 * while it overlaps the circle in the middle, Collide.circleCircle(x, y, r, cx, cy, R). The
 * window's edges are handled by the library too: Edges.circleCrossed says which edges the
 * ball has crossed, Edges.bounceX/bounceY turn its speed back inside, and
 * Edges.circleClampX/circleClampY put it back in the window.
 *
 * Try this: make the ball bigger than the circle; add a second ball and test the two balls
 * against each other; make the circle follow the mouse.
 * Keys: d shows the maths (distance, both radii, dist < r + R, the edges crossed). Space
 * pauses. Click to put the ball at the mouse.
 */
import hitbox.*;
import hitbox.processing.*;

// The circle in the middle.
float cx = 300;
float cy = 200;
float R = 90;

// The ball: position, speed (pixels a frame), radius.
float x = 110;
float y = 90;
float vx = 3.3;
float vy = 2.1;
float r = 22;

boolean inside;       // does the ball overlap the circle this frame?
color ballColour;       // what the ball is drawn in, kept for the tests
int crossed;          // the window edges the ball crossed last time it bounced
int bounceFrame = -1000;
boolean paused;
boolean showMaths;    // the 'd' overlay

// A short trail of past positions, oldest first.
float[] trailX = new float[14];
float[] trailY = new float[14];

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  for (int i = 0; i < trailX.length; i++) {
    trailX[i] = x;
    trailY[i] = y;
  }
}

void draw() {
  background(Palette.BACKGROUND);
  if (!paused) {
    move();
  }

  // The whole idea in one line: does the ball overlap the circle?
  inside = Collide.circleCircle(x, y, r, cx, cy, R);
  ballColour = inside ? Palette.HIT : Palette.MISS;

  // The circle: an obstacle the ball passes through.
  stroke(Palette.OBSTACLE);
  strokeWeight(2);
  fill(Palette.OBSTACLE, 50);
  circle(cx, cy, 2 * R);

  noStroke();
  for (int i = 0; i < trailX.length; i++) {
    fill(ballColour, 10 + i * 6);
    circle(trailX[i], trailY[i], 2 * r * (0.4 + 0.04 * i));
  }
  fill(ballColour);
  circle(x, y, 2 * r);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "d: show the maths     space: pause     click: put the ball there");
  drawBounce();
}

/** One step: move, then bounce off (and stay inside) the window's edges. */
void move() {
  x += vx;
  y += vy;
  int edges = Edges.circleCrossed(x, y, r, width, height);
  if (edges != Edges.NONE) {
    vx = Edges.bounceX(edges, vx);
    vy = Edges.bounceY(edges, vy);
    x = Edges.circleClampX(x, r, width);
    y = Edges.circleClampY(y, r, height);
    crossed = edges;
    bounceFrame = frameCount;
  }
  for (int i = 0; i < trailX.length - 1; i++) {
    trailX[i] = trailX[i + 1];
    trailY[i] = trailY[i + 1];
  }
  trailX[trailX.length - 1] = x;
  trailY[trailY.length - 1] = y;
}

/** The edge the ball just bounced off lights up for a moment. */
void drawBounce() {
  int age = frameCount - bounceFrame;
  if (age > 25) {
    return;
  }
  stroke(Palette.ACCENT, 255 - age * 10);
  strokeWeight(5);
  if (Edges.has(crossed, Edges.LEFT)) line(2, 0, 2, height);
  if (Edges.has(crossed, Edges.RIGHT)) line(width - 3, 0, width - 3, height);
  if (Edges.has(crossed, Edges.TOP)) line(0, 2, width, 2);
  if (Edges.has(crossed, Edges.BOTTOM)) line(0, height - 3, width, height - 3);
  if (showMaths) {
    // Which edges the bounce crossed, as the library names them, written beside the ball on
    // the window's side of it.
    float inX = Edges.has(crossed, Edges.LEFT) ? 1 : (Edges.has(crossed, Edges.RIGHT) ? -1 : 0);
    float inY = Edges.has(crossed, Edges.TOP) ? 1 : (Edges.has(crossed, Edges.BOTTOM) ? -1 : 0);
    Overlay.labelBeside(g, x + inX * (r + 6), y + inY * (r + 6), inX, inY, "crossed: " + Edges.describe(crossed), Palette.ACCENT);
  }
}

/** The distance between the centres, both radii, dist < r + R, and the edges of the last bounce. */
void drawMaths() {
  float d = dist(x, y, cx, cy);
  float ux = d > 0.5 ? (cx - x) / d : 1;
  float uy = d > 0.5 ? (cy - y) / d : 0;

  Overlay.radius(g, x, y, ux, uy, r, "r");
  Overlay.radius(g, cx, cy, -ux, -uy, R, "R");
  Overlay.guide(g, x, y, cx, cy);
  noStroke();
  fill(Overlay.GUIDE);
  circle(x, y, 6);
  circle(cx, cy, 6);
  Overlay.labelBeside(g, (x + cx) / 2 + uy * 18, (y + cy) / 2 - ux * 18, uy, -ux, "dist = " + Overlay.number(d), Overlay.GUIDE);

  color colour = inside ? Overlay.HIT : Overlay.MISS;
  float verdictY = y - r < 60 && abs(x - width / 2) < 150 ? height - 46 : 28;
  Overlay.labelCentered(g, width / 2, verdictY, "dist < r + R\n" + Overlay.verdict(d, "<", r + R, inside), colour);
}

void mousePressed() {
  x = Edges.circleClampX(mouseX, r, width);
  y = Edges.circleClampY(mouseY, r, height);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ') {
    paused = !paused;
  }
}
