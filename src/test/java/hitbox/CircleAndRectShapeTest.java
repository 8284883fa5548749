package hitbox;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.function.Executable;

/**
 * The {@link Circle} and {@link Rect} values themselves: validating constructors and their
 * messages, bounds, moving, the rectangle's edges and centre, and value equality. The
 * collision tests for each pair live in the pair's own test class.
 */
class CircleAndRectShapeTest {

    @Test
    void circle_keepsItsValues() {
        Circle c = new Circle(1.5f, -2, 3);
        assertAll(() -> assertEquals(1.5f, c.x()), () -> assertEquals(-2f, c.y()), () -> assertEquals(3f, c.r()));
    }

    @Test
    void rect_keepsItsValues() {
        Rect r = new Rect(1.5f, -2, 3, 4);
        assertAll(() -> assertEquals(1.5f, r.x()), () -> assertEquals(-2f, r.y()),
                () -> assertEquals(3f, r.w()), () -> assertEquals(4f, r.h()));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "zeroRadius,     0, 0, 0",
            "hugeCentre,     1.0E30, -1.0E30, 1",
            "tinyRadius,     0, 0, 1.4E-45",
            "largestRadius,  0, 0, 3.4028235E38"})
    void circle_acceptsEveryFiniteCentreAndRadiusZeroOrMore(String scenario, float x, float y, float r) {
        Circle c = new Circle(x, y, r);
        assertEquals(r, c.r());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "zeroSize,       0, 0, 0, 0",
            "zeroWidth,      0, 0, 0, 5",
            "zeroHeight,     0, 0, 5, 0",
            "hugeCorner,     -1.0E30, 1.0E30, 1, 1"})
    void rect_acceptsEveryFiniteCornerAndSizeZeroOrMore(String scenario, float x, float y, float w, float h) {
        Rect r = new Rect(x, y, w, h);
        assertEquals(w, r.w());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            xNaN            | NaN       | 0         | 1         | x must be a finite number, was NaN
            xInfinity       | Infinity  | 0         | 1         | x must be a finite number, was Infinity
            xMinusInfinity  | -Infinity | 0         | 1         | x must be a finite number, was -Infinity
            yNaN            | 0         | NaN       | 1         | y must be a finite number, was NaN
            yInfinity       | 0         | Infinity  | 1         | y must be a finite number, was Infinity
            yMinusInfinity  | 0         | -Infinity | 1         | y must be a finite number, was -Infinity
            radiusNaN       | 0         | 0         | NaN       | radius r must be a finite number, was NaN
            radiusInfinity  | 0         | 0         | Infinity  | radius r must be a finite number, was Infinity
            radiusMinusInf  | 0         | 0         | -Infinity | radius r must be a finite number, was -Infinity
            radiusNegative  | 0         | 0         | -1        | radius r must be >= 0, was -1.0
            radiusNegHalf   | 0         | 0         | -0.5      | radius r must be >= 0, was -0.5
            radiusNegTiny   | 0         | 0         | -1.4E-45  | radius r must be >= 0, was -1.4E-45
            """)
    void circle_rejectsBadValuesNamingParameterAndValue(String scenario, float x, float y, float r, String message) {
        assertThrowsWithMessage(message, () -> new Circle(x, y, r));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            xNaN            | NaN       | 0         | 1         | 1         | x must be a finite number, was NaN
            xInfinity       | Infinity  | 0         | 1         | 1         | x must be a finite number, was Infinity
            xMinusInfinity  | -Infinity | 0         | 1         | 1         | x must be a finite number, was -Infinity
            yNaN            | 0         | NaN       | 1         | 1         | y must be a finite number, was NaN
            yInfinity       | 0         | Infinity  | 1         | 1         | y must be a finite number, was Infinity
            yMinusInfinity  | 0         | -Infinity | 1         | 1         | y must be a finite number, was -Infinity
            widthNaN        | 0         | 0         | NaN       | 1         | width w must be a finite number, was NaN
            widthInfinity   | 0         | 0         | Infinity  | 1         | width w must be a finite number, was Infinity
            widthMinusInf   | 0         | 0         | -Infinity | 1         | width w must be a finite number, was -Infinity
            widthNegative   | 0         | 0         | -1        | 1         | width w must be >= 0, was -1.0
            heightNaN       | 0         | 0         | 1         | NaN       | height h must be a finite number, was NaN
            heightInfinity  | 0         | 0         | 1         | Infinity  | height h must be a finite number, was Infinity
            heightMinusInf  | 0         | 0         | 1         | -Infinity | height h must be a finite number, was -Infinity
            heightNegative  | 0         | 0         | 1         | -2.5      | height h must be >= 0, was -2.5
            """)
    void rect_rejectsBadValuesNamingParameterAndValue(String scenario, float x, float y, float w, float h,
                                                      String message) {
        assertThrowsWithMessage(message, () -> new Rect(x, y, w, h));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            cxNaN           | NaN       | 0   | 1   | 1   | cx must be a finite number, was NaN
            cxInfinity      | Infinity  | 0   | 1   | 1   | cx must be a finite number, was Infinity
            cyMinusInfinity | 0         | -Infinity | 1 | 1 | cy must be a finite number, was -Infinity
            widthNegative   | 0         | 0   | -1  | 1   | width w must be >= 0, was -1.0
            widthNaN        | 0         | 0   | NaN | 1   | width w must be a finite number, was NaN
            heightNegative  | 0         | 0   | 1   | -3  | height h must be >= 0, was -3.0
            heightInfinity  | 0         | 0   | 1   | Infinity | height h must be a finite number, was Infinity
            """)
    void centered_rejectsBadValuesNamingParameterAndValue(String scenario, float cx, float cy, float w, float h,
                                                          String message) {
        assertThrowsWithMessage(message, () -> Rect.centered(cx, cy, w, h));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "evenSize,     50,   40,  20, 10,    40,   35",
            "oddSize,       0,    0,   3,  3,  -1.5, -1.5",
            "zeroSize,      7,    8,   0,  0,     7,    8",
            "hugeCentre, 1000000, -1000000, 10, 20, 999995, -1000010"})
    void centered_putsTheCentreWhereAsked(String scenario, float cx, float cy, float w, float h,
                                          float expectedX, float expectedY) {
        Rect r = Rect.centered(cx, cy, w, h);
        assertAll(
                () -> assertEquals(new Rect(expectedX, expectedY, w, h), r),
                () -> assertEquals(cx, r.centerX(), "centerX"),
                () -> assertEquals(cy, r.centerY(), "centerY"));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "whole,          10, 20, 30, 40,   40,  60,  25,  40",
            "negative,      -10, -20, 4,  6,   -6, -14,  -8, -17",
            "zeroSize,        5,  5,  0,  0,    5,   5,   5,   5",
            "halves,        0.5, 1.5, 2, 3,   2.5, 4.5, 1.5,   3"})
    void rect_edgesAndCentre(String scenario, float x, float y, float w, float h,
                             float right, float bottom, float centerX, float centerY) {
        Rect r = new Rect(x, y, w, h);
        assertAll(
                () -> assertEquals(right, r.right(), "right"),
                () -> assertEquals(bottom, r.bottom(), "bottom"),
                () -> assertEquals(centerX, r.centerX(), "centerX"),
                () -> assertEquals(centerY, r.centerY(), "centerY"));
    }

    @Test
    void at_movesTheCornerAndKeepsTheSize() {
        Rect r = new Rect(1, 2, 30, 40);
        assertAll(
                () -> assertEquals(new Rect(-5, 7, 30, 40), r.at(-5, 7)),
                () -> assertEquals(new Rect(1, 2, 30, 40), r, "the original is unchanged"));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            newXNaN       | NaN      | 0        | newX must be a finite number, was NaN
            newYInfinity  | 0        | Infinity | newY must be a finite number, was Infinity
            """)
    void at_rejectsBadValues(String scenario, float x, float y, String message) {
        assertThrowsWithMessage(message, () -> new Rect(1, 2, 3, 4).at(x, y));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "whole,       10,  20,  5,    5,   15,  10, 10",
            "zeroRadius,  10,  20,  0,   10,   20,   0,  0",
            "halves,     0.5, 1.5, 2.5,  -2,   -1,   5,  5",
            "huge,   1000000, -1000000, 100, 999900, -1000100, 200, 200"})
    void circleBounds_isTheSquareAroundIt(String scenario, float x, float y, float r,
                                          float bx, float by, float bw, float bh) {
        assertEquals(new Rect(bx, by, bw, bh), new Circle(x, y, r).bounds());
    }

    @Test
    void rectBounds_isTheRectItself() {
        Rect r = new Rect(1, 2, 3, 4);
        assertSame(r, r.bounds());
    }

    @ParameterizedTest(name = "by ({0}, {1})")
    @CsvSource({"10, -20", "1000000, 1000000", "-1000000, 0.5", "0, 0"})
    void translated_movesAndKeepsTheSize(float dx, float dy) {
        assertAll(
                () -> assertEquals(new Circle(3 + dx, 4 + dy, 5), new Circle(3, 4, 5).translated(dx, dy)),
                () -> assertEquals(new Rect(3 + dx, 4 + dy, 5, 6), new Rect(3, 4, 5, 6).translated(dx, dy)));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            dxNaN        | NaN      | 0        | 0       | dx must be a finite number, was NaN
            dyInfinity   | 0        | Infinity | 0       | dy must be a finite number, was Infinity
            xOverflows   | 3.0E38   | 0        | 3.0E38  | x + dx must be a finite number, was Infinity
            """)
    void translated_rejectsAMoveToABadValue(String scenario, float dx, float dy, float x, String message) {
        assertAll(
                () -> assertThrowsWithMessage(message, () -> new Circle(x, 0, 1).translated(dx, dy)),
                () -> assertThrowsWithMessage(message, () -> new Rect(x, 0, 1, 1).translated(dx, dy)));
    }

    @Test
    void overlaps_rejectsNull() {
        assertAll(
                () -> assertThrowsWithMessage("other must not be null", () -> new Circle(0, 0, 1).overlaps(null)),
                () -> assertThrowsWithMessage("other must not be null", () -> new Rect(0, 0, 1, 1).overlaps(null)));
    }

    @Test
    void equals_sameValuesAreEqualWithEqualHashCodes() {
        assertAll(
                () -> assertEquals(new Circle(1, 2, 3), new Circle(1, 2, 3)),
                () -> assertEquals(new Circle(1, 2, 3).hashCode(), new Circle(1, 2, 3).hashCode()),
                () -> assertEquals(new Rect(1, 2, 3, 4), new Rect(1, 2, 3, 4)),
                () -> assertEquals(new Rect(1, 2, 3, 4).hashCode(), new Rect(1, 2, 3, 4).hashCode()),
                () -> assertEquals(Rect.centered(2, 4, 2, 4), new Rect(1, 2, 2, 4)));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "otherX,  9, 2, 3",
            "otherY,  1, 9, 3",
            "otherR,  1, 2, 9"})
    void equals_circlesDifferingInOneValueAreNotEqual(String scenario, float x, float y, float r) {
        assertNotEquals(new Circle(1, 2, 3), new Circle(x, y, r));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "otherX,  9, 2, 3, 4",
            "otherY,  1, 9, 3, 4",
            "otherW,  1, 2, 9, 4",
            "otherH,  1, 2, 3, 9"})
    void equals_rectsDifferingInOneValueAreNotEqual(String scenario, float x, float y, float w, float h) {
        assertNotEquals(new Rect(1, 2, 3, 4), new Rect(x, y, w, h));
    }

    @Test
    void equals_aCircleIsNeverARect() {
        assertAll(
                () -> assertNotEquals(new Circle(0, 0, 0), new Rect(0, 0, 0, 0)),
                () -> assertNotEquals(new Rect(0, 0, 0, 0), new Circle(0, 0, 0)));
    }

    private static void assertThrowsWithMessage(String message, Executable makeIt) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, makeIt);
        assertEquals(message, e.getMessage());
    }
}
