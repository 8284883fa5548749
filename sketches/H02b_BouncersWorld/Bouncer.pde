// One bouncer: its body in the world, its speed, and its colour.
class Bouncer {
  Body body;
  float vx;
  float vy;
  color colour = 0;
  ArrayList<Collision> met = new ArrayList<Collision>();   // this frame's, for the maths

  Bouncer(Body body, float vx, float vy) {
    this.body = body;
    this.vx = vx;
    this.vy = vy;
    changeColour();
  }

  // One frame: the world moves the body, bouncing off what it meets with the rest of the
  // move; the speed is turned round along each normal met, and a hit obstacle changes the
  // colour (the window's edges do not).
  void move() {
    met.clear();
    met.addAll(world.move(body, vx, vy, bounceOffEverything));
    boolean hitObstacle = false;
    for (Collision c : met) {
      if (c.reaction() == Reaction.BOUNCE) {
        Vec v = Response.bounce(vx, vy, c.nx(), c.ny(), 1);
        vx = v.x();
        vy = v.y();
      }
      int i = obstacles.indexOf(c.other());
      if (i >= 0) {
        glow[i] = 10;
        hitObstacle = true;
      }
    }
    if (hitObstacle) {
      changeColour();   // the homework: a hit changes its colour
      hitsThisFrame++;
    }
  }

  // A bright random colour, never the one it had.
  void changeColour() {
    color old = colour;
    while (colour == old) {
      colour = color(random(30, 330), 70, 100);
    }
  }
}

float randomSpeed() {
  return random(1, 2.5) * (random(1) < 0.5 ? -1 : 1);
}
