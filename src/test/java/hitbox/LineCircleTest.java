package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.lineCircle and Segment-Circle overlaps: the closed segment must reach the open disk. */
class LineCircleTest {

    /** One case, every way: both shape orders, the segment either way round, moved by a million. */
    static void assertLineCircle(boolean expected, float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float a = x1 + shift, b = y1 + shift, c = x2 + shift, d = y2 + shift, e = cx + shift, f = cy + shift;
            String where = " (shifted by " + shift + ")";
            assertEquals(expected, Collide.lineCircle(a, b, c, d, e, f, r), "as given" + where);
            assertEquals(expected, Collide.lineCircle(c, d, a, b, e, f, r), "segment reversed" + where);
            assertEquals(expected, new Segment(a, b, c, d).overlaps(new Circle(e, f, r)), "segment first" + where);
            assertEquals(expected, new Circle(e, f, r).overlaps(new Segment(a, b, c, d)), "circle first" + where);
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // scenario,                             x1,  y1, x2,  y2, cx, cy, r, expected
            "through the centre,                    -10,   0, 10,   0,  0,  0, 5, true",
            "tangent to the top,                    -10,   5, 10,   5,  0,  0, 5, false",
            "one pixel inside the tangent,          -10,   4, 10,   4,  0,  0, 5, true",
            "vertical tangent,                        5, -10,  5,  10,  0,  0, 5, false",
            "vertical through,                        3, -10,  3,  10,  0,  0, 5, true",
            "diagonal tangent at (3 4),              -1,   7,  7,   1,  0,  0, 5, false",
            "diagonal just inside,                   -1,   6,  7,   0,  0,  0, 5, true",
            "end touches the outline,                 5,   0, 10,   0,  0,  0, 5, false",
            "end just inside,                         4,   0, 10,   0,  0,  0, 5, true",
            "wholly inside,                          -1,   0,  1,   0,  0,  0, 5, true",
            "line would cross but the segment stops,  6,   0, 10,   0,  0,  0, 5, false",
            "closest point is an end on the outline,  3,   4, 10,   4,  0,  0, 5, false",
            "far away,                               20,  20, 30,  30,  0,  0, 5, false",
    })
    void lineCircle_table(String scenario, float x1, float y1, float x2, float y2, float cx, float cy, float r, boolean expected) {
        assertLineCircle(expected, x1, y1, x2, y2, cx, cy, r);
    }

    /** Radius 0 has no inside (a segment and a zero-size shape never collide); length 0 is a point. */
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "radius 0 on the segment,                -10,   0, 10,   0,  0,  0, 0, false",
            "radius 0 at an end,                       0,   0, 10,   0,  0,  0, 0, false",
            "point segment at the centre,              0,   0,  0,   0,  0,  0, 5, true",
            "point segment just inside,                3,   3,  3,   3,  0,  0, 5, true",
            "point segment on the outline,             3,   4,  3,   4,  0,  0, 5, false",
            "point segment and radius 0 together,      0,   0,  0,   0,  0,  0, 0, false",
            "negative radius,                        -10,   0, 10,   0,  0,  0, -5, false",
    })
    void lineCircle_zeroSize(String scenario, float x1, float y1, float x2, float y2, float cx, float cy, float r, boolean expected) {
        assertEquals(expected, Collide.lineCircle(x1, y1, x2, y2, cx, cy, r));
        assertEquals(expected, Collide.lineCircle(x2, y2, x1, y1, cx, cy, r));
        if (r >= 0) {
            assertEquals(expected, new Circle(cx, cy, r).overlaps(new Segment(x1, y1, x2, y2)));
        }
    }

    /**
     * Near-tangent segments with coordinates near a million, where cross^2 and r^2 * length^2
     * differ by less than a double's rounding: a plain double comparison answers false here.
     */
    @ParameterizedTest(name = "{0} {1} {2} {3} r={4}")
    @CsvSource({
            "-116461, -288992, 624892,  499958, 113026, true",
            "-370462,   62070, 437665, -676653, 204138, true",
            "-392545, -241309, 429566,   12169, 114938, true",
            "-760833,  620652, -301756, -236158, 377515, true",
            " 157170, -197653, 594941,  566721, 234616, true",
            "-732774,  281027, 108757, -536654, 309097, true",
            // exactly tangent at (300000, 400000): touching, not colliding
            "-100000,  700000, 700000,  100000, 500000, false",
    })
    void lineCircle_nearTangentWithBigNumbers(float x1, float y1, float x2, float y2, float r, boolean expected) {
        assertEquals(expected, Collide.lineCircle(x1, y1, x2, y2, 0, 0, r));
        assertEquals(expected, Collide.lineCircle(x2, y2, x1, y1, 0, 0, r));
        assertEquals(expected, ExactReference.segmentCircle(x1, y1, x2, y2, 0, 0, r));
    }

    @ParameterizedTest(name = "NaN as argument {0}")
    @CsvSource({"0", "1", "2", "3", "4", "5", "6"})
    void lineCircle_nanIsNoCollision(int slot) {
        float[] v = {-10, 0, 10, 0, 0, 0, 5};
        v[slot] = Float.NaN;
        assertEquals(false, Collide.lineCircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6]));
    }

    @Property(tries = 3000)
    void lineCircle_agreesWithExactReference(@ForAll @IntRange(min = -6, max = 6) int x1, @ForAll @IntRange(min = -6, max = 6) int y1,
                                             @ForAll @IntRange(min = -6, max = 6) int x2, @ForAll @IntRange(min = -6, max = 6) int y2,
                                             @ForAll @IntRange(min = -6, max = 6) int cx, @ForAll @IntRange(min = -6, max = 6) int cy,
                                             @ForAll @IntRange(min = 0, max = 6) int r) {
        assertEquals(ExactReference.segmentCircle(x1, y1, x2, y2, cx, cy, r), Collide.lineCircle(x1, y1, x2, y2, cx, cy, r));
    }

    /** Scaled by up to 200 000 and moved by up to a million, small cases keep their answer. */
    @Property(tries = 2000)
    void lineCircle_exactWhenScaledAndMoved(@ForAll @IntRange(min = -6, max = 6) int x1, @ForAll @IntRange(min = -6, max = 6) int y1,
                                            @ForAll @IntRange(min = -6, max = 6) int x2, @ForAll @IntRange(min = -6, max = 6) int y2,
                                            @ForAll @IntRange(min = -6, max = 6) int cx, @ForAll @IntRange(min = -6, max = 6) int cy,
                                            @ForAll @IntRange(min = 0, max = 6) int r, @ForAll @IntRange(min = 1, max = 200_000) int k,
                                            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean expected = ExactReference.segmentCircle(x1, y1, x2, y2, cx, cy, r);
        assertEquals(expected, Collide.lineCircle(k * x1, k * y1, k * x2, k * y2, k * cx, k * cy, k * r), "scaled");
        assertEquals(expected, Collide.lineCircle(x1 + dx, y1 + dy, x2 + dx, y2 + dy, cx + dx, cy + dy, r), "moved");
    }
}
