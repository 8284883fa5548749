package hitbox;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Circle and rectangle: {@link Collide#circleRect}, and {@link Shape#overlaps} both ways round
 * ({@code circle.overlaps(rect)} and {@code rect.overlaps(circle)}).
 */
class CircleRectTest {

    // scenario, cx, cy, r, rx, ry, rw, rh, expected
    private static final String OVERLAP = """
            centreInside,                 5,   5,  3,    0,  0, 10, 10, true
            reachingInFromLeft,          -4,   5,  5,    0,  0, 10, 10, true
            reachingInFromBelow,          5,  14,  5,    0,  0, 10, 10, true
            reachingInAtCorner,          -3,  -4,  6,    0,  0, 10, 10, true
            apartFromLeft,               -6,   5,  5,    0,  0, 10, 10, false
            apartAtCorner,               -4,  -4,  5,    0,  0, 10, 10, false
            """;
    private static final String TOUCHING = """
            touchingLeftEdge,            -5,   5,  5,    0,  0, 10, 10, false
            touchingRightEdge,           15,   5,  5,    0,  0, 10, 10, false
            touchingTopEdge,              5,  -5,  5,    0,  0, 10, 10, false
            touchingBottomEdge,           5,  15,  5,    0,  0, 10, 10, false
            touchingEdgeInLineWithCorner,-5,   0,  5,    0,  0, 10, 10, false
            touchingTopLeftCorner345,    -3,  -4,  5,    0,  0, 10, 10, false
            touchingTopLeftCorner435,    -4,  -3,  5,    0,  0, 10, 10, false
            touchingTopRightCorner,      13,  -4,  5,    0,  0, 10, 10, false
            touchingBottomLeftCorner,    -3,  14,  5,    0,  0, 10, 10, false
            touchingBottomRightCorner,   13,  14,  5,    0,  0, 10, 10, false
            touchingCorner304050,       -30, -40, 50,    0,  0, 10, 10, false
            touchingEdgeHalves,        -2.5,   1, 2.5,   0,  0,  2,  2, false
            """;
    private static final String CONTAINMENT = """
            circleInsideRect,            50,  50, 10,    0,  0, 100, 100, true
            circleInscribed,              5,   5,  5,    0,  0, 10, 10, true
            rectInsideCircle,             0,   0, 100, -10, -10, 20, 20, true
            rectInsideCircleOffCentre,    0,   0, 100,  10,  10, 20, 20, true
            rectCornersOnCircle,          0,   0,  5,   -3,  -4,  6,  8, true
            """;
    private static final String ZERO_SIZE = """
            # A circle of radius 0 is a point; a rectangle of width or height 0 is a segment
            # (or a point). Each collides only by reaching into the other's inside.
            zeroRadiusInside,             5,   5,  0,    0,  0, 10, 10, true
            zeroRadiusOnEdge,             0,   5,  0,    0,  0, 10, 10, false
            zeroRadiusOnCorner,          10,  10,  0,    0,  0, 10, 10, false
            zeroRadiusOutside,           -1,   5,  0,    0,  0, 10, 10, false
            zeroWidthThroughCircle,       0,   0,  5,    1, -10,  0, 20, true
            zeroWidthThroughCentre,       0,   0,  5,    0, -10,  0, 20, true
            zeroWidthTangent,             0,   0,  5,    5, -10,  0, 20, false
            zeroHeightEndingOnOutline,    0,   0,  5,    5,  0,  5,  0, false
            zeroHeightEndingInside,       0,   0,  5,    4,  0,  5,  0, true
            zeroSizeAtCentre,             0,   0,  5,    0,  0,  0,  0, true
            zeroSizeOnOutline,            0,   0,  5,    3,  4,  0,  0, false
            zeroRadiusOnZeroSize,         5,   5,  0,    5,  5,  0,  0, false
            zeroRadiusOnZeroWidth,        5,   5,  0,    5,  0,  0, 10, false
            """;
    private static final String HUGE = """
            hugeTouchingCorner,     999997, 999996, 5, 1000000, 1000000, 10, 10, false
            hugeReachingIn,         999997, 999996, 6, 1000000, 1000000, 10, 10, true
            hugeTouchingEdge,     -1000005, -999995, 5, -1000000, -1000000, 10, 10, false
            """;

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = OVERLAP)
    void circleRect_overlapOrApart(String scenario, float cx, float cy, float r,
                                   float rx, float ry, float rw, float rh, boolean expected) {
        assertCircleRect(expected, cx, cy, r, rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TOUCHING)
    void circleRect_touchingEdgeOrCornerIsNotOverlapping(String scenario, float cx, float cy, float r,
                                                         float rx, float ry, float rw, float rh, boolean expected) {
        assertCircleRect(expected, cx, cy, r, rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = CONTAINMENT)
    void circleRect_containment(String scenario, float cx, float cy, float r,
                                float rx, float ry, float rw, float rh, boolean expected) {
        assertCircleRect(expected, cx, cy, r, rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = ZERO_SIZE)
    void circleRect_zeroSize(String scenario, float cx, float cy, float r,
                             float rx, float ry, float rw, float rh, boolean expected) {
        assertCircleRect(expected, cx, cy, r, rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = HUGE)
    void circleRect_hugeCoordinates(String scenario, float cx, float cy, float r,
                                    float rx, float ry, float rw, float rh, boolean expected) {
        assertCircleRect(expected, cx, cy, r, rx, ry, rw, rh);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = OVERLAP + TOUCHING + CONTAINMENT + ZERO_SIZE + HUGE)
    void circleRect_translatedBy1e6(String scenario, float cx, float cy, float r,
                                    float rx, float ry, float rw, float rh, boolean expected) {
        for (float[] d : ExactReference.WHOLE_OFFSETS) {
            assertCircleRect(expected, cx + d[0], cy + d[1], r, rx + d[0], ry + d[1], rw, rh);
        }
    }

    @ParameterizedTest(name = "NaN as {0}")
    @CsvSource({"cx, 0", "cy, 1", "r, 2", "rx, 3", "ry, 4", "rw, 5", "rh, 6"})
    void circleRect_nanArgumentGivesFalse(String name, int position) {
        // The centre inside, beside each edge, and near a corner: each reaches the rectangle by
        // a different road through the method.
        float[][] collidingCases = {
                {5, 5, 3, 0, 0, 10, 10}, {5, -1, 5, 0, 0, 10, 10}, {-1, 5, 5, 0, 0, 10, 10},
                {5, 11, 5, 0, 0, 10, 10}, {11, 5, 5, 0, 0, 10, 10}, {-1, -1, 5, 0, 0, 10, 10},
                {5, 5, 0, 0, 0, 10, 10}, {0, 0, 5, 0, 0, 0, 0}};
        for (float[] a : collidingCases) {
            assertTrue(Collide.circleRect(a[0], a[1], a[2], a[3], a[4], a[5], a[6]),
                    "the case must collide without NaN");
            float[] withNan = a.clone();
            withNan[position] = Float.NaN;
            assertFalse(Collide.circleRect(withNan[0], withNan[1], withNan[2], withNan[3], withNan[4], withNan[5],
                    withNan[6]), "NaN as " + name + " in circleRect" + java.util.Arrays.toString(a));
        }
    }

    /** Asks the question through Collide and both shapes' overlaps, and of the reference. */
    private static void assertCircleRect(boolean expected, float cx, float cy, float r,
                                         float rx, float ry, float rw, float rh) {
        Circle circle = new Circle(cx, cy, r);
        Rect rect = new Rect(rx, ry, rw, rh);
        String where = " for " + circle + " and " + rect;
        assertAll(
                () -> assertEquals(expected, Collide.circleRect(cx, cy, r, rx, ry, rw, rh), "Collide" + where),
                () -> assertEquals(expected, circle.overlaps(rect), "circle.overlaps(rect)" + where),
                () -> assertEquals(expected, rect.overlaps(circle), "rect.overlaps(circle)" + where),
                () -> assertEquals(expected, ExactReference.circleRect(cx, cy, r, rx, ry, rw, rh), "Reference" + where));
    }
}
