/**
 * Many objects: one box, a list of obstacles
 * Tutorial section 8: Many objects
 *
 * The moving-objects check from section 6, over a whole list: Motion.rectBlocked takes the
 * list of obstacles and answers for all of them at once (an axis is blocked if it is blocked
 * by any of them), and Hits.all says WHICH ones the next-position boxes would hit, so they
 * light up. Click to add an obstacle where the mouse is.
 *
 * With many obstacles there is one new trap: reversing can point the box straight at
 * ANOTHER obstacle that is closer than one frame's move (squeeze two obstacles together and
 * watch). So Motion.bounce, after reversing, asks once more and only moves along the axes
 * that are free; on a blocked axis the box waits a frame.
 *
 * A click on top of the box is refused: the check only looks one move ahead, so an obstacle
 * placed over the box would have it stuck inside from the start.
 *
 * Try this: click to build a narrow corridor and watch the box rattle through it; click to
 * box it in completely.
 * Keys: click adds an obstacle, d shows the maths, p pauses, n steps one frame while paused.
 */
import hitbox.*;
import hitbox.processing.*;

ArrayList<Rect> obstacles = new ArrayList<Rect>();
float x = 20;
float y = 20;
float w = 30;
float h = 30;
float vx = 3.3;
float vy = 2.7;
float newW = 60;   // the size of a clicked obstacle
float newH = 30;

int blocked = Motion.NONE;
int[] hitsX = new int[0];   // which obstacles the box moved across only would hit
int[] hitsY = new int[0];   // ... and moved down only
int[] hitsXY = new int[0];  // ... and moved diagonally, when only that hits (a corner)
int[] glow = new int[0];    // frames left to light each obstacle up
String message = "";
int messageFrames = 0;
boolean showMaths = false;
boolean paused = false;
boolean stepOnce = false;

void setup() {
  size(600, 400);
  obstacles.add(new Rect(90, 70, 80, 40));
  obstacles.add(new Rect(260, 40, 40, 110));
  obstacles.add(new Rect(400, 80, 110, 30));
  obstacles.add(new Rect(60, 200, 40, 100));
  obstacles.add(new Rect(180, 220, 120, 30));
  obstacles.add(new Rect(360, 180, 50, 50));
  obstacles.add(new Rect(470, 230, 60, 90));
  obstacles.add(new Rect(250, 310, 140, 25));
  glow = new int[obstacles.size()];
}

void draw() {
  background(Palette.BACKGROUND);

  // Section 6's check, against every obstacle at once, and which ones it would hit.
  blocked = Motion.rectBlocked(x, y, w, h, vx, vy, obstacles);
  hitsX = Hits.all(x + vx, y, w, h, obstacles);
  hitsY = Hits.all(x, y + vy, w, h, obstacles);
  hitsXY = blocked == Motion.BOTH && hitsX.length == 0 && hitsY.length == 0
      ? Hits.all(x + vx, y + vy, w, h, obstacles) : new int[0];
  lightUp(hitsX);
  lightUp(hitsY);
  lightUp(hitsXY);

  for (int i = 0; i < obstacles.size(); i++) {
    noStroke();
    fill(glow[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    Draw.shape(g, obstacles.get(i));
  }
  noStroke();
  if (showMaths) {
    fill(Palette.PLAYER, 110);
    stroke(Palette.NEUTRAL);
  } else {
    fill(Palette.PLAYER);
  }
  rect(x, y, w, h);

  if (showMaths) {
    drawMaths();
  }
  if (messageFrames > 0) {
    Overlay.label(g, 8, 8, message, message.startsWith("not") ? Overlay.HIT : Overlay.TEXT);
  } else {
    Overlay.label(g, 8, 8, obstacles.size() + " obstacles" + (paused ? "   paused: n steps, p goes on" : "   click to add one"));
  }
  Overlay.hint(g, "d: show the maths   click: add an obstacle   p: pause   n: one frame");

  if (paused && !stepOnce) {
    return;
  }
  stepOnce = false;
  messageFrames = max(0, messageFrames - 1);
  for (int i = 0; i < glow.length; i++) {
    glow[i] = max(0, glow[i] - 1);
  }
  move();
}

void move() {
  // Section 6's reverse-and-move, made safe for many obstacles: see Motion.bounce.
  Motion.Step step = Motion.bounce(x, y, w, h, vx, vy, obstacles, width, height);
  x = step.x();
  y = step.y();
  vx = step.vx();
  vy = step.vy();
}

void lightUp(int[] indices) {
  for (int i : indices) {
    glow[i] = 12;
  }
}

// Every obstacle's index, the two next-position boxes, and which obstacles each would hit.
void drawMaths() {
  for (int i = 0; i < obstacles.size(); i++) {
    Rect o = obstacles.get(i);
    Overlay.label(g, o.x() + 3, o.y() + 3, "" + i, glow[i] > 0 ? Overlay.HIT : Overlay.TEXT);
  }
  nextBox(x + vx, y, hitsX.length > 0);
  nextBox(x, y + vy, hitsY.length > 0);
  if (hitsXY.length > 0) {
    nextBox(x + vx, y + vy, true);
  }
  Draw.arrow(g, x + w / 2, y + h / 2, vx * 8, vy * 8);
  String text = "next x (x + vx, y) hits: " + list(hitsX)
      + "\nnext y (x, y + vy) hits: " + list(hitsY)
      + (hitsXY.length > 0 ? "\ncorner (x + vx, y + vy) hits: " + list(hitsXY) : "")
      + "\nMotion.rectBlocked: " + Motion.describe(blocked);
  boolean any = blocked != Motion.NONE;
  float lx = x + w + 10 > width - 190 ? x - 200 : x + w + 10;
  float ly = y + h + 10 > height - 90 ? y - 70 : y + h + 10;
  Overlay.label(g, lx, ly, text, any ? Overlay.HIT : Overlay.MISS);
}

String list(int[] indices) {
  if (indices.length == 0) {
    return "none";
  }
  String s = "";
  for (int i = 0; i < indices.length; i++) {
    s += (i > 0 ? ", " : "") + indices[i];
  }
  return s;
}

void nextBox(float bx, float by, boolean colliding) {
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  pushStyle();
  fill(colour, 60);
  strokeWeight(2);
  stroke(colour);
  rect(bx, by, w, h);
  popStyle();
}

void mousePressed() {
  Rect added = Rect.centered(mouseX, mouseY, newW, newH);
  if (added.overlaps(new Rect(x, y, w, h))) {
    message = "not added: it would be on top of the box";
  } else {
    obstacles.add(added);
    glow = append(glow, 0);
    message = "added obstacle " + (obstacles.size() - 1);
  }
  messageFrames = 90;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'p') {
    paused = !paused;
  } else if (key == 'n') {
    stepOnce = true;
  }
}
