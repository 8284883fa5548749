package sketches;

import hitbox.Rect;
import java.util.Set;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import hitbox.Collide;
import hitbox.Edges;
import hitbox.processing.Overlay;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * The bouncing rectangle looks one move ahead on each axis, so it bounces off the side of the
 * center rectangle it would hit; the tutorial's code misses the corner, Motion.rectBlocked does not.
 */
class S06_MovingObjectsTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void library_tenThousandFrames_neverOverlapsTheCenterRectangle_andStaysInTheWindow() {
        SketchRun.of(new S06_MovingObjects()).script(new Script().frames(10_000).key(1, 'l')).everyFrame(s -> {
            assertFalse(Collide.rectRect(s.bouncingRectX, s.bouncingRectY, s.bouncingRectWidth, s.bouncingRectHeight,
                    s.centerRectX, s.centerRectY, s.centerRectWidth, s.centerRectHeight),
                    "it overlaps the center rectangle at (" + s.bouncingRectX + ", " + s.bouncingRectY + ")");
            assertEquals(Set.of(), Edges.crossed(new Rect(s.bouncingRectX, s.bouncingRectY, s.bouncingRectWidth, s.bouncingRectHeight), s.width, s.height),
                    "it left the window at (" + s.bouncingRectX + ", " + s.bouncingRectY + ")");
        }).run();
    }

    /**
     * Both ways: a speed reverses when the move along its axis alone would collide with the
     * center rectangle, and neither changes far from it and from the window's edges.
     */
    @ParameterizedTest(name = "Motion.rectBlocked: {0}")
    @ValueSource(booleans = {false, true})
    void bouncesOffTheSideItWouldHit_lookingOneMoveAhead(boolean library) {
        float[] prev = new float[4];  // x, y, speed x, speed y after the previous frame
        int[] bounces = new int[2];   // off a left/right side, off the top/bottom
        Script script = new Script().frames(3000);
        if (library) {
            script.key(1, 'l');
        }
        SketchRun.of(new S06_MovingObjects()).script(script).everyFrame(s -> {
            float w = s.bouncingRectWidth, h = s.bouncingRectHeight;
            if (s.frameCount > 2) {
                float px = prev[0], py = prev[1], pvx = prev[2], pvy = prev[3];
                boolean across = Collide.rectRect(px + pvx, py, w, h, s.centerRectX, s.centerRectY, s.centerRectWidth, s.centerRectHeight);
                boolean down = Collide.rectRect(px, py + pvy, w, h, s.centerRectX, s.centerRectY, s.centerRectWidth, s.centerRectHeight);
                boolean diagonal = Collide.rectRect(px + pvx, py + pvy, w, h, s.centerRectX, s.centerRectY, s.centerRectWidth, s.centerRectHeight);
                boolean nearAnEdge = !Edges.crossed(new Rect(px - Math.abs(pvx), py - Math.abs(pvy), w + 2 * Math.abs(pvx), h + 2 * Math.abs(pvy)), s.width, s.height).isEmpty();
                if (across) {
                    assertEquals(-pvx, s.bouncingRectSpeedX, "the move across would collide: bouncingRectSpeedX *= -1, frame " + s.frameCount);
                    bounces[0]++;
                }
                if (down) {
                    assertEquals(-pvy, s.bouncingRectSpeedY, "the move down would collide: bouncingRectSpeedY *= -1, frame " + s.frameCount);
                    bounces[1]++;
                }
                if (!across && !down && !diagonal && !nearAnEdge) {
                    assertEquals(pvx, s.bouncingRectSpeedX, "nothing ahead: speed kept, frame " + s.frameCount);
                    assertEquals(pvy, s.bouncingRectSpeedY, "nothing ahead: speed kept, frame " + s.frameCount);
                }
            }
            prev[0] = s.bouncingRectX;
            prev[1] = s.bouncingRectY;
            prev[2] = s.bouncingRectSpeedX;
            prev[3] = s.bouncingRectSpeedY;
        }).run();
        assertTrue(bounces[0] > 0, "it bounced off a left or right side of the center rectangle");
        assertTrue(bounces[1] > 0, "it bounced off the top or bottom of the center rectangle");
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
                .everyFrame(s -> states.add(new float[] {s.bouncingRectX, s.bouncingRectY, s.bouncingRectSpeedX,
                        s.bouncingRectSpeedY, s.framesInside})).run();
        return states;
    }

    private static boolean inside(float[] state) {
        return Collide.rectRect(state[0], state[1], 40, 40, 220, 140, 160, 100);
    }

    @Test
    void tutorialsCode_aimedAtTheCorner_endsAFrameInsideTheBlock() {
        // The tutorial's code is the default; c after frame 10: frame 11 makes the diagonal move into the corner.
        List<float[]> states = track(new Script().frames(20).key(10, 'c'));
        assertFalse(inside(states.get(10)));
        assertTrue(inside(states.get(11)), "neither one-axis check saw the corner: the box is in the block");
        assertEquals(1, states.get(11)[4], "and the counter says so");
        assertTrue(states.get(12)[2] < 0 && states.get(12)[3] < 0, "from in there both checks hit: both speeds reverse");
        assertFalse(inside(states.get(12)), "and it comes back out the way it went in");
        assertEquals(1, states.get(20)[4]);
    }

    @Test
    void library_aimedAtTheCorner_bouncesBackWithoutGoingIn() {
        List<float[]> states = track(new Script().frames(20).key(1, 'l').key(10, 'c'));
        for (int f = 1; f <= 20; f++) {
            assertFalse(inside(states.get(f)), "frame " + f);
        }
        assertTrue(states.get(11)[2] < 0 && states.get(11)[3] < 0, "Motion.rectBlocked reported both axes: both reversed");
        assertEquals(0, states.get(20)[4]);
    }

    @Test
    void tutorialsCode_checksTheWindowWhereTheBoxIs_soItPokesOut() {
        List<float[]> states = track(new Script().frames(600));
        boolean pokedOut = false;
        for (int f = 2; f < states.size(); f++) {
            float[] s = states.get(f);
            pokedOut |= s[0] < 0 || s[0] + 40 > 600 || s[1] < 0 || s[1] + 40 > 400;
        }
        assertTrue(pokedOut, "the tutorial's window check lets the box out for a frame");
    }
}
