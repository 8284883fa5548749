// The drawing and the "show the maths" overlay (d): the stages along the top, the circles
// and boxes the first two stages compare, the first shared pixel.

// One colour per stage that can decide.
color CIRCLES_COLOUR = #B48EF0;      // apart by the circles: the cheapest answer
color BOXES_COLOUR = Palette.ACCENT; // apart by the boxes
color PIXELS_COLOUR = Palette.MISS;  // the pixel test ran: no shared pixel
color HIT_COLOUR = Palette.HIT;      // the pixel test ran: colliding

boolean showMaths;
PixelMask.Pixel firstPixel;           // the first pixel the star and the ring share, in the star's pixels
int sharedPixels;                     // how many pixels they share

void drawPair() {
  firstPixel = result.overlaps() ? starMask.firstOverlap(ringMask, ringX - starX, ringY - starY) : null;
  sharedPixels = result.overlaps() ? starMask.overlapCount(ringMask, ringX - starX, ringY - starY) : 0;

  sprite(star, starX, starY, stageColour(result), 255);
  sprite(ring, ringX, ringY, Palette.PLAYER, 190);

  if (showMaths) {
    drawPairMaths();
  }
  if (firstPixel != null) {
    markPixel(starX + firstPixel.x(), starY + firstPixel.y());
  }
  drawStages(result, null);
  Overlay.label(g, 8, height - 57, "checks so far: " + counter.total() + "   circles "
      + counter.decidedBy(Hybrid.Stage.CIRCLES) + ", boxes " + counter.decidedBy(Hybrid.Stage.BOXES)
      + ", pixels " + counter.decidedBy(Hybrid.Stage.PRECISE) + " (" + counter.overlapping() + " colliding)\n" + thisFrame());
}

// This frame's runs of each stage, and stage 3's time.
String thisFrame() {
  return "this frame the stages ran " + ran[0] + ", " + ran[1] + " and " + ran[2] + " times; stage 3 ("
      + (hitboxDecides ? "PixelMask" : "pixel loop") + ") took " + nf(pixelNanos / 1e6, 0, 3) + " ms";
}

void drawCrowd() {
  for (int i = 0; i < crowdX.length; i++) {
    sprite(smallStar, crowdX[i], crowdY[i], stageColour(crowdResults[i]), 255);
    if (showMaths && crowdResults[i].decidedBy() != Hybrid.Stage.CIRCLES) {
      // The stars the circle stage could not dismiss: their boxes.
      Rect b = smallMask.bounds();
      noFill();
      stroke(BOXES_COLOUR, 200);
      strokeWeight(1);
      rect(crowdX[i] + b.x(), crowdY[i] + b.y(), b.w(), b.h());
    }
  }
  sprite(ring, ringX, ringY, Palette.PLAYER, 190);
  if (showMaths) {
    Rect b = ringMask.bounds();
    noFill();
    stroke(CIRCLES_COLOUR);
    strokeWeight(1.5);
    circle(ringX + b.x() + b.w() / 2, ringY + b.y() + b.h() / 2, dist(0, 0, b.w(), b.h()));
  }
  drawStages(null, crowdCounter);
  int precise = crowdCounter.decidedBy(Hybrid.Stage.PRECISE);
  Overlay.label(g, 8, height - 72, "this frame: " + crowdCounter.total() + " checks   circles "
      + crowdCounter.decidedBy(Hybrid.Stage.CIRCLES) + ", boxes " + crowdCounter.decidedBy(Hybrid.Stage.BOXES)
      + ", pixels " + precise + " (" + crowdCounter.overlapping() + " colliding)\n"
      + "the pixel test ran " + precise + " times instead of " + crowdCounter.total() + "\n" + thisFrame());
}

// The colour of the stage that decided.
color stageColour(Hybrid.Result r) {
  if (r.overlaps()) {
    return HIT_COLOUR;
  }
  if (r.decidedBy() == Hybrid.Stage.CIRCLES) {
    return CIRCLES_COLOUR;
  }
  return r.decidedBy() == Hybrid.Stage.BOXES ? BOXES_COLOUR : PIXELS_COLOUR;
}

// The three stages along the top. For one check, the stage that decided is filled in its
// colour; for the crowd, how many checks each stage decided.
void drawStages(Hybrid.Result r, Hybrid.Counter crowd) {
  String[] names = {"1  circles apart?", "2  boxes apart?", "3  pixels shared?"};
  int[] colours = {CIRCLES_COLOUR, BOXES_COLOUR, r != null && r.overlaps() ? HIT_COLOUR : PIXELS_COLOUR};
  textSize(13);
  textAlign(CENTER, CENTER);
  for (int i = 0; i < 3; i++) {
    float x = 12 + i * 196;
    float w = 184;
    boolean decided = r != null && r.decidedBy().ordinal() == i;
    boolean passed = r != null && r.decidedBy().ordinal() > i;
    stroke(colours[i]);
    strokeWeight(decided ? 3 : 1.5);
    fill(decided ? colours[i] : Palette.BACKGROUND);
    rect(x, 10, w, 26, 6);
    fill(decided ? Palette.BACKGROUND : colours[i]);
    text(names[i], x + w / 2, 22);
    if (r != null) {
      String answer;
      if (i == 2) {
        answer = decided ? (r.overlaps() ? "yes: colliding" : "no: apart") : "not needed";
      } else {
        answer = decided ? "yes: apart, done" : "no: go on";
      }
      fill(decided || passed ? Palette.NEUTRAL : Palette.LINE);
      textSize(12);
      text(answer, x + w / 2, 46);
      textSize(13);
    } else if (crowd != null) {
      Hybrid.Stage stage = Hybrid.Stage.values()[i];
      int n = crowd.decidedBy(stage);
      String answer = i < 2 ? n + " apart, done" : n + " ran: " + crowd.overlapping() + " colliding";
      fill(Palette.NEUTRAL);
      textSize(12);
      text(answer, x + w / 2, 46);
      textSize(13);
    }
  }
}

// The circles and boxes the first two stages compare, and the pixel count.
void drawPairMaths() {
  Rect a = starMask.bounds();
  Rect b = ringMask.bounds();
  // Each sprite's box (its solid pixels' bounds) where it is placed.
  float ax = starX + a.x(), ay = starY + a.y();
  float bx = ringX + b.x(), by = ringY + b.y();
  // Stage 1: the circle around each box: centre the box's centre, radius half its diagonal.
  float acx = ax + a.w() / 2, acy = ay + a.h() / 2, ar = dist(0, 0, a.w(), a.h()) / 2;
  float bcx = bx + b.w() / 2, bcy = by + b.h() / 2, br = dist(0, 0, b.w(), b.h()) / 2;
  noFill();
  stroke(CIRCLES_COLOUR);
  strokeWeight(1.5);
  circle(acx, acy, 2 * ar);
  circle(bcx, bcy, 2 * br);
  float d = dist(acx, acy, bcx, bcy);
  Overlay.guide(g, acx, acy, bcx, bcy);
  noStroke();
  fill(Overlay.GUIDE);
  circle(acx, acy, 6);
  circle(bcx, bcy, 6);
  Overlay.labelCentered(g, acx, acy + 16, "r1 = " + Overlay.number(ar), CIRCLES_COLOUR);
  Overlay.labelCentered(g, bcx, bcy + 16, "r2 = " + Overlay.number(br), CIRCLES_COLOUR);
  boolean circlesMeet = result.decidedBy() != Hybrid.Stage.CIRCLES;
  String lines = "1 circles meet: dist < r1 + r2:  " + Overlay.comparison(d, "<", ar + br, circlesMeet)
      + (circlesMeet ? "" : "  -> apart, done");

  // Stage 2: the boxes, only if the circles meet.
  if (circlesMeet) {
    noFill();
    stroke(BOXES_COLOUR);
    strokeWeight(1.5);
    rect(ax, ay, a.w(), a.h());
    rect(bx, by, b.w(), b.h());
    boolean boxesMeet = result.decidedBy() == Hybrid.Stage.PRECISE;
    // The four edge comparisons of rect/rect, on the boxes' pixel edges.
    lines += "\n2 boxes overlap: " + (int) (bx + b.w()) + " > " + (int) ax + " && " + (int) bx + " < " + (int) (ax + a.w())
        + " && " + (int) (by + b.h()) + " > " + (int) ay + " && " + (int) by + " < " + (int) (ay + a.h()) + ": " + boxesMeet
        + (boxesMeet ? "" : "  -> apart, done");
    if (boxesMeet) {
      lines += "\n3 pixels solid in both: " + sharedPixels + (result.overlaps() ? "  -> colliding" : "  -> apart");
    }
  }
  Overlay.label(g, 8, height - 77 - 15 * (lines.split("\n").length - 1), lines, Overlay.TEXT);
}

// The first pixel both sprites share (reading order): a cross on it and its coordinates.
void markPixel(int px, int py) {
  noFill();
  stroke(Palette.ACCENT);
  strokeWeight(2);
  rect(px - 3, py - 3, 7, 7);
  line(px - 12, py + 0.5, px - 5, py + 0.5);
  line(px + 6, py + 0.5, px + 13, py + 0.5);
  line(px + 0.5, py - 12, px + 0.5, py - 5);
  line(px + 0.5, py + 6, px + 0.5, py + 13);
  Overlay.labelBeside(g, px - 14, py, -1, 0, "first shared pixel (" + px + ", " + py + ")", Palette.ACCENT);
}
