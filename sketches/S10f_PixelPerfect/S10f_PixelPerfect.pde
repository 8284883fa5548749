/**
 * Pixel-perfect, and the hybrid check
 * Tutorial section 10: Pixel-perfect, and the hybrid approach
 *
 * Two sprites collide when some pixel is solid in both: exact, but slow if every pair is
 * tested pixel by pixel. So section 10 suggests a hybrid: "first do a distance-based check,
 * which can be done very fast and with little code. If that check is true, then spend more
 * time doing something like hit box detection. If that is true, then you can do more
 * specific or even pixel-perfect collision detection." hybrid() below is those three stages,
 * one after another, each counted as it runs: 1) the circles around the sprites' boxes,
 * 2) the boxes, 3) the pixels (PixelMask, made from each sprite's alpha). The first stage
 * that can say "apart" decides; only stage 3 can say "colliding". The big star is coloured by
 * the stage that decided; the first pixel the two share is marked. The tutorial gives no code
 * for these stages: the code here is ours, written out, stage 3 as a plain loop over the
 * pixels, and that loop is what makes pixel-perfect slow.
 *
 * Where Hitbox differs: in stage 3. Press l for Hitbox's PixelMask.overlaps: it keeps each row
 * of a sprite as bits, 64 pixels to a long, and compares 64 pixels in one step. The time stage
 * 3 took this frame is on screen for both. (Hitbox's Hybrid.check runs the same three stages
 * in one call, with the same answers.)
 *
 * Try this: put the ring between two of the star's points (the boxes overlap, the pixels
 * do not); press c and sweep the ring through a crowd to see how rarely the pixel test has
 * to run; make the sprites from your own PNGs with loadImage.
 * Keys: c crowd of stars, l stage 3 as PixelMask / a plain pixel loop, d shows the maths
 * (circles, boxes and the comparisons).
 */
import hitbox.*;
import hitbox.processing.*;

PGraphics star, ring, smallStar;       // the sprites, drawn in code (Sprites.pde)
PixelMask starMask, ringMask, smallMask;

// Where the sprites are: top-left corners, whole pixels. The ring follows the mouse.
int starX = 215;
int starY = 100;
int ringX, ringY;

Hybrid.Result result;                 // the big star against the ring, this frame
Hybrid.Counter counter = new Hybrid.Counter();      // every check since the start

int[] ran = new int[3];               // how many times each stage ran this frame
long pixelNanos;                      // and how long stage 3 took, in nanoseconds
boolean hitboxDecides;                // l: stage 3 as Hitbox's PixelMask.overlaps, not the pixel loop

boolean crowdMode;                    // c: a crowd of small stars instead
int[] crowdX = new int[48];
int[] crowdY = new int[48];
Hybrid.Result[] crowdResults = new Hybrid.Result[48];
Hybrid.Counter crowdCounter = new Hybrid.Counter(); // the crowd's checks this frame

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  star = starSprite(170, 82, 34);
  ring = ringSprite(100, 40, 12);
  smallStar = starSprite(36, 17, 7);
  // A pixel is solid where the sprite is more than half opaque.
  starMask = mask(star);
  ringMask = mask(ring);
  smallMask = mask(smallStar);
  placeCrowd();
}

void draw() {
  background(Palette.BACKGROUND);
  ringX = mouseX - ring.width / 2;
  ringY = mouseY - ring.height / 2;
  ran = new int[3];
  pixelNanos = 0;
  if (crowdMode) {
    // One check per star in the crowd: most end at the first stage.
    crowdCounter.reset();
    for (int i = 0; i < crowdX.length; i++) {
      crowdResults[i] = crowdCounter.add(hybrid(smallMask, crowdX[i], crowdY[i], ringMask, ringX, ringY));
    }
    drawCrowd();   // Maths.pde
  } else {
    result = counter.add(hybrid(starMask, starX, starY, ringMask, ringX, ringY));
    drawPair();    // Maths.pde
  }
  Overlay.hint(g, "move the ring   c: " + (crowdMode ? "one big star" : "a crowd of stars")
      + "   l: stage 3 " + (hitboxDecides ? "as a pixel loop" : "as PixelMask") + "   d: show the maths");
}

// Distance, then hit boxes, then pixels: section 10's stages in its order, each run only if
// the one before said "close". Hybrid.check(a, ax, ay, b, bx, by) does the same in one call.
Hybrid.Result hybrid(PixelMask a, int ax, int ay, PixelMask b, int bx, int by) {
  // Each sprite's box: the bounds of its solid pixels, where the sprite is placed.
  Rect boxA = a.bounds().translated(ax, ay);
  Rect boxB = b.bounds().translated(bx, by);

  // 1. Distance: the circles around the boxes (radius half the diagonal). Are their centres
  //    further apart than the two radii?
  ran[0]++;
  float centres = dist(boxA.centerX(), boxA.centerY(), boxB.centerX(), boxB.centerY());
  float radii = dist(0, 0, boxA.w(), boxA.h()) / 2 + dist(0, 0, boxB.w(), boxB.h()) / 2;
  if (centres > radii) {
    return new Hybrid.Result(false, Hybrid.Stage.CIRCLES);
  }
  // 2. Hit boxes: section 5's rectangle/rectangle if (Collide.rectRect asks the same).
  ran[1]++;
  if (!(boxA.x() + boxA.w() > boxB.x() && boxA.x() < boxB.x() + boxB.w()
      && boxA.y() + boxA.h() > boxB.y() && boxA.y() < boxB.y() + boxB.h())) {
    return new Hybrid.Result(false, Hybrid.Stage.BOXES);
  }
  // 3. Pixels: is some pixel solid in both sprites?
  ran[2]++;
  long start = System.nanoTime();
  boolean shared = hitboxDecides ? a.overlaps(b, bx - ax, by - ay) : pixelLoop(a, ax, ay, b, bx, by);
  pixelNanos += System.nanoTime() - start;
  return new Hybrid.Result(shared, Hybrid.Stage.PRECISE);
}

// Stage 3 as a plain loop: each of a's pixels, one at a time; is it solid, and is the pixel of
// b on the same spot of the screen solid too?
boolean pixelLoop(PixelMask a, int ax, int ay, PixelMask b, int bx, int by) {
  for (int y = 0; y < a.height(); y++) {
    for (int x = 0; x < a.width(); x++) {
      if (a.contains(x, y) && b.contains(ax + x - bx, ay + y - by)) {
        return true;
      }
    }
  }
  return false;
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'c') {
    crowdMode = !crowdMode;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  }
}
