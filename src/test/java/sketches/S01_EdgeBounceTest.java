package sketches;

import hitbox.Circle;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Edges;
import hitbox.Side;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S01_EdgeBounce: the tutorial's code by default (the centre tested against 0, width, 0 and
 * height, the speed flipped) and Hitbox's after l (the ball's edge tested, the speed's sign
 * set), against the window's edges or a box's (150..450 across, 100..300 down, after e). The
 * ball is red on the frames an edge test fires.
 */
class S01_EdgeBounceTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The ball's colour, read a half radius from its centre, away from the labels at the top and the bottom. */
    private static int ballColour(S01_EdgeBounce s) {
        int py = Math.round(s.y + (s.y < s.height / 2 ? s.r / 2 : -s.r / 2));
        return s.get(Math.round(s.x), py) | 0xFF000000;
    }

    @Test
    void hitboxWay_bouncesOffAllFourEdges_neverPastOneForTwoFramesRunning() {
        Set<Side> edgesCrossed = EnumSet.noneOf(Side.class);
        List<Set<Side>> previous = new ArrayList<>(List.of(Set.of()));
        SketchRun.of(new S01_EdgeBounce()).script(new Script().frames(5000).key(1, 'l'))
                .everyFrame(s -> {
                    if (s.frameCount < 2) {
                        return;
                    }
                    Set<Side> crossed = Edges.crossed(new Circle(s.x, s.y, s.r), s.width, s.height);
                    Set<Side> twice = EnumSet.noneOf(Side.class);
                    twice.addAll(crossed);
                    twice.retainAll(previous.get(0));
                    assertEquals(Set.of(), twice,
                            "ball at (" + s.x + ", " + s.y + ") is past the same edge two frames running");
                    assertTrue(s.x - s.r > -4.5f - 1e-3f && s.x + s.r < s.width + 4.5f + 1e-3f, "at most one step past, x = " + s.x);
                    assertTrue(s.y - s.r > -3.2f - 1e-3f && s.y + s.r < s.height + 3.2f + 1e-3f, "at most one step past, y = " + s.y);
                    assertEquals(Integer.toHexString(!crossed.isEmpty() ? Palette.HIT : Palette.PLAYER),
                            Integer.toHexString(ballColour(s)), "red exactly on the frames it crossed an edge");
                    edgesCrossed.addAll(crossed);
                    previous.set(0, crossed);
                })
                .run();
        assertEquals(Set.of(Side.LEFT, Side.RIGHT, Side.TOP, Side.BOTTOM), edgesCrossed,
                "in 5000 frames the ball reaches and bounces off all four edges");
    }

    @Test
    void byDefault_theTutorialsCode_testsTheCentre_soTheBallGoesHalfOutBeforeItTurns() {
        float[] furthest = {0};
        int[] previousSign = {1};
        SketchRun.of(new S01_EdgeBounce()).frames(2000)
                .everyFrame(s -> {
                    furthest[0] = Math.max(furthest[0], s.x + s.r - s.width);
                    // The tutorial's ifs, as section 1 writes them, on where the ball is now.
                    boolean xIf = s.x < 0 || s.x > s.width;
                    boolean yIf = s.y < 0 || s.y > s.height;
                    int sign = s.xSpeed > 0 ? 1 : -1;
                    assertEquals(xIf, sign != previousSign[0], "xSpeed flips exactly when x < 0 || x > width, x = " + s.x);
                    previousSign[0] = sign;
                    // A pixel of the ball inside the window (its centre may be past the edge), off the labels.
                    int px = Math.round(Math.max(3, Math.min(s.width - 4, s.x)));
                    int py = Math.round(Math.max(3, Math.min(s.height - 4, s.y + (s.y < s.height / 2 ? s.r / 2 : -s.r / 2))));
                    if ((py < 30 && px < 420) || py > s.height - 30) {
                        return;
                    }
                    assertEquals(Integer.toHexString(xIf || yIf ? Palette.HIT : Palette.PLAYER),
                            Integer.toHexString(s.get(px, py) | 0xFF000000), "red exactly on the frames the tutorial's ifs fire");
                })
                .run();
        // Hitbox's way turns it within a step (4.5) of the edge; the tutorial's when the centre is past it.
        assertTrue(furthest[0] > 24, "the ball reached " + furthest[0] + " past the right edge");
    }

    @Test
    void tutorialsCode_aBallDroppedInTheWall_staysStuckThere_flippingEveryFrame() {
        // Dropped left of the box (its left edge is at 150), then the box's edges swapped in.
        Script script = new Script().frames(200).click(4, 90, 190).key(6, 'e');
        float[] lastSpeed = {Float.NaN};
        float[] stuckAt = {Float.NaN};
        SketchRun.Result<S01_EdgeBounce> r = SketchRun.of(new S01_EdgeBounce()).script(script).everyFrame(s -> {
            if (s.frameCount == 9) {
                stuckAt[0] = s.x;
                assertTrue(s.x + s.r < s.left, "in the wall, x = " + s.x);
            }
            if (s.frameCount >= 10) {
                assertTrue(Math.abs(s.x - stuckAt[0]) <= 4.5f, "stuck where it was, x = " + s.x + ", was " + stuckAt[0]);
                assertEquals(-lastSpeed[0], s.xSpeed, "xSpeed flips every frame");
                assertEquals(Integer.toHexString(Palette.HIT), Integer.toHexString(ballColour(s)), "the test fires every frame: red");
            }
            lastSpeed[0] = s.xSpeed;
        }).run();
        assertEquals(150f, r.sketch().left, "e moved the left edge in");
    }

    @Test
    void hitboxWay_theSameDrop_comesBackInsideTheBox_andBouncesThere() {
        Script script = new Script().frames(400).key(1, 'l').click(4, 90, 190).key(6, 'e');
        boolean[] inside = {false};
        SketchRun.Result<S01_EdgeBounce> r = SketchRun.of(new S01_EdgeBounce()).script(script).everyFrame(s -> {
            if (s.frameCount == 40) {
                assertTrue(s.x - s.r >= s.left, "back inside the box by frame 40, x = " + s.x);
            }
            if (s.frameCount >= 40) {
                Set<Side> crossed = Edges.crossed(new Circle(s.x - s.left, s.y - s.top, s.r), s.right - s.left, s.bottom - s.top);
                inside[0] |= crossed.isEmpty();
                assertTrue(s.x - s.r > s.left - 4.5f - 1e-3f && s.x + s.r < s.right + 4.5f + 1e-3f, "stays in the box, x = " + s.x);
                assertTrue(s.y - s.r > s.top - 3.2f - 1e-3f && s.y + s.r < s.bottom + 3.2f + 1e-3f, "stays in the box, y = " + s.y);
            }
        }).capture(300).run();
        assertTrue(inside[0]);
        PImage frame = r.frame(300);
        assertNotEquals(Integer.toHexString(Palette.BACKGROUND), Integer.toHexString(frame.get(580, 60) | 0xFF000000),
                "outside the box is drawn as wall");
        SketchPixels.assertColour(frame, 150, 200, Palette.OBSTACLE, "the box's left edge");
    }

    @Test
    void eKeyAgain_givesTheWindowsEdgesBack() {
        S01_EdgeBounce s = SketchRun.of(new S01_EdgeBounce()).script(new Script().frames(10).key(2, 'e').key(5, 'e'))
                .run().sketch();
        assertEquals(0f, s.left);
        assertEquals(600f, s.right);
        assertEquals(0f, s.top);
        assertEquals(400f, s.bottom);
    }

    @Test
    void overlayKey_writesOutTheEdgeTests_andPressingAgainHidesThem() {
        // The ball starts right of the middle and high up: the tests' panel goes at the bottom left.
        SketchRun.Result<S01_EdgeBounce> r = SketchRun.of(new S01_EdgeBounce())
                .script(new Script().frames(8).key(1, 'd').key(4, 'd'))
                .capture(1).capture(3).run();
        int before = SketchPixels.count(r.frame(1), 10, 270, 250, 350, Palette.BACKGROUND);
        assertTrue(before > 15000, "nothing there before d, background pixels: " + before);
        assertTrue(SketchPixels.count(r.frame(3), 10, 270, 250, 350, Palette.BACKGROUND) < before / 2, "d writes the maths");
        assertEquals(before, SketchPixels.count(r.lastFrame(), 10, 270, 250, 350, Palette.BACKGROUND), "a second d hides it");
    }
}
