/**
 * 100 bouncers among 100 obstacles
 * Homework 2: 100 obstacles, 100 bouncers
 *
 * The homework: a hundred randomly placed obstacles, a hundred random rectangles that bounce
 * off them, and a new colour for a bouncer each time it hits one. The homework gives no code;
 * here it is section 8's program twice over, and that runs by default: a loop over the
 * bouncers, and inside it section 8's loop over the obstacles, which flips a speed as soon as
 * one obstacle blocks the next move; then the window's edges, tested where the bouncer is as
 * section 6 tests them.
 *
 * Random obstacles overlap and leave gaps narrower than one move, where a flip inside the loop
 * can send a bouncer into an obstacle (S08 shows that): the count at the bottom left says how
 * many are caught inside one now. Either way that is 100 x 100 = 10,000 bouncer-obstacle
 * pairs a frame, a few comparisons each: far below a millisecond, so no grid or other broad
 * phase is needed.
 *
 * Where Hitbox differs: press l for its loop (Hitbox.pde): each bouncer asks every obstacle
 * first (Motion.blocked), combines the answers, reverses once and moves only where it is
 * free, so none is ever caught.
 *
 * Everything random comes from randomSeed, so every run is the same.
 *
 * Try this: make it 1,000 bouncers; make the obstacles bigger until the bouncers are trapped
 * in pockets; give every bouncer the same speed and see patterns appear.
 * Keys: l Hitbox's loop / section 8's, d shows the maths (counts, and bouncer 0's
 * next-position boxes).
 */
import hitbox.*;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import hitbox.processing.*;

int obstacleCount = 100;
int bouncerCount = 100;
float size = 8;   // every bouncer is size x size

ArrayList<Rect> obstacles = new ArrayList<Rect>();
ArrayList<Bouncer> bouncers = new ArrayList<Bouncer>();
int[] glow;       // frames left to show each obstacle red after a hit
int hitsThisFrame = 0;
int totalHits = 0;
boolean hitboxDecides;  // l: Hitbox's loop (combine, reverse once) instead of section 8's

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
    if (!Hits.any(new Rect(x, y, size, size), obstacles)) {  // start in a free spot
      bouncers.add(new Bouncer(x, y, randomSpeed(), randomSpeed()));
    }
  }
}

void draw() {
  background(Palette.BACKGROUND);
  hitsThisFrame = 0;
  for (Bouncer b : bouncers) {
    if (hitboxDecides) {
      hitboxStep(b);   // Hitbox.pde
      continue;
    }
    boolean hit = false;
    //iterate over the obstacles: section 8's loop, for this bouncer
    for (int i = 0; i < obstacles.size(); i++) {
      Rect o = obstacles.get(i);
      //check X movement bounce
      if (b.x + size + b.vx > o.x() && b.x + b.vx < o.x() + o.w() && b.y + size > o.y() && b.y < o.y() + o.h()) {
        b.vx *= -1;
        glow[i] = 10;
        hit = true;
      }
      //check Y movement bounce
      if (b.x + size > o.x() && b.x < o.x() + o.w() && b.y + size + b.vy > o.y() && b.y + b.vy < o.y() + o.h()) {
        b.vy *= -1;
        glow[i] = 10;
        hit = true;
      }
    }
    //bounce off the edges of the window, where the bouncer is now, as section 6 does
    if (b.x < 0 || b.x + size > width) {
      b.vx *= -1;
    }
    if (b.y < 0 || b.y + size > height) {
      b.vy *= -1;
    }
    if (hit) {
      b.changeColour();   // the homework: a hit changes its colour
      hitsThisFrame++;
    }
    b.x += b.vx;
    b.y += b.vy;
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

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
