// Where r1 goes, the drawing of the two forms, and the "show the maths" overlay (key d).

// The panels of the two forms: left the && form, right the || form.
float panelTop = 262;
float panelW = 405;
String[] andCode = {"if (r1Right  > r2Left", " && r1Left   < r2Right", " && r1Bottom > r2Top", " && r1Top    < r2Bottom)"};
String[] orCode = {"if (r1Right  < r2Left", " || r1Left   > r2Right", " || r1Bottom < r2Top", " || r1Top    > r2Bottom)"};
String[] andOps = {">", "<", ">", "<"};
String[] orOps = {"<", ">", "<", ">"};
color SKIPPED_GREY = #6A7080;
PFont code, sans, title;   // made on the first frame

/** The top of comparison row i in either panel (the tests find the rows here too). */
float rowTop(int i) {
  return panelTop + 30 + i * 20;
}

/** The left of a form's panel: 0 the && form, 1 the || form. */
float panelLeft(int form) {
  return 10 + form * (panelW + 10);
}

/** r1 at the mouse by its corner; with t, moved the shortest way to touch r2's nearest side. */
void placeR1() {
  r1x = mouseX;
  r1y = mouseY;
  if (!touching) {
    return;
  }
  float toLeft = abs(r1x - (r2x - r1w)), toRight = abs(r1x - (r2x + r2w));
  float toTop = abs(r1y - (r2y - r1h)), toBottom = abs(r1y - (r2y + r2h));
  if (min(toLeft, toRight) <= min(toTop, toBottom)) {
    r1x = toLeft <= toRight ? r2x - r1w : r2x + r2w;
    r1y = constrain(r1y, r2y - r1h, r2y + r2h);   // still sharing some of the edge, or a corner
  } else {
    r1y = toTop <= toBottom ? r2y - r1h : r2y + r2h;
    r1x = constrain(r1x, r2x - r1w, r2x + r2w);
  }
}

/** A new frame: nothing lit, nothing counted yet. */
void startFrame() {
  for (int i = 0; i < 4; i++) {
    andLit[i] = SKIPPED;
    orLit[i] = SKIPPED;
  }
  andNow = 0;
  orNow = 0;
  frames++;
}

void drawRectangles(boolean colliding) {
  noStroke();
  fill(colliding ? Palette.HIT : Palette.MISS);
  rect(r2x, r2y, r2w, r2h);
  stroke(Palette.PLAYER);
  strokeWeight(2);
  fill(Palette.PLAYER, 150);
  rect(r1x, r1y, r1w, r1h);
  if (code == null) {
    code = createFont("Monospaced", 13);
    sans = createFont("SansSerif", 13);
    title = createFont("SansSerif", 14);
  }
  fill(Palette.BACKGROUND);
  textFont(sans);
  textAlign(LEFT, TOP);
  text("r2", r2x + 6, r2y + 4);
  fill(Palette.NEUTRAL);
  text("r1", r1x + 6, r1y + 4);
  Overlay.label(g, 8, 8, "Collide.rectRect (the && form): " + (colliding ? "colliding" : "not colliding"),
      colliding ? Overlay.HIT : Overlay.MISS);
  if (touching) {
    Overlay.label(g, 8, 30, "touching (t): r1 shares an edge with r2\n&& says " + says(andSays) + ", || says " + says(orSays),
        Overlay.GUIDE);
  }
}

String says(boolean colliding) {
  return colliding ? "colliding" : "not colliding";
}

/** Both forms, each comparison lit as it was evaluated, and the counts. */
void drawForms() {
  noStroke();
  fill(#171A20);
  rect(0, panelTop - 10, width, height - panelTop + 10);
  float[] left = {r1x + r1w, r1x, r1y + r1h, r1y};
  float[] right = {r2x, r2x + r2w, r2y, r2y + r2h};
  drawForm(0, "the tutorial's && form: true means colliding", andCode, andOps, andLit, true, andSays, andNow, andTotal, left, right);
  drawForm(1, "the flipped || form: true means NOT colliding", orCode, orOps, orLit, false, orSays, orNow, orTotal, left, right);
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
    text(Overlay.number(left[i]) + " " + ops[i] + " " + Overlay.number(right[i]), x + 222, y);
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
 * Every edge as a line across the play area, with its name and value (r1's a row nearer the
 * rectangles than r2's, so equal edges do not hide each other), and why the || form is not
 * quite the opposite of the && form.
 */
void drawMaths() {
  float bottom = panelTop - 14;
  edgeLine(r1x, true, "r1Left", bottom - 22);
  edgeLine(r1x + r1w, true, "r1Right", bottom - 22);
  edgeLine(r2x, true, "r2Left", bottom);
  edgeLine(r2x + r2w, true, "r2Right", bottom);
  edgeLine(r1y, false, "r1Top", width - 235);
  edgeLine(r1y + r1h, false, "r1Bottom", width - 235);
  edgeLine(r2y, false, "r2Top", width - 110);
  edgeLine(r2y + r2h, false, "r2Bottom", width - 110);
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
