/**
 * Snapping to any side: the arrow-key rectangle
 * Tutorial section 7: Snapping to an edge, on every side
 *
 * Section 7 ends with an idea it leaves to you: "a rectangle that you can move with the
 * arrow keys, and another rectangle in the center". Detect when your rectangle is about to
 * collide with the center one, and snap it to the appropriate side. The tutorial gives no
 * code for it; here it is written the way section 6 writes its checks, one axis at a time:
 * would the move across (by playerSpeedX) collide? Then snap to the center rectangle's left
 * side when moving right, its right side when moving left. Then the same down the page: the
 * top when moving down, the bottom when moving up. The side it rests against lights up.
 *
 * Press l for Hitbox's Snap.pushBack, one call per axis: the move, and the speed it was made
 * with, in; the snapped position and the side out.
 *
 * Where Hitbox differs: it does not move the rectangle differently (the tests run both and
 * compare every frame). pushBack works the side out from the speed for you, and where
 * centerRectX - playerWidth would round in float it keeps the rectangle just outside.
 *
 * Try this: make playerSpeed 20 and watch it still stop flush; snap only when moving down
 * (a platform you can jump up through); add a second center rectangle.
 * Keys: arrow keys move, l Snap.pushBack / the ifs written out, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

float centerRectX = 250;
float centerRectY = 130;
float centerRectWidth = 100;
float centerRectHeight = 140;

float playerX = 60;
float playerY = 60;
float playerWidth = 40;
float playerHeight = 40;
float playerSpeed = 5;

boolean leftHeld, rightHeld, upHeld, downHeld;  // the arrow keys held down
boolean snapCall;    // l: Snap.pushBack instead of the ifs
boolean showMaths;   // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  float playerSpeedX = (rightHeld ? playerSpeed : 0) - (leftHeld ? playerSpeed : 0);
  float playerSpeedY = (downHeld ? playerSpeed : 0) - (upHeld ? playerSpeed : 0);

  if (!snapCall) {
    //if I move across by playerSpeedX, will I collide with the center rectangle?
    float nextX = constrain(playerX + playerSpeedX, 0, width - playerWidth);
    if (nextX + playerWidth > centerRectX && nextX < centerRectX + centerRectWidth
        && playerY + playerHeight > centerRectY && playerY < centerRectY + centerRectHeight) {
      //snap to the appropriate side
      if (playerSpeedX > 0) {
        nextX = centerRectX - playerWidth;        // its left side
      } else {
        nextX = centerRectX + centerRectWidth;    // its right side
      }
    }
    playerX = nextX;

    //if I move down by playerSpeedY, will I collide with the center rectangle?
    float nextY = constrain(playerY + playerSpeedY, 0, height - playerHeight);
    if (playerX + playerWidth > centerRectX && playerX < centerRectX + centerRectWidth
        && nextY + playerHeight > centerRectY && nextY < centerRectY + centerRectHeight) {
      if (playerSpeedY > 0) {
        nextY = centerRectY - playerHeight;       // its top
      } else {
        nextY = centerRectY + centerRectHeight;   // its bottom
      }
    }
    playerY = nextY;
  } else {
    // Hitbox: move, then Snap.pushBack puts it back against the side it came in through.
    float nextX = constrain(playerX + playerSpeedX, 0, width - playerWidth);
    Snap.Push across = Snap.pushBack(nextX, playerY, playerWidth, playerHeight, playerSpeedX, 0,
        centerRectX, centerRectY, centerRectWidth, centerRectHeight);
    playerX = across.x();
    float nextY = constrain(playerY + playerSpeedY, 0, height - playerHeight);
    Snap.Push down = Snap.pushBack(playerX, nextY, playerWidth, playerHeight, 0, playerSpeedY,
        centerRectX, centerRectY, centerRectWidth, centerRectHeight);
    playerY = down.y();
  }

  //draw the center rectangle, and the side the player rests against
  noFill();
  stroke(255);
  strokeWeight(2);
  rect(centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  drawTouchedSide();
  //draw the player rectangle
  noStroke();
  fill(Palette.PLAYER);
  rect(playerX, playerY, playerWidth, playerHeight);

  Overlay.label(g, 8, 8, snapCall ? "Snap.pushBack, across then down" : "the ifs: across, then down, snapped to a side");
  if (showMaths) {
    drawMaths(playerSpeedX, playerSpeedY);
  }
  Overlay.hint(g, "arrow keys: move     l: " + (snapCall ? "the ifs" : "Snap.pushBack") + "     d: show the maths");
}

void keyPressed() {
  if (key == 'l') {
    snapCall = !snapCall;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
  arrowKey(true);
}

void keyReleased() {
  arrowKey(false);
}

void arrowKey(boolean held) {
  if (key != CODED) {
    return;
  }
  if (keyCode == LEFT) leftHeld = held;
  if (keyCode == RIGHT) rightHeld = held;
  if (keyCode == UP) upHeld = held;
  if (keyCode == DOWN) downHeld = held;
}
