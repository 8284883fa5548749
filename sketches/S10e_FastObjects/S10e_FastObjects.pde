/**
 * Fast objects: tunnelling, and the swept test that stops it
 * Beyond the tutorial: fast objects (neither source goes into them)
 *
 * Two balls are shot at the same thin wall at the same speed. The top one is tested as the
 * tutorial's sections 1 and 7 test: move, then look at where the ball landed
 * (Collide.circleRect). That test only ever sees the positions the ball lands on, so once a
 * step is longer than the ball and the wall together the ball can jump right over the wall:
 * it tunnels. (Section 6's next-position check looks one step ahead, but still at one
 * position, so it misses the same way.) The tutorial does not go into fast objects; Hitbox
 * differs because no test of positions can see a wall between two of them: the bottom ball
 * asks Sweep.timeOfImpact about the whole step before taking it. When, as a fraction t of
 * this step, does the ball first touch the wall? t <= 1 means "this frame": it moves t of the
 * way and stops, touching the wall. It never tunnels, at any speed.
 *
 * Try this: raise the speed to thousands of pixels a frame; make the wall 1 pixel thin;
 * shoot the balls at an angle (give them a vy).
 * Keys: + / - change the speed, d shows the maths (the positions the naive test saw, the gap
 * it never tested, the swept path and the time of impact t).
 */
import hitbox.*;
import hitbox.processing.*;

// The speeds + and - step through, in pixels per frame.
float[] speeds = {2, 5, 10, 20, 40, 80, 150, 300, 600, 1200, 2500, 5000};
int speedIndex = 5;

// The wall both balls are shot at: thin, and the same for both.
float wallX = 420;
float wallY = 70;
float wallW = 6;
float wallH = 236;

float r = 12;                  // both balls' radius
Ball naive = new Ball(112);    // the lanes they fly along
Ball swept = new Ball(254);

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  randomSeed(7);
  newShot();
}

void draw() {
  if (!holdingAShot()) {   // the shots and the drawing are in Maths.pde
    if (!naive.done) {
      moveNaive();
    }
    if (!swept.done) {
      moveSwept();
    }
    if (naive.done && swept.done) {
      endShot();   // count it, and hold it on screen a moment
    }
  }
  drawAll();
}

// The naive way: move, then test where the ball landed.
void moveNaive() {
  naive.x += naive.vx;
  boolean hit = Collide.circleRect(naive.x, naive.y, r, wallX, wallY, wallW, wallH);
  naive.landed(hit);   // if it hit, it stops there: already inside the wall
}

// Hitbox's way: ask about the whole step before taking it.
void moveSwept() {
  Hit hit = Sweep.timeOfImpact(new Circle(swept.x, swept.y, r), swept.vx, 0, new Rect(wallX, wallY, wallW, wallH));
  if (hit != null && !hit.alreadyOverlapping()) {
    remember(hit);                   // for the maths overlay
    swept.x += hit.t() * swept.vx;   // only t of the way: touching the wall
    swept.landed(true);
  } else {
    swept.x += swept.vx;
    swept.landed(false);
  }
}
