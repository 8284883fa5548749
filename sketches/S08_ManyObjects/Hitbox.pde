// Hitbox's loop (key l): ask every rectangle first, reverse once, then move only where it is
// free. Motion.blocked is section 6's next-position check, its answer the blocked axes' sides.

void hitboxStep() {
  Set<Side> blocked = blockedByAny(bouncingRectSpeedX, bouncingRectSpeedY);
  bouncingRectSpeedX = Motion.reverseX(blocked, bouncingRectSpeedX);
  bouncingRectSpeedY = Motion.reverseY(blocked, bouncingRectSpeedY);
  Set<Side> still = blockedByAny(bouncingRectSpeedX, bouncingRectSpeedY);   // squeezed: the reversed move is blocked too
  if (!still.contains(Side.LEFT)) {   // a blocked axis names both its sides
    bouncingRectX += bouncingRectSpeedX;
  }
  if (!still.contains(Side.TOP)) {
    bouncingRectY += bouncingRectSpeedY;
  }
}

// Section 6's check against every rectangle, the answers combined.
Set<Side> blockedByAny(float speedX, float speedY) {
  Set<Side> blocked = EnumSet.noneOf(Side.class);
  for (Rectangle o : rectangles) {
    Set<Side> answer = blockedBy(o, speedX, speedY);
    if (!answer.isEmpty()) {
      o.hit();
    }
    blocked.addAll(answer);
  }
  return blocked;
}

// Section 6's check against one rectangle.
Set<Side> blockedBy(Rectangle o, float speedX, float speedY) {
  return Motion.blocked(new Rect(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight),
      speedX, speedY, List.of(new Rect(o.x, o.y, o.rectWidth, o.rectHeight)));
}
