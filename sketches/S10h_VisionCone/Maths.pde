// The 'd' overlay: the cone's two edges with their angles, each of the player's three points
// with its line of sight (dashed when it is in the cone and clear, red where a wall blocks it).

void drawMaths(float[][] points, float start, float stop) {
  Overlay.guide(g, gx, gy, gx + range * cos(start), gy + range * sin(start));
  Overlay.guide(g, gx, gy, gx + range * cos(stop), gy + range * sin(stop));
  Overlay.label(g, gx + 60 * cos(start) + 6, gy + 60 * sin(start) - 6, "start " + Overlay.number(start), Overlay.GUIDE);
  Overlay.label(g, gx + 60 * cos(stop) + 6, gy + 60 * sin(stop) + 14, "stop " + Overlay.number(stop), Overlay.GUIDE);
  for (int i = 0; i < 3; i++) {
    float x = points[i][0], y = points[i][1];
    boolean inCone = Collide.arcPoint(gx, gy, range, range, start, stop, PIE, x, y);
    stroke(pointSeen[i] ? Overlay.HIT : inCone ? Overlay.MISS : Overlay.GUIDE);
    strokeWeight(1);
    if (inCone) {
      line(gx, gy, x, y);
    }
    noStroke();
    fill(pointSeen[i] ? Overlay.HIT : Overlay.TEXT);
    circle(x, y, 6);
  }
  Overlay.labelCentered(g, width / 2, 28, "Collide.arcPoint(guard, range, start, stop, PIE, point)\n"
      + "&& no wall crosses the line of sight  ->  " + (seen ? "seen" : "hidden"), seen ? Overlay.HIT : Overlay.MISS);
}
