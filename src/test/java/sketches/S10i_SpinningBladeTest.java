package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/** S10i_SpinningBlade: the turning sweep stops the blade at every post; the end-of-frame test lets it pass through. */
class S10i_SpinningBladeTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void turningSweep_bouncesOffThePosts_andNeverPassesThrough() {
        SketchRun.Result<S10i_SpinningBlade> r = SketchRun.of(new S10i_SpinningBlade()).script(new Script().frames(120)).run();
        assertEquals(0, r.sketch().passedThrough, "posts passed through");
        assertTrue(r.sketch().hits >= 5, "hits: " + r.sketch().hits);
    }

    @Test
    void endOfFrameTest_passesThroughThePosts() {
        SketchRun.Result<S10i_SpinningBlade> r = SketchRun.of(new S10i_SpinningBlade())
                .script(new Script().frames(120).key(1, 't')).run();
        assertTrue(r.sketch().passedThrough >= 5, "passed through: " + r.sketch().passedThrough);
    }

    @Test
    void onAHitFrame_onlyThePostHitIsRed() {
        int[] hitFrames = new int[1];
        SketchRun.of(new S10i_SpinningBlade()).script(new Script().frames(120)).everyFrame(s -> {
            if (s.lastHit == null) {
                return;
            }
            hitFrames[0]++;
            int lit = 0;
            for (int f : s.flash) {
                lit += f > 0 ? 1 : 0;   // after drawing: the one just hit still has frames left
            }
            assertEquals(1, lit, "frame " + s.frameCount + ": one post red, the one hit");
        }).run();
        assertTrue(hitFrames[0] >= 5, "hit frames: " + hitFrames[0]);
    }
}
