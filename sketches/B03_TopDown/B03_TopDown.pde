/**
 * Turning rocks, turned walls, a ship, and a sentry's line of sight
 * Beyond the tutorial: the world, turning bodies and sight
 *
 * Seen from above: rocks that turn, walls set at angles, and a ship that turns and thrusts. A
 * sketch draws a turning thing with pushMatrix(); translate(x, y); rotate(angle); and its shape
 * around (0, 0), and world.add(shape, x, y, angle) makes the body that stands exactly there,
 * so the collision tests test what you see: body.turnBy turns it, body.pivotX(),
 * body.pivotY() and body.angle() are what translate and rotate take, and body.shape() is the
 * turned outline on the screen. The ship is a CharacterBody with up(0, 0): seen from above there is no ground,
 * every surface is a wall, and ship.move(vx, vy) slides it along the walls and round the rocks
 * (Response.slide then drops the part of its velocity that went into them). The rocks and
 * walls ignore each other (a category and a mask); world.step() reports each time the ship
 * comes into contact with one.
 *
 * The sentry in the corner looks at the ship: world.raycastFirst casts a ray from it
 * towards the ship and answers the nearest body in the way. If that is the ship, it is seen.
 *
 * With no key pressed, the ship flies a demo circle; the first arrow key hands it to you.
 *
 * Try this: hide the ship behind a rock or a wall from the sentry; fly along a wall and round
 * a rock; make the rocks turn ten times faster and watch their boxes with d; write
 * Response.bounce(vx, vy, c.nx(), c.ny(), 0.8) for Response.slide and the ship glances off
 * what it meets instead of gliding along it.
 * Keys: LEFT and RIGHT turn, UP thrusts, d shows the maths (every body's box, which grows
 * and shrinks as it turns, the grid's cells, the ship's contacts with their normals, and the
 * ray's answer).
 */
import hitbox.*;
import hitbox.processing.*;

int SHIP = 1, ROCK = 2, WALL = 4;

World world = new World();
CharacterBody ship;      // a body that slides: seen from above, every surface a wall
float vx = 0, vy = 0;
ArrayList<Body> rocks = new ArrayList<Body>();
FloatList spin = new FloatList();                      // each rock's turn a frame
ArrayList<Body> walls = new ArrayList<Body>();
ArrayList<Collision> met = new ArrayList<Collision>(); // the ship's collisions this frame
int hits = 0;            // times the ship came into contact with a rock or a wall
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
  ship = world.addCharacter(shipShape, 300, 200, -HALF_PI).up(0, 0);
  ship.body().layers(SHIP, ROCK | WALL);
  float[][] at = {{110, 90}, {470, 110}, {490, 300}, {250, 320}, {140, 230}, {320, 100}};
  for (float[] p : at) {
    Body rock = world.add(rockShape(random(30, 42)), p[0], p[1], random(TWO_PI)).layers(ROCK, SHIP);
    rocks.add(rock);
    spin.append(random(-0.01, 0.01));
  }
  // The walls: long thin rects, each turned about its middle.
  float[][] wallAt = {{400, 210, 1.0}, {560, 60, 0.7}, {380, 360, -0.25}, {40, 180, 1.3}};
  for (float[] w : wallAt) {
    walls.add(world.add(new Rect(-60, -7, 120, 14), w[0], w[1], w[2]).layers(WALL, SHIP));
  }
}

// A rock in its own frame: a ring of 9 corners at random distances around (0, 0).
Polygon rockShape(float r) {
  float[] xy = new float[18];
  for (int i = 0; i < 9; i++) {
    float a = TWO_PI * i / 9;
    float d = r * random(0.85, 1.0);
    xy[2 * i] = d * cos(a);
    xy[2 * i + 1] = d * sin(a);
  }
  return Polygon.of(xy);
}

void draw() {
  // The rocks turn where they stand: a teleport, nothing in their way is asked (a rock that
  // turns into the ship pushes it out on its next move).
  for (int i = 0; i < rocks.size(); i++) {
    rocks.get(i).turnBy(spin.get(i));
  }
  if (demo) {
    left = false;
    right = frameCount % 120 < 50;   // the demo: a wide circle, thrusting out of the turns
    thrust = frameCount % 120 > 40;
  }
  // The ship turns and thrusts, then slides through the rocks and walls.
  if (left) {
    ship.body().turnBy(-0.08);
  }
  if (right) {
    ship.body().turnBy(0.08);
  }
  if (thrust) {
    vx += 0.12 * cos(ship.body().angle());
    vy += 0.12 * sin(ship.body().angle());
  }
  float speed = dist(0, 0, vx, vy);
  if (speed > 4) {
    vx *= 4 / speed;
    vy *= 4 / speed;
  }
  met.clear();
  met.addAll(ship.move(vx, vy));
  for (Collision c : met) {
    Vec v = Response.slide(vx, vy, c.nx(), c.ny());   // keep only the part along the surface
    vx = v.x();
    vy = v.y();
  }
  wrap(ship.body(), 20);
  for (BodyEvent e : world.step()) {
    if (e.kind() == BodyEvent.Kind.ENTER && e.involves(ship.body())) {
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
  float x = ship.body().pivotX(), y = ship.body().pivotY();
  if (dist(sentryX, sentryY, x, y) < 1) {
    return;
  }
  Ray ray = Ray.between(sentryX, sentryY, x, y);
  sight = world.raycastFirst(ray, body -> true);
  seen = sight != null && sight.body() == ship.body();
}

// Off one edge of the window, on at the other.
void wrap(Body b, float margin) {
  float x = b.pivotX(), y = b.pivotY();
  if (x < -margin) x += width + 2 * margin;
  if (x > width + margin) x -= width + 2 * margin;
  if (y < -margin) y += height + 2 * margin;
  if (y > height + margin) y -= height + 2 * margin;
  if (x != b.pivotX() || y != b.pivotY()) {
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
  fill(Palette.NEUTRAL);
  for (Body wall : walls) {
    drawTurned(wall);
  }
  fill(flash > 0 ? Palette.HIT : Palette.PLAYER);
  drawTurned(ship.body());
  flash = max(0, flash - 1);
  drawSentry();
  drawMaths();   // Maths.pde
}

// As a sketch draws anything that turns: move the origin to the body, turn, draw its shape
// around (0, 0). body.shape() is this outline, where the screen shows it.
void drawTurned(Body b) {
  pushMatrix();
  translate(b.pivotX(), b.pivotY());
  rotate(b.angle());
  Draw.shape(g, b.homeShape());
  popMatrix();
}

void drawSentry() {
  float endX = seen || sight == null ? ship.body().pivotX() : sight.hit().x();
  float endY = seen || sight == null ? ship.body().pivotY() : sight.hit().y();
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
