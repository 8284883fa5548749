package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10g_Quadtree: boxes drifting in a BroadPhase.quadtree(); every frame the boxes it marks as
 * in a pair, and those the mouse's query finds, are exactly the ones an all-pairs loop over
 * Collide.rectRect gives, with far fewer tests.
 */
class S10g_QuadtreeTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void everyFrame_pairsAndQuery_areTheAllPairsLoopsAnswers() {
        checkAgainstAllPairs(new Script().frames(400).mouse(1, 300, 200).mouse(150, 140, 130).key(200, '+').key(300, '-'), false);
    }

    @Test
    void rKey_theRTreeKind_dynamicTree_givesTheSameAnswers_andDrawsItsBoxes() {
        S10g_Quadtree s = checkAgainstAllPairs(new Script().frames(400).key(1, 'r').mouse(1, 300, 200)
                .mouse(150, 140, 130).key(200, '+').key(300, '-'), true);
        assertTrue(s.rTree, "r: the dynamic tree");
        assertTrue(s.tree.toString().toLowerCase().contains("tree") && !s.tree.toString().toLowerCase().contains("quad"),
                "the structure is the dynamic tree: " + s.tree);
        List<float[]> boxes = squares(s);
        assertTrue(boxes.size() > s.count, "a box per leaf and the boxes that hold them: " + boxes.size());
    }

    private static S10g_Quadtree checkAgainstAllPairs(Script script, boolean rTree) {
        long[] tests = {0, 0};
        SketchRun.Result<S10g_Quadtree> r = SketchRun.of(new S10g_Quadtree())
                .script(script)
                .everyFrame(s -> {
                    if (s.frameCount == 1 && rTree) {
                        return;  // r came after the first frame's draw
                    }
                    if (s.frameCount == 200 || s.frameCount == 300) {
                        return;  // + and - came after this frame's draw: the new count is drawn next frame
                    }
                    int pairs = 0;
                    boolean[] inPair = new boolean[s.count];
                    for (int i = 0; i < s.count; i++) {
                        for (int j = i + 1; j < s.count; j++) {
                            if (Collide.rectRect(s.x[i], s.y[i], s.w[i], s.h[i], s.x[j], s.y[j], s.w[j], s.h[j])) {
                                inPair[i] = true;
                                inPair[j] = true;
                                pairs++;
                            }
                        }
                    }
                    float qx = s.mouseX - s.queryW / 2, qy = s.mouseY - s.queryH / 2;
                    for (int i = 0; i < s.count; i++) {
                        assertEquals(inPair[i], s.hit[i], "frame " + s.frameCount + ": box " + i + " in a pair");
                        assertEquals(Collide.rectRect(qx, qy, s.queryW, s.queryH, s.x[i], s.y[i], s.w[i], s.h[i]), s.found[i],
                                "frame " + s.frameCount + ": box " + i + " found by the mouse's box");
                    }
                    assertEquals(pairs, s.pairCount, "frame " + s.frameCount + ": pairs");
                    tests[0] += s.pairChecks;
                    tests[1] += (long) s.count * (s.count - 1) / 2;
                }).run();
        assertTrue(tests[0] * 5 < tests[1], "the tree made " + tests[0] + " tests, an all-pairs loop " + tests[1]);
        return r.sketch();  // the instance that ran
    }

    @Test
    void squares_splitWhereBoxesCrowd_andMergeWhenTheyGo() {
        SketchRun.Result<S10g_Quadtree> start = SketchRun.of(new S10g_Quadtree()).frames(2).run();
        int before = squares(start.sketch()).size();
        assertTrue(before > 4, "150 boxes split the root: " + before + " squares");
        for (float[] q : squares(start.sketch())) {
            assertEquals(q[2], q[3], "a square");
            assertEquals(Math.getExponent(q[2]), Math.log(q[2]) / Math.log(2), 1e-9, "a power of two wide: " + q[2]);
        }
        Script more = new Script().frames(10);
        for (int i = 0; i < 8; i++) {
            more.key(1 + i, '+');
        }
        S10g_Quadtree crowded = SketchRun.of(new S10g_Quadtree()).script(more).run().sketch();
        assertEquals(350, crowded.count);
        int after = squares(crowded).size();
        assertTrue(after > before, "more boxes, more squares: " + before + " then " + after);
        Script fewer = new Script().frames(10);
        for (int i = 0; i < 6; i++) {
            fewer.key(1 + i, '-');
        }
        S10g_Quadtree sparse = SketchRun.of(new S10g_Quadtree()).script(fewer).run().sketch();
        assertEquals(25, sparse.count);
        assertEquals(25, sparse.tree.size(), "the removed boxes left the tree");
        assertTrue(squares(sparse).size() < before, "fewer boxes, squares merged: " + squares(sparse).size());
    }

    private static List<float[]> squares(S10g_Quadtree s) {
        List<float[]> out = new ArrayList<>();
        s.tree.cells((depth, x, y, w, h) -> out.add(new float[] {x, y, w, h}));
        return out;
    }

    @Test
    void overlay_writesTheTestCounts() {
        PImage off = SketchRun.of(new S10g_Quadtree()).frames(60).run().lastFrame();
        SketchRun.Result<S10g_Quadtree> on = SketchRun.of(new S10g_Quadtree()).script(new Script().frames(60).key(2, 'd')).run();
        assertTrue(on.sketch().showMaths);
        assertTrue(SketchPixels.differing(off, on.lastFrame(), 8, 8, 300, 50) > 300, "the counts are written top left");
        assertTrue(on.sketch().pairChecks > 0 && on.sketch().pairChecks < 150L * 149 / 2);
    }
}
