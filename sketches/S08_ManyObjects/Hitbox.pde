// Hitbox's loop (key l): ask every rectangle first, reverse once, then move only where it is
// free. Motion.rectBlocked is section 6's next-position check, its answer a Side mask.

void hitboxStep() {
  int blocked = blockedByAny(bouncingRectSpeedX, bouncingRectSpeedY);
  bouncingRectSpeedX = Motion.reverseX(blocked, bouncingRectSpeedX);
  bouncingRectSpeedY = Motion.reverseY(blocked, bouncingRectSpeedY);
  int still = blockedByAny(bouncingRectSpeedX, bouncingRectSpeedY);   // squeezed: the reversed move is blocked too
  if (!Side.hasAny(still, Side.LEFT_RIGHT)) {
    bouncingRectX += bouncingRectSpeedX;
  }
  if (!Side.hasAny(still, Side.TOP_BOTTOM)) {
    bouncingRectY += bouncingRectSpeedY;
  }
}

// Section 6's check against every rectangle, the answers combined with |.
int blockedByAny(float speedX, float speedY) {
  int blocked = Motion.NONE;
  for (Rectangle o : rectangles) {
    int answer = Motion.rectBlocked(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight,
        speedX, speedY, o.x, o.y, o.rectWidth, o.rectHeight);
    if (answer != Motion.NONE) {
      o.hit();
    }
    blocked |= answer;
  }
  return blocked;
}
