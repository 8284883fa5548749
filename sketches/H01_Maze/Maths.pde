// The guards' view: for each guard, how far it sees in every direction (the farthest point
// along each ray that grid.lineOfSight still reaches, up to guardView), and the line to the
// player with lineOfSight's answer.
void drawMaths() {
  for (Guard guard : guards) {
    drawView(guard);
  }
  for (Guard guard : guards) {
    float d = dist(guard.x, guard.y, playerX(), playerY());
    if (d < guardView * 1.5) {
      boolean clear = grid.lineOfSight(guard.x, guard.y, playerX(), playerY());
      pushStyle();
      stroke(clear ? Overlay.MISS : Overlay.HIT);
      strokeWeight(2);
      line(guard.x, guard.y, playerX(), playerY());
      popStyle();
      String text = "lineOfSight = " + clear + "\ndistance " + Overlay.number(d) + (d < guardView ? " < " : " >= ")
          + Overlay.number(guardView) + "\n" + (guard.seeing ? "sees the player" : "does not see");
      Overlay.label(g, playerX() + 10, playerY() + 14, text, guard.seeing ? Overlay.HIT : Overlay.MISS);
    }
  }
}

void drawView(Guard guard) {
  int rays = 90;
  pushStyle();
  fill(255, 255, 255, 70);
  stroke(255, 200);
  strokeWeight(1);
  beginShape();
  for (int i = 0; i < rays; i++) {
    float a = TWO_PI * i / rays;
    float reach = farthestSeen(guard.x, guard.y, cos(a), sin(a));
    vertex(guard.x + cos(a) * reach, guard.y + sin(a) * reach);
  }
  endShape(CLOSE);
  popStyle();
}

// Sight along a ray is clear up to some distance and blocked beyond it, so halving finds it.
float farthestSeen(float x, float y, float dx, float dy) {
  if (grid.lineOfSight(x, y, x + dx * guardView, y + dy * guardView)) {
    return guardView;
  }
  float lo = 0;
  float hi = guardView;
  for (int i = 0; i < 12; i++) {
    float mid = (lo + hi) / 2;
    if (grid.lineOfSight(x, y, x + dx * mid, y + dy * mid)) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo;
}
