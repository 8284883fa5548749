/**
 * Snapping to an edge: the player and the ground
 * Tutorial section 7: Snapping to an edge
 *
 * The tutorial's program: the player falls (gravity: playerSpeedY++ every frame it is in the
 * air), and a key makes it jump (playerSpeedY = -15) unless it is already jumping. The frame
 * it reaches the ground it has already gone a little into it. The tutorial names two ways to
 * stop it before the one it uses, and gives code only for the third; here all four run:
 *   1: set its speed to 0 where it is: it stays "a little bit inside" the ground;
 *   2: check the next position first (section 6's logic) and stop if it is in the ground: it
 *      stops short, floating above the ground, then creeps down;
 *   3: the tutorial's code, which runs in draw() below (the default): snap its bottom onto
 *      the ground, playerY = groundY - playerHeight, then playerSpeedY = 0;
 *   4 (or l): Hitbox's, Snap.onGround and Snap.standY in the same places.
 * The other three are in Ways.pde.
 *
 * Where Hitbox differs: Snap.onGround counts a player standing exactly on the ground as on
 * it (playerY + playerHeight >= groundY; the tutorial's test is >), so a standing player's
 * speed stays 0, where the tutorial's gravity makes it 1 every other frame and the snap
 * takes it back (the maths shows it), and a jump that comes down exactly onto the ground
 * lands that frame, not the next. The player is drawn in the same place every frame either
 * way. Where groundY - playerHeight would round in float, standY keeps the player just
 * above the ground, never in it.
 *
 * Try this: jump in 1 and in 2 and watch where the player stops; make gravity stronger
 * (playerSpeedY += 3) and see the gaps grow; snap to a ceiling as well (S07b snaps to every
 * side of a rectangle).
 * Keys: 1 speed 0 only, 2 next position, 3 the tutorial's snap, 4 or l Hitbox's Snap; d shows
 * the maths; any other key jumps.
 */
import hitbox.*;
import hitbox.processing.*;

float groundY = 350;
float playerX = 290;
float playerY = 100;
float playerWidth = 20;
float playerHeight = 50;
float playerSpeedY = 0;
//only allow jumping if the player is not already jumping
boolean jumping = false;

int way = 3;        // 1 speed 0 only, 2 next position, 3 the tutorial's snap, 4 Snap
boolean showMaths;  // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  float movedY = playerY + playerSpeedY;  // where this frame's move takes it, for the maths

  if (way != 3) {
    otherWay();   // keys 1, 2 and 4 (Ways.pde)
  } else {
    //move the player
    playerY += playerSpeedY;
    //is the player colliding with the ground?
    if (playerY + playerHeight > groundY) {
      //snap the player's bottom to the ground's position
      playerY = groundY - playerHeight;
      //stop the player falling
      playerSpeedY = 0;
      //allow jumping again
      jumping = false;
    }
    //player is not colliding with the ground
    else {
      //gravity accelerates the movement speed
      playerSpeedY++;
    }
  }

  drawGround();
  //draw the player rectangle
  noStroke();
  fill(Palette.PLAYER);
  rect(playerX, playerY, playerWidth, playerHeight);
  drawEarth();

  if (showMaths) {
    drawMaths(movedY);
  }
  drawWay();
}

void keyPressed() {
  if (key == '1' || key == '2' || key == '3' || key == '4' || key == 'l') {
    way = key == '1' ? 1 : key == '2' ? 2 : key == '3' ? 3 : 4;
    dropAgain();
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
  //you can only jump if you aren't already jumping
  else if (!jumping) {
    //going up
    playerSpeedY = -15;
    //disallow jumping while already jumping
    jumping = true;
  }
}
