/**
 * Many objects: one box, a list of rectangles
 * Tutorial section 8: Many objects
 *
 * The tutorial's program: a Rectangle class, a list of them called rectangles (four walls and
 * some blocks), and a loop over the list that does section 6's next-position check against
 * each one, flips a speed when it would collide, and draws the obstacle. That loop runs here
 * and moves the box.
 *
 * It reverses a speed as soon as one rectangle blocks it, and the rectangles after it test
 * the reversed speed. Press s to put the box in the slot between two pillars, only 2 pixels
 * wider than the box: one pillar flips the speed and the other flips it back, so the box
 * moves into a pillar and stays there, flickering.
 *
 * Where Hitbox differs: because of that. Press l for Hitbox's loop (Hitbox.pde): it asks
 * every rectangle first (Motion.blocked), combines the answers, reverses once, and asks
 * again before it moves, so a box with nowhere to go waits a frame.
 *
 * Try this (the tutorial's): click to add a rectangle, mousePressed below; build another
 * narrow slot and watch both loops in it.
 * Keys: l Hitbox's loop / the tutorial's, s puts the box in the slot, click adds a rectangle,
 * d shows the maths, p pauses, n steps one frame.
 */
import hitbox.*;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import hitbox.processing.*;

ArrayList<Rectangle> rectangles = new ArrayList<Rectangle>();
float bouncingRectX = 150;
float bouncingRectY = 150;
float bouncingRectWidth = 30;
float bouncingRectHeight = 30;
float bouncingRectSpeedX = 3.3;
float bouncingRectSpeedY = 2.7;

boolean hitboxDecides;  // l: Hitbox's loop moves the box instead of the tutorial's

void setup() {
  size(600, 400);
  // The tutorial's four walls (the bottom one above the key hint)...
  rectangles.add(new Rectangle(0, 0, width, 20));
  rectangles.add(new Rectangle(0, height - 38, width, 20));
  rectangles.add(new Rectangle(0, 0, 20, height));
  rectangles.add(new Rectangle(width - 20, 0, 20, height));
  // ...and blocks; 5 and 6 are two pillars with a 32-pixel slot between them.
  rectangles.add(new Rectangle(90, 70, 80, 40));
  rectangles.add(new Rectangle(230, 60, 40, 180));
  rectangles.add(new Rectangle(302, 60, 40, 180));
  rectangles.add(new Rectangle(420, 80, 110, 30));
  rectangles.add(new Rectangle(60, 220, 40, 90));
  rectangles.add(new Rectangle(470, 230, 60, 90));
  rectangles.add(new Rectangle(150, 300, 130, 25));
  rectangles.add(new Rectangle(390, 170, 50, 50));
}

void draw() {
  background(Palette.BACKGROUND);
  boolean moving = goesOn();   // not while paused (Maths.pde)
  if (moving && hitboxDecides) {
    hitboxStep();
  }
  //iterate over the obstacles
  for (int i = 0; i < rectangles.size(); i++) {
    //check collision for this obstacle
    Rectangle rectangle = rectangles.get(i);
    if (moving && !hitboxDecides) {
      //check X movement bounce
      if (bouncingRectX + bouncingRectWidth + bouncingRectSpeedX > rectangle.x
          && bouncingRectX + bouncingRectSpeedX < rectangle.x + rectangle.rectWidth
          && bouncingRectY + bouncingRectHeight > rectangle.y
          && bouncingRectY < rectangle.y + rectangle.rectHeight) {
        bouncingRectSpeedX *= -1;
        rectangle.hit();
      }
      //check Y movement bounce
      if (bouncingRectX + bouncingRectWidth > rectangle.x
          && bouncingRectX < rectangle.x + rectangle.rectWidth
          && bouncingRectY + bouncingRectHeight + bouncingRectSpeedY > rectangle.y
          && bouncingRectY + bouncingRectSpeedY < rectangle.y + rectangle.rectHeight) {
        bouncingRectSpeedY *= -1;
        rectangle.hit();
      }
    }
    //draw the obstacle rectangle: red for a while after it flipped a speed
    noStroke();
    fill(rectangle.lit() ? Palette.HIT : Palette.OBSTACLE);
    rect(rectangle.x, rectangle.y, rectangle.rectWidth, rectangle.rectHeight);
  }
  if (moving && !hitboxDecides) {
    bouncingRectX += bouncingRectSpeedX;
    bouncingRectY += bouncingRectSpeedY;
  }
  //draw the bouncing rectangle
  drawBox();
  drawMathsAndLabels();   // in Maths.pde
}

// The tutorial's try-this: "a new obstacle is added when the user clicks the mouse". One more
// Rectangle in the list, and both loops test it from the next frame on, with no new code.
void mousePressed() {
  Rectangle added = new Rectangle(mouseX - 30, mouseY - 15, 60, 30);
  if (added.overlaps(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight)) {
    say("not added: it would be on top of the box");   // it would start inside it
  } else {
    rectangles.add(added);
    say("added rectangle " + (rectangles.size() - 1));
  }
}
