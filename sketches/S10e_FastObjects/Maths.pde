// The shots, the drawing, the "show the maths" overlay (d) and the keys.
import java.util.Locale;

// The swept test's last impact: the step it was asked about and its answer.
Hit impact;
float impactFromX, impactToX, impactAtX;

int shots, naiveTunnels, sweptTunnels;   // the tally at this speed
int hold;                                // frames left showing a finished shot
boolean showMaths;

void newShot() {
  // Both balls start together, a little further on each shot (up to one step, or 80 px),
  // so each shot's frames land on different positions.
  float v = speeds[speedIndex];
  float x0 = 40 + random(0, min(v, 80));
  naive.start(x0, v);
  swept.start(x0, v);
  impact = null;
}

void remember(Hit hit) {
  impact = hit;
  impactFromX = swept.x;
  impactToX = swept.x + swept.vx;
  impactAtX = swept.x + hit.t() * swept.vx;
}

void endShot() {
  shots++;
  naiveTunnels += naive.tunnelled ? 1 : 0;
  sweptTunnels += swept.tunnelled ? 1 : 0;
  hold = 50;
}

// True while a finished shot is on show; then the next shot starts.
boolean holdingAShot() {
  if (hold == 0) {
    return false;
  }
  hold--;
  if (hold == 0) {
    newShot();
  }
  return true;
}

void drawAll() {
  background(Palette.BACKGROUND);
  // The lanes, faint, and their names.
  stroke(Palette.LINE);
  strokeWeight(1);
  line(0, naive.y, width, naive.y);
  line(0, swept.y, width, swept.y);
  fill(Palette.NEUTRAL);
  textAlign(LEFT, BOTTOM);
  textSize(14);
  text("naive: move, then Collide.circleRect", 12, naive.y - r - 26);
  text("swept: Sweep.timeOfImpact, then move", 12, swept.y - r - 26);
  noStroke();
  fill(Palette.OBSTACLE);
  rect(wallX, wallY, wallW, wallH);

  drawBall(naive);
  drawBall(swept);
  if (showMaths) {
    drawMaths();
  }
  drawStatus();
  Overlay.hint(g, "+ / -: speed     d: show the maths");
}

void drawBall(Ball b) {
  if (b.x >= -r && b.x <= width + r) {
    noStroke();
    fill(b.hitNow ? Palette.HIT : Palette.PLAYER);
    circle(b.x, b.y, 2 * r);
    return;
  }
  // Off the window: an arrow at the edge, and where it is now.
  stroke(Palette.PLAYER);
  strokeWeight(2);
  Draw.arrow(g, width - 36, b.y, 30, 0);
  Overlay.labelBeside(g, width - 20, b.y - 6, 0, -1, "now at x = " + Overlay.number(b.x), Overlay.TEXT);
}

void drawStatus() {
  Overlay.label(g, 8, 8, "speed: " + (int) speeds[speedIndex] + " px/frame   (ball "
      + (int) (2 * r) + " px, wall " + (int) wallW + " px)");
  if (naive.done && swept.done) {
    shotResult(naive, "stopped, inside the wall");
    shotResult(swept, "stopped, touching the wall");
  }
  Overlay.label(g, 8, height - 46, "shots at this speed " + shots + ":  the naive ball went through " + naiveTunnels
      + ",  the swept one " + sweptTunnels);
}

void shotResult(Ball b, String stopped) {
  Overlay.label(g, wallX + 20, b.y - r - 44, b.tunnelled ? "went through the wall!" : stopped,
      b.tunnelled ? Overlay.HIT : Overlay.MISS);
}

// The positions each test saw, the gap the naive one never looked at, and t.
void drawMaths() {
  // The naive test only sees the positions the ball lands on.
  float before = Float.NaN, after = Float.NaN;
  for (int i = 0; i < naive.samples.size(); i++) {
    float[] s = naive.samples.get(i);
    sample(s[0], naive.y, s[1] == 1);
    if (i > 0 && naive.samples.get(i - 1)[0] < wallX && s[0] > wallX + wallW) {
      before = naive.samples.get(i - 1)[0];
      after = s[0];
    }
  }
  if (!Float.isNaN(before)) {
    // The jump over the wall: nothing between these two positions was ever tested.
    float gy = naive.y + r + 14;
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

  for (float[] s : swept.samples) {
    sample(s[0], swept.y, s[1] == 1);
  }
  if (impact != null) {
    // The whole step the swept test was asked about, and where on it the ball touches.
    float py = swept.y + r + 14;
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
    circle(impactAtX, swept.y, 2 * r);
    fill(Overlay.GUIDE);
    noStroke();
    circle(impactAtX + r, swept.y, 7);   // the point of impact: on the wall's face
    String t = String.format(Locale.ROOT, "%.2f", impact.t());
    Overlay.labelBeside(g, (impactFromX + shownTo) / 2, py + 4, 0, 1,
        "this frame's step: x " + Overlay.number(impactFromX) + " to " + Overlay.number(impactToX) + "\n"
        + "t = " + t + " <= 1: hits this frame, at x + t * vx = " + Overlay.number(impactAtX), Overlay.HIT);
    Overlay.labelBeside(g, impactAtX, swept.y - r - 4, 0, -1, "t = " + t, Overlay.GUIDE);
  }
}

// A position a test saw: an outline, red where it found the wall.
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

// A new speed starts a new shot and a new tally.
void newSpeed(int index) {
  speedIndex = index;
  shots = 0;
  naiveTunnels = 0;
  sweptTunnels = 0;
  hold = 0;
  newShot();
}
