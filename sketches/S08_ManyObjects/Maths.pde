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
  rect(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight);
  noStroke();
}

// The first obstacle the box overlaps now, or -1.
int insideWhich() {
  for (int i = 0; i < rectangles.size(); i++) {
    if (rectangles.get(i).overlaps(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight)) {
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
  String mode = hitboxDecides ? "Hitbox's loop (l: the tutorial's)" : "the tutorial's loop (l: Hitbox's)";
  if (messageFrames > 0) {
    Overlay.label(g, 24, 24, message, message.startsWith("not") ? Overlay.HIT : Overlay.TEXT);
  } else if (inside >= 0) {
    Overlay.label(g, 24, 24, mode + ":  the box is inside rectangle " + inside + "!", Overlay.HIT);
  } else {
    Overlay.label(g, 24, 24, mode + ",  " + rectangles.size() + " rectangles" + (paused ? ",  paused: n steps" : ""));
  }
  Overlay.hint(g, "l: Hitbox's loop / the tutorial's   s: into the slot   d: show the maths   click: add a rectangle   p: pause   n: one frame");
}

// The next frame's checks, from where the box is now: the two next-position boxes, and what
// the loop that moves the box will do with them.
void drawMaths() {
  for (int i = 0; i < rectangles.size(); i++) {
    Rectangle o = rectangles.get(i);
    Overlay.labelCentered(g, o.x + o.rectWidth / 2, o.y + min(o.rectHeight, 40) / 2, "" + i, o.lit() ? Overlay.HIT : Overlay.TEXT);
  }
  String text = hitboxDecides ? hitboxPreview() : tutorialPreview();
  // The free one first, so a blocked one's red is on top where they overlap.
  boolean blockedX = blocksAny(bouncingRectX + bouncingRectSpeedX, bouncingRectY);
  boolean blockedY = blocksAny(bouncingRectX, bouncingRectY + bouncingRectSpeedY);
  if (blockedX) {
    nextBox(bouncingRectX, bouncingRectY + bouncingRectSpeedY, blockedY);
    nextBox(bouncingRectX + bouncingRectSpeedX, bouncingRectY, true);
  } else {
    nextBox(bouncingRectX + bouncingRectSpeedX, bouncingRectY, false);
    nextBox(bouncingRectX, bouncingRectY + bouncingRectSpeedY, blockedY);
  }
  stroke(Overlay.GUIDE);
  strokeWeight(2);
  Draw.arrow(g, bouncingRectX + bouncingRectWidth / 2, bouncingRectY + bouncingRectHeight / 2,
      bouncingRectSpeedX * 8, bouncingRectSpeedY * 8);
  // Below the box, on the side with more room.
  float lx = bouncingRectX + bouncingRectWidth / 2 < width / 2 ? bouncingRectX + bouncingRectWidth + 12
      : bouncingRectX - 12 - labelWidth(text);
  Overlay.label(g, lx, bouncingRectY + bouncingRectHeight + 8, text, text.contains("!") ? Overlay.HIT : Overlay.TEXT);
}

// The tutorial's loop, run ahead on copies of the speeds: the same two tests as the loop in
// draw(), in the same order, so it says which rectangles will flip which speed.
String tutorialPreview() {
  float sx = bouncingRectSpeedX;
  float sy = bouncingRectSpeedY;
  IntList byX = new IntList();
  IntList byY = new IntList();
  for (int i = 0; i < rectangles.size(); i++) {
    Rectangle o = rectangles.get(i);
    if (bouncingRectX + bouncingRectWidth + sx > o.x && bouncingRectX + sx < o.x + o.rectWidth
        && bouncingRectY + bouncingRectHeight > o.y && bouncingRectY < o.y + o.rectHeight) {
      sx *= -1;
      byX.append(i);
    }
    if (bouncingRectX + bouncingRectWidth > o.x && bouncingRectX < o.x + o.rectWidth
        && bouncingRectY + bouncingRectHeight + sy > o.y && bouncingRectY + sy < o.y + o.rectHeight) {
      sy *= -1;
      byY.append(i);
    }
  }
  String text = "the tutorial's loop, next frame:\n" + flips("vx", byX) + "\n" + flips("vy", byY);
  int landsIn = -1;
  for (int i = 0; i < rectangles.size() && landsIn < 0; i++) {
    landsIn = rectangles.get(i).overlaps(bouncingRectX + sx, bouncingRectY + sy, bouncingRectWidth, bouncingRectHeight) ? i : -1;
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
  Set<Side> blocked = EnumSet.noneOf(Side.class);
  for (int i = 0; i < rectangles.size(); i++) {
    Set<Side> answer = blockedBy(rectangles.get(i), bouncingRectSpeedX, bouncingRectSpeedY);
    if (!answer.isEmpty()) {
      said += (said.isEmpty() ? "" : ", ") + i + " says " + answer;
    }
    blocked.addAll(answer);
  }
  String text = "Hitbox's loop, next frame:\nMotion.blocked: " + (said.isEmpty() ? "nobody blocks" : said)
      + "\ncombined: " + blocked;
  if (blocked.isEmpty()) {
    return text + ", so it moves";
  }
  Set<Side> still = EnumSet.noneOf(Side.class);
  for (Rectangle o : rectangles) {
    still.addAll(blockedBy(o, Motion.reverseX(blocked, bouncingRectSpeedX), Motion.reverseY(blocked, bouncingRectSpeedY)));
  }
  return text + ", reversed once\nasked again: " + still
      + (still.contains(Side.LEFT) ? ", waits across" : "") + (still.contains(Side.TOP) ? ", waits down" : "");
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
  for (Rectangle o : rectangles) {
    if (o.overlaps(bx, by, bouncingRectWidth, bouncingRectHeight)) {
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
  rect(bx, by, bouncingRectWidth, bouncingRectHeight);
  popStyle();
}

// s: the box in the slot between pillars 5 and 6, 1 pixel from each, going left and down.
void intoTheSlot() {
  bouncingRectX = 271;
  bouncingRectY = 70;
  bouncingRectSpeedX = -3.3;
  bouncingRectSpeedY = 2.7;
}

void keyPressed() {
  if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 's') {
    intoTheSlot();
  } else if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'p') {
    paused = !paused;
  } else if (key == 'n') {
    stepOnce = true;
  }
}
