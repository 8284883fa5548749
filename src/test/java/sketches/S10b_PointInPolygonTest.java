package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
 * S10b_PointInPolygon: the crown (corners at y = 70 and y = 140 level with each other, a
 * notch at the bottom) is red while the mouse is inside; the ray to the right shows the
 * crossings, whose count is odd exactly when the point is inside.
 */
class S10b_PointInPolygonTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "mouse ({0}, {1}): inside {2}, {3} crossings")
    @CsvSource({
            // mouse x, y, inside, crossings counted, corners touched but not crossed
            "300, 180, true,  1, 0",
            "160, 140, true,  1, 2",   // level with both valley corners: they are touched, not crossed
            "100, 70,  false, 6, 0",   // level with the peaks: each peak is counted twice
            "60,  190, false, 2, 0",   // level with the left corner: it is passed through, counted once
            "300, 280, false, 2, 0",   // in the notch
            "200, 260, true,  3, 0",   // in the lower left lobe: out across the notch and back in
            "560, 140, false, 0, 0",   // right of everything
            "300, 40,  false, 0, 0",   // above the middle peak
    })
    void crown_isRedWhileTheMouseIsInside_andTheCountIsOddExactlyThen(int mx, int my, boolean inside,
                                                                       int crossings, int touched) {
        SketchRun.Result<S10b_PointInPolygon> r = SketchRun.of(new S10b_PointInPolygon())
                .script(new Script().frames(4).mouse(1, mx, my)).run();
        S10b_PointInPolygon s = r.sketch();
        assertEquals(s.crossings % 2 == 1, s.inside, "the colour is the count's answer: odd means inside");
        assertEquals(Collide.polygonPoint(s.crown.coordinates(), mx, my), s.inside, "and the library agrees");
        assertEquals(inside, s.inside, "inside");
        assertEquals(crossings, s.crossings, "crossings");
        assertEquals(touched, s.touched.size(), "corners touched");
        assertFalse(s.onOutline);
        SketchPixels.assertColour(r.lastFrame(), 300, 200, inside ? Palette.HIT : Palette.MISS, "the crown");
    }

    @ParameterizedTest(name = "mouse ({0}, {1})")
    @CsvSource({
            "220, 140",   // a valley corner
            "90,  190",   // the left corner
            "170, 105",   // the middle of edge e0, from (120, 70) to (220, 140)
    })
    void pointOnTheOutline_theCountAloneCannotSeeIt_CollidePolygonPointAfterL_saysNotInside(int mx, int my) {
        S10b_PointInPolygon s = SketchRun.of(new S10b_PointInPolygon())
                .script(new Script().frames(3).mouse(1, mx, my)).run().sketch();
        assertTrue(s.onOutline, "the ray starts on an edge");
        assertEquals(s.crossings % 2 == 1, s.inside, "by default the count decides, even on the outline");
        assertFalse(s.hitboxSays, "polygons are open: the outline is not inside");
        S10b_PointInPolygon l = SketchRun.of(new S10b_PointInPolygon())
                .script(new Script().frames(3).mouse(1, mx, my).key(1, 'l')).run().sketch();
        assertFalse(l.inside, "with l, Collide.polygonPoint decides: not inside");
    }

    @Test
    void crossingCount_isOddExactlyWhenInside_allOverTheWindow() {
        Script script = new Script();
        int frame = 1;
        for (int y = 5; y < 400; y += 9) {
            for (int x = 3; x < 600; x += 9) {
                script.mouse(frame++, x, y);
            }
        }
        // The row y = 5 + 9 * 15 = 140 is level with the two valley corners.
        int[] checked = {0, 0};
        SketchRun.of(new S10b_PointInPolygon()).script(script.frames(frame - 1)).everyFrame(s -> {
            assertEquals(s.crossings % 2 == 1, s.inside, "the count decides the colour");
            if (!s.onOutline) {
                assertEquals(s.hitboxSays, s.crossings % 2 == 1,
                        "off the outline, Collide.polygonPoint agrees, at (" + s.px + ", " + s.py + "): " + s.crossings + " crossings");
                checked[s.inside ? 1 : 0]++;
            }
        }).run();
        assertTrue(checked[0] > 500 && checked[1] > 500, "points inside and outside, " + checked[1] + " and " + checked[0]);
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 160, 140).key(3, 'd').key(8, 'd');
        SketchRun.Result<S10b_PointInPolygon> r = SketchRun.of(new S10b_PointInPolygon()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 2000, "the overlay numbers the edges and writes out the rule");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }

    @Test
    void writtenOutCrossingRule_isRayCrossesEdge_forEveryEdge_allOverTheWindow() {
        S10b_PointInPolygon s = SketchRun.of(new S10b_PointInPolygon()).frames(1).run().sketch();
        int counted = 0;
        for (int y = 0; y <= 400; y += 5) {
            for (int x = 0; x <= 600; x += 5) {
                s.px = x;
                s.py = y;
                for (int i = 0; i < s.crown.size(); i++) {
                    hitbox.Segment e = s.crown.edge(i);
                    boolean expected = Collide.rayCrossesEdge(e.x1(), e.y1(), e.x2(), e.y2(), x, y);
                    assertEquals(expected, s.crosses(e.x1(), e.y1(), e.x2(), e.y2()), "edge " + i + " from (" + x + ", " + y + ")");
                    counted += expected ? 1 : 0;
                }
            }
        }
        assertTrue(counted > 1000, "many crossings were compared: " + counted);
    }

    @Test
    void ball_overlapsTheCrown_exactlyAsTheLibrarySays_andColoursIt() {
        int[] seen = new int[3];
        Script script = new Script().frames(2 + 61 * 41).key(1, 'b');
        int f = 2;
        for (int y = 0; y <= 400; y += 10) {
            for (int x = 0; x <= 600; x += 10) {
                script.mouse(f++, x, y);
            }
        }
        SketchRun.of(new S10b_PointInPolygon()).script(script).everyFrame(s -> {
            if (s.frameCount < 3) {
                return;
            }
            assertTrue(s.ballMode);
            boolean expected = s.crown.overlaps(new hitbox.Circle(s.px, s.py, s.ballRadius));
            assertEquals(expected, s.ballHits, "the ball at (" + s.px + ", " + s.py + ")");
            if (expected && !s.inside) {
                seen[0]++;   // overlapping with its centre outside: an edge cuts into it
            } else if (expected) {
                seen[1]++;
            } else {
                seen[2]++;
            }
        }).run();
        assertTrue(seen[0] > 20 && seen[1] > 20 && seen[2] > 20, "centre outside but touching, inside, apart: "
                + java.util.Arrays.toString(seen));
        SketchRun.Result<S10b_PointInPolygon> r = SketchRun.of(new S10b_PointInPolygon())
                .script(new Script().frames(4).key(1, 'b').mouse(1, 330, 255)).run();
        assertFalse(r.sketch().inside, "the centre is in the notch, outside");
        assertTrue(r.sketch().ballHits, "but the ball reaches the notch's point");
        SketchPixels.assertColour(r.lastFrame(), 300, 200, Palette.HIT, "the crown is red");
    }
}
