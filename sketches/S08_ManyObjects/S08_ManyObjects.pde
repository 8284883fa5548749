/**
 * Many objects: one box, a list of obstacles
 * Tutorial section 8: Many objects
 *
 * The tutorial's recipe: an Obstacle class, a list of obstacles (four walls and some blocks),
 * and a loop that does section 6's next-position check against each one. The box starts in a
 * slot between two pillars only 2 pixels wider than itself.
 *
 * Press t for the tutorial's own loop: it reverses a speed as soon as one obstacle blocks it,
 * and the obstacles after it test the reversed speed. In the slot, one pillar flips the speed
 * and the other flips it back (or was tested already), so the box moves into a pillar and
 * stays there, flickering. Hitbox differs because of that: it asks every obstacle first,
 * combines the answers, reverses once, and asks again before it moves, so a box with nowhere
 * to go waits a frame (Motion.bounce does the same for a list of Rects).
 *
 * Try this (the tutorial's): click to add obstacles, mousePressed below; build another
 * narrow slot and watch both loops in it.
 * Keys: t the tutorial's loop / Hitbox's, click adds an obstacle, d shows the maths,
 * p pauses, n steps one frame.
 */
import hitbox.*;
import hitbox.processing.*;

ArrayList<Obstacle> obstacles = new ArrayList<Obstacle>();
float x, y, vx, vy;      // the bouncing box: its top-left corner and its speed
float w = 30;
float h = 30;
boolean tutorialLoop = false;   // t switches between the two loops

void setup() {
  size(600, 400);
  // The tutorial's four walls (the bottom one above the key hint)...
  obstacles.add(new Obstacle(0, 0, width, 20));
  obstacles.add(new Obstacle(0, height - 38, width, 20));
  obstacles.add(new Obstacle(0, 0, 20, height));
  obstacles.add(new Obstacle(width - 20, 0, 20, height));
  // ...and blocks; 5 and 6 are two pillars with a 32-pixel slot between them.
  obstacles.add(new Obstacle(90, 70, 80, 40));
  obstacles.add(new Obstacle(230, 60, 40, 180));
  obstacles.add(new Obstacle(302, 60, 40, 180));
  obstacles.add(new Obstacle(420, 80, 110, 30));
  obstacles.add(new Obstacle(60, 220, 40, 90));
  obstacles.add(new Obstacle(470, 230, 60, 90));
  obstacles.add(new Obstacle(150, 300, 130, 25));
  obstacles.add(new Obstacle(390, 170, 50, 50));
  startAgain();
}

void startAgain() {
  x = 271;   // in the slot, 1 pixel from each pillar
  y = 70;
  vx = -3.3;
  vy = 2.7;
}

void draw() {
  background(Palette.BACKGROUND);
  for (Obstacle o : obstacles) {
    o.draw();
  }
  drawBox();
  drawMathsAndLabels();   // in Maths.pde
  if (goesOn()) {         // not while paused
    if (tutorialLoop) {
      tutorialStep();
    } else {
      hitboxStep();
    }
  }
}

// The tutorial's try-this: "a new obstacle is added when the user clicks the mouse". One more
// Obstacle in the list, and both loops test it from the next frame on, with no new code.
void mousePressed() {
  Obstacle added = new Obstacle(mouseX - 30, mouseY - 15, 60, 30);
  if (added.overlaps(x, y, w, h)) {
    say("not added: it would be on top of the box");   // it would start inside it
  } else {
    obstacles.add(added);
    say("added obstacle " + (obstacles.size() - 1));
  }
}

// The tutorial's loop: each obstacle that blocks a move reverses that speed, there and then.
void tutorialStep() {
  for (Obstacle o : obstacles) {
    // check X movement bounce
    if (x + w + vx > o.x && x + vx < o.x + o.w && y + h > o.y && y < o.y + o.h) {
      vx *= -1;
      o.hit();
    }
    // check Y movement bounce
    if (x + w > o.x && x < o.x + o.w && y + h + vy > o.y && y + vy < o.y + o.h) {
      vy *= -1;
      o.hit();
    }
  }
  x += vx;
  y += vy;
}

// Hitbox's loop: ask every obstacle first, reverse once, then move only where it is free.
void hitboxStep() {
  int blocked = blockedByAny(vx, vy);
  vx = Motion.reverseX(blocked, vx);
  vy = Motion.reverseY(blocked, vy);
  int still = blockedByAny(vx, vy);   // squeezed: the reversed move is blocked too
  if (!Side.hasAny(still, Side.LEFT_RIGHT)) {
    x += vx;
  }
  if (!Side.hasAny(still, Side.TOP_BOTTOM)) {
    y += vy;
  }
}

// Section 6's check against every obstacle, the answers combined with |.
int blockedByAny(float speedX, float speedY) {
  int blocked = Motion.NONE;
  for (Obstacle o : obstacles) {
    int answer = Motion.rectBlocked(x, y, w, h, speedX, speedY, o.x, o.y, o.w, o.h);
    if (answer != Motion.NONE) {
      o.hit();
    }
    blocked |= answer;
  }
  return blocked;
}
