/**
 * Homework 2 again, on a world of bodies
 * Beyond the tutorial: the world, homework 2 again
 *
 * The same homework as H02_Bouncers: a hundred randomly placed obstacles, a hundred random
 * rectangles that bounce off them, and a new colour for a bouncer each time it hits one.
 * There, each bouncer loops over every obstacle itself, as section 8 does. Here every
 * obstacle and every bouncer is a body in one World, and world.move(bouncer, vx, vy, filter)
 * does the loop: it finds what is near through the world's grid, sweeps the bouncer to the
 * first thing in its way (so no speed makes it jump an obstacle) and, where the filter says
 * BOUNCE, sends the rest of the move back off it. Each collision it returns names the body
 * met and the normal there; the sketch turns its speed round along that normal and changes
 * its colour.
 *
 * The homework says nothing about bouncers meeting each other; H02, as section 8's loop
 * does, lets them pass through each other, and so do the layers here: obstacles and bouncers
 * are in different categories, and a bouncer's mask takes obstacles and walls only. Press b
 * and the masks take bouncers too: they bounce off each other as well.
 *
 * Everything random comes from randomSeed, so every run is the same.
 *
 * Try this: make the bouncers ten times faster and see that none goes through an obstacle;
 * make it 1,000 bouncers; return Reaction.CROSS for obstacles and watch the colours change
 * as the bouncers pass through.
 * Keys: b bouncers bounce off each other too, d shows the maths (every body's box, the
 * grid's cells, this frame's contacts with their normals, and the counts).
 */
import hitbox.*;
import hitbox.processing.*;

int obstacleCount = 100;
int bouncerCount = 100;
float size = 8;   // every bouncer is size x size

// Layers: the bits each body is (its category); a body meets another only if each one's
// mask holds the other's category.
int WALL = 1, OBSTACLE = 2, BOUNCER = 4;

World world = new World();
ArrayList<Body> obstacles = new ArrayList<Body>();
ArrayList<Bouncer> bouncers = new ArrayList<Bouncer>();
int[] glow = new int[obstacleCount];   // frames left to show each obstacle red after a hit
int hitsThisFrame = 0;
int totalHits = 0;
boolean bounceOffEachOther = false;    // b

// What a bouncer does at whatever it meets: bounce off it, with the rest of its move.
CollisionFilter bounceOffEverything = (mover, other) -> Reaction.BOUNCE;

void setup() {
  size(600, 400);
  randomSeed(2);
  colorMode(HSB, 360, 100, 100);
  // The window's edges, as bodies just outside it.
  world.add(new Rect(-50, -50, width + 100, 50)).layers(WALL, BOUNCER);
  world.add(new Rect(-50, height, width + 100, 50)).layers(WALL, BOUNCER);
  world.add(new Rect(-50, 0, 50, height)).layers(WALL, BOUNCER);
  world.add(new Rect(width, 0, 50, height)).layers(WALL, BOUNCER);
  for (int i = 0; i < obstacleCount; i++) {
    float w = random(10, 26);
    float h = random(10, 26);
    obstacles.add(world.add(new Rect(random(0, width - w), random(0, height - h), w, h)).layers(OBSTACLE, BOUNCER));
  }
  ArrayList<Body> inTheWay = new ArrayList<Body>();
  while (bouncers.size() < bouncerCount) {
    Rect r = new Rect(random(0, width - size), random(0, height - size), size, size);
    inTheWay.clear();
    world.queryShape(r, body -> body.category() == OBSTACLE, inTheWay);   // the obstacles r overlaps
    if (inTheWay.isEmpty()) {   // start clear of obstacles
      Body body = world.add(r).layers(BOUNCER, WALL | OBSTACLE);
      bouncers.add(new Bouncer(body, randomSpeed(), randomSpeed()));
    }
  }
}

void draw() {
  background(Palette.BACKGROUND);
  hitsThisFrame = 0;
  for (Bouncer b : bouncers) {
    b.move();   // Bouncer.pde: world.move, then the speed turned round at each bounce
  }
  world.step();   // the frame ends: its contacts are kept for the maths
  totalHits += hitsThisFrame;

  noStroke();
  for (int i = 0; i < obstacles.size(); i++) {
    fill(glow[i] > 0 ? Palette.HIT : Palette.OBSTACLE);
    Draw.shape(g, obstacles.get(i).shape());
    glow[i] = max(0, glow[i] - 1);
  }
  for (Bouncer b : bouncers) {
    fill(b.colour);
    Draw.shape(g, b.body.shape());
  }
  drawMaths();   // Maths.pde: only with d
}

void keyPressed() {
  if (key == 'b') {
    bounceOffEachOther = !bounceOffEachOther;
    for (Bouncer b : bouncers) {
      b.body.layers(BOUNCER, bounceOffEachOther ? WALL | OBSTACLE | BOUNCER : WALL | OBSTACLE);
    }
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
