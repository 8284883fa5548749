/**
 * Fast objects: tunnelling, and the swept test that stops it
 * Tutorial section 10: Fast objects
 *
 * Two balls are shot at the same thin wall at the same speed. The top one does what the
 * tutorial does: move, then test where it landed (Collide.circleRect). Its test only ever
 * sees the positions it lands on, so once a frame's step is longer than the ball and the wall
 * together it can jump right over the wall: it tunnels. The bottom one asks
 * Sweep.circleRectHit about the whole step instead: when, as a fraction t of this frame's
 * motion, does the ball first touch the wall? t <= 1 means "this frame": it moves only t of
 * the way and stops, touching the wall. It never tunnels, at any speed.
 *
 * Try this: raise the speed to thousands of pixels a frame; make the wall 1 pixel thin;
 * shoot the balls at an angle (give them a vy).
 * Keys: + / - change the speed, d shows the maths (the positions the naive test saw, the gap
 * it never tested, the swept path and the time of impact t).
 */
import hitbox.*;
import hitbox.processing.*;
import java.util.Locale;

// The speeds + and - step through, in pixels per frame.
float[] speeds = {2, 5, 10, 20, 40, 80, 150, 300, 600, 1200, 2500, 5000};
int speedIndex = 5;

// The wall both balls are shot at: thin, and the same for both.
float wallX = 420;
float wallY = 70;
float wallW = 6;
float wallH = 236;

float r = 12;          // both balls' radius
float naiveY = 112;    // the lanes
float sweptY = 254;

// The balls: x and speed across (they move along their lane).
float naiveX, naiveVx;
float sweptX, sweptVx;
boolean naiveDone, sweptDone;   // stopped at the wall or left the window, this shot
boolean naiveHitNow;            // the naive test said "colliding" this frame
boolean sweptHitNow;            // the swept test found an impact this frame
boolean naiveTunnelled;         // this shot, the naive ball got past the wall
boolean sweptTunnelled;         // never happens: the tests check it

// Every position each test saw this shot: x, and 1 where it found the wall.
ArrayList<float[]> naiveSamples = new ArrayList<float[]>();
ArrayList<float[]> sweptSamples = new ArrayList<float[]>();

// The swept test's last impact: the step it was asked about and its answer.
Hit impact;
float impactFromX, impactToX, impactAtX;

int shots, naiveTunnels, sweptTunnels;   // the tally
int hold;                                // frames left showing a finished shot
boolean showMaths;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  randomSeed(7);
  newShot();
}

void newShot() {
  // Both balls start together, a little further on each shot (up to one step, or 80 px),
  // so each shot's frames land on different positions.
  float v = speeds[speedIndex];
  float x0 = 40 + random(0, min(v, 80));
  naiveX = x0;
  sweptX = x0;
  naiveVx = v;
  sweptVx = v;
  naiveDone = false;
  sweptDone = false;
  naiveTunnelled = false;
  sweptTunnelled = false;
  naiveHitNow = false;
  sweptHitNow = false;
  impact = null;
  naiveSamples.clear();
  sweptSamples.clear();
  naiveSamples.add(new float[] {x0, 0});
  sweptSamples.add(new float[] {x0, 0});
}

void draw() {
  if (hold > 0) {
    hold--;
    if (hold == 0) {
      newShot();
    }
  } else {
    step();
  }

  background(Palette.BACKGROUND);
  drawLanes();
  drawBalls();
  if (showMaths) {
    drawMaths();
  }
  drawStatus();
  Overlay.hint(g, "+ / -: speed     d: show the maths");
}

/** One frame of motion for each ball. */
void step() {
  if (!naiveDone) {
    // The tutorial's way: move, then test where the ball landed.
    naiveX += naiveVx;
    naiveHitNow = Collide.circleRect(naiveX, naiveY, r, wallX, wallY, wallW, wallH);
    naiveSamples.add(new float[] {naiveX, naiveHitNow ? 1 : 0});
    naiveTunnelled |= !naiveHitNow && naiveX > wallX + wallW;
    // It stops where the test caught it: already inside the wall.
    naiveDone = naiveHitNow || naiveX > width + r;
  }
  if (!sweptDone) {
    // The swept way: ask about the whole step before taking it.
    Hit hit = Sweep.circleRectHit(sweptX, sweptY, r, sweptVx, 0, wallX, wallY, wallW, wallH);
    sweptHitNow = hit != null && !hit.alreadyOverlapping();
    if (sweptHitNow) {
      impact = hit;
      impactFromX = sweptX;
      impactToX = sweptX + sweptVx;
      sweptX += hit.t() * sweptVx;     // only t of the way: touching the wall, and stop
      impactAtX = sweptX;
    } else {
      sweptX += sweptVx;
    }
    sweptSamples.add(new float[] {sweptX, sweptHitNow ? 1 : 0});
    sweptTunnelled |= !sweptHitNow && sweptX > wallX + wallW;
    sweptDone = sweptHitNow || sweptX > width + r;
  }
  if (naiveDone && sweptDone) {
    shots++;
    naiveTunnels += naiveTunnelled ? 1 : 0;
    sweptTunnels += sweptTunnelled ? 1 : 0;
    hold = 50;   // show the finished shot for a moment
  }
}

void drawLanes() {
  // The lanes, faint, and their names.
  stroke(Palette.LINE);
  strokeWeight(1);
  line(0, naiveY, width, naiveY);
  line(0, sweptY, width, sweptY);
  fill(Palette.NEUTRAL);
  textAlign(LEFT, BOTTOM);
  textSize(14);
  text("naive: move, then Collide.circleRect", 12, naiveY - r - 26);
  text("swept: Sweep.circleRectHit, then move", 12, sweptY - r - 26);

  noStroke();
  fill(Palette.OBSTACLE);
  rect(wallX, wallY, wallW, wallH);
}

void drawBalls() {
  ball(naiveX, naiveY, naiveHitNow, naiveDone);
  ball(sweptX, sweptY, sweptHitNow, sweptDone);
  // Where a ball went that is off the window: an arrow at the edge.
  offscreen(naiveX, naiveY);
  offscreen(sweptX, sweptY);
}

void ball(float x, float y, boolean hitNow, boolean done) {
  if (x < -r || x > width + r) {
    return;
  }
  noStroke();
  fill(hitNow ? Palette.HIT : Palette.PLAYER);
  circle(x, y, 2 * r);
}

void offscreen(float x, float y) {
  if (x >= -r && x <= width + r) {
    return;
  }
  stroke(Palette.PLAYER);
  strokeWeight(2);
  Draw.arrow(g, width - 36, y, 30, 0);
  Overlay.labelBeside(g, width - 20, y - 6, 0, -1, "now at x = " + Overlay.number(x), Overlay.TEXT);
}

void drawStatus() {
  Overlay.label(g, 8, 8, "speed: " + (int) speeds[speedIndex] + " px/frame   (ball "
      + (int) (2 * r) + " px, wall " + (int) wallW + " px)");
  if (naiveDone && sweptDone) {
    Overlay.label(g, wallX + 20, naiveY - r - 44, naiveTunnelled ? "went through the wall!" : "stopped, inside the wall",
        naiveTunnelled ? Overlay.HIT : Overlay.MISS);
    Overlay.label(g, wallX + 20, sweptY - r - 44, sweptTunnelled ? "went through the wall!" : "stopped, touching the wall",
        sweptTunnelled ? Overlay.HIT : Overlay.MISS);
  }
  Overlay.label(g, 8, height - 46, "shots at this speed " + shots + ":  the naive ball went through " + naiveTunnels
      + ",  the swept one " + sweptTunnels);
}

/** The positions each test saw, the gap the naive one never looked at, and t. */
void drawMaths() {
  // The naive test only sees the positions the ball lands on.
  float before = Float.NaN, after = Float.NaN;
  for (int i = 0; i < naiveSamples.size(); i++) {
    float[] s = naiveSamples.get(i);
    sample(s[0], naiveY, s[1] == 1);
    if (i > 0 && naiveSamples.get(i - 1)[0] < wallX && s[0] > wallX + wallW) {
      before = naiveSamples.get(i - 1)[0];
      after = s[0];
    }
  }
  if (!Float.isNaN(before)) {
    // The jump over the wall: nothing between these two positions was ever tested.
    float gy = naiveY + r + 14;
    float shownAfter = min(after, width - 4);
    Overlay.guide(g, before, gy, shownAfter, gy);
    stroke(Overlay.GUIDE);
    line(before, gy - 5, before, gy + 5);
    if (after <= width) {
      line(after, gy - 5, after, gy + 5);
    }
    Overlay.labelBeside(g, (before + shownAfter) / 2, gy + 4, 0, 1,
        "one frame's step: " + Overlay.number(after - before) + " px, never tested in between\n"
        + "circleRect at x = " + Overlay.number(before) + ": false,  at x = "
        + Overlay.number(after) + ": false", Overlay.GUIDE);
  }

  for (float[] s : sweptSamples) {
    sample(s[0], sweptY, s[1] == 1);
  }
  if (impact != null) {
    // The whole step the swept test was asked about, and where on it the ball touches.
    float py = sweptY + r + 14;
    float shownTo = constrain(impactToX, 4, width - 4);
    Overlay.guide(g, impactFromX, py, shownTo, py);
    stroke(Overlay.GUIDE);
    strokeWeight(1.5);
    line(impactFromX, py - 5, impactFromX, py + 5);
    if (impactToX <= width) {
      line(impactToX, py - 5, impactToX, py + 5);
    }
    stroke(Overlay.HIT);
    strokeWeight(2.5);
    line(impactAtX, py - 7, impactAtX, py + 7);   // t of the way along the step
    noFill();
    stroke(Overlay.HIT);
    strokeWeight(2);
    circle(impactAtX, sweptY, 2 * r);
    fill(Overlay.GUIDE);
    noStroke();
    circle(impactAtX + r, sweptY, 7);   // the point of impact: on the wall's face
    String t = String.format(Locale.ROOT, "%.2f", impact.t());
    Overlay.labelBeside(g, (impactFromX + shownTo) / 2, py + 4, 0, 1,
        "this frame's step: x " + Overlay.number(impactFromX) + " to " + Overlay.number(impactToX) + "\n"
        + "t = " + t + " <= 1: hits this frame, at x + t * vx = " + Overlay.number(impactAtX), Overlay.HIT);
    Overlay.labelBeside(g, impactAtX, sweptY - r - 4, 0, -1, "t = " + t, Overlay.GUIDE);
  }
}

/** A position a test saw: an outline, red where it found the wall. */
void sample(float x, float y, boolean hit) {
  if (speeds[speedIndex] < r && !hit) {   // packed close together: the centres are enough
    noStroke();
    fill(Overlay.GUIDE);
    circle(x, y, 4);
    return;
  }
  noFill();
  stroke(hit ? Overlay.HIT : Overlay.GUIDE, 170);
  strokeWeight(1.5);
  circle(x, y, 2 * r);
  noStroke();
  fill(hit ? Overlay.HIT : Overlay.GUIDE);
  circle(x, y, 4);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if ((key == '+' || key == '=') && speedIndex < speeds.length - 1) {
    newSpeed(speedIndex + 1);
  } else if ((key == '-' || key == '_') && speedIndex > 0) {
    newSpeed(speedIndex - 1);
  }
}

/** A new speed starts a new shot and a new tally. */
void newSpeed(int index) {
  speedIndex = index;
  shots = 0;
  naiveTunnels = 0;
  sweptTunnels = 0;
  hold = 0;
  newShot();
}
