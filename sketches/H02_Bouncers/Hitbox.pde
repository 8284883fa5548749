// Hitbox's loop for one bouncer (key l): ask every obstacle, combine the answers, then reverse
// once and move where it is free (Bouncer.bounce).

void hitboxStep(Bouncer b) {
  Set<Side> blocked = EnumSet.noneOf(Side.class);
  Rect box = new Rect(b.x, b.y, size, size);
  for (int i = 0; i < obstacles.size(); i++) {
    Set<Side> answer = Motion.blocked(box, b.vx, b.vy, List.of(obstacles.get(i)));
    if (!answer.isEmpty()) {
      glow[i] = 10;
    }
    blocked.addAll(answer);
  }
  if (!blocked.isEmpty()) {
    b.changeColour();   // the homework: a hit changes its colour
    hitsThisFrame++;
  }
  b.bounce(blocked);    // reverse once, then move where it is free (Bouncer.pde)
}
