package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
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
 * S10e_FastObjects: two balls shot at a 6 px wall at the same speed; the naive one (move,
 * then Collide.circleRect) jumps over it once a step is longer than ball and wall together
 * (30 px), the swept one (Sweep.circleRectHit) never does, at any speed.
 */
class S10e_FastObjectsTest {

    /** The sketch starts at speeds[5] = 80 px/frame. */
    private static final int START_INDEX = 5;

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** A script that steps the speed from 80 px/frame to the given index, one key a frame. */
    private static Script atSpeed(int index, int frames) {
        Script script = new Script().frames(frames);
        int presses = Math.abs(index - START_INDEX);
        for (int i = 0; i < presses; i++) {
            script.key(1 + 2 * i, index > START_INDEX ? '+' : '-');
        }
        return script;
    }

    @ParameterizedTest(name = "{1} px/frame: the naive ball goes through {2}")
    @CsvSource({
            // speed index, px/frame, how often the naive ball goes through
            "0,  2,    never",
            "2,  10,   never",
            "3,  20,   never",       // a step shorter than 30 px always lands in the wall
            "5,  80,   sometimes",
            "6,  150,  sometimes",
            "7,  300,  sometimes",
            "8,  600,  always",      // the first step already lands past the window
            "9,  1200, always",
            "11, 5000, always",
    })
    void sweptBall_neverGoesThroughTheWall_theNaiveOneDoesWhenFast(int index, int speed, String naive) {
        int[] sweptStops = {0};
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects())
                .script(atSpeed(index, speed < 20 ? 3000 : 1500))
                .everyFrame(s -> {
                    assertFalse(s.sweptTunnelled, "the swept ball went past the wall at x = " + s.sweptX);
                    assertTrue(s.sweptX < s.wallX, "the swept ball's centre stays left of the wall, x = " + s.sweptX);
                    // It may touch the wall, never reach into it (by more than float rounding).
                    assertFalse(Collide.circleRect(s.sweptX - 1e-3f, s.sweptY, s.r, s.wallX, s.wallY, s.wallW, s.wallH),
                            "the swept ball overlaps the wall at x = " + s.sweptX);
                    if (s.sweptHitNow) {
                        sweptStops[0]++;
                        assertNotNull(s.impact);
                        assertEquals(s.wallX - s.r, s.sweptX, 1e-3f, "stopped touching the wall");
                        assertEquals(s.impactFromX + s.impact.t() * (s.impactToX - s.impactFromX), s.sweptX, 1e-3f,
                                "it moved t of the step");
                    }
                })
                .run();
        S10e_FastObjects s = r.sketch();
        assertEquals(speed, (int) s.speeds[s.speedIndex], "speed");
        assertTrue(s.shots >= 5, "several shots were fired, " + s.shots);
        assertEquals(0, s.sweptTunnels, "the swept ball never went through");
        assertTrue(sweptStops[0] >= s.shots, "the swept ball stopped at the wall every shot");
        switch (naive) {
            case "never" -> assertEquals(0, s.naiveTunnels, "the naive ball went through " + s.naiveTunnels + " of " + s.shots);
            case "always" -> assertEquals(s.shots, s.naiveTunnels, "the naive ball went through every shot");
            default -> assertTrue(s.naiveTunnels > 0 && s.naiveTunnels < s.shots,
                    "the naive ball went through some shots, not all: " + s.naiveTunnels + " of " + s.shots);
        }
    }

    @Test
    void naiveBall_thatIsCaught_stopsInsideTheWall() {
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects())
                .script(atSpeed(3, 60)).run();
        S10e_FastObjects s = r.sketch();
        assertTrue(s.naiveDone && s.naiveHitNow, "the naive test caught the ball");
        assertTrue(Collide.circleRect(s.naiveX, s.naiveY, s.r, s.wallX, s.wallY, s.wallW, s.wallH),
                "caught after the move: it is already inside the wall");
    }

    @Test
    void finishedShot_showsTheSweptBallRedAtTheWall_andTheOverlayToggles() {
        // At 1200 px/frame a shot is over in one frame; the next 50 frames hold still.
        Script script = atSpeed(9, 40).key(20, 'd').key(30, 'd');
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects()).script(script)
                .capture(18).capture(25).run();
        S10e_FastObjects s = r.sketch();
        assertTrue(s.naiveDone && s.sweptDone && s.hold > 0, "holding a finished shot");
        assertTrue(s.naiveX > s.width, "the naive ball is past the window, x = " + s.naiveX);
        PImage off = r.frame(18);
        SketchPixels.assertColour(off, Math.round(s.sweptX), Math.round(s.sweptY), Palette.HIT, "swept ball at the wall");
        SketchPixels.assertColour(off, Math.round(s.wallX + 3), 20 + Math.round(s.wallY), Palette.OBSTACLE, "the wall");
        assertTrue(SketchPixels.differing(off, r.frame(25)) > 1000,
                "the overlay draws the sampled positions, the step and t");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
