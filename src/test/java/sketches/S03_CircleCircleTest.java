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
 * S03_CircleCircle: the centre circle (300, 200, radius 100) is red while the mouse circle
 * (radius 75) overlaps it, green when it is apart or only touching (distance exactly 175).
 */
class S03_CircleCircleTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): colliding {2}")
    @CsvSource({
            // mouse x, y, colliding, a pixel of the centre circle away from the mouse circle
            "180, 290, true,  360, 160",   // distance 150 (120, 90): overlapping
            "300, 200, true,  388, 200",   // same centre
            "60,  60,  false, 360, 160",   // far apart
            "440, 305, false, 240, 160",   // distance exactly 175 (140, 105): touching is not colliding
            "439, 305, true,  240, 160",   // a pixel closer: overlapping
            "475, 200, false, 240, 200",   // touching on the right
            "474, 200, true,  240, 200",
            "300, 375, false, 300, 130",   // touching below
            "300, 374, true,  300, 130",
    })
    void centreCircle_isRedOnlyWhileTheCirclesOverlap(int mx, int my, boolean colliding, int px, int py) {
        SketchRun.Result<S03_CircleCircle> r = SketchRun.of(new S03_CircleCircle())
                .script(new Script().frames(5).mouse(1, mx, my)).run();
        S03_CircleCircle s = r.sketch();
        assertEquals(Collide.circleCircle(mx, my, s.smallCircleRadius, 300, 200, s.bigCircleRadius), s.colliding,
                "the sketch's answer is the library's");
        assertEquals(colliding, s.colliding, "colliding");
        SketchPixels.assertColour(r.lastFrame(), px, py, colliding ? Palette.HIT : Palette.MISS, "centre circle");
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 180, 290).key(3, 'd').key(8, 'd');
        SketchRun.Result<S03_CircleCircle> r = SketchRun.of(new S03_CircleCircle()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 500, "the overlay draws the distance, both radii and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
