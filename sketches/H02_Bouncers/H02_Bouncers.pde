/**
 * 100 bouncers among 100 obstacles
 * Homework 2: 100 obstacles, 100 bouncers
 *
 * A hundred small boxes bounce around a hundred obstacles and the window, and each one takes
 * a new colour every time it hits an obstacle. Each bouncer does exactly what the single box
 * of sections 6 and 8 does: Motion.bounce checks its next position, one axis at a time,
 * against the whole list of obstacles, reverses the blocked speeds and moves only where it
 * is free. That is 100 x 100 =
 * 10,000 bouncer-obstacle pairs a frame, a few rectangle comparisons each: plain loops, far
 * below a millisecond, so no grid or other broad phase is needed at this size.
 *
 * Everything random comes from randomSeed, so every run is the same.
 *
 * Try this: make it 1,000 bouncers; make the obstacles bigger until the bouncers are trapped
 * in pockets; give every bouncer the same speed and see patterns appear.
 * Keys: d shows the maths (counts, and bouncer 0's next-position boxes).
 */
import hitbox.*;
import hitbox.processing.*;

int obstacleCount = 100;
int bouncerCount = 100;
float size = 8;   // every bouncer is size x size

ArrayList<Rect> obstacles = new ArrayList<Rect>();
ArrayList<Bouncer> bouncers = new ArrayList<Bouncer>();
int[] glow;                 // frames left to light each obstacle up after a hit
int hitsThisFrame = 0;
int totalHits = 0;
boolean showMaths = false;

class Bouncer {
  float x;
  float y;
  float vx;
  float vy;
  color colour;
  int blocked = Motion.NONE;  // this frame's answer for its next position
  int colourChanges = 0;

  Bouncer(float x, float y, float vx, float vy) {
    this.x = x;
    this.y = y;
    this.vx = vx;
    this.vy = vy;
    colour = newColour(0);
  }

  void step() {
    // Sections 6 and 8 for each bouncer: reverse what is blocked, bounce off the window,
    // and move only where it is free (see Motion.bounce).
    Motion.Step next = Motion.bounce(x, y, size, size, vx, vy, obstacles, width, height);
    blocked = next.blocked();
    if (next.hitObstacle()) {
      colour = newColour(colour);
      colourChanges++;
      hitsThisFrame++;
      lightUp();
    }
    x = next.x();
    y = next.y();
    vx = next.vx();
    vy = next.vy();
  }

  // Which obstacles it ran into: the ones its next-position boxes overlap.
  void lightUp() {
    int i = Hits.first(x + vx, y, size, size, obstacles);
    int j = Hits.first(x, y + vy, size, size, obstacles);
    int k = i < 0 && j < 0 ? Hits.first(x + vx, y + vy, size, size, obstacles) : -1;
    if (i >= 0) {
      glow[i] = 10;
    }
    if (j >= 0) {
      glow[j] = 10;
    }
    if (k >= 0) {
      glow[k] = 10;
    }
  }
}

void setup() {
  size(600, 400);
  randomSeed(2);
  colorMode(HSB, 360, 100, 100);
  for (int i = 0; i < obstacleCount; i++) {
    float w = random(10, 26);
    float h = random(10, 26);
    obstacles.add(new Rect(random(0, width - w), random(0, height - h), w, h));
  }
  glow = new int[obstacles.size()];
  while (bouncers.size() < bouncerCount) {
    float x = random(0, width - size);
    float y = random(0, height - size);
    if (!Hits.any(x, y, size, size, obstacles)) {  // start in a free spot
      bouncers.add(new Bouncer(x, y, randomSpeed(), randomSpeed()));
    }
  }
}

float randomSpeed() {
  return random(1, 2.5) * (random(1) < 0.5 ? -1 : 1);
}

// A bright random colour, never the one it had.
color newColour(color old) {
  color c = old;
  while (c == old) {
    c = color(random(30, 330), 70, 100);  // any hue but red, which means "hit" here
  }
  return c;
}

void draw() {
  background(Palette.BACKGROUND);
  hitsThisFrame = 0;
  for (Bouncer b : bouncers) {
    b.step();
  }

  noStroke();
  for (int i = 0; i < obstacles.size(); i++) {
    fill(glow[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    Draw.shape(g, obstacles.get(i));
    glow[i] = max(0, glow[i] - 1);
  }
  for (Bouncer b : bouncers) {
    fill(b.colour);
    rect(b.x, b.y, size, size);
  }
  totalHits += hitsThisFrame;

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "d: show the maths (counts, and bouncer 0's next-position boxes)");
}

void drawMaths() {
  int pairs = bouncers.size() * obstacles.size();
  Overlay.label(g, 8, 8, bouncers.size() + " bouncers x " + obstacles.size() + " obstacles = " + pairs
      + " pairs a frame\nhits this frame: " + hitsThisFrame + "   hits so far: " + totalHits);

  // Bouncer 0, ringed, with the two boxes its check tests next frame and what they hit.
  Bouncer b = bouncers.get(0);
  int next = Motion.rectBlocked(b.x, b.y, size, size, b.vx, b.vy, obstacles);
  int hitX = Hits.first(b.x + b.vx, b.y, size, size, obstacles);
  int hitY = Hits.first(b.x, b.y + b.vy, size, size, obstacles);
  pushStyle();
  noFill();
  stroke(Overlay.GUIDE);
  strokeWeight(1.5);
  ellipse(b.x + size / 2, b.y + size / 2, 34, 34);
  strokeWeight(1);
  stroke(hitX >= 0 ? Overlay.HIT : Overlay.MISS);
  rect(b.x + b.vx, b.y, size, size);
  stroke(hitY >= 0 ? Overlay.HIT : Overlay.MISS);
  rect(b.x, b.y + b.vy, size, size);
  popStyle();
  nameObstacle(hitX);
  nameObstacle(hitY);
  String text = "bouncer 0\nnext x: " + (hitX >= 0 ? "hits obstacle " + hitX : "free")
      + "\nnext y: " + (hitY >= 0 ? "hits obstacle " + hitY : "free");
  if (next == Motion.BOTH && hitX < 0 && hitY < 0) {
    text += "\ncorner: hits obstacle " + Hits.first(b.x + b.vx, b.y + b.vy, size, size, obstacles);
  }
  float lx = b.x + 22 > width - 170 ? b.x - 180 : b.x + 22;
  float ly = b.y + 22 > height - 80 ? b.y - 70 : b.y + 22;
  Overlay.label(g, lx, ly, text, next != Motion.NONE ? Overlay.HIT : Overlay.MISS);
}

// Writes an obstacle's index next to it, so "hits obstacle 12" can be found.
void nameObstacle(int i) {
  if (i >= 0) {
    Rect o = obstacles.get(i);
    Overlay.label(g, o.right() + 3, o.y() - 4, "" + i, Overlay.HIT);
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
