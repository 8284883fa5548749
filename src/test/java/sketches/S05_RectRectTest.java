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
 * S05_RectRect: r2 (220, 150, 160 x 100) is red while r1 (120 x 80, centred on the mouse)
 * overlaps it, green when apart or side by side (sharing an edge or a corner).
 */
class S05_RectRectTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): colliding {2}")
    @CsvSource({
            // mouse x, y, colliding, a pixel of r2 that r1 does not cover
            "300, 200, true,  230, 245",   // r1 inside r2's middle
            "420, 272, true,  240, 240",   // r1 over r2's bottom-right corner
            "60,  60,  false, 300, 200",   // far apart
            "160, 200, false, 300, 200",   // r1's right edge on r2's left edge (x = 220): side by side
            "161, 200, true,  300, 200",   // one pixel further: overlapping
            "440, 200, false, 300, 200",   // r1's left edge on r2's right edge (x = 380)
            "439, 200, true,  300, 200",
            "300, 110, false, 300, 230",   // r1's bottom edge on r2's top edge (y = 150)
            "300, 111, true,  300, 230",
            "300, 290, false, 300, 170",   // r1's top edge on r2's bottom edge (y = 250)
            "300, 289, true,  300, 170",
            "160, 110, false, 300, 200",   // corner to corner
    })
    void r2_isRedOnlyWhileTheRectanglesOverlap(int mx, int my, boolean colliding, int px, int py) {
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect())
                .script(new Script().frames(5).mouse(1, mx, my)).run();
        S05_RectRect s = r.sketch();
        assertEquals(mx - s.r1w / 2, s.r1x, "r1 is centred on the mouse");
        assertEquals(Collide.rectRect(s.r1x, s.r1y, s.r1w, s.r1h, s.r2x, s.r2y, s.r2w, s.r2h), s.colliding,
                "the sketch's answer is the library's");
        assertEquals(colliding, s.colliding, "colliding");
        SketchPixels.assertColour(r.lastFrame(), px, py, colliding ? Palette.HIT : Palette.MISS, "r2");
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 420, 272).key(3, 'd').key(8, 'd');
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 500, "the overlay draws the four comparisons and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
