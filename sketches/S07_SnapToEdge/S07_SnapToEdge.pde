/**
 * Snapping to an edge: a tiny platformer
 * Tutorial section 7: Snapping to an edge
 *
 * Gravity pulls the player down a little more every frame, so the frame it reaches the
 * ground it has already gone a little into it. Section 7 names two wrong ways to stop, then
 * snapping. Press 1 to stop falling where it is (vy = 0): it stays inside, and here, with
 * gravity pulling on, it sinks on through. Press 2 to look at the next position and stop if
 * it is taken: it stops short, hangs above the ground, and creeps down. Press 3 for the
 * tutorial's snap: the player's bottom onto the ground's top (y = top - h), then vy = 0; and
 * going up into something, its head against the bottom (the tutorial's "appropriate side").
 * Press 4 (the default) for the library: Snap.pushBack, which also says which side it hit:
 * TOP landed, BOTTOM a head bump, LEFT or RIGHT a wall. Walking across always uses it.
 *
 * Where Hitbox differs: moving one axis at a time, Snap.pushBack puts the player exactly
 * where the tutorial's formula does (the tests check it, frame by frame); one call serves
 * floors, ceilings and walls, and where top - h would round in float it keeps the player
 * just outside, because a snapped player must never overlap.
 *
 * Try this: stand still in 1 and watch the player sink; land in 2 from the high ledge and
 * watch it hang; jump under the low shelf in 3 and in 4; raise gravity and maxFall.
 * Keys: LEFT / RIGHT walk, UP or SPACE jumps (on the ground only), 1 sink, 2 stop short,
 * 3 the tutorial's snap, 4 Snap.pushBack, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

int SINK = 1, STOP_SHORT = 2, SNAP = 3, LIBRARY = 4;
int way = LIBRARY;

float gravity = 0.5, jumpSpeed = 11, walkSpeed = 3;
float maxFall = 12;      // far below 48 (player height + shelf thickness): no fall skips a shelf

Rect ground = new Rect(0, 360, 600, 40);
Rect shelf = new Rect(120, 255, 160, 16);
Rect crate = new Rect(430, 300, 60, 60);
Rect ledge = new Rect(290, 190, 110, 16);
Rect high = new Rect(60, 150, 110, 16);
Rect[] solids = {ground, shelf, crate, ledge, high};

float x = 20, y = 60, w = 24, h = 32;
float vx = 0, vy = 0;
boolean onGround, leftDown, rightDown, jumpPressed;

void setup() {
  size(600, 400);
}

void draw() {
  walk();
  fall();
  drawScene();
}

// Across: move, then snap out of a wall it walked into (one it is already inside, when
// sinking, it walks on through).
void walk() {
  vx = (rightDown ? walkSpeed : 0) - (leftDown ? walkSpeed : 0);
  float before = x;
  x = Edges.rectClampX(x + vx, w, width);
  xSide = Side.NONE;
  for (Rect s : solids) {
    Snap.Push p = Snap.pushBack(x, y, w, h, vx, 0, s.x(), s.y(), s.w(), s.h());
    if (p.hit() && !Collide.rectRect(before, y, w, h, s.x(), s.y(), s.w(), s.h())) {
      remember(true, s, p.side());
      x = p.x();
      vx = p.vxAfter(vx);
    }
  }
}

// Down (or up, jumping): section 7's ways to stop.
void fall() {
  if (jumpPressed && onGround) {
    vy = -jumpSpeed;
  }
  jumpPressed = false;  // a press in the air is not kept for later
  vy = min(vy + gravity, maxFall);
  onGround = false;
  ySide = Side.NONE;
  boolean falling = vy > 0;
  for (Rect s : solids) {
    if (way == STOP_SHORT && Collide.rectRect(x, y + vy, w, h, s.x(), s.y(), s.w(), s.h())) {
      onGround = falling;   // 2: the next position is taken, so do not go there
      vy = 0;
    }
  }
  y += vy;
  for (Rect s : solids) {
    if (!Collide.rectRect(x, y, w, h, s.x(), s.y(), s.w(), s.h())) {
      continue;
    }
    if (way == SINK) {
      onGround = true;      // 1: stop falling, and nothing else
      vy = 0;
    } else if (way == SNAP) {
      // 3: the tutorial's snap: the player's bottom on the top, and stop (going up: its
      // head against the bottom).
      remember(false, s, falling ? Side.TOP : Side.BOTTOM);
      if (falling) {
        y = s.y() - h;
        onGround = true;
      } else {
        y = s.y() + s.h();
      }
      vy = 0;
    } else {
      Snap.Push p = Snap.pushBack(x, y, w, h, 0, vy, s.x(), s.y(), s.w(), s.h());
      remember(false, s, p.side());
      onGround |= p.landed();   // 4: the library's snap
      y = p.y();
      vy = p.vyAfter(vy);
    }
  }
  if (y > height) {
    y = -h;   // sunk right through (1): drop in again from the top
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key >= '1' && key <= '4') {
    way = key - '0';
  } else if (key == ' ' || (key == CODED && keyCode == UP)) {
    jumpPressed = true;
  }
  walkKey(true);
}

void keyReleased() {
  walkKey(false);
}

void walkKey(boolean down) {
  if (key == CODED && keyCode == LEFT) leftDown = down;
  if (key == CODED && keyCode == RIGHT) rightDown = down;
}
