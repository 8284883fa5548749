package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.Collide;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S05_RectRect, the tutorial's program: the mouse rectangle (200 x 100, its top-left corner at
 * the mouse) is red while it overlaps the center rectangle (250, 100, 100 x 200), green when
 * apart or side by side (sharing an edge or a corner); the center one stays a white outline.
 */
class S05_RectRectTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): colliding {2}")
    @CsvSource({
            // mouse x, y (the mouse rectangle's top-left corner), colliding, a pixel of it off the center outline
            "200, 150, true,  210, 160",   // across the center rectangle
            "20,  280, false, 30,  290",   // far apart
            "50,  150, false, 60,  160",   // its right edge on the center one's left edge (x = 250): side by side
            "51,  150, true,  60,  160",   // one pixel further: overlapping
            "350, 150, false, 540, 160",   // its left edge on the center one's right edge (x = 350)
            "349, 150, true,  539, 160",
            "300, 0,   false, 490, 10",    // its bottom edge on the center one's top edge (y = 100)
            "300, 1,   true,  490, 10",
            "200, 300, false, 210, 310",   // its top edge on the center one's bottom edge (y = 300)
            "200, 299, true,  210, 310",
            "50,  0,   false, 245, 95",    // corner to corner
    })
    void theMouseRectangle_isRedOnlyWhileTheRectanglesOverlap(int mx, int my, boolean colliding, int px, int py) {
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect())
                .script(new Script().frames(5).mouse(1, mx, my)).run();
        SketchPixels.assertColour(r.lastFrame(), px, py, colliding ? Palette.HIT : Palette.MISS, "the mouse rectangle");
        // The center rectangle is the tutorial's white outline, never filled.
        SketchPixels.assertColour(r.lastFrame(), 250, 200, 0xFFFFFFFF, "the center rectangle's left side");
        if (mx > 4) {
            // The mouse rectangle hangs from the mouse by its corner: nothing of it left of the mouse.
            int left = r.lastFrame().get(mx - 4, my + 40);
            assertTrue(left != Palette.HIT && left != Palette.MISS, "no mouse rectangle left of the mouse");
        }
    }

    @ParameterizedTest(name = "l pressed {0} times")
    @CsvSource({"0", "1", "2"})
    void mouseSweep_theColourFollowsTheTutorialsIf_orCollideRectRectAfterL_andTheyAgree(int lPresses) {
        Script script = SketchPixels.lThenMouse(700, lPresses, f -> new int[] {(f * 13) % 400, 60 + (f / 25) * 13 % 210});
        int[] seen = {0, 0};
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect()).script(script).everyFrame(s -> {
            if (s.frameCount < 5) {
                return;
            }
            boolean library = Collide.rectRect(s.mouseX, s.mouseY, 200, 100, 250, 100, 100, 200);
            // The tutorial's if, as its section writes it, with the sketch's variables.
            boolean tutorialsIf = s.mouseX + s.mouseRectWidth > s.centerRectX && s.mouseX < s.centerRectX + s.centerRectWidth
                    && s.mouseY + s.mouseRectHeight > s.centerRectY && s.mouseY < s.centerRectY + s.centerRectHeight;
            assertEquals(library, tutorialsIf, "the tutorial's if and Collide.rectRect, mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            boolean colliding = s.hitboxDecides ? library : tutorialsIf;
            // The mouse rectangle's corner farthest from the center rectangle is never on its outline.
            int cx = s.mouseX + 100 < 300 ? s.mouseX + 3 : s.mouseX + 197;
            int cy = s.mouseY + 50 < 200 ? s.mouseY + 3 : s.mouseY + 97;
            assertEquals(Integer.toHexString(colliding ? Palette.HIT : Palette.MISS), Integer.toHexString(s.get(cx, cy)),
                    "the mouse rectangle at (" + cx + ", " + cy + ") with the mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            seen[colliding ? 1 : 0]++;
        }).run();
        assertEquals(lPresses % 2 == 1, r.sketch().hitboxDecides, "l hands the colour to Collide.rectRect and back");
        assertTrue(seen[0] > 100 && seen[1] > 50, "frames apart and overlapping: " + seen[0] + ", " + seen[1]);
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 300, 170).key(3, 'd').key(8, 'd');
        SketchRun.Result<S05_RectRect> r = SketchRun.of(new S05_RectRect()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 500, "the overlay draws the four comparisons and the verdict");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
