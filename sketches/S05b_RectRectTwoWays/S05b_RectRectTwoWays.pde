/**
 * Rectangle/Rectangle, two ways: && and the flipped ||
 * Tutorial section 5: Rectangle/Rectangle
 *
 * The tutorial writes the rectangle test twice. First as "not colliding": four comparisons
 * joined by || (r1's right edge left of r2's left edge, or ...); an else after it would be
 * the collision. Then reversed: four comparisons joined by && that hold when they ARE
 * colliding (it names the rectangles rectOne and rectTwo; here r1 and r2). The
 * video shows both and calls the || form "a bit more efficient". Here both forms run on the
 * same rectangles every frame. Each comparison lights up as Java evaluates it (red: it points
 * to "colliding", green: to "not colliding"); grey ones were skipped, because && stops at
 * the first false and || at the first true. Under each form, a running count.
 *
 * The counts stay equal: comparison i of the || form is the opposite of comparison i of the
 * && form, so both stop at the same place, and neither form is the more efficient (timed in
 * Java, src/jmh RectRectFormsBench, they are as fast as each other within the noise). Only
 * touching rectangles tell them apart (press t): the opposite of > is <=, not <, so with the
 * tutorial's strict comparisons the || form calls rectangles that share an edge colliding,
 * and the && form does not.
 *
 * Where Hitbox differs: Collide.rectRect is the && form, because touching is not colliding
 * everywhere in Hitbox; the || form would agree with it only with <= and >=.
 *
 * Try this: write the || form with <= and >= and press t again; reorder the comparisons so
 * the one that fails most often comes first, and watch the counts.
 * Keys: t touching (r1 snaps against r2's nearest side), r resets the counts, d shows the
 * maths (every edge's value, and why < is not the opposite of >).
 */
import hitbox.*;
import hitbox.processing.*;

// r1 hangs from the mouse by its top-left corner; r2 stays in the middle.
float r1x, r1y;
float r1w = 100;
float r1h = 60;
float r2x = 370;
float r2y = 85;
float r2w = 100;
float r2h = 80;
boolean touching;     // t: r1 is snapped against r2's nearest side
boolean showMaths;    // d

// What each form did this frame: per comparison SKIPPED, TRUE or FALSE, and its answer;
// and how many comparisons each has evaluated, this frame and since the counts were reset.
int SKIPPED = 0, TRUE = 1, FALSE = 2;
int[] andLit = new int[4];
int[] orLit = new int[4];
boolean andSays, orSays;
int andNow, orNow;
long andTotal, orTotal, frames;

void setup() {
  size(840, 470);
}

void draw() {
  background(Palette.BACKGROUND);
  placeR1();
  float r1Left = r1x, r1Right = r1x + r1w, r1Top = r1y, r1Bottom = r1y + r1h;
  float r2Left = r2x, r2Right = r2x + r2w, r2Top = r2y, r2Bottom = r2y + r2h;
  startFrame();

  // The tutorial's && form: true when they ARE colliding. Each comparison goes through
  // byAnd(i, ...), which lights it up and counts it; && skips the rest at the first false.
  if (byAnd(0, r1Right > r2Left) && byAnd(1, r1Left < r2Right)
      && byAnd(2, r1Bottom > r2Top) && byAnd(3, r1Top < r2Bottom)) {
    andSays = true;     // colliding
  } else {
    andSays = false;    // not colliding
  }

  // The flipped || form: true when they are NOT colliding; || skips the rest at the first true.
  if (byOr(0, r1Right < r2Left) || byOr(1, r1Left > r2Right)
      || byOr(2, r1Bottom < r2Top) || byOr(3, r1Top > r2Bottom)) {
    orSays = false;     // not colliding
  } else {
    orSays = true;      // colliding
  }

  // Hitbox's call: the && form.
  boolean colliding = Collide.rectRect(r1x, r1y, r1w, r1h, r2x, r2y, r2w, r2h);

  drawRectangles(colliding);
  drawForms();
  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "move r1 (the mouse holds its top-left corner)     t: touching " + (touching ? "off" : "on")
      + "     r: reset the counts     d: show the maths");
}

/** One comparison of the && form, as Java evaluates it: lit and counted, its value passed on. */
boolean byAnd(int i, boolean value) {
  andLit[i] = value ? TRUE : FALSE;
  andNow++;
  andTotal++;
  return value;
}

/** One comparison of the || form, as Java evaluates it. */
boolean byOr(int i, boolean value) {
  orLit[i] = value ? TRUE : FALSE;
  orNow++;
  orTotal++;
  return value;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 't') {
    touching = !touching;
  } else if (key == 'r') {
    andTotal = 0;
    orTotal = 0;
    frames = 0;
  }
}
