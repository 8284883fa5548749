// The drawing, and the "show the maths" overlay (key d): where the move put the player, the
// overlap with what it ran into, and the side it was snapped out through.

String[] wayNames = {"", "1 sink: stop falling (vy = 0)", "2 stop short: the next position is taken",
    "3 the tutorial's snap: y = top - h", "4 Snap.pushBack"};

// What the last move ran into, per axis: where the move put the player before the snap,
// what it overlapped, and the side it was snapped out through.
Side xSide = Side.NONE;
Side ySide = Side.NONE;
Rect xMoved, xHit, yMoved, yHit;
boolean showMaths = false;

/** Notes a snap before it happens: across or down, what was hit, through which side. */
void remember(boolean across, Rect hit, Side side) {
  Rect moved = new Rect(x, y, w, h);
  if (across) {
    xMoved = moved;
    xHit = hit;
    xSide = side;
  } else {
    yMoved = moved;
    yHit = hit;
    ySide = side;
  }
}

void drawScene() {
  background(Palette.BACKGROUND);
  // The player first: what it has sunk into hides the part inside.
  noStroke();
  fill(Palette.PLAYER);
  rect(x, y, w, h);
  fill(Palette.OBSTACLE);
  for (Rect s : solids) {
    Draw.shape(g, s);
  }

  if (showMaths) {
    drawMaths();
  }
  standing();
  Overlay.label(g, 8, 8, "way: " + wayNames[way] + "\n" + (onGround ? "on the ground: UP or SPACE jumps" : "in the air"));
  Overlay.hint(g, "LEFT / RIGHT: walk   UP or SPACE: jump   1 sink, 2 stop short, 3 snap, 4 Snap.pushBack   d: show the maths");
}

/** On what it stands: exactly on it, inside it (1), or hanging above it (2). */
void standing() {
  for (Rect s : solids) {
    float into = y + h - s.y();
    boolean near = into > 0 ? y < s.bottom() : into > -14 && (onGround || way == STOP_SHORT) && vy >= 0;
    if (x < s.right() && x + w > s.x() && near) {
      String text = into > 0 ? "sunk " + Overlay.number(into) + " px into it"
          : into < 0 ? "hanging " + Overlay.number(-into) + " px above it" : "standing exactly on it";
      Overlay.labelBeside(g, x + w, y + h / 2, 1, 0, text, into == 0 ? Overlay.MISS : Overlay.HIT);
      return;
    }
  }
}

void drawMaths() {
  if (ySide != Side.NONE) {
    showSnap(yMoved, yHit, ySide, ySide == Side.TOP ? "landed on TOP" : "hit head (BOTTOM side)",
        "pushed " + (ySide == Side.TOP ? "up " : "down ") + Overlay.number(abs(yMoved.y() - y)) + " px", y - 44);
  }
  if (xSide != Side.NONE) {
    showSnap(xMoved, xHit, xSide, "wall (" + xSide + " side)",
        "pushed " + (xSide == Side.LEFT ? "left " : "right ") + Overlay.number(abs(xMoved.x() - x)) + " px", y - 88);
  }
  pushStyle();
  noFill();
  stroke(Palette.NEUTRAL);
  strokeWeight(1);
  rect(x, y, w, h);
  popStyle();
  stroke(Palette.NEUTRAL);
  Draw.arrow(g, x + w / 2, y + h / 2, vx * 6, vy * 6);
  Overlay.label(g, 8, 44, "onGround: " + onGround + "\nvx = " + Overlay.number(vx) + "   vy = " + Overlay.number(vy)
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
