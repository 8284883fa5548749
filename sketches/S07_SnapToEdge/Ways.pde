// The other ways to stop the player at the ground (keys 1, 2 and 4): two the tutorial names
// before its snap (it gives no code for them; this code is ours), and Hitbox's Snap.

void otherWay() {
  if (way == 1) {
    stopWhereItIs();
  } else if (way == 2) {
    stopAtTheNextPosition();
  } else {
    hitboxSnap();
  }
}

// Wrong way 1: stop falling where it is.
void stopWhereItIs() {
  playerY += playerSpeedY;
  if (playerY + playerHeight > groundY) {
    playerSpeedY = 0;   // no snap: it stays where the move left it, a little inside
    jumping = false;
  } else {
    playerSpeedY++;
  }
}

// Wrong way 2: look where the player will be, and do not go there if it is in the ground.
void stopAtTheNextPosition() {
  playerSpeedY++;
  if (playerY + playerSpeedY + playerHeight > groundY) {
    playerSpeedY = 0;   // the next position is in the ground: stop short, above it
    jumping = false;
  }
  playerY += playerSpeedY;
}

// Hitbox's (4 or l): the tutorial's steps, with Snap.onGround (playerY + playerHeight >=
// groundY) for its if and Snap.standY for its snap.
void hitboxSnap() {
  playerY += playerSpeedY;
  if (Snap.onGround(playerY, playerHeight, groundY)) {
    playerY = Snap.standY(playerHeight, groundY);
    playerSpeedY = 0;
    jumping = false;
  } else {
    playerSpeedY++;
  }
}
