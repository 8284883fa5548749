// The "show the maths" overlay (d), the labels, and the keys.

String message = "";   // what the last click did, shown for a while
int messageFrames = 0;
boolean showMaths, paused, stepOnce;
int moves = 0;         // how many frames the box has moved

// Does the box move this frame? Not while paused, except one frame for n.
boolean goesOn() {
  if (paused && !stepOnce) {
    return false;
  }
  stepOnce = false;
  moves++;
  messageFrames = max(0, messageFrames - 1);
  return true;
}

void say(String text) {
  message = text;
  messageFrames = 90;
}

// The box: see-through with the maths on; ringed red when it is inside an obstacle, which
// only the tutorial's loop lets happen.
void drawBox() {
  int inside = insideWhich();
  if (showMaths) {
    fill(Palette.PLAYER, 110);
    stroke(Palette.NEUTRAL);
    strokeWeight(1);
  } else {
    fill(Palette.PLAYER);
    noStroke();
  }
  if (inside >= 0) {
    stroke(Palette.HIT);
    strokeWeight(3);
  }
  rect(x, y, w, h);
  noStroke();
}

// The first obstacle the box overlaps now, or -1.
int insideWhich() {
  for (int i = 0; i < obstacles.size(); i++) {
    if (obstacles.get(i).overlaps(x, y, w, h)) {
      return i;
    }
  }
  return -1;
}

void drawMathsAndLabels() {
  if (showMaths) {
    drawMaths();
  }
  int inside = insideWhich();
  String mode = tutorialLoop ? "the tutorial's loop (t: Hitbox's)" : "Hitbox's loop (t: the tutorial's)";
  if (messageFrames > 0) {
    Overlay.label(g, 24, 24, message, message.startsWith("not") ? Overlay.HIT : Overlay.TEXT);
  } else if (inside >= 0) {
    Overlay.label(g, 24, 24, mode + ":  the box is inside obstacle " + inside + "!", Overlay.HIT);
  } else {
    Overlay.label(g, 24, 24, mode + ",  " + obstacles.size() + " obstacles" + (paused ? ",  paused: n steps" : ""));
  }
  Overlay.hint(g, "t: tutorial's loop / Hitbox's   d: show the maths   click: add an obstacle   p: pause   n: one frame");
}

// This frame's checks, before the box moves: the two next-position boxes, and what each loop
// is about to do with them.
void drawMaths() {
  for (int i = 0; i < obstacles.size(); i++) {
    Obstacle o = obstacles.get(i);
    Overlay.labelCentered(g, o.x + o.w / 2, o.y + min(o.h, 40) / 2, "" + i, o.lit() ? Overlay.HIT : Overlay.TEXT);
  }
  String text = tutorialLoop ? tutorialPreview() : hitboxPreview();
  // The free one first, so a blocked one's red is on top where they overlap.
  boolean blockedX = blocksAny(x + vx, y);
  boolean blockedY = blocksAny(x, y + vy);
  if (blockedX) {
    nextBox(x, y + vy, blockedY);
    nextBox(x + vx, y, true);
  } else {
    nextBox(x + vx, y, false);
    nextBox(x, y + vy, blockedY);
  }
  stroke(Overlay.GUIDE);
  strokeWeight(2);
  Draw.arrow(g, x + w / 2, y + h / 2, vx * 8, vy * 8);
  // Below the box, on the side with more room.
  float lx = x + w / 2 < width / 2 ? x + w + 12 : x - 12 - labelWidth(text);
  Overlay.label(g, lx, y + h + 8, text, text.contains("!") ? Overlay.HIT : Overlay.TEXT);
}

// The tutorial's loop, run on copies of the speeds: the same two tests as tutorialStep, in
// the same order, so it says which obstacles will flip which speed.
String tutorialPreview() {
  float sx = vx;
  float sy = vy;
  IntList byX = new IntList();
  IntList byY = new IntList();
  for (int i = 0; i < obstacles.size(); i++) {
    Obstacle o = obstacles.get(i);
    if (x + w + sx > o.x && x + sx < o.x + o.w && y + h > o.y && y < o.y + o.h) {
      sx *= -1;
      byX.append(i);
    }
    if (x + w > o.x && x < o.x + o.w && y + h + sy > o.y && y + sy < o.y + o.h) {
      sy *= -1;
      byY.append(i);
    }
  }
  String text = "the tutorial's loop, this frame:\n" + flips("vx", byX) + "\n" + flips("vy", byY);
  int landsIn = -1;
  for (int i = 0; i < obstacles.size() && landsIn < 0; i++) {
    landsIn = obstacles.get(i).overlaps(x + sx, y + sy, w, h) ? i : -1;
  }
  return text + "\nthen x += vx, y += vy" + (landsIn >= 0 ? ": it lands inside " + landsIn + "!" : "");
}

String flips(String speed, IntList by) {
  if (by.size() == 0) {
    return speed + ": not flipped";
  }
  String text = speed + " flipped by " + by.get(0);
  for (int i = 1; i < by.size(); i++) {
    text += ", then by " + by.get(i);
  }
  return text + (by.size() % 2 == 0 ? ": back as it was, no bounce" : "");
}

// Hitbox's loop: every obstacle's answer, combined, reversed once, then asked again.
String hitboxPreview() {
  String said = "";
  int blocked = Motion.NONE;
  for (int i = 0; i < obstacles.size(); i++) {
    Obstacle o = obstacles.get(i);
    int answer = Motion.rectBlocked(x, y, w, h, vx, vy, o.x, o.y, o.w, o.h);
    if (answer != Motion.NONE) {
      said += (said.isEmpty() ? "" : ", ") + i + " says " + Side.describe(answer);
    }
    blocked |= answer;
  }
  String text = "Hitbox's loop, this frame:\nMotion.rectBlocked: " + (said.isEmpty() ? "nobody blocks" : said)
      + "\ncombined: " + Side.describe(blocked);
  if (blocked == Motion.NONE) {
    return text + ", so it moves";
  }
  float sx = Motion.reverseX(blocked, vx);
  float sy = Motion.reverseY(blocked, vy);
  int still = Motion.NONE;
  for (Obstacle o : obstacles) {
    still |= Motion.rectBlocked(x, y, w, h, sx, sy, o.x, o.y, o.w, o.h);
  }
  return text + ", reversed once\nasked again: " + Side.describe(still)
      + (Side.hasAny(still, Side.LEFT_RIGHT) ? ", waits across" : "") + (Side.hasAny(still, Side.TOP_BOTTOM) ? ", waits down" : "");
}

// How wide Overlay.label draws this text: its longest line at size 12, and 8 pixels.
float labelWidth(String text) {
  pushStyle();
  textSize(12);
  float longest = 0;
  for (String line : text.split("\n")) {
    longest = max(longest, textWidth(line));
  }
  popStyle();
  return longest + 8;
}

boolean blocksAny(float bx, float by) {
  for (Obstacle o : obstacles) {
    if (o.overlaps(bx, by, w, h)) {
      return true;
    }
  }
  return false;
}

// A next-position box: red if it would overlap an obstacle, green if not.
void nextBox(float bx, float by, boolean colliding) {
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  pushStyle();
  fill(colour, 60);
  strokeWeight(2);
  stroke(colour);
  rect(bx, by, w, h);
  popStyle();
}

void keyPressed() {
  if (key == 't') {
    tutorialLoop = !tutorialLoop;
    startAgain();
  } else if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'p') {
    paused = !paused;
  } else if (key == 'n') {
    stepOnce = true;
  }
}
