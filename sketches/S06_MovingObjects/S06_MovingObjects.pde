/**
 * Moving objects: look before you move
 * Tutorial section 6: Moving objects
 *
 * A box bounces around the window and off the block in the middle. Before it moves, it asks
 * where it WOULD be next frame, one axis at a time: moved across only, at (x + vx, y), and
 * moved down only, at (x, y + vy). Motion.rectBlocked answers with the axes that would run
 * into the block, and only those speeds are reversed, so the box bounces off the side it
 * really hit: off the left or right side it turns back across, off the top or bottom it turns
 * back up or down. Edges does the same for the window.
 *
 * Try this: pause (p) just before the box reaches the block and step (n) frame by frame with
 * the maths on (d): when one of the two next-position boxes turns red, that speed reverses.
 * Set vx to 250, more than the block and the box are wide together: now and then the box
 * jumps clean over the block between two frames, because the check only looks where the
 * box lands, not at the path (Sweep looks at the path).
 * Keys: d shows the maths, p pauses, n steps one frame while paused.
 */
import hitbox.*;
import hitbox.processing.*;

Rect block = Rect.centered(300, 190, 160, 100);
float x = 60;
float y = 40;
float w = 40;
float h = 40;
float vx = 3.5;
float vy = 2.5;

int blocked = Motion.NONE;   // this frame's answer from Motion.rectBlocked
int crossed = Edges.NONE;    // this frame's answer from Edges.rectCrossed
int flash = 0;               // frames left to show the block red after a bounce
boolean showMaths = false;
boolean paused = false;
boolean stepOnce = false;

void setup() {
  size(600, 400);
  textSize(14);
}

void draw() {
  background(Palette.BACKGROUND);

  // The tutorial's check, before moving: would the box, moved on one axis, hit the block?
  blocked = Motion.rectBlocked(x, y, w, h, vx, vy, block);
  if (blocked != Motion.NONE) {
    flash = 12;
  }

  // The block glows red for a moment after each bounce off it.
  fill(Palette.OBSTACLE);
  if (flash > 0) {
    stroke(Palette.HIT);
    strokeWeight(4);
  } else {
    noStroke();
  }
  Draw.shape(g, block);
  noStroke();
  if (showMaths) {
    // See-through, so the next-position boxes show around and under it.
    fill(Palette.PLAYER, 110);
    stroke(Palette.NEUTRAL);
    strokeWeight(1);
  } else {
    fill(Palette.PLAYER);
  }
  rect(x, y, w, h);

  if (showMaths) {
    drawMaths();
  }
  Overlay.label(g, 8, 8, paused ? "paused: n steps one frame, p goes on" : "Motion.rectBlocked: " + Motion.describe(blocked));
  Overlay.hint(g, "d: show the maths (the next-position boxes)   p: pause   n: one frame");

  if (paused && !stepOnce) {
    return;
  }
  stepOnce = false;
  if (flash > 0) {
    flash--;
  }
  // Reverse exactly the speeds whose axis is blocked, then look at the window the same way.
  vx = Motion.reverseX(blocked, vx);
  vy = Motion.reverseY(blocked, vy);
  crossed = Edges.rectCrossed(x + vx, y + vy, w, h, width, height);
  vx = Edges.bounceX(crossed, vx);
  vy = Edges.bounceY(crossed, vy);
  x += vx;
  y += vy;
}

// The two boxes the check tests, drawn where they are, each with its answer.
void drawMaths() {
  boolean hitX = Collide.rectRect(x + vx, y, w, h, block.x(), block.y(), block.w(), block.h());
  boolean hitY = Collide.rectRect(x, y + vy, w, h, block.x(), block.y(), block.w(), block.h());
  nextBox(x + vx, y, hitX);
  nextBox(x, y + vy, hitY);
  if (blocked == Motion.BOTH && !hitX && !hitY) {
    // The corner case: neither axis alone hits, the diagonal move does; both speeds reverse.
    nextBox(x + vx, y + vy, true);
    Overlay.label(g, x + vx + w + 6, y + vy + h + 6, "next x and y (corner): colliding", Overlay.HIT);
  }
  Draw.arrow(g, x + w / 2, y + h / 2, vx * 8, vy * 8);

  // "next x" on the side the box is moving to across, "next y" on the side it moves to down.
  String sx = "next x: (x + vx, y) = (" + Overlay.number(x + vx) + ", " + Overlay.number(y) + ")\n"
      + (hitX ? "colliding: reverse vx" : "not colliding");
  String sy = "next y: (x, y + vy) = (" + Overlay.number(x) + ", " + Overlay.number(y + vy) + ")\n"
      + (hitY ? "colliding: reverse vy" : "not colliding");
  float lx = vx > 0 ? x + w + 10 : x - 200;
  float ly = vy > 0 ? y + h + 10 : y - 44;
  Overlay.label(g, lx, y, sx, hitX ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, x - 40, ly, sy, hitY ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, 8, 30, "vx = " + Overlay.number(vx) + "   vy = " + Overlay.number(vy)
      + "\nwindow: Edges.rectCrossed(next) = " + Edges.describe(Edges.rectCrossed(x + vx, y + vy, w, h, width, height)));
}

void nextBox(float bx, float by, boolean colliding) {
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  pushStyle();
  fill(colour, 60);
  strokeWeight(2);
  stroke(colour);
  rect(bx, by, w, h);
  popStyle();
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'p') {
    paused = !paused;
  } else if (key == 'n') {
    stepOnce = true;
  }
}
