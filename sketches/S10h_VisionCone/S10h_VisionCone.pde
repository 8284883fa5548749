/**
 * Vision cone: a guard's pie-slice view and a capsule player
 * Beyond the tutorial: arcs and capsules (neither source has them)
 *
 * The guard sees what is inside the pie slice Processing draws with
 * arc(x, y, 2 * range, 2 * range, start, stop, PIE): Collide.arcPoint answers that for a point,
 * with arc()'s own angles (radians, clockwise on screen). The player is a capsule, the usual
 * top-down body; the guard sees it when one of its three points (both ends and the middle) is
 * in the slice and the line of sight to it crosses no wall (Collide.lineRect for each wall).
 * A player touching a wall is pushed out with Contact and Response.separate.
 *
 * Try this: widen the cone; give the guard a second, short cone for hearing; stand behind a
 * wall at the edge of the cone and lean out.
 * Keys: the mouse moves the player, d shows the maths (the three points and the lines of sight).
 */
import hitbox.*;
import hitbox.processing.*;

float gx = 110, gy = 200;         // the guard
float facing = 0;                 // where the guard looks, radians (0 is to the right)
float halfAngle = 0.55;          // half the cone's width
float range = 330;
boolean turning = true;           // the guard sweeps its gaze back and forth

Rect[] walls = {
    new Rect(300, 60, 24, 110),
    new Rect(300, 250, 24, 110),
    new Rect(430, 170, 90, 22),
};
Capsule player = new Capsule(470, 280, 470, 310, 14);
boolean seen;                      // this frame's answer, for the drawing and the tests
boolean[] pointSeen = new boolean[3];
boolean showMaths;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  if (turning) {
    facing = 0.45 * sin(frameCount * 0.02);
  }
  // The player follows the mouse, but never into a wall.
  if (mouseX > 0 || mouseY > 0) {
    player = new Capsule(mouseX, mouseY - 15, mouseX, mouseY + 15, 14);
  }
  for (Rect w : walls) {
    player = Response.separate(player, w);
  }

  // The whole idea: is a point of the player in the slice, with no wall in the way?
  float start = facing - halfAngle, stop = facing + halfAngle;
  float[][] points = playerPoints();
  seen = false;
  for (int i = 0; i < 3; i++) {
    pointSeen[i] = Collide.arcPoint(gx, gy, range, range, start, stop, PIE, points[i][0], points[i][1])
        && clearSight(points[i][0], points[i][1]);
    seen |= pointSeen[i];
  }

  noStroke();
  fill(seen ? Palette.HIT : Palette.ACCENT, 70);
  arc(gx, gy, 2 * range, 2 * range, start, stop, PIE);

  fill(Palette.OBSTACLE);
  for (Rect w : walls) {
    rect(w.x(), w.y(), w.w(), w.h());
  }
  fill(seen ? Palette.HIT : Palette.PLAYER);
  Draw.capsule(g, player);
  fill(Palette.NEUTRAL);
  circle(gx, gy, 22);

  if (showMaths) {
    drawMaths(points, start, stop);
  }
  Overlay.hint(g, seen ? "SEEN     d: show the maths" : "hidden: move the player with the mouse     d: show the maths");
}

/** The capsule's two ends and its middle. */
float[][] playerPoints() {
  return new float[][] {{player.x1(), player.y1()}, {(player.x1() + player.x2()) / 2, (player.y1() + player.y2()) / 2},
      {player.x2(), player.y2()}};
}

/** Does the line from the guard to (x, y) cross no wall? */
boolean clearSight(float x, float y) {
  for (Rect w : walls) {
    if (Collide.lineRect(gx, gy, x, y, w.x(), w.y(), w.w(), w.h())) {
      return false;
    }
  }
  return true;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ') {
    turning = !turning;
  }
}
