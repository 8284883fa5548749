package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.lineLine and Segment-Segment overlaps: closed segments, exact on whole numbers. */
class LineLineTest {

    /**
     * Checks one case every way it can be asked: both argument orders, each segment's ends
     * either way round, moved far away (by a million, where floats still hold whole numbers),
     * and through the shapes.
     */
    static void assertLineLine(boolean expected, float x1, float y1, float x2, float y2,
                               float x3, float y3, float x4, float y4) {
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float a = x1 + shift, b = y1 - shift, c = x2 + shift, d = y2 - shift;
            float e = x3 + shift, f = y3 - shift, g = x4 + shift, h = y4 - shift;
            String where = " (shifted by " + shift + ")";
            assertEquals(expected, Collide.lineLine(a, b, c, d, e, f, g, h), "as given" + where);
            assertEquals(expected, Collide.lineLine(e, f, g, h, a, b, c, d), "segments swapped" + where);
            assertEquals(expected, Collide.lineLine(c, d, a, b, e, f, g, h), "first reversed" + where);
            assertEquals(expected, Collide.lineLine(a, b, c, d, g, h, e, f), "second reversed" + where);
            assertEquals(expected, new Segment(a, b, c, d).overlaps(new Segment(e, f, g, h)), "shapes" + where);
            assertEquals(expected, new Segment(e, f, g, h).overlaps(new Segment(a, b, c, d)), "shapes swapped" + where);
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // scenario,                                   x1, y1, x2, y2, x3, y3, x4, y4, expected
            "crossing diagonals,                            0,  0, 10, 10,  0, 10, 10,  0, true",
            "vertical crosses horizontal,                   5,  0,  5, 10,  0,  5, 10,  5, true",
            "lines cross beyond the second segment,         0,  0, 10,  0, 20, -5, 20,  5, false",
            "lines cross beyond both segments,              0,  0,  1,  1,  5,  0,  4,  1, false",
            "end touches the other's middle (T),            0,  0, 10,  0,  5,  0,  5, 10, true",
            "T one pixel short,                             0,  0, 10,  0,  5,  1,  5, 10, false",
            "ends meet at a corner,                         0,  0, 10,  0, 10,  0, 10, 10, true",
            "ends one pixel apart,                          0,  0, 10,  0, 11,  0, 11, 10, false",
            "identical segments,                            0,  0, 10, 10,  0,  0, 10, 10, true",
            "shallow crossing far out,                      0,  0, 1000000, 1, 0, 1, 1000000, 0, true",
    })
    void lineLine_crossingAndTouching(String scenario, float x1, float y1, float x2, float y2,
                                      float x3, float y3, float x4, float y4, boolean expected) {
        assertLineLine(expected, x1, y1, x2, y2, x3, y3, x4, y4);
    }

    /** The tutorial's formula divides by the lines' cross product: 0 for these. */
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "parallel horizontal (regression: division by 0), 0, 0, 10, 0,  0,  5, 10,  5, false",
            "parallel vertical (regression: division by 0),   0, 0,  0, 10, 5,  0,  5, 10, false",
            "parallel with almost the same slope,                 0, 0, 1000000, 1, 0, 1, 1000000, 2, false",
            "collinear overlapping (regression),              0, 0, 10, 0,  5,  0, 15,  0, true",
            "collinear with one inside the other,                 0, 0, 10, 0,  2,  0,  8,  0, true",
            "collinear touching end to end,                   0, 0, 10, 0, 10,  0, 20,  0, true",
            "collinear apart,                                 0, 0, 10, 0, 11,  0, 20,  0, false",
            "collinear diagonal apart,                        0, 0, 10, 10, 11, 11, 20, 20, false",
            "collinear diagonal touching,                     0, 0, 10, 10, 10, 10, 20, 20, true",
            "vertical collinear overlapping (regression),     3, 0,  3, 10, 3,  5,  3, 15, true",
            "vertical collinear apart,                        3, 0,  3, 10, 3, 11,  3, 15, false",
    })
    void lineLine_parallelAndCollinear(String scenario, float x1, float y1, float x2, float y2,
                                       float x3, float y3, float x4, float y4, boolean expected) {
        assertLineLine(expected, x1, y1, x2, y2, x3, y3, x4, y4);
    }

    /** A segment of length 0 is a point: closed, so it meets a segment through it. */
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "point in the middle of a segment,   5, 0,  5, 0,  0, 0, 10, 0, true",
            "point at a segment's end,          10, 0, 10, 0,  0, 0, 10, 0, true",
            "point beside a segment,             5, 1,  5, 1,  0, 0, 10, 0, false",
            "point on the line past the end,   11, 0, 11, 0,  0, 0, 10, 0, false",
            "point on a diagonal,                3, 3,  3, 3,  0, 0, 10, 10, true",
            "two points at the same place,       3, 3,  3, 3,  3, 3,  3, 3, true",
            "two points apart,                   3, 3,  3, 3,  4, 4,  4, 4, false",
    })
    void lineLine_zeroLength(String scenario, float x1, float y1, float x2, float y2,
                             float x3, float y3, float x4, float y4, boolean expected) {
        assertLineLine(expected, x1, y1, x2, y2, x3, y3, x4, y4);
    }

    @ParameterizedTest(name = "NaN as argument {0}")
    @CsvSource({"0", "1", "2", "3", "4", "5", "6", "7"})
    void lineLine_nanIsNoCollision(int slot) {
        float[] v = {0, 0, 10, 10, 0, 10, 10, 0};
        v[slot] = Float.NaN;
        assertEquals(false, Collide.lineLine(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }

    @Property(tries = 3000)
    void lineLine_agreesWithExactReference(@ForAll @IntRange(min = -4, max = 4) int x1, @ForAll @IntRange(min = -4, max = 4) int y1,
                                           @ForAll @IntRange(min = -4, max = 4) int x2, @ForAll @IntRange(min = -4, max = 4) int y2,
                                           @ForAll @IntRange(min = -4, max = 4) int x3, @ForAll @IntRange(min = -4, max = 4) int y3,
                                           @ForAll @IntRange(min = -4, max = 4) int x4, @ForAll @IntRange(min = -4, max = 4) int y4) {
        boolean expected = ExactReference.segmentsMeet(x1, y1, x2, y2, x3, y3, x4, y4);
        assertEquals(expected, Collide.lineLine(x1, y1, x2, y2, x3, y3, x4, y4));
    }

    @Property(tries = 500)
    void lineLine_symmetricAndTranslationInvariant(
            @ForAll @IntRange(min = -4, max = 4) int x1, @ForAll @IntRange(min = -4, max = 4) int y1,
            @ForAll @IntRange(min = -4, max = 4) int x2, @ForAll @IntRange(min = -4, max = 4) int y2,
            @ForAll @IntRange(min = -4, max = 4) int x3, @ForAll @IntRange(min = -4, max = 4) int y3,
            @ForAll @IntRange(min = -4, max = 4) int x4, @ForAll @IntRange(min = -4, max = 4) int y4,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx, @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean here = Collide.lineLine(x1, y1, x2, y2, x3, y3, x4, y4);
        assertEquals(here, Collide.lineLine(x3, y3, x4, y4, x1, y1, x2, y2));
        assertEquals(here, Collide.lineLine(x1 + dx, y1 + dy, x2 + dx, y2 + dy, x3 + dx, y3 + dy, x4 + dx, y4 + dy));
    }

    /** Scaled-up near misses: the crossing test must stay exact with big whole numbers. */
    @Property(tries = 1000)
    void lineLine_exactWhenScaledUp(@ForAll @IntRange(min = -4, max = 4) int x1, @ForAll @IntRange(min = -4, max = 4) int y1,
                                    @ForAll @IntRange(min = -4, max = 4) int x2, @ForAll @IntRange(min = -4, max = 4) int y2,
                                    @ForAll @IntRange(min = -4, max = 4) int x3, @ForAll @IntRange(min = -4, max = 4) int y3,
                                    @ForAll @IntRange(min = -4, max = 4) int x4, @ForAll @IntRange(min = -4, max = 4) int y4,
                                    @ForAll @IntRange(min = 1, max = 250_000) int k) {
        boolean expected = ExactReference.segmentsMeet(x1, y1, x2, y2, x3, y3, x4, y4);
        assertEquals(expected, Collide.lineLine(k * x1, k * y1, k * x2, k * y2, k * x3, k * y3, k * x4, k * y4));
    }
}
