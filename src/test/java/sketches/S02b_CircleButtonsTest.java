package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S02b_CircleButtons: four round buttons, centres (120, 240, 360, 480) at y 300, radius 42;
 * the one under the mouse has a white ring, and a click on one lights the lamp (300, 120)
 * in its colour. The lamp starts blue (the fourth button).
 */
class S02b_CircleButtonsTest {

    private static final int[] BUTTON_X = {120, 240, 360, 480};
    private static final int[] COLOURS = {Palette.HIT, Palette.ACCENT, Palette.MISS, Palette.PLAYER};

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The colour of each button's rim, on its left side (the mouse is never there in these tests). */
    private static void assertRings(PImage frame, int hovered) {
        for (int i = 0; i < 4; i++) {
            SketchPixels.assertColour(frame, BUTTON_X[i] - 42, 300, i == hovered ? Palette.NEUTRAL : Palette.LINE,
                    "button " + i + "'s rim");
        }
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): button {2} under it")
    @CsvSource({
            "120, 300, 0",    // a centre
            "265, 330, 1",    // inside, off centre (25, 30: 39.1 from it)
            "389, 329, 2",    // 29, 29 from the centre: 41.0, just inside
            "390, 330, -1",   // 30, 30: 42.4, in the corner of the square, not on the button
            "510, 270, -1",   // the same corner on the last button
            "480, 342, -1",   // exactly on the outline (42 below): touching is not inside
            "480, 341, 3",
            "300, 120, -1",   // the lamp is not a button
    })
    void theButtonUnderTheMouse_getsTheRing_andOnlyIt_byTheTutorialsIf_andByCollideCirclePointAfterL(int mx, int my, int hovered) {
        for (int i = 0; i < 4; i++) {
            // The tutorial's if, as section 2 writes it, with this button's numbers.
            assertEquals(i == hovered, processing.core.PApplet.dist(mx, my, BUTTON_X[i], 300) < 42, "dist() < buttonRadius, button " + i);
        }
        SketchRun.Result<S02b_CircleButtons> r = SketchRun.of(new S02b_CircleButtons())
                .script(new Script().frames(4).mouse(1, mx, my)).run();
        assertFalse(r.sketch().hitboxDecides);
        assertRings(r.lastFrame(), hovered);
        SketchRun.Result<S02b_CircleButtons> l = SketchRun.of(new S02b_CircleButtons())
                .script(new Script().frames(4).mouse(1, mx, my).key(1, 'l')).run();
        assertTrue(l.sketch().hitboxDecides);
        assertRings(l.lastFrame(), hovered);
        assertEquals(0, r.sketch().disagreements + l.sketch().disagreements, "the two tests agree");
    }

    @Test
    void aClickOnAButton_lightsTheLamp_andAClickInItsSquaresCorner_doesNot() {
        Script script = new Script().frames(40)
                .click(3, 110, 310)     // on the red button
                .click(10, 270, 270)    // the yellow button's corner: 30, 30 from its centre, 42.4
                .mouse(14, 560, 60);
        SketchRun.Result<S02b_CircleButtons> r = SketchRun.of(new S02b_CircleButtons()).script(script)
                .capture(2).capture(8).run();
        SketchPixels.assertColour(r.frame(2), 300, 120, Palette.PLAYER, "the lamp before any click");
        SketchPixels.assertColour(r.frame(8), 300, 120, Palette.HIT, "the lamp after a click on the red button");
        SketchPixels.assertColour(r.lastFrame(), 300, 120, Palette.HIT, "a click in the corner changes nothing");
        assertEquals(0, r.sketch().picked);
    }

    @Test
    void eachButton_lightsTheLampInItsColour() {
        for (int i = 0; i < 4; i++) {
            SketchRun.Result<S02b_CircleButtons> r = SketchRun.of(new S02b_CircleButtons())
                    .script(new Script().frames(6).click(2, BUTTON_X[i] + 20, 290)).run();
            SketchPixels.assertColour(r.lastFrame(), 300, 120, COLOURS[i], "the lamp after clicking button " + i);
        }
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 272, 268).key(3, 'd').key(8, 'd');
        SketchRun.Result<S02b_CircleButtons> r = SketchRun.of(new S02b_CircleButtons()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 1000, "the overlay draws the squares, the distance and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
