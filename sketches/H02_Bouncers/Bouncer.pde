// One bouncer: where it is, its speed, and its colour.
class Bouncer {
  float x;
  float y;
  float vx;
  float vy;
  color colour = 0;

  Bouncer(float x, float y, float vx, float vy) {
    this.x = x;
    this.y = y;
    this.vx = vx;
    this.vy = vy;
    changeColour();
  }

  // A bright random colour, never the one it had, never red ("hit" here).
  void changeColour() {
    color old = colour;
    while (colour == old) {
      colour = color(random(30, 330), 70, 100);
    }
  }

  // Reverse each blocked speed once, bounce off the window's edges, then ask the obstacles
  // again: squeezed between two, the reversed move is blocked too, so wait on that axis.
  // (Motion.bounce does these steps in one call.)
  void bounce(Set<Side> blocked) {
    vx = Motion.reverseX(blocked, vx);
    vy = Motion.reverseY(blocked, vy);
    Set<Side> crossed = Edges.crossed(new Rect(x + vx, y + vy, size, size), width, height);
    vx = Edges.bounceX(crossed, vx);
    vy = Edges.bounceY(crossed, vy);
    Set<Side> still = Motion.blocked(new Rect(x, y, size, size), vx, vy, obstacles);
    if (!still.contains(Side.LEFT)) {   // a blocked axis names both its sides
      x += vx;
    }
    if (!still.contains(Side.TOP)) {
      y += vy;
    }
  }
}

float randomSpeed() {
  return random(1, 2.5) * (random(1) < 0.5 ? -1 : 1);
}
