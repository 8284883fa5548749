/**
 * 10,000 bouncers
 * Homework 2: 10,000 bouncers, through a broad phase
 *
 * Homework 2 a hundred times over: 10,000 small boxes bounce off 24 obstacles, off the window
 * and, though the homework says nothing about bouncers meeting, off each other. Testing every pair would be 50 million tests a frame. Instead, every
 * frame each bouncer is put into a BroadPhase at its new place, and pairs() reports every
 * overlapping pair once: two bouncers coming together swap speeds (equal masses, an elastic
 * bounce), and a bouncer in an obstacle is pushed out the short way (Snap.pushOut) and turned
 * back on that axis. The grid finds all the pairs with a few tens of thousands of tests, in
 * about a millisecond; the time of that collision step is on screen, beside the frame rate,
 * which drawing 10,000 boxes limits. Bouncers that hit something this frame flash red.
 *
 * Everything random comes from randomSeed, so every run is the same.
 *
 * Where Hitbox differs: section 10 only names two of these structures, R-trees and
 * quadtrees, and writes neither; Hitbox has both kinds and more. The dynamic tree (3) is
 * an R-tree kind: it groups nearby boxes under a box that holds them, those groups under
 * bigger boxes, up to one box round everything, and a search skips every group whose box it
 * misses (the maths draws its boxes near the mouse). The quadtree (4) cuts the window into
 * squares instead, and the grid (1) keeps each bouncer in a cell, section 9's "each grid cell
 * could contain an object (or even multiple objects)".
 *
 * Try this: press 1 to 5 to switch structures and compare their collision steps; brute force
 * keeps only 1,500 bouncers moving and is still the slowest; make the bouncers bigger.
 * Keys: 1 grid, 2 sweep and prune, 3 dynamic tree (an R-tree kind), 4 quadtree, 5 brute
 * force (1,500 bouncers), d shows the maths (tests this frame against n(n-1)/2, and the
 * structure's cells or boxes around the mouse).
 */
import hitbox.*;
import java.util.Set;
import hitbox.processing.*;

int n = 10000;
int bruteForceCap = 1500;
float size = 3;                  // every bouncer is size x size
int obstacleCount = 24;

float[] x = new float[n];
float[] y = new float[n];
float[] vx = new float[n];
float[] vy = new float[n];
int[] flash = new int[n];        // 1: hit something this frame (drawn red)
Rect[] obstacles = new Rect[obstacleCount];

// One of each structure; bouncer i is id i, obstacle k is id n + k.
BroadPhase[] structures = {
  BroadPhase.grid(), BroadPhase.sweepAndPrune(), BroadPhase.dynamicTree(),
  BroadPhase.quadtree(), BroadPhase.bruteForce()
};
int current = 0;
int active = n;                  // the bouncers that move: all, or the brute-force cap

int pairsThisFrame;
int hitsThisFrame;
float stepMillis;                // this frame's collision step: put every bouncer, then pairs
float smoothMillis;              // the same, smoothed for reading
boolean showMaths = false;

void setup() {
  size(800, 600);
  randomSeed(4);
  placeObstacles();
  for (int i = 0; i < n; i++) {
    do {
      x[i] = random(0, width - size);
      y[i] = random(0, height - size);
    } while (inAnObstacle(x[i], y[i]));
    float speed = random(0.5, 2);
    float angle = random(TWO_PI);
    vx[i] = speed * cos(angle);
    vy[i] = speed * sin(angle);
  }
  for (BroadPhase structure : structures) {
    for (int k = 0; k < obstacleCount; k++) {
      structure.put(n + k, obstacles[k]);
    }
  }
}

void draw() {
  background(Palette.BACKGROUND);
  active = current == 4 ? bruteForceCap : n;
  for (int i = 0; i < active; i++) {
    x[i] += vx[i];
    y[i] += vy[i];
    Set<Side> crossed = Edges.crossed(new Rect(x[i], y[i], size, size), width, height);
    vx[i] = Edges.bounceX(crossed, vx[i]);
    vy[i] = Edges.bounceY(crossed, vy[i]);
    x[i] = Edges.rectClampX(x[i], size, width);
    y[i] = Edges.rectClampY(y[i], size, height);
  }

  // The collision step, timed: every bouncer into the broad phase, then every pair.
  BroadPhase world = structures[current];
  long start = System.nanoTime();
  for (int i = 0; i < active; i++) {
    world.put(i, x[i], y[i], size, size);
  }
  pairsThisFrame = 0;
  hitsThisFrame = 0;
  world.pairs((a, b) -> bounce(a, b));
  stepMillis = (System.nanoTime() - start) / 1e6;
  smoothMillis = frameCount == 1 ? stepMillis : 0.9 * smoothMillis + 0.1 * stepMillis;

  drawBouncers();
  noStroke();
  fill(Palette.OBSTACLE);
  for (Rect o : obstacles) {
    Draw.shape(g, o);
  }
  if (showMaths) {
    drawMaths();
  }
  Overlay.label(g, 8, 8, world + ": " + nfc(active) + " bouncers\ncollision step "
      + nf(smoothMillis, 0, 2) + " ms   frame rate " + round(frameRate) + " fps");
  Overlay.hint(g, "1 grid  2 sweep and prune  3 dynamic tree (R-tree kind)  4 quadtree  5 brute force   d: maths");
}

// One overlapping pair, a < b: two obstacles (nothing to do), a bouncer in an obstacle, or two bouncers.
void bounce(int a, int b) {
  pairsThisFrame++;
  if (a >= n) {
    return;
  }
  if (b >= n) {
    Rect o = obstacles[b - n];
    Snap.Push push = Snap.pushOut(x[a], y[a], size, size, o.x(), o.y(), o.w(), o.h());
    x[a] = push.x();
    y[a] = push.y();
    if (push.side() == Side.LEFT || push.side() == Side.RIGHT) {
      vx[a] = push.side() == Side.LEFT ? -abs(vx[a]) : abs(vx[a]);
    } else {
      vy[a] = push.side() == Side.TOP ? -abs(vy[a]) : abs(vy[a]);
    }
    flash[a] = 1;
    hitsThisFrame++;
  } else if ((x[b] - x[a]) * (vx[b] - vx[a]) + (y[b] - y[a]) * (vy[b] - vy[a]) < 0) {
    // Coming together: swap speeds. (Moving apart already, they are left to separate.)
    float t = vx[a];
    vx[a] = vx[b];
    vx[b] = t;
    t = vy[a];
    vy[a] = vy[b];
    vy[b] = t;
    flash[a] = 1;
    flash[b] = 1;
    hitsThisFrame++;
  }
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key >= '1' && key <= '5') {
    current = key - '1';
  }
}
