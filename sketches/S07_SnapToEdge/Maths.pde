// The ground, the words beside the player, and the "show the maths" overlay (key d).

String[] wayNames = {"", "1: speed 0 where it is (no snap)", "2: stop if the next position is in the ground",
    "3: the tutorial's snap, playerY = groundY - playerHeight", "4 (or l): Hitbox's Snap.onGround and Snap.standY"};

/** A new way starts with a new fall, from where the tutorial's player starts. */
void dropAgain() {
  playerY = 100;
  playerSpeedY = 0;
  jumping = false;
}

/** The tutorial's ground: a white line at groundY. */
void drawGround() {
  stroke(255);
  strokeWeight(2);
  line(0, groundY, width, groundY);
}

/** The earth under the line, see-through, over the player: a part inside the ground shows as under it. */
void drawEarth() {
  noStroke();
  fill(Palette.OBSTACLE, 110);
  rect(0, groundY, width, height - groundY);
  drawGround();
}

/** The way at the top; beside the player, where it stands: inside, above, or exactly on the ground. */
void drawWay() {
  Overlay.label(g, 8, 8, "way " + wayNames[way]);
  float gap = groundY - (playerY + playerHeight);
  float sx = playerX + playerWidth + 8;
  float sy = playerY + playerHeight / 2;
  if (gap < 0) {
    Overlay.labelBeside(g, sx, sy, 1, 0, "a little bit inside the ground: " + Overlay.number(-gap) + " px", Overlay.HIT);
  } else if (gap == 0) {
    Overlay.labelBeside(g, sx, sy, 1, 0, "standing exactly on the ground", Overlay.MISS);
  } else if (!jumping && gap < 20 && playerSpeedY < 5) {
    Overlay.labelBeside(g, sx, sy, 1, 0, "floating " + Overlay.number(gap) + " px above the ground", Overlay.HIT);
  }
  Overlay.hint(g, "1 speed 0   2 next position   3 the tutorial's snap   4 or l: Snap   d: show the maths   any other key: jump");
}

/**
 * The numbers the test compares: the ground line and the player's bottom, each labelled;
 * where this frame's move took the player, if a snap moved it back; the state.
 */
void drawMaths(float movedY) {
  float bottom = playerY + playerHeight;
  Overlay.guide(g, playerX - 60, bottom, playerX + playerWidth + 60, bottom);
  Overlay.labelBeside(g, width - 12, groundY - 6, -1, -1, "groundY = " + Overlay.number(groundY), Overlay.GUIDE);
  Overlay.labelBeside(g, playerX - 64, bottom, -1, 0, "playerY + playerHeight = " + Overlay.number(bottom), Overlay.GUIDE);

  if ((way == 3 || way == 4) && movedY != playerY) {
    // The move went into the ground and the snap took it back: the box where the move put it.
    noFill();
    stroke(Overlay.HIT);
    strokeWeight(1.5);
    rect(playerX, movedY, playerWidth, playerHeight);
    Overlay.label(g, 8, 100, "the move put its bottom at " + Overlay.number(movedY + playerHeight) + ", "
        + Overlay.number(movedY + playerHeight - groundY) + " px into the ground (the red box):\nsnapped up to playerY = "
        + (way == 3 ? "groundY - playerHeight" : "Snap.standY(playerHeight, groundY)") + " = " + Overlay.number(playerY), Overlay.HIT);
  }

  String test;
  if (way == 2) {
    float next = playerY + playerSpeedY + 1 + playerHeight;
    test = "next frame: playerY + (playerSpeedY + 1) + playerHeight > groundY\n"
        + Overlay.comparison(next, ">", groundY, next > groundY) + (next > groundY ? ": stop here" : ": move");
  } else {
    String op = way == 4 ? ">=" : ">";
    boolean colliding = way == 4 ? movedY + playerHeight >= groundY : movedY + playerHeight > groundY;
    test = "this frame: playerY + playerHeight " + op + " groundY (after the move)\n"
        + Overlay.comparison(movedY + playerHeight, op, groundY, colliding)
        + (colliding ? (way == 1 ? ": playerSpeedY = 0, no snap" : ": snap, playerSpeedY = 0") : ": playerSpeedY++");
  }
  Overlay.label(g, 8, 32, test + "\nplayerY = " + Overlay.number(playerY) + "   playerSpeedY = " + Overlay.number(playerSpeedY)
      + "   jumping = " + jumping, Overlay.TEXT);
}
