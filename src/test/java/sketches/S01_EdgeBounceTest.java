package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Edges;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

class S01_EdgeBounceTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void bounce_ballStaysInsideTheWindow_overThousandsOfFrames() {
        int[] edgesCrossed = new int[1];
        SketchRun.of(new S01_EdgeBounce()).frames(5000)
                .everyFrame(s -> {
                    assertEquals(Edges.NONE, Edges.circleCrossed(s.x, s.y, s.r, s.width, s.height),
                            "ball at (" + s.x + ", " + s.y + ") is past an edge");
                    edgesCrossed[0] |= s.crossedThisFrame;
                })
                .run();
        assertEquals(Edges.LEFT | Edges.RIGHT | Edges.TOP | Edges.BOTTOM, edgesCrossed[0],
                "in 5000 frames the ball reaches and bounces off all four edges");
    }

    @Test
    void wrap_ballLeavesOneSideAndComesBackOnTheOther() {
        boolean[] wrapped = new boolean[1];
        float[] previousX = {Float.NaN};
        SketchRun.of(new S01_EdgeBounce()).script(new Script().frames(400).key(1, 'w'))
                .everyFrame(s -> {
                    // Moving right at 4.5 a frame, x only ever falls when it wraps to the left.
                    if (s.x < previousX[0]) {
                        wrapped[0] = true;
                        assertTrue(s.x <= 0, "reappears at the left edge, was x = " + s.x);
                    }
                    previousX[0] = s.x;
                    assertTrue(s.x >= -s.r && s.x <= s.width + s.r, "stays within one radius of the window");
                })
                .run();
        assertTrue(wrapped[0], "the ball wrapped around");
    }

    @Test
    void stop_ballStopsAtTheEdgesItReaches_andBounceStartsItAgain() {
        SketchRun.Result<S01_EdgeBounce> stopped = SketchRun.of(new S01_EdgeBounce())
                .script(new Script().frames(300).key(1, 's')).run();
        S01_EdgeBounce s = stopped.sketch();
        assertEquals(0f, s.vx, "stopped across");
        assertEquals(0f, s.vy, "stopped down");
        assertEquals(Edges.NONE, Edges.circleCrossed(s.x, s.y, s.r, s.width, s.height));

        S01_EdgeBounce again = SketchRun.of(new S01_EdgeBounce())
                .script(new Script().frames(320).key(1, 's').key(300, 'b')).run().sketch();
        assertTrue(again.vx != 0 && again.vy != 0, "b sets it moving again");
    }

    @Test
    void overlayKey_drawsTheEdgeComparisons_andHidesThemAgain() {
        SketchRun.Result<S01_EdgeBounce> r = SketchRun.of(new S01_EdgeBounce())
                .script(new Script().frames(3).key(1, 'd'))
                .capture(1).capture(2).run();
        assertTrue(r.sketch().showMaths);
        // The ball moves between frames; the overlay's guides and labels add far more.
        assertTrue(SketchPixels.differing(r.frame(1), r.frame(2)) > 2000, "the overlay appears");
        assertTrue(!SketchRun.of(new S01_EdgeBounce()).script(new Script().frames(4).key(1, 'd').key(2, 'd'))
                .run().sketch().showMaths, "a second d hides it");
    }
}
