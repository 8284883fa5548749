// Where rectOne goes, which comparisons each form evaluated, the drawing of the two forms, and
// the "show the maths" overlay (key d).

// The panels of the two forms shown: left the && form, right the || form.
float panelTop = 262;
float panelW = 405;
String[] andCode = {"if (rectOneRight > rectTwoLeft", " && rectOneLeft < rectTwoRight", " && rectOneBottom > rectTwoTop", " && rectOneTop < rectTwoBottom)"};
String[] orCode = {"if (rectOneRight < rectTwoLeft", " || rectOneLeft > rectTwoRight", " || rectOneBottom < rectTwoTop", " || rectOneTop > rectTwoBottom)"};
String[] videoAndCode = {"if (x1 < x2 + w2", " && x1 + w1 > x2", " && y1 < y2 + h2", " && y1 + h1 > y2)"};
String[] videoOrCode = {"if (x1 > x2 + w2", " || x1 + w1 < x2", " || y1 > y2 + h2", " || y1 + h1 < y2)"};
color SKIPPED_GREY = #6A7080;
PFont code, sans, title;   // made on the first frame

// What each form shown did this frame: per comparison SKIPPED, TRUE or FALSE; how many
// comparisons each evaluated, this frame and since the counts were reset.
int SKIPPED = 0, TRUE = 1, FALSE = 2;
int[] andLit = new int[4];
int[] orLit = new int[4];
int andNow, orNow;
long andTotal, orTotal, frames;

/** The top of comparison row i in either panel (the tests find the rows here too). */
float rowTop(int i) {
  return panelTop + 30 + i * 20;
}

/** The left of a form's panel: 0 the && form, 1 the || form. */
float panelLeft(int form) {
  return 10 + form * (panelW + 10);
}

/** rectOne at the mouse by its corner; with t, moved the shortest way to touch rectTwo's nearest side. */
void placeRectOne() {
  x1 = mouseX;
  y1 = mouseY;
  if (!touching) {
    return;
  }
  float toLeft = abs(x1 - (x2 - w1)), toRight = abs(x1 - (x2 + w2));
  float toTop = abs(y1 - (y2 - h1)), toBottom = abs(y1 - (y2 + h2));
  if (min(toLeft, toRight) <= min(toTop, toBottom)) {
    x1 = toLeft <= toRight ? x2 - w1 : x2 + w2;
    y1 = constrain(y1, y2 - h1, y2 + h2);   // still sharing some of the edge, or a corner
  } else {
    y1 = toTop <= toBottom ? y2 - h1 : y2 + h2;
    x1 = constrain(x1, x2 - w1, x2 + w2);
  }
}

/** The left side of each of the && form's comparisons, in the order the form shown writes them. */
float[] andLeft() {
  return videoForms ? new float[] {x1, x1 + w1, y1, y1 + h1} : new float[] {x1 + w1, x1, y1 + h1, y1};
}

/** And the right side. */
float[] andRight() {
  return videoForms ? new float[] {x2 + w2, x2, y2 + h2, y2} : new float[] {x2, x2 + w2, y2, y2 + h2};
}

/** The comparison operators of the && form shown; the || form's are the other way round. */
String[] andOps() {
  return videoForms ? new String[] {"<", ">", "<", ">"} : new String[] {">", "<", ">", "<"};
}

String[] orOps() {
  return videoForms ? new String[] {">", "<", ">", "<"} : new String[] {"<", ">", "<", ">"};
}

/**
 * The comparisons of the two forms shown, in their order, as Java evaluates them: && stops at
 * the first false, || at the first true. Lit and counted.
 */
void countComparisons() {
  float[] left = andLeft();
  float[] right = andRight();
  andNow = evaluate(andLit, left, andOps(), right, false);
  orNow = evaluate(orLit, left, orOps(), right, true);
  andTotal += andNow;
  orTotal += orNow;
  frames++;
}

/** Four comparisons in order until one gives stopOn; returns how many were evaluated. */
int evaluate(int[] lit, float[] left, String[] ops, float[] right, boolean stopOn) {
  int evaluated = 0;
  for (int i = 0; i < 4; i++) {
    lit[i] = SKIPPED;
  }
  for (int i = 0; i < 4; i++) {
    boolean value = ops[i].equals("<") ? left[i] < right[i] : left[i] > right[i];
    lit[i] = value ? TRUE : FALSE;
    evaluated++;
    if (value == stopOn) {
      break;
    }
  }
  return evaluated;
}

void resetCounts() {
  andTotal = 0;
  orTotal = 0;
  frames = 0;
}

void drawRectangles(boolean colliding, boolean hitboxSays) {
  noStroke();
  fill(colliding ? Palette.HIT : Palette.MISS);
  rect(x2, y2, w2, h2);
  stroke(Palette.PLAYER);
  strokeWeight(2);
  fill(Palette.PLAYER, 150);
  rect(x1, y1, w1, h1);
  if (code == null) {
    code = createFont("Monospaced", 13);
    sans = createFont("SansSerif", 13);
    title = createFont("SansSerif", 14);
  }
  fill(Palette.BACKGROUND);
  textFont(sans);
  textAlign(LEFT, TOP);
  text("rectTwo", x2 + 6, y2 + 4);
  fill(Palette.NEUTRAL);
  text("rectOne", x1 + 6, y1 + 4);
  Overlay.label(g, 8, 8, (hitboxDecides ? "Collide.rectRect" : "the tutorial's &&") + " colours rectTwo: " + says(colliding)
      + "\nCollide.rectRect: " + says(hitboxSays) + (hitboxSays == andSays ? ", agrees with" : ", DISAGREES with") + " the tutorial's &&",
      colliding ? Overlay.HIT : Overlay.MISS);
  if (touching) {
    Overlay.label(g, 8, 48, "touching (t): rectOne shares an edge with rectTwo\nthe tutorial's: && says " + says(andSays)
        + ", || says " + says(orSays) + "\nthe video's: && says " + says(videoAndSays) + ", || says " + says(videoOrSays),
        Overlay.GUIDE);
  }
}

/** A number as short as it can be written: 430, or 430.5. */
String whole(float v) {
  return v == (int) v ? str((int) v) : Overlay.number(v);
}

String says(boolean colliding) {
  return colliding ? "colliding" : "not colliding";
}

/** Both forms, each comparison lit as it was evaluated, and the counts. */
void drawForms() {
  noStroke();
  fill(#171A20);
  rect(0, panelTop - 10, width, height - panelTop + 10);
  float[] left = andLeft();
  float[] right = andRight();
  if (videoForms) {
    drawForm(0, "the video's && form: true means colliding", videoAndCode, andOps(), andLit, true, videoAndSays, andNow, andTotal, left, right);
    drawForm(1, "the video's flipped || form: true means NOT colliding", videoOrCode, orOps(), orLit, false, videoOrSays, orNow, orTotal, left, right);
  } else {
    drawForm(0, "the tutorial's && form (its second): true means colliding", andCode, andOps(), andLit, true, andSays, andNow, andTotal, left, right);
    drawForm(1, "the tutorial's || form (its first): true means NOT colliding", orCode, orOps(), orLit, false, orSays, orNow, orTotal, left, right);
  }
}

/**
 * One form's panel. A comparison that holds in the && form points to "colliding"; one that
 * holds in the || form points to "not colliding": each is coloured by where it points.
 */
void drawForm(int form, String title, String[] lines, String[] ops, int[] lit, boolean trueMeansColliding,
              boolean colliding, int now, long total, float[] left, float[] right) {
  float x = panelLeft(form);
  textFont(this.title);
  textAlign(LEFT, TOP);
  fill(Palette.NEUTRAL);
  text(title, x + 8, panelTop);
  textFont(code);
  for (int i = 0; i < 4; i++) {
    float y = rowTop(i);
    if (lit[i] == SKIPPED) {
      fill(SKIPPED_GREY);
      textAlign(LEFT, TOP);
      text(lines[i], x + 8, y);
      textAlign(RIGHT, TOP);
      text("skipped", x + panelW - 8, y);
      continue;
    }
    boolean holds = lit[i] == TRUE;
    color c = holds == trueMeansColliding ? Overlay.HIT : Overlay.MISS;
    noStroke();
    fill(c, 40);
    rect(x + 2, y - 2, panelW - 4, 19, 3);
    fill(c);
    textAlign(LEFT, TOP);
    text(lines[i], x + 8, y);
    text(whole(left[i]) + " " + ops[i] + " " + whole(right[i]), x + 262, y);
    textAlign(RIGHT, TOP);
    text(holds ? "true" : "false", x + panelW - 8, y);
  }
  // The two branches; the one taken in its colour.
  textAlign(LEFT, TOP);
  String first = trueMeansColliding ? "  { colliding }" : "  { not colliding }";
  String second = trueMeansColliding ? " else { not colliding }" : " else { colliding }";
  boolean tookFirst = colliding == trueMeansColliding;
  float y = rowTop(4);
  fill(tookFirst ? (colliding ? Overlay.HIT : Overlay.MISS) : SKIPPED_GREY);
  text(first, x + 8, y);
  fill(!tookFirst ? (colliding ? Overlay.HIT : Overlay.MISS) : SKIPPED_GREY);
  text(second, x + 8 + textWidth(first), y);

  textFont(sans);
  fill(Palette.NEUTRAL);
  text("this frame: " + now + " of 4 comparisons evaluated: " + says(colliding), x + 8, rowTop(5) + 6);
  text("since r: " + total + " comparisons in " + frames + " frames, "
      + String.format(java.util.Locale.ROOT, "%.2f", frames == 0 ? 0 : (float) total / frames) + " a frame", x + 8, rowTop(5) + 24);
}

/**
 * Every edge as a line across the play area, with its name and value (rectOne's a row nearer the
 * rectangles than rectTwo's, so equal edges do not hide each other), and why the || form is not
 * quite the opposite of the && form.
 */
void drawMaths() {
  float bottom = panelTop - 14;
  edgeLine(x1, true, "rectOneLeft", bottom - 22);
  edgeLine(x1 + w1, true, "rectOneRight", bottom - 22);
  edgeLine(x2, true, "rectTwoLeft", bottom);
  edgeLine(x2 + w2, true, "rectTwoRight", bottom);
  edgeLine(y1, false, "rectOneTop", width - 250);
  edgeLine(y1 + h1, false, "rectOneBottom", width - 250);
  edgeLine(y2, false, "rectTwoTop", width - 115);
  edgeLine(y2 + h2, false, "rectTwoBottom", width - 115);
  Overlay.label(g, width - 300, 8, "comparison i of || is the opposite of comparison i of &&,\n"
      + "except when the two sides are equal:\n"
      + "the opposite of a > b is a <= b, and || tests a < b.\n"
      + "Equal sides (touching): false in both forms.", Overlay.GUIDE);
}

/** An edge extended across the play area, labelled at one end with its name and value. */
void edgeLine(float at, boolean vertical, String name, float labelAt) {
  stroke(Overlay.GUIDE, 110);
  strokeWeight(1);
  String text = name + " " + Overlay.number(at);
  if (vertical) {
    line(at, 0, at, panelTop - 10);
    Overlay.labelBeside(g, at, labelAt, 0, -1, text, Overlay.TEXT);
  } else {
    line(0, at, width, at);
    Overlay.labelBeside(g, labelAt, at, 0, 0, text, Overlay.TEXT);
  }
}
