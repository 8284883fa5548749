package sketches;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/** S02c_Ellipses: an ellipse is red while the mouse (a point, or a circle) is inside it. */
class S02c_EllipsesTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private static SketchRun.Result<S02c_Ellipses> run(Script script) {
        return SketchRun.of(new S02c_Ellipses()).script(script).run();
    }

    @Test
    void pointInTheWideEllipse_turnsOnlyItRed() {
        SketchRun.Result<S02c_Ellipses> r = run(new Script().frames(5).mouse(1, 240, 200));
        assertArrayEquals(new boolean[] {true, false, false}, r.sketch().hit);
        SketchPixels.assertColour(r.lastFrame(), 100, 200, Palette.HIT, "the wide ellipse");
        SketchPixels.assertColour(r.lastFrame(), 380, 100, Palette.MISS, "the tall ellipse");
    }

    @Test
    void pointOnTheRightEnd_isNotInside_butTheMouseCircleReachesIn() {
        // (260, 200) is the wide ellipse's right end: on the outline, not inside.
        SketchRun.Result<S02c_Ellipses> point = run(new Script().frames(5).mouse(1, 260, 200));
        assertArrayEquals(new boolean[] {false, false, false}, point.sketch().hit);
        SketchRun.Result<S02c_Ellipses> circle = run(new Script().frames(6).mouse(1, 260, 200).key(2, ' '));
        assertTrue(circle.sketch().hit[0], "the mouse circle of radius 30 reaches into it");
        SketchPixels.assertColour(circle.lastFrame(), 100, 200, Palette.HIT, "the wide ellipse");
    }

    @Test
    void overlayKey_drawsTheMaths() {
        SketchRun.Result<S02c_Ellipses> r = SketchRun.of(new S02c_Ellipses())
                .script(new Script().frames(10).mouse(1, 200, 215).key(3, 'd')).capture(2).run();
        assertTrue(SketchPixels.differing(r.frame(2), r.lastFrame()) > 300, "the overlay draws the radii and the test");
    }
}
