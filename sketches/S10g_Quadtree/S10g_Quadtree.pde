/**
 * Quadtrees (and an R-tree kind): only test what is nearby
 * Tutorial section 10: Quadtrees and R-trees
 *
 * Section 10 names "location-based data structures like R-trees and Quadtrees" that cut down
 * the collision checks: "if you know your player is on the left side of the screen, you
 * probably don't need to check for collision against objects on the right side of the
 * screen." Here 150 boxes start in three crowds and drift apart, in a BroadPhase.quadtree().
 * Each square of the tree (the grey lines) holds the boxes whose corner is in it; a square
 * holding more than 8 splits into four, so the squares are small where the boxes crowd and
 * large where they are few. Every frame the tree's pairs() finds each overlapping pair (red)
 * by testing each box only against the boxes of its own square, its neighbours and the squares
 * inside them, and the mouse's box asks query() which boxes it overlaps (outlined in yellow).
 * Both answer exactly as Collide.rectRect would for every pair: boxes that only touch are not
 * a pair.
 *
 * Where Hitbox differs: the tutorial only names R-trees and quadtrees, and writes neither.
 * Press r for the same boxes in BroadPhase.dynamicTree(), Hitbox's R-tree kind of structure:
 * instead of cutting the window into squares, it groups nearby boxes under a box that holds
 * them, those groups under bigger boxes, and so on up to one box round everything (the grey
 * outlines); a search skips every group whose box it misses. (A textbook R-tree packs many
 * boxes a node; this one packs two, as game engines' box trees do.)
 *
 * Try this: move the mouse's box over a crowd; press + a few times and watch the squares
 * split, then - and watch them merge; compare the tests in the maths with n(n-1)/2, for the
 * quadtree and the R-tree kind.
 * Keys: + / - add or remove 25 boxes, r quadtree / dynamic tree (an R-tree kind), d shows the
 * maths (the tests the tree made this frame against the n(n-1)/2 of an all-pairs loop).
 */
import hitbox.*;
import java.util.Set;
import hitbox.processing.*;

BroadPhase tree = BroadPhase.quadtree();
boolean rTree = false;     // r: BroadPhase.dynamicTree() instead, an R-tree kind
int count = 150;           // boxes 0 to count - 1 are in the tree
int most = 1000;
float[] x = new float[most];
float[] y = new float[most];
float[] w = new float[most];
float[] h = new float[most];
float[] vx = new float[most];
float[] vy = new float[most];
boolean[] hit = new boolean[most];     // in an overlapping pair this frame
boolean[] found = new boolean[most];   // found by the mouse's query this frame

float queryW = 120;
float queryH = 80;
int pairCount;
long pairChecks;           // the box tests pairs() made this frame
int foundCount;
long queryChecks;          // and query()
boolean showMaths = false;

// Where the three crowds start.
float[] crowdX = {140, 430, 470};
float[] crowdY = {130, 290, 90};

void setup() {
  size(600, 400);
  randomSeed(3);
  for (int i = 0; i < most; i++) {
    int c = i % 3;
    w[i] = random(6, 18);
    h[i] = random(6, 18);
    x[i] = constrain(crowdX[c] + random(-60, 60), 0, width - w[i]);
    y[i] = constrain(crowdY[c] + random(-50, 50), 0, height - h[i]);
    vx[i] = random(-0.8, 0.8);
    vy[i] = random(-0.8, 0.8);
  }
}

void draw() {
  background(Palette.BACKGROUND);
  // Move every box, bounce it off the window, and put it in the tree at its new place.
  for (int i = 0; i < count; i++) {
    x[i] += vx[i];
    y[i] += vy[i];
    Set<Side> crossed = Edges.crossed(new Rect(x[i], y[i], w[i], h[i]), width, height);
    vx[i] = Edges.bounceX(crossed, vx[i]);
    vy[i] = Edges.bounceY(crossed, vy[i]);
    tree.put(i, x[i], y[i], w[i], h[i]);
    hit[i] = false;
    found[i] = false;
  }

  // Every overlapping pair, and how many box tests the tree needed to find them.
  pairCount = 0;
  tree.pairs((a, b) -> {
    hit[a] = true;
    hit[b] = true;
    pairCount++;
  });
  pairChecks = tree.checks();

  // What the mouse's box overlaps.
  foundCount = 0;
  tree.query(mouseX - queryW / 2, mouseY - queryH / 2, queryW, queryH, id -> {
    found[id] = true;
    foundCount++;
  });
  queryChecks = tree.checks();

  // The tree's squares (or the dynamic tree's boxes), deeper ones a little brighter.
  noFill();
  tree.cells((depth, cx, cy, cw, ch) -> {
    stroke(90 + 12 * min(depth, 8));
    rect(cx, cy, cw, ch);
  });

  for (int i = 0; i < count; i++) {
    noStroke();
    fill(hit[i] ? Palette.HIT : Palette.PLAYER);
    rect(x[i], y[i], w[i], h[i]);
    if (found[i]) {
      noFill();
      stroke(Palette.ACCENT);
      strokeWeight(2);
      rect(x[i] - 2, y[i] - 2, w[i] + 4, h[i] + 4);
      strokeWeight(1);
    }
  }
  noFill();
  stroke(Palette.ACCENT);
  rect(mouseX - queryW / 2, mouseY - queryH / 2, queryW, queryH);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, "+ / -: more or fewer boxes   r: " + (rTree ? "the quadtree" : "an R-tree kind (dynamic tree)") + "   d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'r') {
    // A new, empty structure: draw() puts every box in it on the next frame.
    rTree = !rTree;
    tree = rTree ? BroadPhase.dynamicTree() : BroadPhase.quadtree();
  } else if (key == '+' || key == '=') {
    count = min(most, count + 25);
  } else if (key == '-') {
    int fewer = max(25, count - 25);
    for (int i = fewer; i < count; i++) {
      tree.remove(i);
    }
    count = fewer;
  }
}
