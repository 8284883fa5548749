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
 * S03_CircleCircle, the tutorial's program: the mouse circle (radius 75) is red while it
 * overlaps the big circle (300, 200, radius 100, a white outline), green when it is apart or
 * only touching (distance exactly 175).
 */
class S03_CircleCircleTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): colliding {2}")
    @CsvSource({
            // mouse x, y, colliding, a pixel of the mouse circle off the big circle's outline
            "180, 290, true,  150, 330",   // distance 150 (120, 90): overlapping
            "300, 200, true,  300, 240",   // same centre
            "60,  330, false, 40,  340",   // far apart
            "440, 305, false, 470, 330",   // distance exactly 175 (140, 105): touching is not colliding
            "439, 305, true,  470, 330",   // a pixel closer: overlapping
            "475, 200, false, 520, 200",   // touching on the right
            "474, 200, true,  520, 200",
            "300, 375, false, 300, 360",   // touching below
            "300, 374, true,  300, 360",
    })
    void mouseCircle_isRedOnlyWhileTheCirclesOverlap(int mx, int my, boolean colliding, int px, int py) {
        SketchRun.Result<S03_CircleCircle> r = SketchRun.of(new S03_CircleCircle())
                .script(new Script().frames(5).mouse(1, mx, my)).run();
        S03_CircleCircle s = r.sketch();
        assertEquals(colliding, Collide.circleCircle(mx, my, s.smallCircleRadius, 300, 200, s.bigCircleRadius), "the library");
        assertEquals(colliding, Math.hypot(mx - 300, my - 200) < s.bigCircleRadius + s.smallCircleRadius, "the tutorial's dist() test");
        SketchPixels.assertColour(r.lastFrame(), px, py, colliding ? Palette.HIT : Palette.MISS, "mouse circle");
        SketchPixels.assertColour(r.lastFrame(), 300, 100, 0xFFFFFFFF, "the big circle: a white outline");
        SketchPixels.assertColour(r.lastFrame(), 300, 130, mx == 300 && my == 200 ? Palette.HIT : Palette.BACKGROUND,
                "inside the big circle: not filled (unless the mouse circle covers it)");
    }

    @ParameterizedTest(name = "l pressed {0} times")
    @CsvSource({"0", "1", "2"})
    void mouseSweep_theColourFollowsTheTutorialsIf_orCollideCircleCircleAfterL_andTheyAgree(int lPresses) {
        Script script = SketchPixels.lThenMouse(600, lPresses, f -> new int[] {40 + (f * 17) % 520, 40 + (f / 20) * 11 % 320});
        int[] seen = {0, 0};
        SketchRun.Result<S03_CircleCircle> r = SketchRun.of(new S03_CircleCircle()).script(script).everyFrame(s -> {
            if (s.frameCount < 5) {
                return;
            }
            float d = processing.core.PApplet.dist(s.mouseX, s.mouseY, 300, 200);
            // The tutorial's if, as its section writes it.
            boolean tutorialsIf = d < s.bigCircleRadius + s.smallCircleRadius;
            boolean library = Collide.circleCircle(s.mouseX, s.mouseY, s.smallCircleRadius, 300, 200, s.bigCircleRadius);
            assertEquals(library, tutorialsIf, "mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            if (d < 1 || Math.abs(d + 60 - s.bigCircleRadius) < 5) {
                return;  // the pixel read below would sit on the big circle's outline
            }
            // A pixel of the small circle, 60 from its centre on the side away from the big one.
            int px = Math.round(s.mouseX + 60 * (s.mouseX - 300) / d);
            int py = Math.round(s.mouseY + 60 * (s.mouseY - 200) / d);
            if (px < 0 || py < 60 || px >= s.width || py >= 380) {
                return;  // off the window, or under the labels
            }
            boolean colliding = s.hitboxDecides ? library : tutorialsIf;
            assertEquals(Integer.toHexString(colliding ? Palette.HIT : Palette.MISS), Integer.toHexString(s.get(px, py) | 0xFF000000),
                    "the small circle at (" + px + ", " + py + ") with the mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            seen[colliding ? 1 : 0]++;
        }).run();
        assertEquals(lPresses % 2 == 1, r.sketch().hitboxDecides, "l hands the colour to Collide.circleCircle and back");
        assertTrue(seen[0] > 50 && seen[1] > 50, "frames apart and overlapping: " + seen[0] + ", " + seen[1]);
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
