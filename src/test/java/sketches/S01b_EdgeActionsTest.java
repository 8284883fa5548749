package sketches;

import hitbox.Circle;
import java.util.Set;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Edges;
import hitbox.Side;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/**
 * S01b_EdgeActions: what happens at an edge. The ball starts at (300, 200), radius 24, moving
 * 4.5 right and 3.2 down a frame: it reaches the bottom (frame 55) a little before the right
 * (frame 61).
 */
class S01b_EdgeActionsTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void byDefault_wrap_theWrittenOutIfs_teleportTheCentrePastAnEdge_toTheOtherSide() {
        boolean[] wrapped = new boolean[2];
        float[] previous = {Float.NaN, Float.NaN};
        SketchRun.of(new S01b_EdgeActions()).script(new Script().frames(400).key(1, 'w'))
                .everyFrame(s -> {
                    assertFalse(s.hitboxDecides);
                    if (!Float.isNaN(previous[0])) {
                        // The if statements, run here on where the ball was, moved by its speed.
                        float x = previous[0] + s.xSpeed;
                        float y = previous[1] + s.ySpeed;
                        float expectedX = x > s.width ? 0 : x < 0 ? s.width : x;
                        float expectedY = y > s.height ? 0 : y < 0 ? s.height : y;
                        assertEquals(expectedX, s.x, 1e-3f, "frame " + s.frameCount + ": x");
                        assertEquals(expectedY, s.y, 1e-3f, "frame " + s.frameCount + ": y");
                        wrapped[0] |= x > s.width;
                        wrapped[1] |= y > s.height;
                    }
                    previous[0] = s.x;
                    previous[1] = s.y;
                    assertTrue(s.x >= 0 && s.x <= s.width && s.y >= 0 && s.y <= s.height, "the centre stays in the window");
                })
                .run();
        assertTrue(wrapped[0] && wrapped[1], "the ball wrapped around, across and down");
    }

    @Test
    void lKey_wrap_ballWhollyLeavesOneSideAndComesBackOnTheOther() {
        boolean[] wrapped = new boolean[1];
        float[] previousX = {Float.NaN};
        SketchRun.of(new S01b_EdgeActions()).script(new Script().frames(400).key(1, 'w').key(1, 'l'))
                .everyFrame(s -> {
                    // Moving right at 4.5 a frame, x only ever falls when it wraps to the left.
                    if (s.x < previousX[0]) {
                        wrapped[0] = true;
                        assertTrue(s.x <= 0, "reappears at the left edge, was x = " + s.x);
                        assertTrue(previousX[0] - s.r >= s.width - 4.5f, "it had wholly left at the right, x was " + previousX[0]);
                    }
                    previousX[0] = s.x;
                    assertTrue(s.x >= -s.r && s.x <= s.width + s.r, "stays within one radius of the window");
                })
                .run();
        assertTrue(wrapped[0], "the ball wrapped around");
    }

    @Test
    void nextScreen_theCentreNeverLeaves_theWorldMovesOnAScreen() {
        int[] screens = {0, 0};
        SketchRun.Result<S01b_EdgeActions> r = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(100).key(1, 'n'))
                .everyFrame(s -> {
                    assertTrue(s.x >= 0 && s.x <= s.width && s.y >= 0 && s.y <= s.height,
                            "the centre stays on the screen: (" + s.x + ", " + s.y + ")");
                    screens[0] = s.screenX;
                    screens[1] = s.screenY;
                })
                .capture(60).capture(70).run();
        assertEquals(1, screens[0], "off the right edge once: the screen to the right");
        assertEquals(1, screens[1], "off the bottom edge once: the screen below");
        // Frame 60: screen 0, 0, ball at the right; frame 70: screen 1, 0, ball at the left.
        int changed = SketchPixels.differing(r.frame(60), r.frame(70), 150, 40, 450, 380);
        assertTrue(changed > 2000, "the new screen looks different away from the ball: " + changed + " pixels");
    }

    @Test
    void gameOver_theWrittenOutIfs_bounceOffTheBottom_thenEndWithTheCentrePastTheRight_andSpaceServesAgain() {
        boolean[] bouncedOffBottom = {false};
        float[] lastYSpeed = {3.2f};
        SketchRun.Result<S01b_EdgeActions> over = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(90).key(1, 'g'))
                .everyFrame(s -> {
                    if (lastYSpeed[0] > 0 && s.ySpeed < 0) {
                        bouncedOffBottom[0] = true;
                    }
                    if (!s.gameOver) {
                        lastYSpeed[0] = s.ySpeed;
                    }
                })
                .run();
        S01b_EdgeActions s = over.sketch();
        assertTrue(bouncedOffBottom[0], "bounced off the bottom wall");
        assertTrue(s.gameOver, "the ball went out at the right: game over");
        assertTrue(s.x > s.width, "the centre went past the right edge: " + s.x);
        assertEquals(0f, s.xSpeed);
        assertEquals(0f, s.ySpeed);
        int banner = SketchPixels.count(over.lastFrame(), 150, 150, 450, 200, Palette.NEUTRAL);
        assertTrue(banner > 400, "GAME OVER is written: " + banner + " pixels");

        S01b_EdgeActions again = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(120).key(1, 'g').key(100, ' ')).run().sketch();
        assertFalse(again.gameOver, "space serves again");
        assertEquals(300 - 20 * 4.5f, again.x, 1e-3f, "from the middle, away from the side it went out");
    }

    @Test
    void lKey_gameOver_endsAsSoonAsTheBallsEdgeCrossesTheRight() {
        S01b_EdgeActions s = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(90).key(1, 'g').key(1, 'l')).run().sketch();
        assertTrue(s.gameOver);
        assertTrue(Edges.crossed(new Circle(s.x, s.y, s.r), s.width, s.height).contains(Side.RIGHT));
        assertTrue(s.x <= s.width, "over before the centre got past: " + s.x);
    }

    @Test
    void stop_ballStopsAtTheEdgesItReaches_andAnotherActionStartsItAgain() {
        S01b_EdgeActions s = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(300).key(1, 's')).run().sketch();
        assertEquals(0f, s.xSpeed, "stopped across");
        assertEquals(0f, s.ySpeed, "stopped down");
        assertEquals(Set.of(), Edges.crossed(new Circle(s.x, s.y, s.r), s.width, s.height), "put back inside");

        S01b_EdgeActions again = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(320).key(1, 's').key(300, 'w')).run().sketch();
        assertTrue(again.xSpeed != 0 && again.ySpeed != 0, "w sets it moving again");
    }

    @Test
    void overlayKey_writesOutTheRule_andPressingAgainHidesIt() {
        // The rule's label sits at (8, 30), far from the ball in the first frames.
        SketchRun.Result<S01b_EdgeActions> r = SketchRun.of(new S01b_EdgeActions())
                .script(new Script().frames(8).key(1, 'd').key(4, 'd'))
                .capture(1).capture(3).run();
        int before = SketchPixels.count(r.frame(1), 8, 30, 200, 60, Palette.BACKGROUND);
        assertTrue(before > 5000, "nothing there before d, background pixels: " + before);
        assertTrue(SketchPixels.count(r.frame(3), 8, 30, 200, 60, Palette.BACKGROUND) < before / 2, "d writes the maths");
        assertEquals(before, SketchPixels.count(r.lastFrame(), 8, 30, 200, 60, Palette.BACKGROUND), "a second d hides it");
    }
}
