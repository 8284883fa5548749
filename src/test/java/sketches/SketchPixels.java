package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.function.IntFunction;

import hitbox.sketchkit.Script;
import processing.core.PImage;

/** Pixel checks the sketch display tests share. */
final class SketchPixels {
    private SketchPixels() {
    }

    /**
     * A script that presses l on frames 1, 2, ... (handing the decision to the library and
     * back), then moves the mouse every frame from frame 4 on.
     *
     * @param frames   how many frames
     * @param lPresses how many times l is pressed
     * @param mouseAt  where the mouse is on frame f: {x, y}
     * @return the script
     */
    static Script lThenMouse(int frames, int lPresses, IntFunction<int[]> mouseAt) {
        Script script = new Script().frames(frames);
        for (int i = 0; i < lPresses; i++) {
            script.key(1 + i, 'l');
        }
        for (int f = 4; f <= frames; f++) {
            int[] at = mouseAt.apply(f);
            script.mouse(f, at[0], at[1]);
        }
        return script;
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

    /**
     * Counts the pixels in a region that differ between two frames of the same size.
     *
     * @param a  one frame
     * @param b  the other
     * @param x0 the region's left column (clamped to the frame)
     * @param y0 the region's top row
     * @param x1 the region's right column, included
     * @param y1 the region's bottom row, included
     * @return how many pixels differ there
     */
    static int differing(PImage a, PImage b, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int x = Math.max(0, x0); x <= Math.min(a.width - 1, x1); x++) {
            for (int y = Math.max(0, y0); y <= Math.min(a.height - 1, y1); y++) {
                if (a.get(x, y) != b.get(x, y)) {
                    n++;
                }
            }
        }
        return n;
    }

    /**
     * Counts the pixels of one colour (frames are opaque, so alpha is not compared).
     *
     * @param image  what a frame drew
     * @param colour the colour, e.g. Palette.HIT
     * @return how many pixels have it
     */
    static int count(PImage image, int colour) {
        return count(image, 0, 0, image.width - 1, image.height - 1, colour);
    }

    /**
     * Counts the pixels of one colour in a region (alpha is not compared).
     *
     * @param image  what a frame drew
     * @param x0     the region's left column
     * @param y0     the region's top row
     * @param x1     the region's right column, included
     * @param y1     the region's bottom row, included
     * @param colour the colour
     * @return how many pixels there have it
     */
    static int count(PImage image, int x0, int y0, int x1, int y1, int colour) {
        image.loadPixels();
        int n = 0;
        for (int y = Math.max(0, y0); y <= Math.min(image.height - 1, y1); y++) {
            for (int x = Math.max(0, x0); x <= Math.min(image.width - 1, x1); x++) {
                if ((image.pixels[y * image.width + x] | 0xFF000000) == (colour | 0xFF000000)) {
                    n++;
                }
            }
        }
        return n;
    }
}
