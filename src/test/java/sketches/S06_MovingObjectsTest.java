package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.Edges;
import hitbox.Motion;
import hitbox.processing.Overlay;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/** The box looks one frame ahead on each axis, so it bounces off the block's side it hits and never enters it. */
class S06_MovingObjectsTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void tenThousandFrames_neverOverlapsTheBlock_andStaysInTheWindow() {
        SketchRun.of(new S06_MovingObjects()).frames(10_000).everyFrame(s -> {
            assertFalse(Collide.rectRect(s.x, s.y, s.w, s.h, s.blockX, s.blockY, s.blockW, s.blockH),
                    "the box overlaps the block at (" + s.x + ", " + s.y + ")");
            assertEquals(Edges.NONE, Edges.rectCrossed(s.x, s.y, s.w, s.h, s.width, s.height),
                    "the box left the window at (" + s.x + ", " + s.y + ")");
        }).run();
    }

    @Test
    void bouncesOffTheBlock_reversingOnlyTheBlockedSpeed_nextToIt() {
        float[] prev = new float[4];  // x, y, vx, vy after the previous frame
        int[] bounces = new int[2];   // off a left/right side, off the top/bottom
        SketchRun.of(new S06_MovingObjects()).frames(3000).everyFrame(s -> {
            if (s.frameCount > 1 && s.blocked != Motion.NONE) {
                float px = prev[0], py = prev[1], pvx = Math.abs(prev[2]), pvy = Math.abs(prev[3]);
                // Within one frame's move of the block: the box grown by its speed reaches into it.
                assertTrue(Collide.rectRect(px - pvx, py - pvy, s.w + 2 * pvx, s.h + 2 * pvy, s.blockX, s.blockY, s.blockW, s.blockH),
                        "a bounce far from the block, at (" + px + ", " + py + ")");
                if (Motion.has(s.blocked, Motion.X)) {
                    assertEquals(-prev[2], s.vx, "vx reversed");
                    bounces[0]++;
                } else {
                    assertEquals(prev[2], s.vx, "vx kept when only y is blocked");
                }
                if (Motion.has(s.blocked, Motion.Y)) {
                    assertEquals(-prev[3], s.vy, "vy reversed");
                    bounces[1]++;
                } else {
                    assertEquals(prev[3], s.vy, "vy kept when only x is blocked");
                }
            }
            prev[0] = s.x;
            prev[1] = s.y;
            prev[2] = s.vx;
            prev[3] = s.vy;
        }).run();
        assertTrue(bounces[0] > 0, "it bounced off a left or right side of the block");
        assertTrue(bounces[1] > 0, "it bounced off the top or bottom of the block");
    }

    @Test
    void overlay_drawsTheNextPositionBoxes() {
        // Paused from frame 11, so frames 20 (maths off) and 22 (maths on) show the same state.
        SketchRun.Result<S06_MovingObjects> r = SketchRun.of(new S06_MovingObjects())
                .script(new Script().frames(22).key(10, 'p').key(20, 'd'))
                .capture(20).capture(22).run();
        PImage off = r.frame(20);
        PImage on = r.frame(22);
        assertTrue(SketchPixels.differing(off, on) > 500, "the overlay changes what is drawn");
        // Below the labels at the top (the frames-inside counter is green too).
        assertEquals(0, SketchPixels.count(off, 0, 52, 599, 399, Overlay.MISS), "no 'not colliding' green without the overlay");
        assertTrue(SketchPixels.count(on, 0, 52, 599, 399, Overlay.MISS) > 100, "the free next-position boxes and their labels are green");
    }

    /** The box's place and speed after each frame, from frame 1. */
    private static List<float[]> track(Script script) {
        List<float[]> states = new ArrayList<>();
        states.add(null);
        SketchRun.of(new S06_MovingObjects()).script(script)
                .everyFrame(s -> states.add(new float[] {s.x, s.y, s.vx, s.vy, s.framesInside})).run();
        return states;
    }

    private static boolean inside(float[] state) {
        return Collide.rectRect(state[0], state[1], 40, 40, 220, 140, 160, 100);
    }

    @Test
    void tutorialsCode_aimedAtTheCorner_endsAFrameInsideTheBlock() {
        // t after frame 1, c after frame 10: frame 11 makes the diagonal move into the corner.
        List<float[]> states = track(new Script().frames(20).key(1, 't').key(10, 'c'));
        assertFalse(inside(states.get(10)));
        assertTrue(inside(states.get(11)), "neither one-axis check saw the corner: the box is in the block");
        assertEquals(1, states.get(11)[4], "and the counter says so");
        assertTrue(states.get(12)[2] < 0 && states.get(12)[3] < 0, "from in there both checks hit: both speeds reverse");
        assertFalse(inside(states.get(12)), "and it comes back out the way it went in");
        assertEquals(1, states.get(20)[4]);
    }

    @Test
    void library_aimedAtTheCorner_bouncesBackWithoutGoingIn() {
        List<float[]> states = track(new Script().frames(20).key(10, 'c'));
        for (int f = 1; f <= 20; f++) {
            assertFalse(inside(states.get(f)), "frame " + f);
        }
        assertTrue(states.get(11)[2] < 0 && states.get(11)[3] < 0, "Motion.rectBlocked reported both axes: both reversed");
        assertEquals(0, states.get(20)[4]);
    }

    @Test
    void tutorialsCode_checksTheWindowWhereTheBoxIs_soItPokesOut() {
        List<float[]> states = track(new Script().frames(600).key(1, 't'));
        boolean pokedOut = false;
        for (int f = 2; f < states.size(); f++) {
            float[] s = states.get(f);
            pokedOut |= s[0] < 0 || s[0] + 40 > 600 || s[1] < 0 || s[1] + 40 > 400;
        }
        assertTrue(pokedOut, "the tutorial's window check lets the box out for a frame");
    }
}
