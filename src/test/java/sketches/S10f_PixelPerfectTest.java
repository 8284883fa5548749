package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.Hybrid;
import hitbox.Hybrid.Stage;
import hitbox.PixelMask;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10f_PixelPerfect: a star sprite (top-left at 215, 100; centre about 300, 188) and a ring
 * sprite centred on the mouse, checked with Hybrid.check on their pixel masks; the star is
 * coloured by the stage that decided, and the first shared pixel is marked.
 */
class S10f_PixelPerfectTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): decided by {2}, colliding {3}")
    @CsvSource({
            "60,  360, CIRCLES, false",   // far away: the circles are enough
            "150, 190, BOXES,   false",   // beside the star: the circles meet, the boxes do not
            "200, 90,  PRECISE, false",   // in the box's corner between two points: no pixel shared
            "300, 290, PRECISE, false",   // between the two lower points
            "395, 120, PRECISE, false",   // just off the upper right point
            "390, 120, PRECISE, true",    // five pixels further in: the ring touches the point
            "300, 190, PRECISE, true",    // round the star's middle
    })
    void star_isColouredByTheStageThatDecided(int mx, int my, Stage stage, boolean colliding) {
        SketchRun.Result<S10f_PixelPerfect> r = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(4).mouse(1, mx, my)).run();
        S10f_PixelPerfect s = r.sketch();
        assertEquals(mx - 50, s.ringX, "the ring is centred on the mouse");
        assertEquals(Hybrid.check(s.starMask, s.starX, s.starY, s.ringMask, s.ringX, s.ringY), s.result,
                "the sketch's answer is the library's");
        assertEquals(stage, s.result.decidedBy(), "decided by");
        assertEquals(colliding, s.result.overlaps(), "colliding");
        int colour = colliding ? Palette.HIT
                : stage == Stage.CIRCLES ? s.CIRCLES_COLOUR
                : stage == Stage.BOXES ? Palette.ACCENT : Palette.MISS;
        // A pixel well inside the star's lower left point, away from the ring in every case.
        assertNear(r.lastFrame(), 264, 238, colour, "the star's lower left point");
        // Every check is counted, by the stage that decided it.
        assertEquals(4, s.counter.total());
        assertEquals(4, s.counter.decidedBy(stage));
        assertEquals(colliding ? 4 : 0, s.counter.overlapping());
    }

    @ParameterizedTest(name = "mouse ({0}, {1})")
    @CsvSource({"390, 120", "300, 190", "240, 250"})
    void colliding_marksTheFirstPixelBothShare(int mx, int my) {
        SketchRun.Result<S10f_PixelPerfect> r = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(3).mouse(1, mx, my)).run();
        S10f_PixelPerfect s = r.sketch();
        assertTrue(s.result.overlaps());
        PixelMask.Pixel p = s.firstPixel;
        assertNotNull(p, "a first pixel");
        assertEquals(s.starMask.firstOverlap(s.ringMask, s.ringX - s.starX, s.ringY - s.starY), p);
        assertTrue(s.starMask.contains(p.x(), p.y()), "solid in the star");
        assertTrue(s.ringMask.contains(p.x() + s.starX - s.ringX, p.y() + s.starY - s.ringY), "solid in the ring");
        assertTrue(s.sharedPixels > 0);
        // The marker: a small square round the pixel, 3 pixels out, in the accent colour.
        int sx = s.starX + p.x();
        int sy = s.starY + p.y();
        SketchPixels.assertColour(r.lastFrame(), sx - 3, sy, Palette.ACCENT, "marker's left side");
        SketchPixels.assertColour(r.lastFrame(), sx + 4, sy, Palette.ACCENT, "marker's right side");
    }

    @Test
    void apart_marksNoPixel() {
        S10f_PixelPerfect s = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(3).mouse(1, 200, 90)).run().sketch();
        assertNull(s.firstPixel);
        assertEquals(0, s.sharedPixels);
    }

    @Test
    void crowd_mostChecksAreDecidedBeforeThePixels() {
        SketchRun.Result<S10f_PixelPerfect> r = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(5).mouse(1, 330, 200).key(1, 'c')).run();
        S10f_PixelPerfect s = r.sketch();
        assertTrue(s.crowdMode);
        Hybrid.Counter c = s.crowdCounter;
        assertEquals(s.crowdX.length, c.total(), "every star in the crowd is checked once a frame");
        int overlapping = 0;
        for (int i = 0; i < s.crowdX.length; i++) {
            Hybrid.Result expected = Hybrid.check(s.smallMask, s.crowdX[i], s.crowdY[i], s.ringMask, s.ringX, s.ringY);
            assertEquals(expected, s.crowdResults[i], "star " + i);
            overlapping += expected.overlaps() ? 1 : 0;
        }
        assertEquals(overlapping, c.overlapping());
        assertTrue(overlapping >= 1, "the ring touches a star");
        assertTrue(c.decidedBy(Stage.CIRCLES) > 30, "most stars are dismissed by their circles: " + c);
        assertTrue(c.decidedBy(Stage.BOXES) >= 1, "some by their boxes: " + c);
        assertTrue(c.decidedBy(Stage.PRECISE) < 8, "the pixel test runs for a few only: " + c);
        SketchRun.Result<S10f_PixelPerfect> back = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(5).mouse(1, 330, 200).key(1, 'c').key(2, 'c')).run();
        assertTrue(!back.sketch().crowdMode, "c again goes back to the big star");
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 390, 120).key(3, 'd').key(8, 'd');
        SketchRun.Result<S10f_PixelPerfect> r = SketchRun.of(new S10f_PixelPerfect()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 2000, "the overlay draws the circles, the boxes and the comparisons");
        // The tally at the bottom counts every frame's check, so it differs; the rest must not.
        assertEquals(0, SketchPixels.differing(off, r.lastFrame(), 0, 0, 599, 299), "pressing d again hides the overlay");
    }

    /** Asserts a pixel's colour within 3 per channel: a tinted image may round by one or two. */
    private static void assertNear(PImage frame, int x, int y, int expected, String what) {
        int actual = frame.get(x, y);
        for (int shift = 0; shift <= 16; shift += 8) {
            int a = actual >> shift & 0xFF;
            int e = expected >> shift & 0xFF;
            assertTrue(Math.abs(a - e) <= 3, what + " at (" + x + ", " + y + "): expected "
                    + Integer.toHexString(expected) + " but was " + Integer.toHexString(actual));
        }
    }

    @Test
    void writtenOutStages_agreeWithHybridCheck_everywhere_inBothPixelWays() {
        S10f_PixelPerfect s = SketchRun.of(new S10f_PixelPerfect()).frames(1).run().sketch();
        java.util.Random random = new java.util.Random(4);
        int[] byStage = new int[3];
        for (boolean loop : new boolean[] {true, false}) {
            s.hitboxDecides = !loop;
            for (int i = 0; i < 3000; i++) {
                int rx = 100 + random.nextInt(400);
                int ry = 20 + random.nextInt(360);
                int[] before = s.ran.clone();
                Hybrid.Result expected = Hybrid.check(s.starMask, s.starX, s.starY, s.ringMask, rx, ry);
                Hybrid.Result got = s.hybrid(s.starMask, s.starX, s.starY, s.ringMask, rx, ry);
                assertEquals(expected, got, "ring at " + rx + ", " + ry + (loop ? ", pixel loop" : ""));
                int stage = got.decidedBy().ordinal();
                byStage[stage]++;
                // Each stage ran up to the one that decided, and no further.
                for (int k = 0; k < 3; k++) {
                    assertEquals(before[k] + (k <= stage ? 1 : 0), s.ran[k], "stage " + (k + 1) + " ran");
                }
            }
        }
        assertTrue(byStage[0] > 0 && byStage[1] > 0 && byStage[2] > 0, "every stage decided some: "
                + java.util.Arrays.toString(byStage));
    }

    @Test
    void countsPerFrame_matchTheCrowdsStages_andTheDefaultTimesThePixelLoop() {
        SketchRun.Result<S10f_PixelPerfect> r = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(5).mouse(1, 330, 200).key(1, 'c')).run();
        S10f_PixelPerfect s = r.sketch();
        assertFalse(s.hitboxDecides, "by default, stage 3 is the plain pixel loop");
        Hybrid.Counter c = s.crowdCounter;
        assertEquals(c.total(), s.ran[0], "stage 1 runs for every star");
        assertEquals(c.total() - c.decidedBy(Stage.CIRCLES), s.ran[1], "stage 2 for those the circles did not dismiss");
        assertEquals(c.decidedBy(Stage.PRECISE), s.ran[2], "stage 3 for those the boxes did not dismiss");
        assertTrue(s.ran[2] >= 1 && s.pixelNanos > 0, "stage 3 ran and was timed");
        assertTrue(s.thisFrame().contains("pixel loop"), s.thisFrame());
        SketchRun.Result<S10f_PixelPerfect> l = SketchRun.of(new S10f_PixelPerfect())
                .script(new Script().frames(5).mouse(1, 330, 200).key(1, 'c').key(2, 'l')).run();
        assertTrue(l.sketch().hitboxDecides, "l: PixelMask.overlaps");
        assertTrue(l.sketch().thisFrame().contains("PixelMask"), l.sketch().thisFrame());
    }
}
