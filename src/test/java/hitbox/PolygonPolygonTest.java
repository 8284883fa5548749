package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.statistics.Statistics;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.polygonPolygon and Polygon-Polygon overlaps: two open shapes, convex or concave. */
class PolygonPolygonTest {

    /**
     * One case, every way: both argument orders, each polygon in both windings and from every
     * start, moved by a million, as shapes; and the reference agrees.
     */
    static void assertPolygonPolygon(boolean expected, float[] a, float[] b) {
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float[] ma = ExactReference.translated(a, shift, shift);
            float[] mb = ExactReference.translated(b, shift, shift);
            String where = " (shifted by " + shift + ")";
            for (float[] wa : new float[][] {ma, ExactReference.reversed(ma)}) {
                for (float[] wb : new float[][] {mb, ExactReference.reversed(mb)}) {
                    for (int i = 0; i < wa.length / 2; i++) {
                        for (int j = 0; j < wb.length / 2; j++) {
                            float[] ra = ExactReference.rotated(wa, i);
                            float[] rb = ExactReference.rotated(wb, j);
                            assertEquals(expected, Collide.polygonPolygon(ra, rb), "a from " + i + ", b from " + j + where);
                            assertEquals(expected, Collide.polygonPolygon(rb, ra), "swapped, a from " + i + ", b from " + j + where);
                        }
                    }
                }
            }
            assertEquals(expected, Polygon.of(ma).overlaps(Polygon.of(mb)), "shapes" + where);
            assertEquals(expected, Polygon.of(mb).overlaps(Polygon.of(ma)), "shapes swapped" + where);
        }
        assertEquals(expected, ExactReference.polygonsMeet(a, b), "the reference agrees");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // scenario,                                 a,                       b,                                  expected
            "the same square,                            square,                  square,                             true",
            "the same outline with an extra vertex,      square,                  squareWithMidpoint,                 true",
            "side by side sharing an edge,               square,                  10 0 20 0 20 10 10 10,              false",
            "sharing half an edge,                       square,                  10 5 20 5 20 15 10 15,              false",
            "touching at a corner,                       square,                  10 10 20 10 20 20 10 20,            false",
            "overlapping by half,                        square,                  5 0 15 0 15 10 5 10,                true",
            "small square inside (regression),           square,                  2 2 4 2 4 4 2 4,                    true",
            "inside and touching an edge from inside,    square,                  0 2 4 2 4 4 0 4,                    true",
            "diamond inside touching at four points,     square,                  diamond,                            true",
            "triangle's corner on an edge,               square,                  10 5 15 0 15 10,                    false",
            "triangle's corner one pixel in,             square,                  9 5 15 0 15 10,                     true",
            "a cross bar with no corner inside,          square,                  -5 4 15 4 15 6 -5 6,                true",
            "two triangles sharing a diagonal,           0 0 10 0 10 10,          0 0 10 10 0 10,                     false",
            "far apart,                                  square,                  100 100 110 100 105 110,            false",
    })
    void polygonPolygon_convex(String scenario, String a, String b, boolean expected) {
        assertPolygonPolygon(expected, TestShapes.get(a), TestShapes.get(b));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "square filling the cup's notch,             cup,                     4 0 6 0 6 8 4 8,                    false",
            "the notch square one row deeper,            cup,                     4 0 6 0 6 9 4 9,                    true",
            "the notch square one wider,                 cup,                     3 0 6 0 6 8 3 8,                    true",
            "lid on the cup,                             cup,                     -1 -5 11 -5 11 0 -1 0,              false",
            "triangle filling the crown's V,             crown,                   0 0 10 0 5 5,                       false",
            "smaller triangle in the V at its bottom,    crown,                   2 0 8 0 5 5,                        false",
            "triangle through the V's bottom,            crown,                   2 0 8 0 5 6,                        true",
            "square in the ell's missing corner,         ell,                     5 5 10 5 10 10 5 10,                false",
            "that square moved in by one,                ell,                     4 4 9 4 9 9 4 9,                    true",
            "an upside-down crown above the crown,       crown,                   0 -5 5 0 10 -5 10 -10 0 -10,        false",
            "the same crown,                             crown,                   crown,                              true",
            "crown inside a big square,                  crown,                   -1 -1 11 -1 11 11 -1 11,            true",
            "V triangle poking the double V's peak,      doubleV,                 4 -2 8 -2 6 2,                      true",
            "V triangle resting on the double V's peak,  doubleV,                 4 -2 8 -2 6 0,                      false",
            "triangles in both notches of the double V,  doubleV,                 0 0 6 0 3 6,                        false",
    })
    void polygonPolygon_concave(String scenario, String a, String b, boolean expected) {
        assertPolygonPolygon(expected, TestShapes.get(a), TestShapes.get(b));
    }

    @Test
    void polygonPolygon_fewerThanThreeVerticesNeverCollide() {
        assertFalse(Collide.polygonPolygon(new float[0], TestShapes.SQUARE));
        assertFalse(Collide.polygonPolygon(TestShapes.SQUARE, new float[] {0, 0, 10, 10}));
        assertFalse(Collide.polygonPolygon(new float[] {0, 0, 10, 10, 5}, TestShapes.SQUARE));
        assertTrue(Collide.polygonPolygon(new float[] {0, 0, 10, 0, 10, 10, 0, 10, 3}, TestShapes.SQUARE), "odd last coordinate ignored");
    }

    @Provide
    Arbitrary<float[]> polygons() {
        return TestShapes.simplePolygons(5, 6);
    }

    /** The second polygon is moved by up to 4 each way, so apart, touching and overlapping all come up. */
    @StatisticsReport(onFailureOnly = true)
    @Property(tries = 2000)
    void polygonPolygon_agreesWithExactReference(@ForAll("polygons") float[] a, @ForAll("polygons") float[] b,
                                                 @ForAll @IntRange(min = -4, max = 4) int dx,
                                                 @ForAll @IntRange(min = -4, max = 4) int dy) {
        float[] moved = ExactReference.translated(b, dx, dy);
        boolean expected = ExactReference.polygonsMeet(a, moved);
        assertEquals(expected, Collide.polygonPolygon(a, moved));
        Statistics.collect(expected);
        Statistics.coverage(c -> {
            c.check(true).percentage(p -> p > 20);
            c.check(false).percentage(p -> p > 20);
        });
    }

    /** Shifted copies of one polygon share edges and corners with it often: the hard cases. */
    @Property(tries = 1500)
    void polygonPolygon_shiftedCopiesAgreeWithReference(@ForAll("polygons") float[] a,
                                                        @ForAll @IntRange(min = -3, max = 3) int dx,
                                                        @ForAll @IntRange(min = -3, max = 3) int dy,
                                                        @ForAll boolean reverse) {
        float[] moved = ExactReference.translated(a, dx, dy);
        float[] b = reverse ? ExactReference.reversed(moved) : moved;
        assertEquals(ExactReference.polygonsMeet(a, b), Collide.polygonPolygon(a, b));
    }

    @Property(tries = 1000)
    void polygonPolygon_symmetricAndTranslationInvariant(@ForAll("polygons") float[] a, @ForAll("polygons") float[] b,
                                                         @ForAll @IntRange(min = 0, max = 5) int start,
                                                         @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                                         @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean here = Collide.polygonPolygon(a, b);
        assertEquals(here, Collide.polygonPolygon(b, a), "swapped");
        assertEquals(here, Collide.polygonPolygon(ExactReference.reversed(a), b), "other winding");
        assertEquals(here, Collide.polygonPolygon(a, ExactReference.rotated(b, start % (b.length / 2))), "other start");
        assertEquals(here, Collide.polygonPolygon(ExactReference.translated(a, dx, dy), ExactReference.translated(b, dx, dy)), "moved");
    }

    @Property(tries = 500)
    void polygonPolygon_overlapsItself(@ForAll("polygons") float[] a) {
        assertTrue(Collide.polygonPolygon(a, a));
        assertTrue(Collide.polygonPolygon(a, ExactReference.reversed(a)));
    }
}
