package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Collide.lineRect and Segment-Rect overlaps: the closed segment must reach the rectangle's open inside. */
class LineRectTest {

    /** One case, every way: both shape orders, the segment either way round, moved by a million. */
    static void assertLineRect(boolean expected, float x1, float y1, float x2, float y2, float rx, float ry, float rw, float rh) {
        for (float shift : new float[] {0, 1_000_000, -1_000_000}) {
            float a = x1 + shift, b = y1 - shift, c = x2 + shift, d = y2 - shift, e = rx + shift, f = ry - shift;
            String where = " (shifted by " + shift + ")";
            assertEquals(expected, Collide.lineRect(a, b, c, d, e, f, rw, rh), "as given" + where);
            assertEquals(expected, Collide.lineRect(c, d, a, b, e, f, rw, rh), "segment reversed" + where);
            assertEquals(expected, new Segment(a, b, c, d).overlaps(new Rect(e, f, rw, rh)), "segment first" + where);
            assertEquals(expected, new Rect(e, f, rw, rh).overlaps(new Segment(a, b, c, d)), "rect first" + where);
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            // rectangle 0, 0, 10, 10 throughout;     x1,  y1, x2,  y2, expected
            "straight through,                        -5,   5, 15,   5, true",
            "wholly inside (regression: no edge crossed), 2, 2,  8,   8, true",
            "wholly inside and horizontal,             2,   5,  8,   5, true",
            "corner to corner diagonal,                0,   0, 10,  10, true",
            "along the top edge,                      -5,   0, 15,   0, false",
            "along part of the top edge,               2,   0,  8,   0, false",
            "along the left edge,                      0,  -5,  0,  15, false",
            "along the right edge,                    10,  -5, 10,  15, false",
            "one pixel inside the right edge,          9,  -5,  9,  15, true",
            "through the corner only,                 -5,   5,  5,  -5, false",
            "ends at the corner,                      -5,  -5,  0,   0, false",
            "cuts the corner,                         -1,   2,  2,  -1, true",
            "misses the corner,                       -2,   1,  1,  -2, false",
            "ends on an edge from outside,            15,   5, 10,   5, false",
            "ends on an edge from inside,              5,   5, 10,   5, true",
            "from edge to edge across,                 0,   5, 10,   5, true",
            "outside to the right,                    11,   0, 20,  10, false",
            "steep line past the corner,              11,  -1, 12,  30, false",
    })
    void lineRect_table(String scenario, float x1, float y1, float x2, float y2, boolean expected) {
        assertLineRect(expected, x1, y1, x2, y2, 0, 0, 10, 10);
    }

    /** A zero-size rectangle has no inside; a zero-length segment is a point. */
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "point inside,                     5, 5,  5, 5,   0, 0, 10, 10, true",
            "point on an edge,                 0, 5,  0, 5,   0, 0, 10, 10, false",
            "point at a corner,               10,10, 10,10,   0, 0, 10, 10, false",
            "point outside,                   -1, 5, -1, 5,   0, 0, 10, 10, false",
            "rect of width 0 crossed,         -5, 5,  5, 5,   0, 0,  0, 10, false",
            "rect of height 0 crossed,         5,-5,  5, 5,   0, 0, 10,  0, false",
            "rect of size 0 on the segment,   -5, 0,  5, 0,   0, 0,  0,  0, false",
            "point on a zero-width rect,       0, 5,  0, 5,   0, 0,  0, 10, false",
    })
    void lineRect_zeroSize(String scenario, float x1, float y1, float x2, float y2, float rx, float ry, float rw, float rh, boolean expected) {
        assertLineRect(expected, x1, y1, x2, y2, rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "NaN as argument {0}")
    @CsvSource({"0", "1", "2", "3", "4", "5", "6", "7"})
    void lineRect_nanIsNoCollision(int slot) {
        float[] v = {-5, 5, 15, 5, 0, 0, 10, 10};
        v[slot] = Float.NaN;
        assertEquals(false, Collide.lineRect(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }

    @Property(tries = 3000)
    void lineRect_agreesWithExactReference(@ForAll @IntRange(min = -2, max = 8) int x1, @ForAll @IntRange(min = -2, max = 8) int y1,
                                           @ForAll @IntRange(min = -2, max = 8) int x2, @ForAll @IntRange(min = -2, max = 8) int y2,
                                           @ForAll @IntRange(min = 0, max = 3) int rx, @ForAll @IntRange(min = 0, max = 3) int ry,
                                           @ForAll @IntRange(min = 0, max = 4) int rw, @ForAll @IntRange(min = 0, max = 4) int rh) {
        boolean expected = rw > 0 && rh > 0
                && ExactReference.segmentPolygon(ExactReference.rectPolygon(rx, ry, rw, rh), x1, y1, x2, y2);
        assertEquals(expected, Collide.lineRect(x1, y1, x2, y2, rx, ry, rw, rh));
    }

    @Property(tries = 1000)
    void lineRect_translationInvariant(@ForAll @IntRange(min = -2, max = 8) int x1, @ForAll @IntRange(min = -2, max = 8) int y1,
                                       @ForAll @IntRange(min = -2, max = 8) int x2, @ForAll @IntRange(min = -2, max = 8) int y2,
                                       @ForAll @IntRange(min = 0, max = 3) int rx, @ForAll @IntRange(min = 0, max = 3) int ry,
                                       @ForAll @IntRange(min = 0, max = 4) int rw, @ForAll @IntRange(min = 0, max = 4) int rh,
                                       @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                       @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        assertEquals(Collide.lineRect(x1, y1, x2, y2, rx, ry, rw, rh),
                Collide.lineRect(x1 + dx, y1 + dy, x2 + dx, y2 + dy, rx + dx, ry + dy, rw, rh));
    }
}
