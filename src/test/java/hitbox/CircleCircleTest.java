package hitbox;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Circle and circle: {@link Collide#circleCircle} and {@link Circle#overlaps}, every case in
 * both argument orders.
 */
class CircleCircleTest {

    // scenario, x1, y1, r1, x2, y2, r2, expected
    private static final String TUTORIAL = """
            # The tutorial's circles: radii 100 and 75, so they meet when the centres are
            # less than 175 apart.
            tutorial200Apart,            0,   0, 100,  200,   0, 75, false
            tutorial150Apart,            0,   0, 100,  150,   0, 75, true
            tutorial150ApartVertically,  0,   0, 100,    0, 150, 75, true
            tutorial200ApartDiagonally,  0,   0, 100,  120, 160, 75, false
            """;
    private static final String TOUCHING = """
            tutorial175ApartTouching,    0,   0, 100,  175,   0, 75, false
            touchingVertically,          0,   0,   3,    0,   5,  2, false
            touching345,                 0,   0,   2,    3,   4,  3, false
            touching345Opposite,         0,   0,   2,   -3,  -4,  3, false
            touching304050,             10,  20,  10,   40,  60, 40, false
            touchingHalves,              0,   0,   1,  1.5,   2, 1.5, false
            overlapNextToTouching345,    0,   0,   2,    3,   4,  4, true
            gapNextToTouching345,        0,   0,   2,    3,   4,  2, false
            touchingInsideStillOverlaps, 0,   0,  10,    6,   0,  4, true
            """;
    private static final String CONTAINMENT = """
            smallInsideBig,              0,   0, 100,   10,  10,  5, true
            concentric,                  0,   0,  10,    0,   0,  1, true
            """;
    private static final String COINCIDENT = """
            sameCircleTwice,             5,   5,  10,    5,   5, 10, true
            sameTinyCircleTwice,         5,   5, 1.0E-30, 5,  5, 1.0E-30, true
            """;
    private static final String ZERO_SIZE = """
            twoPointsAtOnePlace,         1,   1,   0,    1,   1,  0, false
            twoPointsApart,              1,   1,   0,    2,   1,  0, false
            pointInsideCircle,           0,   0,   0,    1,   1,  5, true
            pointAtCentre,               0,   0,   0,    0,   0,  5, true
            pointOnOutline,              0,   0,   0,    3,   4,  5, false
            pointOutside,                0,   0,   0,    4,   4,  5, false
            """;
    private static final String HUGE = """
            hugeTutorialTouching,  1000000, 1000000, 100, 1000175, 1000000, 75, false
            hugeTutorial150Apart,  1000000, 1000000, 100, 1000150, 1000000, 75, true
            hugeTouching345,      -1000000, 1000000,   2, -999997, 1000004,  3, false
            """;

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TUTORIAL)
    void circleCircle_tutorialNumbers(String scenario, float x1, float y1, float r1, float x2, float y2, float r2,
                                      boolean expected) {
        assertCircleCircle(expected, x1, y1, r1, x2, y2, r2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TOUCHING)
    void circleCircle_touchingIsNotOverlapping(String scenario, float x1, float y1, float r1,
                                               float x2, float y2, float r2, boolean expected) {
        assertCircleCircle(expected, x1, y1, r1, x2, y2, r2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = CONTAINMENT)
    void circleCircle_containment(String scenario, float x1, float y1, float r1, float x2, float y2, float r2,
                                  boolean expected) {
        assertCircleCircle(expected, x1, y1, r1, x2, y2, r2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = COINCIDENT)
    void circleCircle_coincident(String scenario, float x1, float y1, float r1, float x2, float y2, float r2,
                                 boolean expected) {
        assertCircleCircle(expected, x1, y1, r1, x2, y2, r2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = ZERO_SIZE)
    void circleCircle_zeroRadiusIsAPoint(String scenario, float x1, float y1, float r1, float x2, float y2, float r2,
                                         boolean expected) {
        assertCircleCircle(expected, x1, y1, r1, x2, y2, r2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = HUGE)
    void circleCircle_hugeCoordinates(String scenario, float x1, float y1, float r1, float x2, float y2, float r2,
                                      boolean expected) {
        assertCircleCircle(expected, x1, y1, r1, x2, y2, r2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TUTORIAL + TOUCHING + CONTAINMENT + COINCIDENT + ZERO_SIZE + HUGE)
    void circleCircle_translatedBy1e6(String scenario, float x1, float y1, float r1, float x2, float y2, float r2,
                                      boolean expected) {
        for (float[] d : ExactReference.WHOLE_OFFSETS) {
            assertCircleCircle(expected, x1 + d[0], y1 + d[1], r1, x2 + d[0], y2 + d[1], r2);
        }
    }

    @ParameterizedTest(name = "NaN as {0}")
    @CsvSource({"x1, 0", "y1, 1", "r1, 2", "x2, 3", "y2, 4", "r2, 5"})
    void circleCircle_nanArgumentGivesFalse(String name, int position) {
        float[][] collidingCases = {{0, 0, 100, 150, 0, 75}, {5, 5, 10, 5, 5, 10}, {0, 0, 0, 1, 1, 5}};
        for (float[] a : collidingCases) {
            assertTrue(Collide.circleCircle(a[0], a[1], a[2], a[3], a[4], a[5]), "the case must collide without NaN");
            a[position] = Float.NaN;
            assertFalse(Collide.circleCircle(a[0], a[1], a[2], a[3], a[4], a[5]), "NaN as " + name);
        }
    }

    /** Asks the question both ways round, through Collide and the shapes, and of the reference. */
    private static void assertCircleCircle(boolean expected, float x1, float y1, float r1,
                                           float x2, float y2, float r2) {
        Circle a = new Circle(x1, y1, r1);
        Circle b = new Circle(x2, y2, r2);
        String where = " for " + a + " and " + b;
        assertAll(
                () -> assertEquals(expected, Collide.circleCircle(x1, y1, r1, x2, y2, r2), "Collide(a, b)" + where),
                () -> assertEquals(expected, Collide.circleCircle(x2, y2, r2, x1, y1, r1), "Collide(b, a)" + where),
                () -> assertEquals(expected, a.overlaps(b), "a.overlaps(b)" + where),
                () -> assertEquals(expected, b.overlaps(a), "b.overlaps(a)" + where),
                () -> assertEquals(expected, ExactReference.circleCircle(x1, y1, r1, x2, y2, r2), "Reference" + where));
    }
}
