package sketches;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.Collide;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S05b_RectRectTwoWays: rectOne (x1, y1, 100 x 60, its corner at the mouse) against rectTwo (370, 85, 100 x 80),
 * tested by the tutorial's && form and by the flipped || form; each comparison is lit as it
 * is evaluated (1 true, 2 false) or left grey (0 skipped), and the forms' counts add up.
 */
class S05b_RectRectTwoWaysTest {

    private static final int S = 0, T = 1, F = 2;

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private static int[] lit(String pattern) {
        int[] lit = new int[4];
        for (int i = 0; i < 4; i++) {
            lit[i] = "STF".indexOf(pattern.charAt(i));
        }
        return lit;
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): && {2}, || {3}")
    @CsvSource({
            // mouse, what each comparison did (S skipped, T true, F false), and the answer
            "100, 100, FSSS, TSSS, false",   // r1 left of r2: the first comparison decides, in both
            "600, 100, TFSS, FTSS, false",   // right of r2: the second
            "400, 5,   TTFS, FFTS, false",   // above: the third
            "400, 200, TTTF, FFFT, false",   // below: the fourth
            "400, 100, TTTT, FFFF, true",    // overlapping: all four, in both
    })
    void bothForms_evaluateTheSameComparisons_andAgree_whenNotTouching(int mx, int my, String and, String or, boolean colliding) {
        SketchRun.Result<S05b_RectRectTwoWays> r = SketchRun.of(new S05b_RectRectTwoWays())
                .script(new Script().frames(3).mouse(1, mx, my)).run();
        S05b_RectRectTwoWays s = r.sketch();
        assertArrayEquals(lit(and), s.andLit, "the && form's comparisons");
        assertArrayEquals(lit(or), s.orLit, "the || form's comparisons");
        assertEquals(colliding, s.andSays, "&&");
        assertEquals(colliding, s.orSays, "||");
        int evaluated = and.replace("S", "").length();
        assertEquals(evaluated, s.andNow);
        assertEquals(evaluated, s.orNow, "the same count: comparison i of || is the opposite of comparison i of &&");
        SketchPixels.assertColour(r.lastFrame(), 375, 160, colliding ? Palette.HIT : Palette.MISS, "rectTwo, coloured by the tutorial's && form");
        // The rows as drawn: a skipped row has grey text and nothing red or green.
        PImage frame = r.lastFrame();
        for (int form = 0; form < 2; form++) {
            String pattern = form == 0 ? and : or;
            int x0 = (int) s.panelLeft(form);
            for (int i = 0; i < 4; i++) {
                int y0 = (int) s.rowTop(i) - 2;
                int grey = SketchPixels.count(frame, x0, y0, x0 + 405, y0 + 18, s.SKIPPED_GREY);
                int lit = SketchPixels.count(frame, x0, y0, x0 + 405, y0 + 18, Overlay.HIT)
                        + SketchPixels.count(frame, x0, y0, x0 + 405, y0 + 18, Overlay.MISS);
                if (pattern.charAt(i) == 'S') {
                    assertTrue(grey > 20 && lit == 0, "form " + form + " row " + i + " is grey: " + grey + " grey, " + lit + " lit");
                } else {
                    assertTrue(grey == 0 && lit > 20, "form " + form + " row " + i + " is lit: " + grey + " grey, " + lit + " lit");
                }
            }
        }
    }

    @ParameterizedTest(name = "touching, mouse ({0}, {1})")
    @CsvSource({
            "250, 100",   // r1 snaps against r2's left side: r1Right == r2Left
            "480, 120",   // right side
            "400, 10",    // top
            "400, 180",   // bottom
            "262, 20",    // corner to corner (top-left)
    })
    void touching_theOrFormSaysColliding_theAndFormAndTheLibraryDoNot(int mx, int my) {
        SketchRun.Result<S05b_RectRectTwoWays> r = SketchRun.of(new S05b_RectRectTwoWays())
                .script(new Script().frames(5).mouse(1, mx, my).key(1, 't')).run();
        S05b_RectRectTwoWays s = r.sketch();
        assertEquals(false, Collide.rectRect(s.x1, s.y1, s.w1, s.h1, s.x2, s.y2, s.w2, s.h2), "the library: not colliding");
        float ix = Math.min(s.x1 + s.w1, s.x2 + s.w2) - Math.max(s.x1, s.x2);
        float iy = Math.min(s.y1 + s.h1, s.y2 + s.h2) - Math.max(s.y1, s.y2);
        assertTrue(ix >= 0 && iy >= 0 && (ix == 0 || iy == 0), "r1 touches r2: shared edge " + ix + " x " + iy);
        assertEquals(false, s.andSays, "&& says not colliding");
        assertEquals(true, s.orSays, "|| (its else) says colliding");
        assertEquals(4, s.orNow, "|| finds no true comparison, so it evaluates all four");
        assertEquals(false, s.videoAndSays, "the video's && says not colliding");
        assertEquals(true, s.videoOrSays, "the video's flipped || (its else) says colliding");
        SketchPixels.assertColour(r.lastFrame(), 375, 160, Palette.MISS, "rectTwo, coloured by the tutorial's && form");
    }

    @ParameterizedTest(name = "the video''s forms, mouse ({0}, {1}): && {2}, || {3}")
    @CsvSource({
            // the video's order: x1 < x2 + w2, x1 + w1 > x2, y1 < y2 + h2, y1 + h1 > y2
            "100, 100, TFSS, FTSS, false",   // rectOne left of rectTwo: the second comparison decides
            "600, 100, FSSS, TSSS, false",   // right of it: the first
            "400, 200, TTFS, FFTS, false",   // below: the third
            "400, 5,   TTTF, FFFT, false",   // above: the fourth
            "400, 100, TTTT, FFFF, true",    // overlapping: all four
    })
    void vKey_theVideosForms_inXYWidthAndHeight_litAsJavaEvaluatesThem(int mx, int my, String and, String or, boolean colliding) {
        SketchRun.Result<S05b_RectRectTwoWays> r = SketchRun.of(new S05b_RectRectTwoWays())
                .script(new Script().frames(4).mouse(1, mx, my).key(1, 'v')).run();
        S05b_RectRectTwoWays s = r.sketch();
        assertTrue(s.videoForms);
        assertArrayEquals(lit(and), s.andLit, "the video's && form's comparisons");
        assertArrayEquals(lit(or), s.orLit, "the video's || form's comparisons");
        assertEquals(colliding, s.videoAndSays, "the video's &&");
        assertEquals(colliding, s.videoOrSays, "the video's ||");
        assertEquals(colliding, s.andSays, "the tutorial's && agrees");
        assertEquals(and.replace("S", "").length(), s.andNow);
        assertEquals(s.andNow, s.orNow);
    }

    @ParameterizedTest(name = "l pressed {0} times")
    @CsvSource({"0", "1"})
    void mouseSweep_rectTwosColour_followsTheTutorialsAnd_orCollideRectRectAfterL(int lPresses) {
        Script script = new Script().frames(400);
        if (lPresses == 1) {
            script.key(1, 'l');
        }
        for (int f = 3; f <= 400; f++) {
            script.mouse(f, 250 + (f * 17) % 260, (f * 7) % 200);
        }
        int[] seen = {0, 0};
        SketchRun.of(new S05b_RectRectTwoWays()).script(script).everyFrame(s -> {
            if (s.frameCount < 3) {
                return;
            }
            // The tutorial's && form, as section 5 writes it, on the sketch's rectangles.
            boolean tutorials = s.x1 + s.w1 > s.x2 && s.x1 < s.x2 + s.w2 && s.y1 + s.h1 > s.y2 && s.y1 < s.y2 + s.h2;
            boolean library = Collide.rectRect(s.x1, s.y1, s.w1, s.h1, s.x2, s.y2, s.w2, s.h2);
            assertEquals(tutorials, library, "mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            boolean colliding = s.hitboxDecides ? library : tutorials;
            // A pixel near rectTwo's lower right corner, when rectOne does not cover it.
            int px = 466;
            int py = 162;
            if (s.x1 - 3 <= px && px <= s.x1 + s.w1 + 3 && s.y1 - 3 <= py && py <= s.y1 + s.h1 + 3) {   // under rectOne or its outline
                return;
            }
            assertEquals(Integer.toHexString(colliding ? Palette.HIT : Palette.MISS), Integer.toHexString(s.get(px, py) | 0xFF000000),
                    "rectTwo with the mouse at (" + s.mouseX + ", " + s.mouseY + ")");
            seen[colliding ? 1 : 0]++;
        }).run();
        assertTrue(seen[0] > 30 && seen[1] > 30, "frames apart and overlapping: " + seen[0] + ", " + seen[1]);
    }

    @Test
    void mouseSweep_countsStayEqual_untilTheRectanglesTouch() {
        Script script = new Script().frames(600);
        for (int f = 1; f <= 600; f++) {
            script.mouse(f, (f * 17) % 840, (f * 7) % 250);
        }
        long[] touchingFrames = {0};
        SketchRun.of(new S05b_RectRectTwoWays()).script(script).everyFrame(s -> {
            boolean touching = s.x1 + s.w1 == s.x2 || s.x1 == s.x2 + s.w2
                    || s.y1 + s.h1 == s.y2 || s.y1 == s.y2 + s.h2;
            boolean library = Collide.rectRect(s.x1, s.y1, s.w1, s.h1, s.x2, s.y2, s.w2, s.h2);
            assertEquals(library, s.andSays, "the && form is the library's test");
            if (touching) {
                touchingFrames[0]++;
            } else {
                assertEquals(library, s.orSays, "apart from touching, || agrees");
                assertEquals(s.andNow, s.orNow, "and evaluates as many comparisons");
            }
            // Evaluated comparisons come first, then the skipped ones; && stops at a false, || at a true.
            checkShortCircuit(s.andLit, s.andNow, F);
            checkShortCircuit(s.orLit, s.orNow, T);
            assertEquals(s.frames, s.frameCount, "every frame counted");
            if (touchingFrames[0] == 0) {
                assertEquals(s.andTotal, s.orTotal, "equal running counts while nothing has touched");
            }
        }).run();
    }

    private static void checkShortCircuit(int[] lit, int evaluated, int stopsOn) {
        for (int i = 0; i < 4; i++) {
            if (i < evaluated) {
                assertTrue(lit[i] != S, "comparison " + i + " was evaluated");
                if (i < evaluated - 1) {
                    assertTrue(lit[i] != stopsOn, "the form went on after comparison " + i);
                }
            } else {
                assertEquals(S, lit[i], "comparison " + i + " was skipped");
            }
        }
        if (evaluated < 4) {
            assertEquals(stopsOn, lit[evaluated - 1], "it stopped on the value that decides");
        }
    }

    @Test
    void resetKey_startsTheCountsAgain() {
        S05b_RectRectTwoWays s = SketchRun.of(new S05b_RectRectTwoWays())
                .script(new Script().frames(30).mouse(1, 400, 100).key(19, 'r')).run().sketch();
        // Overlapping: 4 comparisons a frame in each form; reset after frame 19.
        assertEquals(11, s.frames, "frames since r");
        assertEquals(44, s.andTotal);
        assertEquals(44, s.orTotal);
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 330, 12).key(3, 'd').key(8, 'd');
        SketchRun.Result<S05b_RectRectTwoWays> r = SketchRun.of(new S05b_RectRectTwoWays()).script(script)
                .capture(2).capture(6).run();
        // The counts change every frame: compare the play area only.
        assertTrue(SketchPixels.differing(r.frame(2), r.frame(6), 0, 0, 839, 240) > 1000, "the overlay draws the edges and the note");
        assertEquals(0, SketchPixels.differing(r.frame(2), r.lastFrame(), 0, 0, 839, 240), "pressing d again hides it");
    }
}
