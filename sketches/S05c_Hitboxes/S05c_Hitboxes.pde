/**
 * Hit boxes: a rectangle for a rocket that is not one
 * Tutorial section 5: Rectangle/Rectangle (hit boxes)
 *
 * The tutorial ends section 5 with hit boxes: even when your objects are not rectangles, an
 * invisible rectangle around them is used for collision. The video adds that the box is only
 * roughly fitted to the sprite, so it is not pixel perfect, but simple and fast. Here square
 * rocks rain on a rocket drawn with Processing shapes, and every frame every rock is tested
 * twice: against the hit box (one Collide.rectRect: what a game would believe) and against
 * the rocket's own outline (its body and fins are library Polygons: exact). The rocks fly on
 * through, coloured by the answers: red where both say hit, yellow for a false hit (the box
 * is hit, the rocket is not), purple for a miss (the rocket is hit, the box is not). A box
 * around the whole rocket never misses but hits falsely at its empty corners; a box inside
 * the body never hits falsely but misses the nose and the fins; the tally counts both.
 *
 * Where Hitbox differs: it does not; the hit box test is section 5's rectangle test. Hitbox
 * also has the exact test for the outline (Polygon.overlaps), the slower, more precise stage
 * that the tutorial's section 10 puts after a box test (S10f shows that hybrid check).
 *
 * Try this: find the box with the fewest mistakes; make the hit box a circle
 * (Collide.circleRect) and compare; make the rocks bigger or faster.
 * Keys: LEFT / RIGHT narrower / wider box, UP / DOWN taller / shorter, 1 inside the body,
 * 2 fitted, 3 around everything, d shows the maths (where false hits and misses come from).
 */
import hitbox.*;
import hitbox.processing.*;

Ship ship;
ArrayList<Rock> rocks = new ArrayList<Rock>();
float boxW = 52;    // the hit box, centred on the ship
float boxH = 90;

// The tally for this box: every frame, every rock that touches the box or the rocket counts
// once, by what the two tests said.
int hits, falseHits, misses;
boolean showMaths;

void setup() {
  size(600, 400);
  randomSeed(3);
  ship = new Ship(300, 260);
}

void draw() {
  background(Palette.BACKGROUND);
  if (frameCount % 2 == 0) {
    rocks.add(new Rock(ship.x + random(-80, 70), -10, random(-0.4, 0.4), random(2.5, 4)));
  }

  for (int i = rocks.size() - 1; i >= 0; i--) {
    Rock rock = rocks.get(i);
    rock.fall();
    // The hit box: one rectangle test, cheap. This is what a game would believe.
    boolean boxHit = Collide.rectRect(rock.x, rock.y, rock.size, rock.size, boxX(), boxY(), boxW, boxH);
    // The rocket itself: exact, one test per part of its outline. This is the truth.
    boolean shipHit = ship.touches(new Rect(rock.x, rock.y, rock.size, rock.size));
    rock.verdict = judge(boxHit, shipHit);
    if (rock.y > height) {
      rocks.remove(i);
    }
  }

  if (showMaths) {
    drawMaths();
  } else {
    ship.draw();
  }
  drawBox();
  for (Rock rock : rocks) {
    rock.draw();
  }
  drawTally();
  Overlay.hint(g, "LEFT / RIGHT, UP / DOWN: resize the box     1 inside, 2 fitted, 3 around everything     d: show the maths");
}

float boxX() {
  return ship.x - boxW / 2;
}

float boxY() {
  return ship.y - boxH / 2;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == '1') {
    resize(24, 56);     // strictly inside the body: no false hits
  } else if (key == '2') {
    resize(52, 90);
  } else if (key == '3') {
    resize(84, 108);    // the rocket's bounding box: no misses
  } else if (key == CODED) {
    if (keyCode == LEFT) resize(boxW - 4, boxH);
    if (keyCode == RIGHT) resize(boxW + 4, boxH);
    if (keyCode == UP) resize(boxW, boxH + 4);
    if (keyCode == DOWN) resize(boxW, boxH - 4);
  }
}
