package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Circle;
import hitbox.Collide;
import hitbox.Hit;
import hitbox.Rect;
import hitbox.Sweep;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10e_FastObjects in a window: what a window can show, in a few shots. The sketch moves the
 * swept ball by Sweep's answer and the naive one by move-then-test, and the naive one tunnels
 * when fast. That Sweep never tunnels at any speed or start is a property of the library,
 * checked headless in {@code hitbox.SweepNoTunnelSketchCaseTest} on this sketch's scene.
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

    @Test
    void at80_theSweptBallStopsWhereSweepSays_touchingTheWall() {
        // The first shot at 80 px/frame, with the sketch's own start: a few frames.
        int[] stops = {0};
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects()).frames(30).everyFrame(s -> {
            S10e_FastObjects.Ball b = s.swept;
            assertTrue(b.x < s.wallX, "the swept ball's centre stays left of the wall, x = " + b.x);
            if (b.hitNow) {
                stops[0]++;
                // The step it was about to take, asked of the library afresh.
                Hit expected = Sweep.timeOfImpact(new Circle(s.impactFromX, b.y, s.r), b.vx, 0,
                        new Rect(s.wallX, s.wallY, s.wallW, s.wallH));
                assertNotNull(expected, "Sweep finds the wall on that step");
                assertEquals(expected, s.impact, "the sketch's answer is Sweep's");
                assertEquals(s.impactFromX + expected.t() * b.vx, b.x, 1e-3f, "it moved t of the step");
                assertEquals(s.wallX - s.r, b.x, 1e-3f, "and stopped touching the wall");
                assertFalse(Collide.circleRect(b.x - 1e-3f, b.y, s.r, s.wallX, s.wallY, s.wallW, s.wallH), "not inside it");
            }
        }).run();
        assertEquals(80, (int) r.sketch().speeds[r.sketch().speedIndex]);
        assertTrue(stops[0] > 0, "it stopped at the wall (and the finished shot is held there)");
        assertTrue(r.sketch().swept.done && r.sketch().hold > 0, "the shot is over and on show");
    }

    @Test
    void at600_theNaiveBallGoesThroughEveryShot_theSweptOneNever() {
        // At 600 px/frame the first step already lands past the window: a shot takes one frame.
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects()).script(atSpeed(8, 160)).run();
        S10e_FastObjects s = r.sketch();
        assertEquals(600, (int) s.speeds[s.speedIndex], "speed");
        assertTrue(s.shots >= 3, "several shots, " + s.shots);
        assertEquals(s.shots, s.naiveTunnels, "the naive ball went through every shot");
        assertEquals(0, s.sweptTunnels, "the swept ball never did");
    }

    @Test
    void at20_theNaiveBallThatIsCaught_stopsInsideTheWall() {
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects())
                .script(atSpeed(3, 60)).run();
        S10e_FastObjects s = r.sketch();
        S10e_FastObjects.Ball b = s.naive;
        assertTrue(b.done && b.hitNow, "the naive test caught the ball");
        assertTrue(Collide.circleRect(b.x, b.y, s.r, s.wallX, s.wallY, s.wallW, s.wallH),
                "caught after the move: it is already inside the wall");
        assertEquals(0, s.naiveTunnels, "and did not go through");
    }

    @Test
    void finishedShot_showsTheSweptBallRedAtTheWall_andTheOverlayToggles() {
        // At 1200 px/frame a shot is over in one frame; the next 50 frames hold still.
        Script script = atSpeed(9, 40).key(20, 'd').key(30, 'd');
        SketchRun.Result<S10e_FastObjects> r = SketchRun.of(new S10e_FastObjects()).script(script)
                .capture(18).capture(25).run();
        S10e_FastObjects s = r.sketch();
        assertTrue(s.naive.done && s.swept.done && s.hold > 0, "holding a finished shot");
        assertTrue(s.naive.x > s.width, "the naive ball is past the window, x = " + s.naive.x);
        PImage off = r.frame(18);
        SketchPixels.assertColour(off, Math.round(s.swept.x), Math.round(s.swept.y), Palette.HIT, "swept ball at the wall");
        SketchPixels.assertColour(off, Math.round(s.wallX + 3), 20 + Math.round(s.wallY), Palette.OBSTACLE, "the wall");
        assertTrue(SketchPixels.differing(off, r.frame(25)) > 1000,
                "the overlay draws the sampled positions, the step and t");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
