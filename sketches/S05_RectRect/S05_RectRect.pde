/**
 * Rectangle/Rectangle
 * Tutorial section 5: Rectangle/Rectangle
 *
 * The tutorial's program: a rectangle in the center and one at the mouse, held by its
 * top-left corner (rect() draws from the corner). They collide when every edge of one is past
 * the opposite edge of the other: the mouse rectangle's right edge past the center one's
 * left, its left edge before the center one's right, and the same down the page. The
 * tutorial's if picks the colour: the mouse rectangle is red while they collide, green
 * otherwise. Rectangles side by side, sharing an edge, do not collide: all four comparisons
 * are strict.
 *
 * Where Hitbox differs: it does not. Collide.rectRect, run beside the tutorial's if, makes the
 * same four strict comparisons; it only adds x + width in double, so that large coordinates
 * cannot round. Both answers are written at the top, and whether they agree; press l and
 * Hitbox's answer picks the colour instead.
 *
 * Try this: delete one of the four comparisons in the tutorial's if and find where the
 * rectangle turns red too soon; make the mouse rectangle as wide as the window (a floor); make its height 0 (a
 * line: it collides only by reaching into the center one); hold it by its center
 * (mouseX - mouseRectWidth / 2) and see which numbers change. S05b shows the test the
 * tutorial writes first, "not colliding" with ||.
 * Keys: l the library picks the colour / the tutorial's if, d shows the maths (the four
 * comparisons, each at the edges it compares).
 */
import hitbox.*;
import hitbox.processing.*;

float centerRectX = 250;
float centerRectY = 100;
float centerRectWidth = 100;
float centerRectHeight = 200;
float mouseRectWidth = 200;
float mouseRectHeight = 100;

boolean hitboxDecides;  // l: Collide.rectRect picks the colour instead of the tutorial's if
boolean showMaths;      // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  //draw the center rectangle
  noFill();
  stroke(255);
  strokeWeight(2);
  rect(centerRectX, centerRectY, centerRectWidth, centerRectHeight);

  //the tutorial's if: are the rectangles colliding?
  boolean tutorialSays = mouseX + mouseRectWidth > centerRectX && mouseX < centerRectX + centerRectWidth
      && mouseY + mouseRectHeight > centerRectY && mouseY < centerRectY + centerRectHeight;
  //Hitbox's call, beside it: the same four comparisons
  boolean hitboxSays = Collide.rectRect(mouseX, mouseY, mouseRectWidth, mouseRectHeight,
      centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  boolean colliding = hitboxDecides ? hitboxSays : tutorialSays;

  //change color if rectangles are colliding
  if (colliding) {
    fill(Palette.HIT);
  } else {
    fill(Palette.MISS);
  }
  //draw the mouse rectangle
  noStroke();
  rect(mouseX, mouseY, mouseRectWidth, mouseRectHeight);
  // The center rectangle's outline again, over it, so the overlap shows.
  noFill();
  stroke(255);
  strokeWeight(2);
  rect(centerRectX, centerRectY, centerRectWidth, centerRectHeight);

  if (showMaths) {
    drawMaths(colliding);
  } else {
    answers("the tutorial's if", tutorialSays, "Collide.rectRect", hitboxSays, hitboxDecides);
  }
  Overlay.hint(g, "move the mouse rectangle (the mouse holds its top-left corner)     l: "
      + (hitboxDecides ? "the tutorial's if" : "Hitbox") + " picks the colour     d: show the maths");
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
