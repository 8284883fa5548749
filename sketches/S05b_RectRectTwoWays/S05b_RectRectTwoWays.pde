/**
 * Rectangle/Rectangle, two ways: || and &&
 * Tutorial section 5: Rectangle/Rectangle
 *
 * The tutorial writes the rectangle test twice, in its names rectOne and rectTwo. First as
 * "not colliding": four comparisons joined by || (rectOneRight < rectTwoLeft, or ...); an else
 * after it would be the collision. Then reversed: four comparisons joined by && that hold when
 * they ARE colliding. The video gives the same test in x, y, width and height, && first
 * (x1 < x2 + w2 && x1 + w1 > x2 && ...: our names for its "x of rectangle 1" and so on), then
 * flips it to || and calls that "a bit more efficient". All four run below every frame; the tutorial's && form colours rectTwo, and
 * Collide.rectRect runs beside it (l lets it pick the colour). The panels show the tutorial's
 * pair, or the video's (v): each comparison lights up as Java evaluates it (red: it points to
 * "colliding", green: to "not colliding"); grey ones were skipped, because && stops at the
 * first false and || at the first true. Under each form, a running count.
 *
 * The counts stay equal: comparison i of the || form is the opposite of comparison i of the
 * && form, so both stop at the same place, and neither is the more efficient (timed in Java,
 * src/jmh RectRectFormsBench, they are as fast as each other within the noise). Only touching
 * rectangles tell them apart (press t): the opposite of > is <=, not <, so with these strict
 * comparisons the || forms call rectangles that share an edge colliding, the && forms do not.
 *
 * Where Hitbox differs: Collide.rectRect is the && form, because touching is not colliding
 * everywhere in Hitbox; the || form would agree with it only with <= and >=.
 *
 * Try this: write the || form with <= and >= and press t again; reorder the comparisons so the
 * one that fails most often comes first, and watch the counts.
 * Keys: t touching (rectOne snaps against rectTwo's nearest side), v the video's forms / the
 * tutorial's, l the library picks the colour, r resets the counts, d shows the maths.
 */
import hitbox.*;
import hitbox.processing.*;

// rectOne hangs from the mouse by its top-left corner; rectTwo stays in the middle.
float x1, y1;
float w1 = 100;
float h1 = 60;
float x2 = 370;
float y2 = 85;
float w2 = 100;
float h2 = 80;

boolean orSays, andSays;            // the tutorial's two forms: colliding?
boolean videoAndSays, videoOrSays;  // the video's two
boolean hitboxDecides;  // l: Collide.rectRect picks rectTwo's colour
boolean videoForms;     // v: the panels show the video's forms
boolean touching;       // t: rectOne is snapped against rectTwo's nearest side
boolean showMaths;      // d

void setup() {
  size(840, 470);
}

void draw() {
  background(Palette.BACKGROUND);
  placeRectOne();   // Maths.pde
  float rectOneLeft = x1, rectOneRight = x1 + w1, rectOneTop = y1, rectOneBottom = y1 + h1;
  float rectTwoLeft = x2, rectTwoRight = x2 + w2, rectTwoTop = y2, rectTwoBottom = y2 + h2;

  //the tutorial's first form: true if rectOne and rectTwo are NOT colliding
  if (rectOneRight < rectTwoLeft || rectOneLeft > rectTwoRight || rectOneBottom < rectTwoTop || rectOneTop > rectTwoBottom) {
    orSays = false;
  } else {
    orSays = true;
  }
  //its reverse: true if rectOne and rectTwo are colliding
  if (rectOneRight > rectTwoLeft && rectOneLeft < rectTwoRight && rectOneBottom > rectTwoTop && rectOneTop < rectTwoBottom) {
    andSays = true;
  } else {
    andSays = false;
  }

  //the video's first form, in x, y, width and height: all four true means colliding
  if (x1 < x2 + w2 && x1 + w1 > x2 && y1 < y2 + h2 && y1 + h1 > y2) {
    videoAndSays = true;
  } else {
    videoAndSays = false;
  }
  //and flipped: one true is enough to know they cannot collide
  if (x1 > x2 + w2 || x1 + w1 < x2 || y1 > y2 + h2 || y1 + h1 < y2) {
    videoOrSays = false;
  } else {
    videoOrSays = true;
  }

  //Hitbox's call, beside them: the && form
  boolean hitboxSays = Collide.rectRect(x1, y1, w1, h1, x2, y2, w2, h2);
  boolean colliding = hitboxDecides ? hitboxSays : andSays;

  countComparisons();   // which comparisons Java evaluated, and how many (Maths.pde)
  drawRectangles(colliding, hitboxSays);
  drawForms();
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move rectOne   t: touching " + (touching ? "off" : "on") + "   v: the " + (videoForms ? "tutorial's" : "video's")
      + " forms   l: " + (hitboxDecides ? "the tutorial's &&" : "Collide.rectRect") + " colours rectTwo   r: reset   d: maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 't') {
    touching = !touching;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'v') {
    videoForms = !videoForms;
    resetCounts();
  } else if (key == 'r') {
    resetCounts();
  }
}
