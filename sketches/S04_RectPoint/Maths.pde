// The "show the maths" overlay: each comparison at its edge, in the order Java reaches them.

/** One answer, written in its colour: "Collide.rectPoint: inside". */
void answer(float x, float y, String who, boolean inside) {
  Overlay.label(g, x, y, who + ": " + (inside ? "inside" : "not inside"), inside ? Overlay.HIT : Overlay.MISS);
}

// The colour of a comparison Java never reaches: && (or the outer if) stopped before it.
color NOT_REACHED = Palette.OBSTACLE;

/**
 * Each of the four comparisons written at its edge: red if it holds, green if it does not,
 * grey if it is never reached. Both forms reach them in the same order and stop at the
 * first false one, so only the code written at the top changes with n.
 */
void drawMaths(boolean hovered) {
  float px = mouseX;
  float py = mouseY;
  boolean left = px > rectX;
  boolean right = px < rectX + rectWidth;
  boolean top = py > rectY;
  boolean bottom = py < rectY + rectHeight;
  // How far Java gets: each comparison is reached only if all before it held.
  boolean[] reached = {true, left, left && right, left && right && top};
  boolean[] holds = {left, right, top, bottom};

  // Each edge, extended across the window as a faint line: the comparison is about the whole
  // line, the four together cut out the rectangle.
  edge(rectX, rectY, rectX, rectY + rectHeight, true, colour(holds[0], reached[0]));
  edge(rectX + rectWidth, rectY, rectX + rectWidth, rectY + rectHeight, true, colour(holds[1], reached[1]));
  edge(rectX, rectY, rectX + rectWidth, rectY, false, colour(holds[2], reached[2]));
  edge(rectX, rectY + rectHeight, rectX + rectWidth, rectY + rectHeight, false, colour(holds[3], reached[3]));

  // Where the mouse is: across, between the left and right edge lines, and down, between
  // the top and bottom edge lines.
  Overlay.guide(g, min(px, rectX), py, max(px, rectX + rectWidth), py);
  Overlay.guide(g, px, min(py, rectY), px, max(py, rectY + rectHeight));

  Overlay.labelBeside(g, rectX - 8, rectY + rectHeight / 2, -1, 0,
      comparison("mouseX > rectX", px, ">", rectX, holds[0], reached[0]), colour(holds[0], reached[0]));
  Overlay.labelBeside(g, rectX + rectWidth + 8, rectY + rectHeight / 2, 1, 0,
      comparison("mouseX < rectX + rectWidth", px, "<", rectX + rectWidth, holds[1], reached[1]), colour(holds[1], reached[1]));
  Overlay.labelBeside(g, rectX + rectWidth / 2, rectY - 8, 0, -1,
      comparison("mouseY > rectY", py, ">", rectY, holds[2], reached[2]), colour(holds[2], reached[2]));
  Overlay.labelBeside(g, rectX + rectWidth / 2, rectY + rectHeight + 8, 0, 1,
      comparison("mouseY < rectY + rectHeight", py, "<", rectY + rectHeight, holds[3], reached[3]), colour(holds[3], reached[3]));

  // The code, written out as this form writes it, with its answer.
  String code;
  if (nestedIf) {
    code = "if (mouseX > rectX && mouseX < rectX + rectWidth) {       " + (left && right) + "\n"
        + "  if (mouseY > rectY && mouseY < rectY + rectHeight) {   "
        + (left && right ? str(top && bottom) : "not reached") + "\n";
  } else {
    code = "if (mouseX > rectX && mouseX < rectX + rectWidth &&\n"
        + "    mouseY > rectY && mouseY < rectY + rectHeight) {\n";
  }
  code += hovered ? "inside: the mouse is over the button" : "not inside";
  Overlay.label(g, 8, 8, code, hovered ? Overlay.HIT : Overlay.MISS);
}

/** A comparison's text: what it compares and, if Java reaches it, with the numbers. */
String comparison(String test, float a, String op, float b, boolean holds, boolean reached) {
  return test + "\n" + (reached ? Overlay.comparison(a, op, b, holds) : "not reached");
}

/** An edge drawn thick in its comparison's colour, and extended across the window, thin. */
void edge(float x1, float y1, float x2, float y2, boolean vertical, color c) {
  stroke(c, 90);
  strokeWeight(1);
  if (vertical) {
    line(x1, 0, x2, height);
  } else {
    line(0, y1, width, y2);
  }
  stroke(c);
  strokeWeight(4);
  line(x1, y1, x2, y2);
}

/** A comparison that holds pushes towards "inside": the colliding colour; one never reached is grey. */
color colour(boolean holds, boolean reached) {
  return !reached ? NOT_REACHED : holds ? Overlay.HIT : Overlay.MISS;
}
