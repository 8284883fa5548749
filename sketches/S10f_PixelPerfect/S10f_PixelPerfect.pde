/**
 * Pixel-perfect, and the hybrid check
 * Tutorial section 10: Pixel-perfect, and the hybrid approach
 *
 * Two sprites collide when some pixel is solid in both: exact, but slow if every pair is
 * tested pixel by pixel. So the tutorial suggests a hybrid: first a distance check, fast and
 * little code; if it says "close", hit boxes; if they overlap, pixel-perfect. Hybrid.check
 * runs exactly those three stages, cheapest first, and the first that can say "apart"
 * decides: 1) the circles around the sprites' boxes, 2) the boxes, 3) the pixels (PixelMask,
 * made from each sprite's alpha). Only stage 3 can say "colliding". The big star is coloured
 * by the stage that decided; the first pixel the two share is marked.
 *
 * The tutorial gives no code for these stages. Hitbox's pixel stage differs from a loop over
 * the pixels because that loop is what makes pixel-perfect slow: PixelMask keeps each row of
 * a sprite as bits, 64 pixels to a long, and compares 64 pixels in one step.
 *
 * Try this: put the ring between two of the star's points (the boxes overlap, the pixels
 * do not); press c and sweep the ring through a crowd to see how rarely the pixel test has
 * to run; make the sprites from your own PNGs with loadImage.
 * Keys: c crowd of stars, d shows the maths (circles, boxes and the comparisons).
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
  if (crowdMode) {
    // One check per star in the crowd: most end at the first stage.
    crowdCounter.reset();
    for (int i = 0; i < crowdX.length; i++) {
      crowdResults[i] = crowdCounter.add(Hybrid.check(smallMask, crowdX[i], crowdY[i], ringMask, ringX, ringY));
    }
    drawCrowd();   // Maths.pde
  } else {
    // Distance, then hit boxes, then pixels: the stages the tutorial names, in its order.
    result = counter.add(Hybrid.check(starMask, starX, starY, ringMask, ringX, ringY));
    drawPair();    // Maths.pde
  }
  Overlay.hint(g, "move the ring     c: " + (crowdMode ? "one big star" : "a crowd of stars") + "     d: show the maths");
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'c') {
    crowdMode = !crowdMode;
  }
}
