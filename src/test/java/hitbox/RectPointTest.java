package hitbox;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Rectangle and point: {@link Collide#rectPoint} and {@link Rect#contains}.
 *
 * <p>A point has no argument order of its own, so every case is also asked in the point's other
 * guises, in both orders: a rectangle of size 0 and a circle of radius 0 (the touching rule
 * says both behave as the point).
 */
class RectPointTest {

    // scenario, rx, ry, rw, rh, px, py, expected
    private static final String INSIDE = """
            centre,                 0,  0, 10, 10,    5,    5, true
            nearTopLeftCorner,      0,  0, 10, 10,  0.5,  0.5, true
            nearBottomRightCorner,  0,  0, 10, 10,  9.5,  9.5, true
            awayFromOrigin,       100, 50, 30, 20,  110,   60, true
            """;
    private static final String OUTSIDE = """
            left,                   0,  0, 10, 10,   -1,    5, false
            right,                  0,  0, 10, 10,   11,    5, false
            above,                  0,  0, 10, 10,    5,   -1, false
            below,                  0,  0, 10, 10,    5,   11, false
            diagonal,               0,  0, 10, 10,   -1,   -1, false
            """;
    private static final String TOUCHING = """
            onLeftEdge,             0,  0, 10, 10,    0,    5, false
            onRightEdge,            0,  0, 10, 10,   10,    5, false
            onTopEdge,              0,  0, 10, 10,    5,    0, false
            onBottomEdge,           0,  0, 10, 10,    5,   10, false
            onTopLeftCorner,        0,  0, 10, 10,    0,    0, false
            onTopRightCorner,       0,  0, 10, 10,   10,    0, false
            onBottomLeftCorner,     0,  0, 10, 10,    0,   10, false
            onBottomRightCorner,    0,  0, 10, 10,   10,   10, false
            onRightEdgeHalves,    0.5, 0.5, 2.5, 2.5,  3,    1, false
            """;
    private static final String ZERO_SIZE = """
            zeroWidthPointOnIt,     5,  0,  0, 10,    5,    5, false
            zeroHeightPointOnIt,    0,  5, 10,  0,    5,    5, false
            zeroSizePointOnIt,      5,  5,  0,  0,    5,    5, false
            """;
    private static final String HUGE = """
            hugeInside,       1000000, 1000000, 10, 10, 1000005, 1000005, true
            hugeOnCorner,     1000000, 1000000, 10, 10, 1000010, 1000010, false
            hugeNegativeEdge, -1000000, -1000000, 10, 10, -1000000, -999995, false
            """;

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = INSIDE)
    void rectPoint_inside(String scenario, float rx, float ry, float rw, float rh, float px, float py,
                          boolean expected) {
        assertRectPoint(expected, rx, ry, rw, rh, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = OUTSIDE)
    void rectPoint_outside(String scenario, float rx, float ry, float rw, float rh, float px, float py,
                           boolean expected) {
        assertRectPoint(expected, rx, ry, rw, rh, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TOUCHING)
    void rectPoint_onEdgeOrCornerIsNotInside(String scenario, float rx, float ry, float rw, float rh,
                                             float px, float py, boolean expected) {
        assertRectPoint(expected, rx, ry, rw, rh, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = ZERO_SIZE)
    void rectPoint_zeroSizeContainsNothing(String scenario, float rx, float ry, float rw, float rh,
                                           float px, float py, boolean expected) {
        assertRectPoint(expected, rx, ry, rw, rh, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = HUGE)
    void rectPoint_hugeCoordinates(String scenario, float rx, float ry, float rw, float rh, float px, float py,
                                   boolean expected) {
        assertRectPoint(expected, rx, ry, rw, rh, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = INSIDE + OUTSIDE + TOUCHING + ZERO_SIZE + HUGE)
    void rectPoint_translatedBy1e6(String scenario, float rx, float ry, float rw, float rh, float px, float py,
                                   boolean expected) {
        for (float[] d : ExactReference.WHOLE_OFFSETS) {
            assertRectPoint(expected, rx + d[0], ry + d[1], rw, rh, px + d[0], py + d[1]);
        }
    }

    @ParameterizedTest(name = "NaN as {0}")
    @CsvSource({"rx, 0", "ry, 1", "rw, 2", "rh, 3", "px, 4", "py, 5"})
    void rectPoint_nanArgumentGivesFalse(String name, int position) {
        float[][] collidingCases = {
                {0, 0, 10, 10, 5, 5}, {-20, 30, 40, 5, -19, 34}, {1e6f, 1e6f, 2, 2, 1e6f + 1, 1e6f + 1}};
        for (float[] a : collidingCases) {
            assertTrue(Collide.rectPoint(a[0], a[1], a[2], a[3], a[4], a[5]), "the case must collide without NaN");
            a[position] = Float.NaN;
            assertFalse(Collide.rectPoint(a[0], a[1], a[2], a[3], a[4], a[5]), "NaN as " + name);
        }
    }

    /** Asks the question in every form the library offers, and of the reference. */
    private static void assertRectPoint(boolean expected, float rx, float ry, float rw, float rh, float px, float py) {
        Rect rect = new Rect(rx, ry, rw, rh);
        Rect pointRect = new Rect(px, py, 0, 0);
        Circle pointCircle = new Circle(px, py, 0);
        String where = String.format(" for %s, point (%s, %s)", rect, px, py);
        assertAll(
                () -> assertEquals(expected, Collide.rectPoint(rx, ry, rw, rh, px, py), "Collide.rectPoint" + where),
                () -> assertEquals(expected, rect.contains(px, py), "Rect.contains" + where),
                () -> assertEquals(expected, Collide.rectRect(rx, ry, rw, rh, px, py, 0, 0),
                        "Collide.rectRect(rect, 0x0 rect)" + where),
                () -> assertEquals(expected, Collide.rectRect(px, py, 0, 0, rx, ry, rw, rh),
                        "Collide.rectRect(0x0 rect, rect)" + where),
                () -> assertEquals(expected, Collide.circleRect(px, py, 0, rx, ry, rw, rh),
                        "Collide.circleRect(radius 0, rect)" + where),
                () -> assertEquals(expected, rect.overlaps(pointRect), "rect.overlaps(0x0 rect)" + where),
                () -> assertEquals(expected, pointRect.overlaps(rect), "0x0 rect.overlaps(rect)" + where),
                () -> assertEquals(expected, rect.overlaps(pointCircle), "rect.overlaps(radius 0)" + where),
                () -> assertEquals(expected, pointCircle.overlaps(rect), "radius 0.overlaps(rect)" + where),
                () -> assertEquals(expected, ExactReference.rectPoint(rx, ry, rw, rh, px, py), "Reference" + where));
    }
}
