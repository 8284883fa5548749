// A short trail behind the ball, and the edge it bounced off lit for a moment.

float[] trailX = new float[14];   // past positions, oldest first
float[] trailY = new float[14];
Set<Side> lastCrossed = java.util.EnumSet.noneOf(Side.class);  // the window edges the ball crossed last time it bounced
int bounceFrame = -1000;          // when that was

void startTrail() {
  for (int i = 0; i < trailX.length; i++) {
    trailX[i] = x;
    trailY[i] = y;
  }
}

/** Remembers this frame's position, and the edges it crossed if it bounced. */
void addToTrail(Set<Side> crossed) {
  if (!crossed.isEmpty()) {
    lastCrossed = crossed;
    bounceFrame = frameCount;
  }
  for (int i = 0; i < trailX.length - 1; i++) {
    trailX[i] = trailX[i + 1];
    trailY[i] = trailY[i + 1];
  }
  trailX[trailX.length - 1] = x;
  trailY[trailY.length - 1] = y;
}

void drawTrail(color colour) {
  noStroke();
  for (int i = 0; i < trailX.length; i++) {
    fill(colour, 10 + i * 6);
    circle(trailX[i], trailY[i], 2 * r * (0.4 + 0.04 * i));
  }
}

/** The edge the ball just bounced off lights up for a moment. */
void drawBounce() {
  int age = frameCount - bounceFrame;
  if (age > 25) {
    return;
  }
  stroke(Palette.ACCENT, 255 - age * 10);
  strokeWeight(5);
  if (lastCrossed.contains(Side.LEFT)) line(2, 0, 2, height);
  if (lastCrossed.contains(Side.RIGHT)) line(width - 3, 0, width - 3, height);
  if (lastCrossed.contains(Side.TOP)) line(0, 2, width, 2);
  if (lastCrossed.contains(Side.BOTTOM)) line(0, height - 3, width, height - 3);
  if (showMaths) {
    // Which edges the bounce crossed, as the library names them, written beside the ball on
    // the window's side of it.
    float inX = lastCrossed.contains(Side.LEFT) ? 1 : (lastCrossed.contains(Side.RIGHT) ? -1 : 0);
    float inY = lastCrossed.contains(Side.TOP) ? 1 : (lastCrossed.contains(Side.BOTTOM) ? -1 : 0);
    Overlay.labelBeside(g, x + inX * (r + 6), y + inY * (r + 6), inX, inY, "crossed: " + lastCrossed, Palette.ACCENT);
  }
}
