package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S04_RectPoint: the button (200, 150, 200 x 100) is red while hovered and counts only the
 * clicks that land inside it; the edges are not inside.
 */
class S04_RectPointTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): hovered {2}, both forms")
    @CsvSource({
            "300, 200, true",
            "201, 151, true",    // just inside the top-left corner
            "399, 249, true",    // just inside the bottom-right corner
            "100, 100, false",
            "200, 200, false",   // on the left edge
            "400, 200, false",   // on the right edge
            "300, 150, false",   // on the top edge
            "300, 250, false",   // on the bottom edge
            "300, 260, false",   // below
    })
    void button_isRedOnlyWhileHovered(int mx, int my, boolean hovered) {
        // The tutorial's combined if, its nested ifs (n), and Collide.rectPoint (l): the same answers.
        assertEquals(hovered, mx > 200 && mx < 200 + 200 && my > 150 && my < 150 + 100, "the tutorial's if, with the button's numbers");
        for (int way = 0; way < 3; way++) {
            Script script = new Script().frames(5).mouse(1, mx, my);
            if (way == 1) {
                script.key(1, 'n');
            } else if (way == 2) {
                script.key(1, 'l');
            }
            SketchRun.Result<S04_RectPoint> r = SketchRun.of(new S04_RectPoint()).script(script).run();
            assertEquals(way == 1, r.sketch().nestedIf);
            assertEquals(way == 2, r.sketch().hitboxDecides);
            String form = way == 0 ? "combined if" : way == 1 ? "nested ifs" : "Collide.rectPoint";
            // A pixel of the button away from the mouse dot, the edges and the counter's text.
            int px = mx < 300 ? 380 : 220;
            SketchPixels.assertColour(r.lastFrame(), px, 235, hovered ? Palette.HIT : Palette.MISS, "button, " + form);
        }
    }

    @ParameterizedTest(name = "mouse ({0}, {1}), nested {2}: {3} comparisons reached")
    @CsvSource({
            "100, 200, true,  1",   // left of the button: mouseX > rectX is false, nothing after it is reached
            "100, 200, false, 1",   // the combined if stops there too
            "500, 200, true,  2",   // right of it: the second comparison is false
            "300, 100, true,  3",   // above it: across holds, mouseY > rectY is false
            "300, 100, false, 3",
            "300, 300, true,  4",   // below it: all four reached, the last is false
            "300, 200, true,  4",   // inside: all four reached and hold
    })
    void overlay_greysTheComparisonsNeverReached(int mx, int my, boolean nested, int reached) {
        Script script = new Script().frames(5).mouse(1, mx, my).key(1, 'd');
        if (nested) {
            script.key(1, 'n');
        }
        PImage frame = SketchRun.of(new S04_RectPoint()).script(script).run().lastFrame();
        // Each comparison's edge, drawn thick in its colour, in the order Java reaches them:
        // left, right, top, bottom; sampled away from the guides through the mouse.
        boolean[] holds = {mx > 200, mx < 400, my > 150, my < 250};
        int[][] at = {{200, 170}, {400, 170}, {220, 150}, {220, 250}};
        String[] names = {"mouseX > rectX", "mouseX < rectX + rectWidth", "mouseY > rectY", "mouseY < rectY + rectHeight"};
        for (int i = 0; i < 4; i++) {
            int expected = i >= reached ? Palette.OBSTACLE : holds[i] ? Overlay.HIT : Overlay.MISS;
            SketchPixels.assertColour(frame, at[i][0], at[i][1], expected,
                    names[i] + (i >= reached ? ", never reached: grey" : ", reached"));
        }
    }

    @Test
    void clicks_countOnlyInsideTheButton() {
        Script script = new Script().frames(60)
                .click(2, 250, 200)     // inside: counts
                .click(6, 100, 100)     // outside
                .click(10, 200, 200)    // on the left edge
                .click(14, 400, 200)    // on the right edge
                .click(18, 300, 150)    // on the top edge
                .click(22, 300, 250)    // on the bottom edge
                .click(26, 200, 150)    // on the top-left corner
                .click(30, 399, 249)    // inside, by the bottom-right corner: counts
                .click(34, 520, 330)    // outside
                .click(38, 300, 200)    // inside: counts
                .mouse(45, 50, 50);
        SketchRun.Result<S04_RectPoint> r = SketchRun.of(new S04_RectPoint()).script(script).run();
        assertEquals(3, r.sketch().clicks, "clicks counted");
    }

    @Test
    void theTutorialsOtherIf_pressedOverTheButton_drawsItPressed_andNotPressedElsewhere() {
        // A press after frame 2, released after frame 3: frame 3 is drawn with the mouse down.
        SketchRun.Result<S04_RectPoint> on = SketchRun.of(new S04_RectPoint())
                .script(new Script().frames(6).click(2, 250, 200)).capture(2).capture(3).capture(5).run();
        SketchPixels.assertColour(on.frame(2), 380, 235, Palette.HIT, "hovered, not pressed yet");
        SketchPixels.assertColour(on.frame(3), 380, 235, Palette.ACCENT, "pressed over the button");
        SketchPixels.assertColour(on.frame(5), 380, 235, Palette.HIT, "released");
        SketchRun.Result<S04_RectPoint> off = SketchRun.of(new S04_RectPoint())
                .script(new Script().frames(6).click(2, 100, 100)).capture(3).run();
        SketchPixels.assertColour(off.frame(3), 380, 235, Palette.MISS, "pressed away from the button: not drawn pressed");
    }

    @Test
    void clickCount_isWrittenOnTheButton() {
        // Same mouse, no clicks vs one click: the counter's text changes what is drawn.
        SketchRun.Result<S04_RectPoint> none = SketchRun.of(new S04_RectPoint())
                .script(new Script().frames(80).mouse(1, 50, 50)).run();
        SketchRun.Result<S04_RectPoint> one = SketchRun.of(new S04_RectPoint())
                .script(new Script().frames(80).click(2, 250, 200).mouse(5, 50, 50)).run();
        assertEquals(1, one.sketch().clicks);
        assertTrue(SketchPixels.differing(none.lastFrame(), one.lastFrame()) > 20, "the counter is drawn");
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 250, 185).key(3, 'd').key(8, 'd');
        SketchRun.Result<S04_RectPoint> r = SketchRun.of(new S04_RectPoint()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 500, "the overlay draws the four comparisons and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
