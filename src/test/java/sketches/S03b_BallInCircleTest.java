package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S03b_BallInCircle: the ball bounces inside the window and is red exactly while it overlaps
 * the centre circle.
 */
class S03b_BallInCircleTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void lKey_hitboxsTests_ballStaysInTheWindow_andIsRedExactlyWhileItOverlapsTheCircle() {
        int[] insideFrames = {0};
        int[] outsideFrames = {0};
        int[] bounces = new int[4];  // left, right, top, bottom
        float[] lastSpeed = {Float.NaN, Float.NaN};
        // Two clicks put the ball in the corners: the clamp must keep it in the window.
        Script script = new Script().frames(3000).key(1, 'l').click(1000, 2, 2).click(2000, 599, 399);
        SketchRun.of(new S03b_BallInCircle()).script(script).everyFrame(s -> {
            if (s.frameCount < 2) {
                return;   // frame 1 ran the tutorial's tests, before l
            }
            assertTrue(s.hitboxDecides);
            assertTrue(s.x - s.r >= 0 && s.x + s.r <= s.width, "ball inside the window across, x = " + s.x);
            assertTrue(s.y - s.r >= 0 && s.y + s.r <= s.height, "ball inside the window down, y = " + s.y);
            boolean overlaps = Collide.circleCircle(s.x, s.y, s.r, s.circleCenterX, s.circleCenterY, s.circleRadius);
            assertEquals(overlaps, s.inside, "the sketch's answer is the library's");
            // What the ball is drawn in, read at its centre; not on the click frames, whose
            // click moves the ball just after the frame is drawn.
            if (s.frameCount != 1000 && s.frameCount != 2000) {
                assertEquals(Integer.toHexString(overlaps ? Palette.HIT : Palette.MISS),
                        Integer.toHexString(s.get(Math.round(s.x), Math.round(s.y)) | 0xFF000000), "ball colour");
            }
            if (overlaps) {
                insideFrames[0]++;
            } else {
                outsideFrames[0]++;
            }
            if (!Float.isNaN(lastSpeed[0])) {
                if (lastSpeed[0] < 0 && s.xSpeed > 0) bounces[0]++;
                if (lastSpeed[0] > 0 && s.xSpeed < 0) bounces[1]++;
                if (lastSpeed[1] < 0 && s.ySpeed > 0) bounces[2]++;
                if (lastSpeed[1] > 0 && s.ySpeed < 0) bounces[3]++;
            }
            lastSpeed[0] = s.xSpeed;
            lastSpeed[1] = s.ySpeed;
        }).run();
        assertTrue(insideFrames[0] > 50, "the ball passes through the circle, frames: " + insideFrames[0]);
        assertTrue(outsideFrames[0] > 50, "the ball leaves the circle, frames: " + outsideFrames[0]);
        for (int i = 0; i < 4; i++) {
            assertTrue(bounces[i] > 0, "bounced off every edge (left, right, top, bottom): "
                    + bounces[0] + ", " + bounces[1] + ", " + bounces[2] + ", " + bounces[3]);
        }
    }

    @Test
    void ball_isDrawnInItsColour() {
        // Remember where the ball was on two frames, then look at those pixels.
        Map<Integer, float[]> at = new HashMap<>();
        SketchRun.Result<S03b_BallInCircle> r = SketchRun.of(new S03b_BallInCircle())
                .script(new Script().frames(100)).capture(30).capture(100)
                .everyFrame(s -> at.put(s.frameCount, new float[] {s.x, s.y, s.inside ? 1 : 0}))
                .run();
        float[] first = at.get(30);
        float[] second = at.get(100);
        assertTrue(first[2] != second[2], "one frame with the ball in the circle and one without");
        for (int frame : new int[] {30, 100}) {
            float[] p = at.get(frame);
            SketchPixels.assertColour(r.frame(frame), Math.round(p[0]), Math.round(p[1]),
                    p[2] == 1 ? Palette.HIT : Palette.MISS, "ball on frame " + frame);
        }
    }

    @Test
    void byDefault_theTutorialsTests_theCentreGoesToTheEdge_andDistSaysInside_andTheColourFollows() {
        boolean[] halfOut = {false};
        int[] insideFrames = {0};
        SketchRun.of(new S03b_BallInCircle()).script(new Script().frames(1500)).everyFrame(s -> {
            assertFalse(s.hitboxDecides);
            // Section 1's test looks at the centre: the ball goes half out before it turns.
            halfOut[0] |= s.x - s.r < 0 || s.x + s.r > s.width || s.y - s.r < 0 || s.y + s.r > s.height;
            assertTrue(s.x > -Math.abs(s.xSpeed) && s.x < s.width + Math.abs(s.xSpeed), "the centre turns back at the edge, x = " + s.x);
            boolean dist = Math.hypot(s.x - s.circleCenterX, s.y - s.circleCenterY) < s.r + s.circleRadius;
            assertEquals(dist, s.inside, "the tutorial's dist() test, frame " + s.frameCount);
            if (s.x - s.r > 10 && s.x + s.r < s.width - 10 && s.y - s.r > 10 && s.y + s.r < s.height - 30) {   // away from the edges' marks
                assertEquals(Integer.toHexString(dist ? Palette.HIT : Palette.MISS),
                        Integer.toHexString(s.get(Math.round(s.x), Math.round(s.y)) | 0xFF000000), "ball colour, frame " + s.frameCount);
            }
            insideFrames[0] += s.inside ? 1 : 0;
        }).run();
        assertTrue(halfOut[0], "with the tutorial's edges the ball goes half out of the window");
        assertTrue(insideFrames[0] > 20, "and it passes through the circle: " + insideFrames[0]);
    }

    @Test
    void spaceKey_pausesTheBall() {
        SketchRun.Result<S03b_BallInCircle> r = SketchRun.of(new S03b_BallInCircle())
                .script(new Script().frames(40).key(10, ' ')).run();
        S03b_BallInCircle s = r.sketch();
        // Paused after frame 10's draw(): 10 steps taken.
        assertEquals(110 + 10 * 3.3f, s.x, 1e-3f, "x after 10 steps");
        assertTrue(s.paused);
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        // Paused first, so the frames differ only by the overlay.
        Script script = new Script().frames(14).key(1, ' ').key(4, 'd').key(9, 'd');
        SketchRun.Result<S03b_BallInCircle> r = SketchRun.of(new S03b_BallInCircle()).script(script)
                .capture(3).capture(7).run();
        PImage off = r.frame(3);
        assertTrue(SketchPixels.differing(off, r.frame(7)) > 500, "the overlay draws the distance, both radii and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
