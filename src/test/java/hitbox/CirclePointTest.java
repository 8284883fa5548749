package hitbox;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Circle and point: {@link Collide#circlePoint} and {@link Circle#contains}.
 *
 * <p>A point has no argument order of its own, so every case is also asked in the point's other
 * guises, in both orders: a circle of radius 0 and a rectangle of size 0 (the touching rule
 * says both behave as the point).
 */
class CirclePointTest {

    // scenario, cx, cy, r, px, py, expected
    private static final String INSIDE = """
            centre,                    0,   0, 10,    0,   0, true
            nearOutline,               0,   0, 10,  9.5,   0, true
            diagonal,                  0,   0,  5,    3,   3, true
            nextToTouching345,         0,   0,  5,    4,   2, true
            awayFromOrigin,          200, 150, 50,  230, 120, true
            """;
    private static final String OUTSIDE = """
            justOutside,               0,   0, 10, 10.5,   0, false
            diagonalInBoundsOnly,      0,   0,  5,    4,   4, false
            far,                       0,   0, 10,  100,-100, false
            """;
    private static final String TOUCHING = """
            onOutlineRight,            0,   0, 10,   10,   0, false
            onOutlineLeft,             0,   0, 10,  -10,   0, false
            onOutlineTop,              0,   0, 10,    0, -10, false
            onOutlineBottom,           0,   0, 10,    0,  10, false
            onOutline345,              0,   0,  5,    3,   4, false
            onOutline345Opposite,      0,   0,  5,   -3,  -4, false
            onOutline345AwayFromOrigin,100, 200, 25, 115, 220, false
            onOutlineHalves,           0,   0, 2.5, 1.5,   2, false
            """;
    private static final String ZERO_SIZE = """
            zeroRadiusAtItsCentre,     5,   5,  0,    5,   5, false
            zeroRadiusNextToCentre,    5,   5,  0,    6,   5, false
            """;
    private static final String HUGE = """
            hugeInside,          1000000, 1000000, 5, 1000003, 1000003, true
            hugeTouching,        1000000, 1000000, 5, 1000003, 1000004, false
            hugeNegativeTouching,-1000000, -1000000, 5, -1000003, -999996, false
            """;

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = INSIDE)
    void circlePoint_inside(String scenario, float cx, float cy, float r, float px, float py, boolean expected) {
        assertCirclePoint(expected, cx, cy, r, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = OUTSIDE)
    void circlePoint_outside(String scenario, float cx, float cy, float r, float px, float py, boolean expected) {
        assertCirclePoint(expected, cx, cy, r, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TOUCHING)
    void circlePoint_onOutlineIsNotInside(String scenario, float cx, float cy, float r, float px, float py,
                                          boolean expected) {
        assertCirclePoint(expected, cx, cy, r, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = ZERO_SIZE)
    void circlePoint_zeroRadiusContainsNothing(String scenario, float cx, float cy, float r, float px, float py,
                                               boolean expected) {
        assertCirclePoint(expected, cx, cy, r, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = HUGE)
    void circlePoint_hugeCoordinates(String scenario, float cx, float cy, float r, float px, float py,
                                     boolean expected) {
        assertCirclePoint(expected, cx, cy, r, px, py);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = INSIDE + OUTSIDE + TOUCHING + ZERO_SIZE + HUGE)
    void circlePoint_translatedBy1e6(String scenario, float cx, float cy, float r, float px, float py,
                                     boolean expected) {
        for (float[] d : ExactReference.WHOLE_OFFSETS) {
            assertCirclePoint(expected, cx + d[0], cy + d[1], r, px + d[0], py + d[1]);
        }
    }

    @ParameterizedTest(name = "NaN as {0}")
    @CsvSource({"cx, 0", "cy, 1", "r, 2", "px, 3", "py, 4"})
    void circlePoint_nanArgumentGivesFalse(String name, int position) {
        float[][] collidingCases = {{0, 0, 10, 1, 1}, {3, -2, 5, 3, -2}, {1e6f, 1e6f, 1, 1e6f, 1e6f}};
        for (float[] a : collidingCases) {
            assertTrue(Collide.circlePoint(a[0], a[1], a[2], a[3], a[4]), "the case must collide without NaN");
            a[position] = Float.NaN;
            assertFalse(Collide.circlePoint(a[0], a[1], a[2], a[3], a[4]), "NaN as " + name);
        }
    }

    /** Asks the question in every form the library offers, and of the reference. */
    private static void assertCirclePoint(boolean expected, float cx, float cy, float r, float px, float py) {
        Circle circle = new Circle(cx, cy, r);
        Circle pointCircle = new Circle(px, py, 0);
        Rect pointRect = new Rect(px, py, 0, 0);
        String where = String.format(" for circle (%s, %s, r=%s), point (%s, %s)", cx, cy, r, px, py);
        assertAll(
                () -> assertEquals(expected, Collide.circlePoint(cx, cy, r, px, py), "Collide.circlePoint" + where),
                () -> assertEquals(expected, circle.contains(px, py), "Circle.contains" + where),
                () -> assertEquals(expected, Collide.circleCircle(cx, cy, r, px, py, 0),
                        "Collide.circleCircle(circle, point)" + where),
                () -> assertEquals(expected, Collide.circleCircle(px, py, 0, cx, cy, r),
                        "Collide.circleCircle(point, circle)" + where),
                () -> assertEquals(expected, Collide.circleRect(cx, cy, r, px, py, 0, 0),
                        "Collide.circleRect(circle, 0x0 rect)" + where),
                () -> assertEquals(expected, circle.overlaps(pointCircle), "circle.overlaps(point circle)" + where),
                () -> assertEquals(expected, pointCircle.overlaps(circle), "point circle.overlaps(circle)" + where),
                () -> assertEquals(expected, circle.overlaps(pointRect), "circle.overlaps(0x0 rect)" + where),
                () -> assertEquals(expected, pointRect.overlaps(circle), "0x0 rect.overlaps(circle)" + where),
                () -> assertEquals(expected, ExactReference.circlePoint(cx, cy, r, px, py), "Reference" + where));
    }
}
