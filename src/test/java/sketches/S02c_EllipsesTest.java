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
        assertArrayEquals(new boolean[] {true, false, false, false}, r.sketch().hit);
        SketchPixels.assertColour(r.lastFrame(), 100, 200, Palette.HIT, "the wide ellipse");
        SketchPixels.assertColour(r.lastFrame(), 380, 100, Palette.MISS, "the tall ellipse");
    }

    @Test
    void pointOnTheRightEnd_isNotInside_butTheMouseCircleReachesIn() {
        // (260, 200) is the wide ellipse's right end: on the outline, not inside.
        SketchRun.Result<S02c_Ellipses> point = run(new Script().frames(5).mouse(1, 260, 200));
        assertArrayEquals(new boolean[] {false, false, false, false}, point.sketch().hit);
        SketchRun.Result<S02c_Ellipses> circle = run(new Script().frames(6).mouse(1, 260, 200).key(2, ' '));
        assertTrue(circle.sketch().hit[0], "the mouse circle of radius 30 reaches into it");
        SketchPixels.assertColour(circle.lastFrame(), 100, 200, Palette.HIT, "the wide ellipse");
    }

    @Test
    void turnedEllipse_answersAlongItsTurnedAxes() {
        // (303, 351) is 55 px along the fourth ellipse's x axis, turned 0.5 radians clockwise:
        // inside it, though 26 px below the centre, beyond an unturned ry of 22.
        SketchRun.Result<S02c_Ellipses> along = run(new Script().frames(5).mouse(1, 303, 351));
        assertArrayEquals(new boolean[] {false, false, false, true}, along.sketch().hit);
        SketchPixels.assertColour(along.lastFrame(), 290, 344, Palette.HIT, "the turned ellipse");
        // (315, 325) is inside the unturned ellipse, outside the turned one.
        SketchRun.Result<S02c_Ellipses> beside = run(new Script().frames(5).mouse(1, 315, 325));
        assertArrayEquals(new boolean[] {false, false, false, false}, beside.sketch().hit);
    }

    @Test
    void turnKey_keepsTheFourthEllipseTurning() {
        SketchRun.Result<S02c_Ellipses> r = SketchRun.of(new S02c_Ellipses())
                .script(new Script().frames(20).mouse(1, 100, 100).key(2, 't')).capture(4).run();
        assertTrue(r.sketch().ellipses[3].angle() > 0.6f, "turned on from 0.5: " + r.sketch().ellipses[3].angle());
        assertTrue(SketchPixels.differing(r.frame(4), r.lastFrame()) > 100, "the drawing turns");
    }

    @Test
    void overlayKey_drawsTheMaths() {
        SketchRun.Result<S02c_Ellipses> r = SketchRun.of(new S02c_Ellipses())
                .script(new Script().frames(10).mouse(1, 200, 215).key(3, 'd')).capture(2).run();
        assertTrue(SketchPixels.differing(r.frame(2), r.lastFrame()) > 300, "the overlay draws the radii and the test");
    }
}
