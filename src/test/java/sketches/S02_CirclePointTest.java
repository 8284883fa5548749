package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.ParameterizedTest;

import hitbox.Collide;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/** S02_CirclePoint: the circle is red while the mouse is inside it, green otherwise. */
class S02_CirclePointTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** Points well inside the circle (centre 300, 200, radius 100), away from the mouse dot. */
    private static final int[][] INSIDE = {{250, 150}, {350, 150}, {250, 250}, {350, 250}, {230, 200}};

    private static SketchRun.Result<S02_CirclePoint> runWithMouseAt(int x, int y) {
        return SketchRun.of(new S02_CirclePoint()).script(new Script().frames(5).mouse(1, x, y)).run();
    }

    private static void assertCircleColour(PImage frame, int expected, String what) {
        for (int[] p : INSIDE) {
            SketchPixels.assertColour(frame, p[0], p[1], expected, what);
        }
    }

    @Test
    void circle_isRed_withTheMouseAtItsCentre() {
        SketchRun.Result<S02_CirclePoint> r = runWithMouseAt(300, 200);
        assertCircleColour(r.lastFrame(), Palette.HIT, "circle colour with the mouse at its centre");
    }

    @Test
    void circle_isGreen_withTheMouseInACorner() {
        SketchRun.Result<S02_CirclePoint> r = runWithMouseAt(5, 5);
        assertCircleColour(r.lastFrame(), Palette.MISS, "circle colour with the mouse in a corner");
    }

    @Test
    void circle_isGreen_withTheMouseExactlyOnTheOutline() {
        // (360, 280) is 60, 80 from the centre: distance 100, the radius. Touching is not inside.
        SketchRun.Result<S02_CirclePoint> r = runWithMouseAt(360, 280);
        assertCircleColour(r.lastFrame(), Palette.MISS, "circle colour with the mouse on the outline");
        // One pixel further in, it is inside.
        SketchRun.Result<S02_CirclePoint> in = runWithMouseAt(359, 280);
        assertCircleColour(in.lastFrame(), Palette.HIT, "circle colour with the mouse just inside the outline");
    }

    @Test
    void closeToTheCircle_aLineToItAndTheDistance_onlyWhileClose() {
        // (420, 290) is 150 from the centre: 50 px from the outline, within closeDistance (70).
        SketchRun.Result<S02_CirclePoint> close = runWithMouseAt(420, 290);
        // Far away (5, 5), inside (300, 200), and 80 px from the outline (364, 328): no line.
        SketchRun.Result<S02_CirclePoint> far = runWithMouseAt(5, 5);
        SketchRun.Result<S02_CirclePoint> inside = runWithMouseAt(300, 200);
        SketchRun.Result<S02_CirclePoint> beyond = SketchRun.of(new S02_CirclePoint())
                .script(new Script().frames(5).mouse(1, 300 + 108, 200 + 144)).run();
        // The line runs from the mouse to the nearest point of the outline, (380, 260): its middle.
        SketchPixels.assertColour(close.lastFrame(), 400, 275, Palette.ACCENT, "the line to the circle");
        assertTrue(SketchPixels.count(close.lastFrame(), 0, 0, 599, 380, Palette.ACCENT) > 20, "the line is drawn");
        assertEquals(0, SketchPixels.count(far.lastFrame(), 0, 0, 599, 380, Palette.ACCENT), "nothing far away");
        assertEquals(0, SketchPixels.count(inside.lastFrame(), 0, 0, 599, 380, Palette.ACCENT), "nothing inside");
        assertEquals(0, SketchPixels.count(beyond.lastFrame(), 0, 0, 599, 380, Palette.ACCENT), "nothing 80 px away");
    }

    @ParameterizedTest(name = "l pressed {0} times")
    @CsvSource({"0", "1", "2"})
    void mouseSweep_theColourFollowsTheTutorialsIf_orCollideCirclePointAfterL_andTheyAgree(int lPresses) {
        Script script = SketchPixels.lThenMouse(600, lPresses, f -> new int[] {150 + (f * 17) % 300, 60 + (f / 20) * 11 % 280});
        int[] seen = {0, 0};
        SketchRun.Result<S02_CirclePoint> r = SketchRun.of(new S02_CirclePoint()).script(script).everyFrame(s -> {
            if (s.frameCount < 5) {
                return;
            }
            // The tutorial's if, as its section writes it.
            boolean tutorialsIf = processing.core.PApplet.dist(s.mouseX, s.mouseY, s.circleCenterX, s.circleCenterY) < s.circleRadius;
            boolean library = Collide.circlePoint(300, 200, 100, s.mouseX, s.mouseY);
            assertEquals(library, tutorialsIf, "mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            boolean inside = s.hitboxDecides ? library : tutorialsIf;
            for (int[] p : INSIDE) {
                if (Math.abs(p[0] - s.mouseX) > 8 || Math.abs(p[1] - s.mouseY) > 8) {
                    assertEquals(Integer.toHexString(inside ? Palette.HIT : Palette.MISS), Integer.toHexString(s.get(p[0], p[1]) | 0xFF000000),
                            "the circle at (" + p[0] + ", " + p[1] + ") with the mouse at (" + s.mouseX + ", " + s.mouseY + ")");
                }
            }
            seen[inside ? 1 : 0]++;
        }).run();
        assertEquals(lPresses % 2 == 1, r.sketch().hitboxDecides, "l hands the colour to Collide.circlePoint and back");
        assertTrue(seen[0] > 50 && seen[1] > 50, "frames outside and inside: " + seen[0] + ", " + seen[1]);
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 355, 268).key(3, 'd').key(8, 'd');
        SketchRun.Result<S02_CirclePoint> r = SketchRun.of(new S02_CirclePoint()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        PImage on = r.frame(6);
        assertTrue(SketchPixels.differing(off, on) > 500, "the overlay draws the distance, radius and verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
