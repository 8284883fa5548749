/**
 * Moving objects: look before you move
 * Tutorial section 6: Moving objects
 *
 * A box bounces around the window and off the block in the middle. Before it moves, it asks
 * where it WOULD be next frame, one axis at a time: moved across only, at (x + vx, y), and
 * moved down only, at (x, y + vy). If the box moved across would hit the block, vx reverses;
 * if the box moved down would, vy reverses. So it bounces off the side it really hits.
 *
 * Press t to run the tutorial's own code instead (written out below, in this sketch's
 * names). Then press c: the box is aimed at the block's corner, where neither move alone
 * hits it but the diagonal move does, so both checks say "free" and the box ends a frame
 * inside the block (the counter at the top). The tutorial's window check also looks where
 * the box is, not where it will be, so the box pokes out of the window for a frame at each
 * edge.
 *
 * Where Hitbox differs: Motion.rectBlocked makes the same two checks and also tests the
 * diagonal move, reporting both axes for a corner hit, and Edges checks the window at the
 * next position too, because a check of the next position should never let the box in.
 *
 * Try this: pause (p) before the box reaches the block and step (n) with the maths on (d):
 * when one of the next-position boxes turns red, that speed reverses. Set vx to 250: the box
 * jumps clean over the block now and then, because the check only looks where the box lands,
 * not along the way (Sweep looks at the path, see S10e).
 * Keys: t the tutorial's code / Motion.rectBlocked, c aim at the corner, p pause, n one
 * frame while paused, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

float blockX = 220;
float blockY = 140;
float blockW = 160;
float blockH = 100;
float x = 60;
float y = 40;
float w = 40;
float h = 40;
float vx = 3.5;
float vy = 2.5;

boolean tutorialWay = false;   // t: the tutorial's code instead of Motion.rectBlocked
int blocked = Motion.NONE;     // this frame's answer: which speeds reversed off the block
int framesInside = 0;          // frames the box ended inside the block
int flash = 0;                 // frames left to show the block red after a bounce
boolean showMaths, paused, stepOnce;

void setup() {
  size(600, 400);
  textSize(14);
}

void draw() {
  if (!paused || stepOnce) {
    stepOnce = false;
    step();
  }
  drawScene();
}

void step() {
  if (tutorialWay) {
    // Section 6 as the tutorial writes it: the rectangle test at the next position, across
    // only, then down only; else the window's edges, where the box is now.
    boolean hitX = x + w + vx > blockX && x + vx < blockX + blockW && y + h > blockY && y < blockY + blockH;
    if (hitX) {
      vx *= -1;
    } else if (x < 0 || x + w > width) {
      vx *= -1;
    }
    boolean hitY = x + w > blockX && x < blockX + blockW && y + h + vy > blockY && y + vy < blockY + blockH;
    if (hitY) {
      vy *= -1;
    } else if (y < 0 || y + h > height) {
      vy *= -1;
    }
    blocked = (hitX ? Motion.X : 0) | (hitY ? Motion.Y : 0);
  } else {
    // Hitbox: the same two checks and the diagonal one in a call, then the window, both
    // at the next position.
    blocked = Motion.rectBlocked(x, y, w, h, vx, vy, blockX, blockY, blockW, blockH);
    vx = Motion.reverseX(blocked, vx);
    vy = Motion.reverseY(blocked, vy);
    int crossed = Edges.rectCrossed(x + vx, y + vy, w, h, width, height);
    vx = Edges.bounceX(crossed, vx);
    vy = Edges.bounceY(crossed, vy);
  }
  x += vx;
  y += vy;

  flash = blocked != Motion.NONE ? 12 : max(0, flash - 1);
  if (Collide.rectRect(x, y, w, h, blockX, blockY, blockW, blockH)) {
    framesInside++;
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 't') {
    tutorialWay = !tutorialWay;
    framesInside = 0;
  } else if (key == 'c') {
    // Just off the block's top-left corner, heading for it: only the diagonal move hits.
    x = blockX - w - 1;
    y = blockY - h - 1;
    vx = abs(vx);
    vy = abs(vy);
  } else if (key == 'p') {
    paused = !paused;
  } else if (key == 'n') {
    stepOnce = true;
  }
}
