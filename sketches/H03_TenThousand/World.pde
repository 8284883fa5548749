// The obstacles, placed once from the random seed.

// Obstacles apart from each other and from the window's edges by more than a bouncer, so a
// bouncer pushed out of one never lands in another, nor outside the window.
void placeObstacles() {
  int k = 0;
  while (k < obstacleCount) {
    float w = random(30, 90);
    float h = random(20, 70);
    Rect candidate = new Rect(random(10, width - w - 10), random(10, height - h - 10), w, h);
    Rect around = new Rect(candidate.x() - 8, candidate.y() - 8, w + 16, h + 16);
    boolean free = true;
    for (int j = 0; j < k; j++) {
      free = free && !around.overlaps(obstacles[j]);
    }
    if (free) {
      obstacles[k++] = candidate;
    }
  }
}

boolean inAnObstacle(float px, float py) {
  for (Rect o : obstacles) {
    if (Collide.rectRect(px, py, size, size, o.x(), o.y(), o.w(), o.h())) {
      return true;
    }
  }
  return false;
}
