/**
 * Moving objects: look before you move
 * Tutorial section 6: Moving objects
 *
 * The tutorial's program: a rectangle bounces off the window's edges and off the sides of
 * the center rectangle. A yes-or-no test cannot say which side was hit, so before it moves
 * it asks where it WILL be, one axis at a time: moved across only (its left and right edges
 * plus bouncingRectSpeedX) and moved down only. If the move across would collide,
 * bouncingRectSpeedX reverses; if the move down would, bouncingRectSpeedY does. The checks
 * are written with the tutorial's own rewrite into variables: currentBouncingLeft,
 * nextBouncingRight and so on (the tutorial writes the across check that way; the down
 * check here follows it, with nextBouncingTop and nextBouncingBottom).
 *
 * Press c: the rectangle is aimed at the center rectangle's corner, where neither move alone
 * collides but the diagonal move does, so both checks say "free" and it ends a frame inside
 * (the counter at the top). The tutorial's window check looks where the rectangle is, not
 * where it will be, so it pokes out of the window for a frame at each edge.
 *
 * Where Hitbox differs: press l for Motion.blocked, which makes the same two checks,
 * also tests the diagonal move and reports both axes for a corner hit; Edges checks the
 * window at the next position too. A check of the next position should never let it in.
 *
 * Try this: pause (p) before it reaches the center rectangle and step (n) with the maths on
 * (d): when a next-position box turns red, that speed reverses. Set bouncingRectSpeedX to
 * 250: it jumps clean over now and then, because the check only looks where it lands, not
 * along the way (beyond the tutorial: Hitbox's Sweep looks at the path, see S10e).
 * Keys: l Motion.blocked / the tutorial's code, c aim at the corner, p pause, n one
 * frame while paused, d shows the maths.
 */
import hitbox.*;
import java.util.List;
import java.util.Set;
import hitbox.processing.*;

float centerRectX = 220;
float centerRectY = 140;
float centerRectWidth = 160;
float centerRectHeight = 100;
float bouncingRectX = 60;
float bouncingRectY = 40;
float bouncingRectWidth = 40;
float bouncingRectHeight = 40;
float bouncingRectSpeedX = 3.5;
float bouncingRectSpeedY = 2.5;

boolean library = false;    // l: Motion.blocked instead of the tutorial's ifs
int framesInside = 0;       // frames the rectangle ended inside the center rectangle
boolean showMaths, paused, stepOnce;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  if (!paused || stepOnce) {
    stepOnce = false;
    move();
  }
  drawScene();
}

void move() {
  float currentBouncingLeft = bouncingRectX;
  float currentBouncingRight = bouncingRectX + bouncingRectWidth;
  float currentBouncingTop = bouncingRectY;
  float currentBouncingBottom = bouncingRectY + bouncingRectHeight;
  float nextBouncingLeft = currentBouncingLeft + bouncingRectSpeedX;
  float nextBouncingRight = currentBouncingRight + bouncingRectSpeedX;
  float nextBouncingTop = currentBouncingTop + bouncingRectSpeedY;
  float nextBouncingBottom = currentBouncingBottom + bouncingRectSpeedY;

  if (!library) {
    //if I keep moving in my current X direction, will I collide with the center rectangle?
    if (nextBouncingRight > centerRectX && nextBouncingLeft < centerRectX + centerRectWidth
        && currentBouncingBottom > centerRectY && currentBouncingTop < centerRectY + centerRectHeight) {
      bouncingRectSpeedX *= -1;
    }
    //bounce off left and right edges of screen
    else if (bouncingRectX < 0 || bouncingRectX + bouncingRectWidth > width) {
      bouncingRectSpeedX *= -1;
    }
    //if I keep moving in my current Y direction, will I collide with the center rectangle?
    if (currentBouncingRight > centerRectX && currentBouncingLeft < centerRectX + centerRectWidth
        && nextBouncingBottom > centerRectY && nextBouncingTop < centerRectY + centerRectHeight) {
      bouncingRectSpeedY *= -1;
    }
    //bounce off top and bottom edges of screen
    else if (bouncingRectY < 0 || bouncingRectY + bouncingRectHeight > height) {
      bouncingRectSpeedY *= -1;
    }
  } else {
    // Hitbox: the same two checks, and the diagonal one, in a call; then the window, also
    // at the next position.
    Set<Side> blocked = Motion.blocked(new Rect(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight),
        bouncingRectSpeedX, bouncingRectSpeedY, List.of(new Rect(centerRectX, centerRectY, centerRectWidth, centerRectHeight)));
    bouncingRectSpeedX = Motion.reverseX(blocked, bouncingRectSpeedX);
    bouncingRectSpeedY = Motion.reverseY(blocked, bouncingRectSpeedY);
    Set<Side> crossed = Edges.crossed(new Rect(bouncingRectX + bouncingRectSpeedX, bouncingRectY + bouncingRectSpeedY,
        bouncingRectWidth, bouncingRectHeight), width, height);
    bouncingRectSpeedX = Edges.bounceX(crossed, bouncingRectSpeedX);
    bouncingRectSpeedY = Edges.bounceY(crossed, bouncingRectSpeedY);
  }
  bouncingRectX += bouncingRectSpeedX;
  bouncingRectY += bouncingRectSpeedY;

  if (Collide.rectRect(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight,
      centerRectX, centerRectY, centerRectWidth, centerRectHeight)) {
    framesInside++;
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'l') {
    library = !library;
    framesInside = 0;
  } else if (key == 'c') {
    // Just off the center rectangle's top-left corner, heading for it: only the diagonal move hits.
    bouncingRectX = centerRectX - bouncingRectWidth - 1;
    bouncingRectY = centerRectY - bouncingRectHeight - 1;
    bouncingRectSpeedX = abs(bouncingRectSpeedX);
    bouncingRectSpeedY = abs(bouncingRectSpeedY);
  } else if (key == 'p') {
    paused = !paused;
  } else if (key == 'n') {
    stepOnce = true;
  }
}
