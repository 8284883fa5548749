/**
 * 100 bouncers among 100 obstacles
 * Homework 2: 100 obstacles, 100 bouncers
 *
 * The homework: a hundred randomly placed obstacles, a hundred random rectangles that bounce
 * off them, and a new colour for a bouncer each time it hits one. It is section 8 twice over:
 * a loop over the bouncers, and inside it section 8's loop over the obstacles.
 *
 * Where Hitbox differs: each bouncer asks every obstacle first, combines the answers
 * (Motion.rectBlocked, once per obstacle), then reverses once and moves only where it is
 * free. The tutorial flips a speed inside the loop instead, but random obstacles overlap and
 * leave gaps narrower than one move, where a flip inside the loop can send a bouncer into an
 * obstacle (S08 shows that). Press t for section 8's own loop, flip and all, and watch the
 * count of bouncers caught inside an obstacle. That is 100 x 100 = 10,000 bouncer-obstacle
 * pairs a frame, a few comparisons each: far below a millisecond, so no grid or other broad
 * phase is needed.
 *
 * Everything random comes from randomSeed, so every run is the same.
 *
 * Try this: make it 1,000 bouncers; make the obstacles bigger until the bouncers are trapped
 * in pockets; give every bouncer the same speed and see patterns appear.
 * Keys: t section 8's loop / Hitbox's, d shows the maths (counts, and bouncer 0's
 * next-position boxes).
 */
import hitbox.*;
import hitbox.processing.*;

int obstacleCount = 100;
int bouncerCount = 100;
float size = 8;   // every bouncer is size x size

ArrayList<Rect> obstacles = new ArrayList<Rect>();
ArrayList<Bouncer> bouncers = new ArrayList<Bouncer>();
int[] glow;       // frames left to show each obstacle red after a hit
int hitsThisFrame = 0;
int totalHits = 0;
boolean tutorialLoop = false;   // t: section 8's own loop, which flips inside the loop

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

void draw() {
  background(Palette.BACKGROUND);
  hitsThisFrame = 0;
  for (Bouncer b : bouncers) {
    if (tutorialLoop) {
      tutorialStep(b);
      continue;
    }
    // Section 8's loop for this bouncer: ask every obstacle, combine the answers.
    int blocked = Motion.NONE;
    for (int i = 0; i < obstacles.size(); i++) {
      Rect o = obstacles.get(i);
      int answer = Motion.rectBlocked(b.x, b.y, size, size, b.vx, b.vy, o.x(), o.y(), o.w(), o.h());
      if (answer != Motion.NONE) {
        glow[i] = 10;
      }
      blocked |= answer;
    }
    if (blocked != Motion.NONE) {
      b.changeColour();   // the homework: a hit changes its colour
      hitsThisFrame++;
    }
    b.bounce(blocked);    // reverse once, then move where it is free (Bouncer.pde)
  }
  totalHits += hitsThisFrame;

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
  drawMaths();   // Maths.pde: only with d
}

// Section 8's own loop for one bouncer: each obstacle that blocks the next move reverses that
// speed there and then, and the obstacles after it test the reversed speed.
void tutorialStep(Bouncer b) {
  boolean hit = false;
  for (int i = 0; i < obstacles.size(); i++) {
    Rect o = obstacles.get(i);
    // check X movement bounce
    if (b.x + size + b.vx > o.x() && b.x + b.vx < o.right() && b.y + size > o.y() && b.y < o.bottom()) {
      b.vx *= -1;
      glow[i] = 10;
      hit = true;
    }
    // check Y movement bounce
    if (b.x + size > o.x() && b.x < o.right() && b.y + size + b.vy > o.y() && b.y + b.vy < o.bottom()) {
      b.vy *= -1;
      glow[i] = 10;
      hit = true;
    }
  }
  // The window's edges, as section 6 bounces off them.
  if (b.x + b.vx < 0 || b.x + size + b.vx > width) {
    b.vx *= -1;
  }
  if (b.y + b.vy < 0 || b.y + size + b.vy > height) {
    b.vy *= -1;
  }
  if (hit) {
    b.changeColour();
    hitsThisFrame++;
  }
  b.x += b.vx;
  b.y += b.vy;
}

void keyPressed() {
  if (key == 't') {
    tutorialLoop = !tutorialLoop;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
