/**
 * Hit boxes: a rectangle for a rocket that is not one
 * Tutorial section 5: Rectangle/Rectangle (hit boxes)
 *
 * The tutorial ends section 5 with hit boxes: even when your objects are not rectangles, an
 * invisible rectangle around them is used for collision. The video adds that the box is only
 * roughly fitted (not pixel perfect, but simple and fast), that a hit box can be a rectangle,
 * a circle or a polygon (b switches), and that with complex shapes you test the simple boxes
 * first and run the advanced check only if they collide. Here square rocks rain on a rocket
 * drawn with Processing shapes, and every frame every rock meets the hit box first (the
 * rectangle as section 5's if, the circle as dist() to the rock's nearest point); only if the
 * box is hit does the rocket's own outline get tested (its body and fins are library Polygons:
 * exact, slower). Red: both say hit; yellow: a false hit (the box is hit, the rocket is not).
 * A rock that touches the rocket but not the box is a miss the game never sees; to count
 * misses (purple) the tally runs one more exact test (Tally.pde), that a game would not run.
 * A box around the whole rocket never misses but hits falsely at its empty corners; a box
 * inside the body never hits falsely but misses the nose and the fins.
 *
 * Where Hitbox differs: it does not; press l and Collide.rectRect and Collide.circleRect test
 * the box instead of the written-out ifs, with the same answers. The polygon box is always
 * Hitbox's Polygon.overlaps (S10c writes that test out). The exact test is Polygon.overlaps,
 * the slower stage that the tutorial's section 10 puts after a box test (S10f).
 *
 * Try this: find the box with the fewest mistakes, of each shape; make the rocks bigger or
 * faster.
 * Keys: b rectangle / circle / polygon box, LEFT / RIGHT narrower / wider box, UP / DOWN
 * taller / shorter, 1 inside the body, 2 fitted, 3 around everything, l Hitbox's box tests /
 * the written-out ifs, d shows the maths (where false hits and misses come from).
 */
import hitbox.*;
import hitbox.processing.*;

Ship ship;
ArrayList<Rock> rocks = new ArrayList<Rock>();
float boxW = 52;    // the hit box, centred on the ship: the rectangle's size, the circle's
float boxH = 90;    // diameter (boxH), the polygon's width and height
String boxShape = "rectangle";   // b: rectangle, circle, polygon
boolean hitboxDecides;           // l: Collide's box tests instead of the written-out ifs

// The tally for this box: every frame, every rock that touches the box or the rocket counts
// once, by what the two tests said.
int hits, falseHits, misses;
int rockTests, exactTests;   // box tests, and the exact tests that followed a box hit
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
    // 1. The hit box first: one cheap test. This is what a game would believe.
    boolean boxHit = boxHit(rock);
    rockTests++;
    // 2. Only if the box is hit: the rocket itself, exact, one test per part of its outline.
    boolean shipHit = false;
    if (boxHit) {
      exactTests++;
      shipHit = ship.touches(new Rect(rock.x, rock.y, rock.size, rock.size));
    }
    rock.verdict = judge(boxHit, shipHit, rock);   // Tally.pde
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
  Overlay.hint(g, "b: box shape   arrows: resize   1 inside, 2 fitted, 3 around everything   l: Hitbox's tests   d: maths");
}

// Does the rock reach into the hit box?
boolean boxHit(Rock rock) {
  if (boxShape.equals("rectangle") && !hitboxDecides) {
    //section 5's if: the rock against the box
    return rock.x + rock.size > boxX() && rock.x < boxX() + boxW
        && rock.y + rock.size > boxY() && rock.y < boxY() + boxH;
  } else if (boxShape.equals("circle") && !hitboxDecides) {
    //the rock's point nearest the circle's centre, then section 2's dist() < radius
    float nearestX = constrain(ship.x, rock.x, rock.x + rock.size);
    float nearestY = constrain(ship.y, rock.y, rock.y + rock.size);
    return dist(nearestX, nearestY, ship.x, ship.y) < boxH / 2;
  } else if (boxShape.equals("rectangle")) {
    return Collide.rectRect(rock.x, rock.y, rock.size, rock.size, boxX(), boxY(), boxW, boxH);
  } else if (boxShape.equals("circle")) {
    return Collide.circleRect(ship.x, ship.y, boxH / 2, rock.x, rock.y, rock.size, rock.size);
  }
  return hitBox().overlaps(new Rect(rock.x, rock.y, rock.size, rock.size));
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
  } else if (key == 'b') {
    boxShape = boxShape.equals("rectangle") ? "circle" : boxShape.equals("circle") ? "polygon" : "rectangle";
    resize(boxW, boxH);   // a new tally
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
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
