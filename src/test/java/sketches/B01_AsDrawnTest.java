package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/**
 * B01_AsDrawn: the mouse is tested against each shape where translate(), rotate() and scale()
 * drew it, checked against shapes built independently of the drawing matrix.
 */
class B01_AsDrawnTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The mouse at (x, y), the turning stopped after frame 1 (the paddle at about 0.61 radians). */
    private static SketchRun.Result<B01_AsDrawn> mouseAt(int x, int y) {
        return SketchRun.of(new B01_AsDrawn()).script(new Script().frames(6).mouse(1, x, y).key(1, ' ')).run();
    }

    @Test
    void thePaddle_isTestedWhereItIsTurned() {
        // Past the unturned rect's bottom edge (y 170..230), on the turned paddle's far end.
        B01_AsDrawn on = mouseAt(224, 237).sketch();
        assertTrue(Polygon.of(Rect.centered(170, 200, 160, 60)).rotated(on.angle, 170, 200).contains(224, 237), "the test's own point");
        assertTrue(on.overPaddle);
        // Inside the unturned rect, but off the turned paddle.
        B01_AsDrawn off = mouseAt(240, 175).sketch();
        assertFalse(Polygon.of(Rect.centered(170, 200, 160, 60)).rotated(off.angle, 170, 200).contains(240, 175));
        assertFalse(off.overPaddle);
    }

    @Test
    void theSquashedBall_isATurnedEllipse() {
        B01_AsDrawn s = mouseAt(488, 94).sketch();
        assertEquals(new Ellipse(440, 120, 72, 28, -0.5f).contains(488, 94), true);
        assertTrue(s.overBall);
        Ellipse ball = (Ellipse) s.ball;
        assertEquals(72, ball.rx(), 1e-3);
        assertEquals(28, ball.ry(), 1e-3);
        assertFalse(mouseAt(440, 160).sketch().overBall, "below the squashed ball, outside it");
    }

    @Test
    void theWindmillsBlades_followTheNestedTurns() {
        B01_AsDrawn s = mouseAt(5, 5).sketch();
        for (int i = 0; i < 4; i++) {
            Polygon blade = (Polygon) s.blades[i];
            // blade i is turned (i + 1) quarter turns after rotate(-1.5 angle) about (440, 290)
            double a = -1.5 * s.angle + (i + 1) * Math.PI / 2;
            float tipX = (float) (440 + 90 * Math.cos(a) + 22 * Math.sin(a));
            float tipY = (float) (290 + 90 * Math.sin(a) - 22 * Math.cos(a));
            assertEquals(tipX, blade.x(1), 1e-3, "blade " + i + "'s tip x");
            assertEquals(tipY, blade.y(1), 1e-3, "blade " + i + "'s tip y");
        }
        assertEquals(-1, s.overBlade);
    }

    @Test
    void theShapeUnderTheMouse_isDrawnRed() {
        int on = SketchPixels.count(mouseAt(224, 237).lastFrame(), Palette.HIT);
        int off = SketchPixels.count(mouseAt(240, 175).lastFrame(), Palette.HIT);
        assertTrue(on > off + 3000, "the paddle drawn red under the mouse: " + on + " vs " + off);
    }
}
