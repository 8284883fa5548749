/**
 * Turning rocks, a ship, and a sentry's line of sight
 * Beyond the tutorial: the world, turning bodies and sight
 *
 * Asteroids-like: rocks that drift and turn, and a ship that turns and thrusts. A sketch
 * draws a turning thing with pushMatrix(); translate(x, y); rotate(angle); and its shape
 * around (0, 0), and world.add(shape, x, y, angle) makes the body that stands exactly there,
 * so the collision tests test what you see: body.turnBy and body.moveBy turn and move it,
 * body.x(), body.y() and body.angle() are what translate and rotate take, and body.shape() is
 * the turned outline on the screen. The ship moves with world.move and bounces off the
 * rocks; the rocks ignore each other (a category and a mask); world.step() reports each
 * time the ship comes into contact with a rock.
 *
 * The sentry in the corner looks at the ship: world.raycastFirst casts a ray from it
 * towards the ship and answers the nearest body in the way. If that is the ship, it is seen.
 *
 * With no key pressed, the ship flies a demo circle; the first arrow key hands it to you.
 *
 * Try this: hide the ship behind a rock from the sentry; make the rocks turn ten times faster
 * and watch their boxes with d; answer Reaction.SLIDE for the rocks and the ship slides along
 * them instead of bouncing off.
 * Keys: LEFT and RIGHT turn, UP thrusts, d shows the maths (every body's box, which grows
 * and shrinks as it turns, the grid's cells, the ship's contacts with their normals, and the
 * ray's answer).
 */
import hitbox.*;
import hitbox.processing.*;

int SHIP = 1, ROCK = 2;

World world = new World();
Body ship;
float vx = 0, vy = 0;
ArrayList<Body> rocks = new ArrayList<Body>();
ArrayList<PVector> drift = new ArrayList<PVector>();   // each rock's move a frame
FloatList spin = new FloatList();                      // and its turn a frame
ArrayList<Collision> met = new ArrayList<Collision>(); // the ship's collisions this frame
int hits = 0;            // times the ship came into contact with a rock
int flash = 0;           // frames left to show the ship red

float sentryX = 40, sentryY = 360;
BodyHit sight;           // what the sentry's ray met first (null: nothing in the way, or no ray)
boolean seen = false;

boolean left, right, thrust;
boolean demo = true;

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  randomSeed(7);
  // The ship, nose along +x in its own frame, placed and turned to point up.
  Polygon shipShape = Polygon.of(16, 0, -10, -10, -5, 0, -10, 10);
  ship = world.add(shipShape, 300, 200, -HALF_PI).layers(SHIP, ROCK);
  float[][] at = {{110, 90}, {470, 100}, {500, 300}, {270, 310}, {150, 240}, {340, 110}, {560, 190}};
  for (float[] p : at) {
    Body rock = world.add(rockShape(random(30, 46)), p[0], p[1], random(TWO_PI)).layers(ROCK, SHIP);
    rocks.add(rock);
    drift.add(PVector.fromAngle(random(TWO_PI)).mult(random(0.2, 0.7)));
    spin.append(random(-0.03, 0.03));
  }
}

// A rock in its own frame: a ring of 9 corners at random distances around (0, 0).
Polygon rockShape(float r) {
  float[] xy = new float[18];
  for (int i = 0; i < 9; i++) {
    float a = TWO_PI * i / 9;
    float d = r * random(0.7, 1.0);
    xy[2 * i] = d * cos(a);
    xy[2 * i + 1] = d * sin(a);
  }
  return Polygon.of(xy);
}

void draw() {
  // The rocks drift and turn: teleports, nothing in their way is asked.
  for (int i = 0; i < rocks.size(); i++) {
    Body rock = rocks.get(i);
    rock.moveBy(drift.get(i).x, drift.get(i).y);
    rock.turnBy(spin.get(i));
    wrap(rock, 40);
  }
  if (demo) {
    left = false;
    right = frameCount % 120 < 50;   // the demo: a wide circle, thrusting out of the turns
    thrust = frameCount % 120 > 40;
  }
  // The ship turns and thrusts, then the world moves it through the rocks.
  if (left) {
    ship.turnBy(-0.08);
  }
  if (right) {
    ship.turnBy(0.08);
  }
  if (thrust) {
    vx += 0.12 * cos(ship.angle());
    vy += 0.12 * sin(ship.angle());
  }
  float speed = dist(0, 0, vx, vy);
  if (speed > 4) {
    vx *= 4 / speed;
    vy *= 4 / speed;
  }
  met.clear();
  met.addAll(world.move(ship, vx, vy, (me, other) -> Reaction.BOUNCE));
  for (Collision c : met) {
    if (c.reaction() == Reaction.BOUNCE) {
      Vec v = Response.bounce(vx, vy, c.nx(), c.ny(), 0.8);   // off the rock, a little slower
      vx = v.x();
      vy = v.y();
    }
  }
  wrap(ship, 20);
  for (BodyEvent e : world.step()) {
    if (e.kind() == BodyEvent.Kind.ENTER && e.involves(ship)) {
      hits++;
      flash = 12;
    }
  }
  lookForTheShip();
  drawScene();
}

// The sentry's line of sight: the nearest body on the ray from it to the ship.
void lookForTheShip() {
  sight = null;
  seen = false;
  if (dist(sentryX, sentryY, ship.x(), ship.y()) < 1) {
    return;
  }
  Ray ray = Ray.between(sentryX, sentryY, ship.x(), ship.y());
  sight = world.raycastFirst(ray, body -> true);
  seen = sight != null && sight.body() == ship;
}

// Off one edge of the window, on at the other.
void wrap(Body b, float margin) {
  float x = b.x(), y = b.y();
  if (x < -margin) x += width + 2 * margin;
  if (x > width + margin) x -= width + 2 * margin;
  if (y < -margin) y += height + 2 * margin;
  if (y > height + margin) y -= height + 2 * margin;
  if (x != b.x() || y != b.y()) {
    b.moveTo(x, y);
  }
}

void drawScene() {
  background(Palette.BACKGROUND);
  noStroke();
  fill(Palette.OBSTACLE);
  for (Body rock : rocks) {
    drawTurned(rock);
  }
  fill(flash > 0 ? Palette.HIT : Palette.PLAYER);
  drawTurned(ship);
  flash = max(0, flash - 1);
  drawSentry();
  drawMaths();   // Maths.pde
}

// As a sketch draws anything that turns: move the origin to the body, turn, draw its shape
// around (0, 0). body.shape() is this outline, where the screen shows it.
void drawTurned(Body b) {
  pushMatrix();
  translate(b.x(), b.y());
  rotate(b.angle());
  Draw.shape(g, b.homeShape());
  popMatrix();
}

void drawSentry() {
  float endX = seen || sight == null ? ship.x() : sight.hit().x();
  float endY = seen || sight == null ? ship.y() : sight.hit().y();
  stroke(seen ? Palette.HIT : Palette.MISS);
  strokeWeight(2);
  line(sentryX, sentryY, endX, endY);
  if (!seen && sight != null) {
    noStroke();
    fill(Palette.MISS);
    circle(endX, endY, 7);   // where a rock blocks the view
  }
  noStroke();
  fill(Palette.NEUTRAL);
  circle(sentryX, sentryY, 18);
  fill(seen ? Palette.HIT : Palette.MISS);
  circle(sentryX, sentryY, 8);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
    return;
  }
  if (key == CODED) {
    if (demo) {
      demo = false;
      left = right = thrust = false;
    }
    setKey(true);
  }
}

void keyReleased() {
  if (!demo && key == CODED) {
    setKey(false);
  }
}

void setKey(boolean down) {
  if (keyCode == LEFT) {
    left = down;
  } else if (keyCode == RIGHT) {
    right = down;
  } else if (keyCode == UP) {
    thrust = down;
  }
}
