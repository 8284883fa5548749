package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.Collide;
import hitbox.SeparatingAxis;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10c_SeparatingAxis: a 170 x 90 rectangle turning about (280, 215) and a regular polygon
 * (radius 52) at the mouse; the rectangle is red while they overlap, and a separating axis is
 * highlighted exactly while they do not.
 */
class S10c_SeparatingAxisTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): overlapping {2}")
    @CsvSource({
            "430, 110, false",   // above right
            "120, 330, false",   // below left
            "340, 230, true",    // across the rectangle's right end
            "280, 215, true",    // on its centre
            "280, 110, false",   // above the middle
            "280, 150, true",
    })
    void rectangle_isRedWhileTheyOverlap_andASeparatingAxisIsShownOtherwise(int mx, int my, boolean overlapping) {
        // Space on frame 1 stops the turning, so every case sees the same rectangle.
        SketchRun.Result<S10c_SeparatingAxis> r = SketchRun.of(new S10c_SeparatingAxis())
                .script(new Script().frames(4).mouse(1, mx, my).key(1, ' ')).run();
        S10c_SeparatingAxis s = r.sketch();
        assertEquals(overlapping, s.overlapping, "overlapping");
        assertEquals(!overlapping, s.separating >= 0, "a separating axis is highlighted exactly when apart");
        SketchPixels.assertColour(r.lastFrame(), 224, 194, overlapping ? Palette.HIT : Palette.MISS, "the rectangle");
    }

    @Test
    void separatingAxis_existsExactlyWhenTheShapesDoNotOverlap_alongAPath() {
        Script script = new Script().frames(900).hold(300, "4", 1).hold(600, "6", 1);
        // The mouse sweeps across the rectangle and back, row by row, while it turns.
        for (int f = 1; f <= 900; f++) {
            int x = 40 + (f * 7) % 500;
            int y = 40 + (f / 72) * 30 % 360;
            script.mouse(f, x, y);
        }
        int[] seen = {0, 0};
        SketchRun.of(new S10c_SeparatingAxis()).script(script).everyFrame(s -> {
            boolean library = Collide.polygonPolygon(s.box.coordinates(), s.mover.coordinates());
            assertEquals(library, s.overlapping, "SAT agrees with the general polygon test");
            assertEquals(s.box.size() + s.mover.size(), s.axes.size(), "one axis per edge");
            boolean anySeparates = s.axes.stream().anyMatch(SeparatingAxis.Axis::separates);
            assertEquals(!s.overlapping, anySeparates, "some axis separates exactly when apart");
            assertEquals(!s.overlapping, s.separating >= 0, "the highlighted axis");
            assertEquals(s.box.overlaps(s.mover), s.hitboxSays);
            assertEquals(s.hitboxSays, s.overlapping, "the written-out loop and box.overlaps(mover) agree");
            // The first tab's axes, written out, are the ones the library lists, in its order.
            List<SeparatingAxis.Axis> libraryAxes = SeparatingAxis.axes(s.box, s.mover);
            assertEquals(libraryAxes.size(), s.axes.size());
            for (int i = 0; i < libraryAxes.size(); i++) {
                SeparatingAxis.Axis mine = s.axes.get(i);
                SeparatingAxis.Axis theirs = libraryAxes.get(i);
                assertEquals(theirs.nx(), mine.nx(), 1e-5f, "axis " + i + " nx");
                assertEquals(theirs.ny(), mine.ny(), 1e-5f, "axis " + i + " ny");
                assertEquals(theirs.minA(), mine.minA(), 1e-3f, "axis " + i + ": box's shadow starts");
                assertEquals(theirs.maxB(), mine.maxB(), 1e-3f, "axis " + i + ": mover's shadow ends");
            }
            // And its projections are the shadows it stores.
            for (SeparatingAxis.Axis a : s.axes) {
                float[] shadowA = s.shadow(s.box, a.nx(), a.ny());
                float[] shadowB = s.shadow(s.mover, a.nx(), a.ny());
                assertEquals(a.minA(), shadowA[0], 1e-3f, "box's shadow starts");
                assertEquals(a.maxA(), shadowA[1], 1e-3f, "box's shadow ends");
                assertEquals(a.minB(), shadowB[0], 1e-3f, "mover's shadow starts");
                assertEquals(a.maxB(), shadowB[1], 1e-3f, "mover's shadow ends");
            }
            if (s.separating >= 0) {
                assertTrue(s.axes.get(s.separating).separates());
                assertEquals(s.separating, s.shown);
            } else {
                assertFalse(s.axes.get(s.shown).separates());
            }
            seen[s.overlapping ? 1 : 0]++;
        }).run();
        assertTrue(seen[0] > 100 && seen[1] > 100, "frames apart and overlapping: " + seen[0] + ", " + seen[1]);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}) with l: overlapping {2}")
    @CsvSource({"430, 110, false", "340, 230, true"})
    void lKey_separatingAxisOverlapsDecides_theSameColours(int mx, int my, boolean overlapping) {
        SketchRun.Result<S10c_SeparatingAxis> r = SketchRun.of(new S10c_SeparatingAxis())
                .script(new Script().frames(4).mouse(1, mx, my).key(1, ' ').key(1, 'l')).run();
        assertTrue(r.sketch().hitboxDecides);
        assertEquals(overlapping, r.sketch().overlapping);
        SketchPixels.assertColour(r.lastFrame(), 224, 194, overlapping ? Palette.HIT : Palette.MISS, "the rectangle");
    }

    @Test
    void sidesKeys_changeTheMouseShape_andTheAxes() {
        S10c_SeparatingAxis s = SketchRun.of(new S10c_SeparatingAxis())
                .script(new Script().frames(4).mouse(1, 430, 110).key(1, '6')).run().sketch();
        assertEquals(6, s.mover.size());
        assertEquals(10, s.axes.size(), "4 for the rectangle, 6 for the hexagon");
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 430, 110).key(1, ' ').key(3, 'd').key(8, 'd');
        SketchRun.Result<S10c_SeparatingAxis> r = SketchRun.of(new S10c_SeparatingAxis()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 1000, "the overlay draws the light and the shadows' numbers");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
