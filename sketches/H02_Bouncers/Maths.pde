// The "show the maths" overlay (d): the counts, and bouncer 0's next-position boxes.

boolean showMaths = false;

void drawMaths() {
  Overlay.hint(g, "l: Hitbox's loop / section 8's   d: show the maths (counts, and bouncer 0's next-position boxes)");
  if (!hitboxDecides) {
    int caught = 0;
    for (Bouncer b : bouncers) {
      caught += Hits.any(new Rect(b.x, b.y, size, size), obstacles) ? 1 : 0;
    }
    Overlay.label(g, 8, height - 48, "section 8's loop (l: Hitbox's): " + caught + " bouncers inside an obstacle now",
        caught > 0 ? Overlay.HIT : Overlay.TEXT);
  }
  if (!showMaths) {
    return;
  }
  int pairs = bouncers.size() * obstacles.size();
  Overlay.label(g, 8, 8, bouncers.size() + " bouncers x " + obstacles.size() + " obstacles = " + pairs
      + " pairs a frame\nhits this frame: " + hitsThisFrame + "   hits so far: " + totalHits);

  // Bouncer 0, ringed, with the two boxes its check tests next frame and what they hit.
  Bouncer b = bouncers.get(0);
  Set<Side> next = Motion.blocked(new Rect(b.x, b.y, size, size), b.vx, b.vy, obstacles);
  int hitX = Hits.first(new Rect(b.x + b.vx, b.y, size, size), obstacles);
  int hitY = Hits.first(new Rect(b.x, b.y + b.vy, size, size), obstacles);
  pushStyle();
  noFill();
  stroke(Overlay.GUIDE);
  strokeWeight(1.5);
  ellipse(b.x + size / 2, b.y + size / 2, 34, 34);
  strokeWeight(1);
  stroke(hitX >= 0 ? Overlay.HIT : Overlay.MISS);
  rect(b.x + b.vx, b.y, size, size);
  stroke(hitY >= 0 ? Overlay.HIT : Overlay.MISS);
  rect(b.x, b.y + b.vy, size, size);
  popStyle();
  nameObstacle(hitX);
  nameObstacle(hitY);
  String text = "bouncer 0\nnext x: " + (hitX >= 0 ? "hits obstacle " + hitX : "free")
      + "\nnext y: " + (hitY >= 0 ? "hits obstacle " + hitY : "free");
  if (next.size() == 4 && hitX < 0 && hitY < 0) {
    text += "\ncorner: hits obstacle " + Hits.first(new Rect(b.x + b.vx, b.y + b.vy, size, size), obstacles);
  }
  float lx = b.x + 22 > width - 170 ? b.x - 180 : b.x + 22;
  float ly = b.y + 22 > height - 80 ? b.y - 70 : b.y + 22;
  Overlay.label(g, lx, ly, text, !next.isEmpty() ? Overlay.HIT : Overlay.MISS);
}

// Writes an obstacle's index next to it, so "hits obstacle 12" can be found.
void nameObstacle(int i) {
  if (i >= 0) {
    Rect o = obstacles.get(i);
    Overlay.label(g, o.right() + 3, o.y() - 4, "" + i, Overlay.HIT);
  }
}
