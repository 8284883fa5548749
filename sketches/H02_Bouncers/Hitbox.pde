// Hitbox's loop for one bouncer (key l): ask every obstacle, combine the answers, then reverse
// once and move where it is free (Bouncer.bounce).

void hitboxStep(Bouncer b) {
  int blocked = Motion.NONE;
  for (int i = 0; i < obstacles.size(); i++) {
    Rect o = obstacles.get(i);
    int answer = Motion.rectBlocked(b.x, b.y, size, size, b.vx, b.vy, o.x(), o.y(), o.w(), o.h());
    if (answer != Motion.NONE) {
      glow[i] = 10;
    }
    blocked |= answer;
  }
  if (blocked != Motion.NONE) {
    b.changeColour();   // the homework: a hit changes its colour
    hitsThisFrame++;
  }
  b.bounce(blocked);    // reverse once, then move where it is free (Bouncer.pde)
}
