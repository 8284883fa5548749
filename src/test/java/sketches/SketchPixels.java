package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;

import processing.core.PImage;

/** Pixel checks the sketch display tests share. */
final class SketchPixels {
    private SketchPixels() {
    }

    /**
     * Asserts one pixel's colour, written in hex on failure.
     *
     * @param frame    what a frame drew
     * @param x        the pixel's x
     * @param y        the pixel's y
     * @param expected the colour, e.g. Palette.HIT
     * @param what     what the pixel shows, for the message
     */
    static void assertColour(PImage frame, int x, int y, int expected, String what) {
        assertEquals(Integer.toHexString(expected), Integer.toHexString(frame.get(x, y)),
                what + " at (" + x + ", " + y + ")");
    }

    /**
     * Counts the pixels that differ between two frames of the same size.
     *
     * @param a one frame
     * @param b the other
     * @return how many pixels differ
     */
    static int differing(PImage a, PImage b) {
        a.loadPixels();
        b.loadPixels();
        int n = 0;
        for (int i = 0; i < a.pixels.length; i++) {
            if (a.pixels[i] != b.pixels[i]) {
                n++;
            }
        }
        return n;
    }
}
