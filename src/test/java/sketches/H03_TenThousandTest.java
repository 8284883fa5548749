package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.BroadPhase;
import hitbox.Collide;
import hitbox.Edges;
import hitbox.Rect;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * H03_TenThousand: 10,000 bouncers through a broad phase. Whichever structure the keys pick,
 * its pairs are brute force's; no bouncer ends a frame in an obstacle or out of the window;
 * brute force moves only its 1,500.
 */
class H03_TenThousandTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void tenThousandBouncers_neverInAnObstacle_norOutOfTheWindow() {
        int[] frames = {0};
        SketchRun.of(new H03_TenThousand()).frames(300).everyFrame(s -> {
            assertEquals(10_000, s.active);
            for (int i = 0; i < s.n; i++) {
                assertEquals(Set.of(), Edges.crossed(new Rect(s.x[i], s.y[i], s.size, s.size), s.width, s.height),
                        "bouncer " + i + " left the window at (" + s.x[i] + ", " + s.y[i] + ")");
                for (Rect o : s.obstacles) {
                    assertTrue(!Collide.rectRect(s.x[i], s.y[i], s.size, s.size, o.x(), o.y(), o.w(), o.h()),
                            "frame " + s.frameCount + ": bouncer " + i + " ends the frame inside obstacle " + o);
                }
            }
            frames[0]++;
        }).run();
        assertEquals(300, frames[0]);
    }

    @Test
    void eachStructure_reportsTheSamePairsAsBruteForce() {
        for (char key = '1'; key <= '5'; key++) {
            H03_TenThousand s = SketchRun.of(new H03_TenThousand()).script(new Script().frames(40).key(1, key)).run().sketch();
            BroadPhase picked = s.structures[key - '1'];
            assertEquals(key == '5' ? 1_500 : 10_000, s.active, picked + " moves this many bouncers");
            BroadPhase reference = BroadPhase.bruteForce();
            picked.forEachBox((id, x, y, w, h) -> reference.put(id, x, y, w, h));
            assertEquals(pairs(reference), pairs(picked), picked + ": the pairs of its boxes");
            assertEquals(s.pairsThisFrame, pairs(picked).size(), picked + ": the pairs the sketch saw this frame");
            assertTrue(s.stepMillis > 0, "the collision step is timed");
        }
    }

    private static Set<Long> pairs(BroadPhase bp) {
        Set<Long> out = new HashSet<>();
        bp.pairs((a, b) -> out.add((long) a << 32 | b));
        return out;
    }

    @Test
    void bruteForce_movesOnlyItsCap_theRestWaitForTheirStructure() {
        SketchRun.Result<H03_TenThousand> r = SketchRun.of(new H03_TenThousand())
                .script(new Script().frames(20).key(1, '5')).run();
        // The key comes after frame 1's draw: until then every bouncer moved, after it only 1,500.
        H03_TenThousand before = SketchRun.of(new H03_TenThousand()).frames(1).run().sketch();
        H03_TenThousand s = r.sketch();
        for (int i = 1_500; i < 10_000; i += 97) {
            assertEquals(before.x[i], s.x[i], "bouncer " + i + " waits under brute force");
        }
        assertEquals("bruteForce", s.structures[s.current].toString());
    }

    @Test
    void label_andOverlay_areDrawn() {
        SketchRun.Result<H03_TenThousand> off = SketchRun.of(new H03_TenThousand()).frames(30).run();
        SketchRun.Result<H03_TenThousand> on = SketchRun.of(new H03_TenThousand())
                .script(new Script().frames(30).mouse(1, 470, 330).key(2, 'd')).run();
        PImage a = off.lastFrame();
        PImage b = on.lastFrame();
        // The structure's name, the step time and the frame rate are always written top left.
        PImage other = SketchRun.of(new H03_TenThousand()).script(new Script().frames(30).key(1, '2')).run().lastFrame();
        assertTrue(SketchPixels.differing(a, other, 8, 8, 200, 22) > 50, "the label names the structure");
        assertTrue(SketchPixels.differing(a, b, 8, 60, 300, 130) > 300, "the maths is written under it");
        assertTrue(SketchPixels.differing(a, b, 370, 255, 570, 405) > 300, "the cells around the mouse");
    }
}
