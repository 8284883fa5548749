/**
 * Snapping to an edge: a tiny platformer
 * Tutorial section 7: Snapping to an edge
 *
 * Gravity pulls the player down a little every frame, so every frame it sinks a little into
 * whatever it stands on. Snapping puts it back: after each move the player is pushed out of
 * anything it went into, to touch the edge it came through, and the library says which side
 * of the obstacle that was. TOP means it landed (it may jump again), BOTTOM that it bumped
 * its head (it stops going up), LEFT or RIGHT that it walked into a wall (it stops there).
 *
 * It moves one axis at a time: across first, snapping out sideways (Snap.pushBack with the
 * speed across), then down, snapping out up or down (Snap.pushBack with the speed down).
 * pushBack goes back the way the player came, so even a fast fall that sank deep into a
 * shelf comes out on top. The player never ends a frame inside anything.
 *
 * Try this: jump under the low shelf and watch the head bump; walk into the crate; climb to
 * the top. Swap Snap.pushBack for Snap.pushOut (least overlap) and raise gravity and
 * maxFall until a fall goes more than halfway into a shelf in one frame: the player now
 * comes out underneath it.
 * Keys: LEFT / RIGHT walk, UP or SPACE jumps (on the ground only), d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

float gravity = 0.5;
float jumpSpeed = 11;
float walkSpeed = 3;
float maxFall = 12;      // far below 48 (player height + shelf thickness): no fall skips a shelf

Rect ground = new Rect(0, 360, 600, 40);
Rect shelf = new Rect(120, 255, 160, 16);
Rect crate = new Rect(430, 300, 60, 60);
Rect ledge = new Rect(290, 190, 110, 16);
Rect high = new Rect(60, 150, 110, 16);
ArrayList<Rect> solids = new ArrayList<Rect>();

float x = 20;
float y = 60;
float w = 24;
float h = 32;
float vx = 0;
float vy = 0;
boolean onGround = false;
boolean leftDown = false;
boolean rightDown = false;
boolean jumpPressed = false;
int jumps = 0;

// What the last move ran into, for the maths overlay: per axis, where the move put the
// player before the snap, what it overlapped, and the side it was pushed out through.
Side xSide = Side.NONE;
Side ySide = Side.NONE;
Rect xMoved;
Rect xHit;
Rect yMoved;
Rect yHit;
boolean showMaths = false;

void setup() {
  size(600, 400);
  solids.add(ground);
  solids.add(shelf);
  solids.add(crate);
  solids.add(ledge);
  solids.add(high);
}

void draw() {
  background(Palette.BACKGROUND);
  step();

  noStroke();
  fill(Palette.OBSTACLE);
  for (Rect s : solids) {
    Draw.shape(g, s);
  }
  fill(Palette.PLAYER);
  rect(x, y, w, h);

  if (showMaths) {
    drawMaths();
  }
  Overlay.label(g, 8, 8, onGround ? "on the ground: UP or SPACE jumps" : "in the air");
  Overlay.hint(g, "d: show the maths   LEFT / RIGHT: walk   UP or SPACE: jump");
}

void step() {
  vx = (rightDown ? walkSpeed : 0) - (leftDown ? walkSpeed : 0);
  if (jumpPressed && onGround) {
    vy = -jumpSpeed;
    jumps++;
  }
  jumpPressed = false;  // a press in the air is not kept for later
  vy = min(vy + gravity, maxFall);

  // Across: move, keep inside the window, then snap out of whatever it walked into.
  x = Edges.rectClampX(x + vx, w, width);
  xSide = Side.NONE;
  for (Rect s : solids) {
    Snap.Push p = Snap.pushBack(x, y, w, h, vx, 0, s.x(), s.y(), s.w(), s.h());
    if (p.hit()) {
      xMoved = new Rect(x, y, w, h);
      xHit = s;
      xSide = p.side();
      x = p.x();
      vx = p.vxAfter(vx);
    }
  }

  // Down (or up): move, then snap out of whatever it fell or jumped into.
  y += vy;
  ySide = Side.NONE;
  onGround = false;
  for (Rect s : solids) {
    Snap.Push p = Snap.pushBack(x, y, w, h, 0, vy, s.x(), s.y(), s.w(), s.h());
    if (p.hit()) {
      yMoved = new Rect(x, y, w, h);
      yHit = s;
      ySide = p.side();
      y = p.y();
      vy = p.vyAfter(vy);
      if (p.landed()) {
        onGround = true;
      }
    }
  }
}

// Where the move put the player, the overlap with what it hit, and the side it came out of.
void drawMaths() {
  if (ySide != Side.NONE) {
    showSnap(yMoved, yHit, ySide, ySide == Side.TOP ? "landed on TOP" : "hit head (BOTTOM side)",
        "pushed " + (ySide == Side.TOP ? "up " : "down ") + Overlay.number(abs(yMoved.y() - y)) + " px", y);
  }
  if (xSide != Side.NONE) {
    showSnap(xMoved, xHit, xSide, "wall (" + xSide + " side)",
        "pushed " + (xSide == Side.LEFT ? "left " : "right ") + Overlay.number(abs(xMoved.x() - x)) + " px", y - 44);
  }
  pushStyle();
  noFill();
  stroke(Palette.NEUTRAL);
  strokeWeight(1);
  rect(x, y, w, h);
  popStyle();
  Draw.arrow(g, x + w / 2, y + h / 2, vx * 6, vy * 6);
  Overlay.label(g, 8, 30, "onGround: " + onGround + "\nvx = " + Overlay.number(vx) + "   vy = " + Overlay.number(vy)
      + "\nacross: " + (xSide == Side.NONE ? "nothing hit" : xSide.toString())
      + "\ndown: " + (ySide == Side.NONE ? "nothing hit" : ySide.toString()), onGround ? Overlay.MISS : Overlay.TEXT);
}

void showSnap(Rect moved, Rect hit, Side side, String what, String push, float labelY) {
  pushStyle();
  // The overlap: the obstacle, drawn only inside the box where the move put the player.
  clip(moved.x(), moved.y(), moved.w(), moved.h());
  noStroke();
  fill(Overlay.HIT);
  Draw.shape(g, hit);
  noClip();
  noFill();
  stroke(Overlay.HIT);
  strokeWeight(1);
  Draw.shape(g, moved);
  // The side it was pushed out through.
  stroke(Overlay.GUIDE);
  strokeWeight(3);
  if (side == Side.TOP) {
    line(hit.x(), hit.y(), hit.right(), hit.y());
  } else if (side == Side.BOTTOM) {
    line(hit.x(), hit.bottom(), hit.right(), hit.bottom());
  } else if (side == Side.LEFT) {
    line(hit.x(), hit.y(), hit.x(), hit.bottom());
  } else {
    line(hit.right(), hit.y(), hit.right(), hit.bottom());
  }
  popStyle();
  Overlay.label(g, x + w + 8, labelY, what + "\n" + push, Overlay.GUIDE);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == ' ' || (key == CODED && keyCode == UP)) {
    jumpPressed = true;
  } else if (key == CODED && keyCode == LEFT) {
    leftDown = true;
  } else if (key == CODED && keyCode == RIGHT) {
    rightDown = true;
  }
}

void keyReleased() {
  if (key == CODED && keyCode == LEFT) {
    leftDown = false;
  } else if (key == CODED && keyCode == RIGHT) {
    rightDown = false;
  }
}
