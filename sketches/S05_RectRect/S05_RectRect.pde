/**
 * Rectangle/Rectangle
 * Tutorial section 5: Rectangle/Rectangle
 *
 * Two rectangles overlap when every edge of one is past the opposite edge of the other: r1's
 * right edge past r2's left, r1's left edge before r2's right, and the same down the page.
 * The mouse holds r1 by its top-left corner, as in the tutorial's sketch (rect() draws from
 * the corner); r2 turns red while they overlap. Rectangles side by side, sharing an edge, do
 * not collide: all four comparisons are strict.
 *
 * Where Hitbox differs: it does not. Collide.rectRect makes the tutorial's four strict
 * comparisons; it only adds x + w in double, so that large coordinates cannot round.
 *
 * Try this: make r1 as wide as the window (a floor); make r1 height 0 (a line: it collides
 * only by reaching into r2); hold r1 by its centre (r1x = mouseX - r1w / 2) and see which
 * numbers change. S05b shows the test written the other way round, with ||.
 * Keys: d shows the maths (the four comparisons, each at the edges it compares).
 */
import hitbox.*;
import hitbox.processing.*;

// r1 hangs from the mouse by its top-left corner; r2 stays in the middle of the window.
float r1x, r1y;
float r1w = 120;
float r1h = 80;
float r2x = 220;
float r2y = 150;
float r2w = 160;
float r2h = 100;
boolean showMaths;    // the 'd' overlay

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);
  r1x = mouseX;
  r1y = mouseY;

  // The tutorial's if: r1's right past r2's left, r1's left before r2's right, r1's bottom
  // below r2's top, r1's top above r2's bottom.
  boolean tutorialSays = r1x + r1w > r2x && r1x < r2x + r2w && r1y + r1h > r2y && r1y < r2y + r2h;
  // The library's call: the same four comparisons.
  boolean colliding = Collide.rectRect(r1x, r1y, r1w, r1h, r2x, r2y, r2w, r2h);

  noStroke();
  fill(colliding ? Palette.HIT : Palette.MISS);
  rect(r2x, r2y, r2w, r2h);

  // r1, see-through so the overlap shows.
  stroke(Palette.PLAYER);
  strokeWeight(2);
  fill(Palette.PLAYER, 150);
  rect(r1x, r1y, r1w, r1h);
  names();

  if (showMaths) {
    drawMaths(colliding);
  } else {
    answer(8, 8, "the tutorial's if", tutorialSays);
    answer(8, 30, "Collide.rectRect", colliding);
  }
  Overlay.hint(g, "move the blue rectangle (the mouse holds its top-left corner)     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  }
}
