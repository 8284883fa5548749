package hitbox;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Rectangle and rectangle: {@link Collide#rectRect} and {@link Rect#overlaps}, every case in
 * both argument orders.
 */
class RectRectTest {

    // scenario, x1, y1, w1, h1, x2, y2, w2, h2, expected
    private static final String OVERLAP = """
            partialOverlap,              0,  0, 10, 10,    5,   5, 10, 10, true
            cornerOverlap,               0,  0, 10, 10,    9,   9, 10, 10, true
            plusShape,                   4,  0,  2, 10,    0,   4, 10,  2, true
            stripAcross,                 0,  4, 10,  2,   -5,   0, 20, 10, true
            overlapByHalf,               0,  0, 10, 10,  9.5,   0, 10, 10, true
            apartHorizontally,           0,  0, 10, 10,   11,   0, 10, 10, false
            apartVertically,             0,  0, 10, 10,    0,  11, 10, 10, false
            apartOnOneAxisOnly,          0,  0, 10, 10,    5,  20, 10, 10, false
            """;
    private static final String TOUCHING = """
            sideBySide,                  0,  0, 10, 10,   10,   0, 10, 10, false
            sideBySideOffset,            0,  0, 10, 10,   10,   5, 10, 10, false
            stacked,                     0,  0, 10, 10,    0,  10, 10, 10, false
            stackedOffset,               0,  0, 10, 10,   -5,  10, 10, 10, false
            cornerToCorner,              0,  0, 10, 10,   10,  10, 10, 10, false
            cornerToCornerOtherDiagonal, 0,  0, 10, 10,  -10,  10, 10, 10, false
            sideBySideHalves,          0.5,0.5,2.5,2.5,    3,   0,  1,  1, false
            """;
    private static final String CONTAINMENT = """
            smallInsideBig,              0,  0, 100, 100, 10, 10, 20, 20, true
            insideSharingAnEdge,         0,  0, 100, 100,  0, 10, 20, 20, true
            insideSharingACorner,        0,  0, 100, 100,  0,  0, 20, 20, true
            """;
    private static final String COINCIDENT = """
            sameRectTwice,               3,  4, 10, 20,    3,   4, 10, 20, true
            sameThinRectTwice,           3,  4, 0.5, 20,   3,   4, 0.5, 20, true
            """;
    private static final String ZERO_SIZE = """
            # A rectangle of width or height 0 is a segment (or a point): it collides only by
            # reaching into the inside of a rectangle that has one.
            zeroWidthInside,             5,  2,  0,  6,    0,   0, 10, 10, true
            zeroWidthAcross,             5, -5,  0, 20,    0,   0, 10, 10, true
            zeroWidthOnLeftEdge,         0,  2,  0,  6,    0,   0, 10, 10, false
            zeroWidthOnRightEdge,       10,  2,  0,  6,    0,   0, 10, 10, false
            zeroWidthEndingAtTopEdge,    5, -5,  0,  5,    0,   0, 10, 10, false
            zeroWidthOutside,           12,  2,  0,  6,    0,   0, 10, 10, false
            zeroHeightAlongTopEdge,     -5,  0, 20,  0,    0,   0, 10, 10, false
            zeroHeightAcross,           -5,  5, 20,  0,    0,   0, 10, 10, true
            zeroSizeInside,              5,  5,  0,  0,    0,   0, 10, 10, true
            zeroSizeOnEdge,              5,  0,  0,  0,    0,   0, 10, 10, false
            zeroSizeOnCorner,           10, 10,  0,  0,    0,   0, 10, 10, false
            # Two zero-size rectangles: only crossing like a plus sign collides (the tutorial's comparisons).
            twoZeroSizeAtOnePlace,       5,  5,  0,  0,    5,   5,  0,  0, false
            twoZeroWidthAlongEachOther,  5,  0,  0, 10,    5,   5,  0, 10, false
            twoZeroHeightAlongEachOther, 0,  5, 10,  0,    5,   5, 10,  0, false
            zeroWidthCrossingZeroHeight, 5,  0,  0, 10,    0,   5, 10,  0, true
            zeroSizeOnZeroWidth,         5,  5,  0,  0,    5,   0,  0, 10, false
            """;
    private static final String HUGE = """
            hugeSideBySide,        1000000, 1000000, 10, 10, 1000010, 1000000, 10, 10, false
            hugeCornerToCorner,   -1000000, -1000000, 10, 10, -999990, -999990, 10, 10, false
            hugeOverlap,           1000000, 1000000, 10, 10, 1000009, 1000009, 10, 10, true
            """;

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = OVERLAP)
    void rectRect_overlapOrApart(String scenario, float x1, float y1, float w1, float h1,
                                 float x2, float y2, float w2, float h2, boolean expected) {
        assertRectRect(expected, x1, y1, w1, h1, x2, y2, w2, h2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = TOUCHING)
    void rectRect_touchingIsNotOverlapping(String scenario, float x1, float y1, float w1, float h1,
                                           float x2, float y2, float w2, float h2, boolean expected) {
        assertRectRect(expected, x1, y1, w1, h1, x2, y2, w2, h2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = CONTAINMENT)
    void rectRect_containment(String scenario, float x1, float y1, float w1, float h1,
                              float x2, float y2, float w2, float h2, boolean expected) {
        assertRectRect(expected, x1, y1, w1, h1, x2, y2, w2, h2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = COINCIDENT)
    void rectRect_coincident(String scenario, float x1, float y1, float w1, float h1,
                             float x2, float y2, float w2, float h2, boolean expected) {
        assertRectRect(expected, x1, y1, w1, h1, x2, y2, w2, h2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = ZERO_SIZE)
    void rectRect_zeroSize(String scenario, float x1, float y1, float w1, float h1,
                           float x2, float y2, float w2, float h2, boolean expected) {
        assertRectRect(expected, x1, y1, w1, h1, x2, y2, w2, h2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = HUGE)
    void rectRect_hugeCoordinates(String scenario, float x1, float y1, float w1, float h1,
                                  float x2, float y2, float w2, float h2, boolean expected) {
        assertRectRect(expected, x1, y1, w1, h1, x2, y2, w2, h2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = OVERLAP + TOUCHING + CONTAINMENT + COINCIDENT + ZERO_SIZE + HUGE)
    void rectRect_translatedBy1e6(String scenario, float x1, float y1, float w1, float h1,
                                  float x2, float y2, float w2, float h2, boolean expected) {
        for (float[] d : ExactReference.WHOLE_OFFSETS) {
            assertRectRect(expected, x1 + d[0], y1 + d[1], w1, h1, x2 + d[0], y2 + d[1], w2, h2);
        }
    }

    @ParameterizedTest(name = "NaN as {0}")
    @CsvSource({"x1, 0", "y1, 1", "w1, 2", "h1, 3", "x2, 4", "y2, 5", "w2, 6", "h2, 7"})
    void rectRect_nanArgumentGivesFalse(String name, int position) {
        float[][] collidingCases = {
                {0, 0, 10, 10, 5, 5, 10, 10}, {3, 4, 10, 20, 3, 4, 10, 20}, {5, 2, 0, 6, 0, 0, 10, 10}};
        for (float[] a : collidingCases) {
            assertTrue(Collide.rectRect(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]),
                    "the case must collide without NaN");
            a[position] = Float.NaN;
            assertFalse(Collide.rectRect(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]), "NaN as " + name);
        }
    }

    /** Asks the question both ways round, through Collide and the shapes, and of the reference. */
    private static void assertRectRect(boolean expected, float x1, float y1, float w1, float h1,
                                       float x2, float y2, float w2, float h2) {
        Rect a = new Rect(x1, y1, w1, h1);
        Rect b = new Rect(x2, y2, w2, h2);
        String where = " for " + a + " and " + b;
        assertAll(
                () -> assertEquals(expected, Collide.rectRect(x1, y1, w1, h1, x2, y2, w2, h2), "Collide(a, b)" + where),
                () -> assertEquals(expected, Collide.rectRect(x2, y2, w2, h2, x1, y1, w1, h1), "Collide(b, a)" + where),
                () -> assertEquals(expected, a.overlaps(b), "a.overlaps(b)" + where),
                () -> assertEquals(expected, b.overlaps(a), "b.overlaps(a)" + where),
                () -> assertEquals(expected, ExactReference.rectRect(x1, y1, w1, h1, x2, y2, w2, h2), "Reference" + where));
    }
}
