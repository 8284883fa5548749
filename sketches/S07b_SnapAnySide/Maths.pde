// The side the player rests against, and the "show the maths" overlay (key d).

/**
 * Which side of the center rectangle the player touches, from where the two are: its right
 * edge on the left side, its bottom on the top, and so on, sharing some of that side.
 */
String touchedSide() {
  boolean acrossOverlap = playerX + playerWidth > centerRectX && playerX < centerRectX + centerRectWidth;
  boolean downOverlap = playerY + playerHeight > centerRectY && playerY < centerRectY + centerRectHeight;
  if (downOverlap && playerX + playerWidth == centerRectX) return "left";
  if (downOverlap && playerX == centerRectX + centerRectWidth) return "right";
  if (acrossOverlap && playerY + playerHeight == centerRectY) return "top";
  if (acrossOverlap && playerY == centerRectY + centerRectHeight) return "bottom";
  return "";
}

/** The side it rests against, thick and yellow. */
void drawTouchedSide() {
  String side = touchedSide();
  float right = centerRectX + centerRectWidth;
  float bottom = centerRectY + centerRectHeight;
  stroke(Palette.ACCENT);
  strokeWeight(6);
  if (side.equals("left")) line(centerRectX, centerRectY, centerRectX, bottom);
  if (side.equals("right")) line(right, centerRectY, right, bottom);
  if (side.equals("top")) line(centerRectX, centerRectY, right, centerRectY);
  if (side.equals("bottom")) line(centerRectX, bottom, right, bottom);
}

/**
 * Where the keys held would move it next frame, across and down, each box red if it would
 * collide (and the snap that would follow), green if free; the side it rests against.
 */
void drawMaths(float playerSpeedX, float playerSpeedY) {
  float nextX = constrain(playerX + playerSpeedX, 0, width - playerWidth);
  float nextY = constrain(playerY + playerSpeedY, 0, height - playerHeight);
  boolean hitX = Collide.rectRect(nextX, playerY, playerWidth, playerHeight, centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  boolean hitY = Collide.rectRect(playerX, nextY, playerWidth, playerHeight, centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  String lines = "playerX = " + Overlay.number(playerX) + "   playerY = " + Overlay.number(playerY)
      + "   speed (" + Overlay.number(playerSpeedX) + ", " + Overlay.number(playerSpeedY) + ")";
  if (playerSpeedX != 0) {
    nextBox(nextX, playerY, hitX);
    lines += "\nacross to " + Overlay.number(nextX) + ": " + (hitX ? "colliding, snap to the "
        + (playerSpeedX > 0 ? "left side: playerX = centerRectX - playerWidth" : "right side: playerX = centerRectX + centerRectWidth") : "free");
  }
  if (playerSpeedY != 0) {
    nextBox(playerX, nextY, hitY);
    lines += "\ndown to " + Overlay.number(nextY) + ": " + (hitY ? "colliding, snap to the "
        + (playerSpeedY > 0 ? "top: playerY = centerRectY - playerHeight" : "bottom: playerY = centerRectY + centerRectHeight") : "free");
  }
  String side = touchedSide();
  lines += "\nresting against: " + (side.isEmpty() ? "no side" : "the " + side + " side");
  Overlay.label(g, 8, 32, lines, hitX || hitY ? Overlay.HIT : Overlay.TEXT);
}

void nextBox(float x, float y, boolean colliding) {
  noFill();
  stroke(colliding ? Overlay.HIT : Overlay.MISS);
  strokeWeight(1.5);
  rect(x, y, playerWidth, playerHeight);
}
