package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.Collide;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S05_RectRect: r2 (220, 150, 160 x 100) is red while r1 (120 x 80, its top-left corner at
 * the mouse, as in the tutorial) overlaps it, green when apart or side by side (sharing an
 * edge or a corner).
 */
class S05_RectRectTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): colliding {2}")
    @CsvSource({
            // mouse x, y (r1's top-left corner), colliding, a pixel of r2 that r1 does not cover
            "240, 160, true,  230, 245",   // r1 inside r2
            "330, 205, true,  240, 170",   // r1 over r2's bottom-right corner
            "20,  300, false, 300, 200",   // far apart
            "100, 160, false, 300, 200",   // r1's right edge on r2's left edge (x = 220): side by side
            "101, 160, true,  300, 200",   // one pixel further: overlapping
            "380, 160, false, 300, 200",   // r1's left edge on r2's right edge (x = 380)
            "379, 160, true,  300, 200",
            "240, 70,  false, 300, 230",   // r1's bottom edge on r2's top edge (y = 150)
            "240, 71,  true,  300, 230",
            "240, 250, false, 300, 170",   // r1's top edge on r2's bottom edge (y = 250)
            "240, 249, true,  300, 170",
            "100, 70,  false, 300, 200",   // corner to corner
    })
    void r2_isRedOnlyWhileTheRectanglesOverlap(int mx, int my, boolean colliding, int px, int py) {
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect())
                .script(new Script().frames(5).mouse(1, mx, my)).run();
        SketchPixels.assertColour(r.lastFrame(), px, py, colliding ? Palette.HIT : Palette.MISS, "r2");
        // r1 hangs from the mouse by its corner: blue (see-through) just inside the corner,
        // nothing blue just left of it.
        assertTrue(blue(r.lastFrame().get(mx + 3, my + 3)) > 130, "r1's fill just inside its top-left corner");
        assertTrue(blue(r.lastFrame().get(mx - 4, my + 40)) < 110, "no r1 left of the mouse");
    }

    private static int blue(int argb) {
        return argb & 0xFF;
    }

    @Test
    void mouseSweep_r2sColourIsTheLibrarysAnswer_forR1AtTheMouseCorner() {
        Script script = new Script().frames(700);
        for (int f = 1; f <= 700; f++) {
            script.mouse(f, (f * 13) % 600, 20 + (f / 25) * 13 % 360);
        }
        int[] seen = {0, 0};
        SketchRun.of(new S05_RectRect()).script(script).everyFrame(s -> {
            boolean colliding = Collide.rectRect(s.mouseX, s.mouseY, 120, 80, 220, 150, 160, 100);
            // r2's corner farthest from r1 is never under r1 (r1 is smaller than r2).
            int cx = s.mouseX + 60 < 300 ? 376 : 223;
            int cy = s.mouseY + 40 < 200 ? 246 : 153;
            assertEquals(Integer.toHexString(colliding ? Palette.HIT : Palette.MISS), Integer.toHexString(s.get(cx, cy)),
                    "r2 at (" + cx + ", " + cy + ") with the mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            seen[colliding ? 1 : 0]++;
        }).run();
        assertTrue(seen[0] > 100 && seen[1] > 50, "frames apart and overlapping: " + seen[0] + ", " + seen[1]);
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 330, 205).key(3, 'd').key(8, 'd');
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 500, "the overlay draws the four comparisons and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
