package hitbox;

import hitbox.internal.RawTests;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@link Ellipse} against every shape, both argument orders: exact tables (touching on an axis,
 * containment, flat ellipses and zero sizes) and a random comparison with {@link Sampled}, an
 * oracle that shares no code with the library; and the plain-float bodies behind them
 * ({@code RawTests}, which the browser's {@code Collide.ellipse...} exports call) for bad values.
 */
class EllipseTest {

    /** Asks both orders of overlaps. */
    static void check(boolean expected, Shape a, Shape b) {
        String where = " for " + a + " and " + b;
        assertAll(
                () -> assertEquals(expected, a.overlaps(b), "a.overlaps(b)" + where),
                () -> assertEquals(expected, b.overlaps(a), "b.overlaps(a)" + where));
    }

    // ellipse x, y, rx, ry, point px, py, expected
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            centre,                0, 0, 4, 2,   0,   0, true
            nearRightEnd,          0, 0, 4, 2, 3.9,   0, true
            onRightEnd,            0, 0, 4, 2,   4,   0, false
            onTop,                 0, 0, 4, 2,   0,   2, false
            onOutline345,          0, 0, 5, 5,   3,   4, false
            onOutlineOblique,      0, 0, 4, 2, 3.2, 1.2, false
            justInsideOblique,     0, 0, 4, 2, 3.2, 1.1999999, true
            outside,               0, 0, 4, 2,   3,   2, false
            flatHasNoInside,       0, 0, 4, 0,   0,   0, false
            pointEllipse,          0, 0, 0, 0,   0,   0, false
            """)
    void ellipsePoint(String scenario, float x, float y, float rx, float ry, float px, float py, boolean expected) {
        Ellipse e = new Ellipse(x, y, rx, ry);
        assertEquals(expected, e.contains(px, py));
        // A point is a circle of radius 0, in both orders.
        check(expected, e, new Circle(px, py, 0));
    }

    // ellipse x, y, rx, ry, circle cx, cy, r
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingRightEnd,        0, 0, 4, 2,   6,   0,   2, false
            reachingRightEnd,        0, 0, 4, 2,   6,   0, 2.5, true
            touchingTop,             0, 0, 4, 2,   0,   5,   3, false
            reachingTop,             0, 0, 4, 2,   0, 4.9,   3, true
            apartOblique,            0, 0, 4, 2,   5,   4,   2, false
            circleInside,            0, 0, 4, 2,   1,   0,   1, true
            ellipseInside,           0, 0, 4, 2,   0,   0,  10, true
            centreOnOutline,         0, 0, 4, 2,   4,   0, 0.01, true
            zeroRadiusInside,        0, 0, 4, 2,   1,   0,   0, true
            zeroRadiusOnOutline,     0, 0, 4, 2,   4,   0,   0, false
            flatCrossingCircle,      0, 0, 4, 0,   0, 2.9,   3, true
            flatTouchingCircle,      0, 0, 4, 0,   0,   3,   3, false
            flatEndTouching,         0, 0, 4, 0,   7,   0,   3, false
            circleEqualsEllipse,     0, 0, 3, 3,   0,   0,   3, true
            circleTouchingCircle,    0, 0, 3, 3,   6,   0,   3, false
            hugeTouching,      1000000, 1000000, 4, 2, 1000006, 1000000, 2, false
            hugeReaching,      1000000, 1000000, 4, 2, 1000005.5, 1000000, 2, true
            """)
    void ellipseCircle(String scenario, float x, float y, float rx, float ry, float cx, float cy, float r, boolean expected) {
        check(expected, new Ellipse(x, y, rx, ry), new Circle(cx, cy, r));
    }

    // ellipse x, y, rx, ry, rect rx, ry, rw, rh
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingRightEnd,       0, 0, 4, 2,    4,   -1,  2, 2, false
            reachingRightEnd,       0, 0, 4, 2,  3.9,   -1,  2, 2, true
            touchingBottom,         0, 0, 4, 2,   -1,    2,  2, 2, false
            cornerOnOutline,        0, 0, 4, 2,  3.2,  1.2,  2, 2, false
            cornerOutside,          0, 0, 4, 2,    3,    2,  2, 2, false
            rectInside,             0, 0, 4, 2,   -1, -0.5,  2, 1, true
            ellipseInside,          0, 0, 4, 2,  -10,  -10, 20, 20, true
            zeroWidthThrough,       0, 0, 4, 2,    0,   -5,  0, 10, true
            zeroWidthTangent,       0, 0, 4, 2,    4,   -5,  0, 10, false
            zeroSizeAtCentre,       0, 0, 4, 2,    0,    0,  0,  0, true
            zeroSizeOnOutline,      0, 0, 4, 2,    4,    0,  0,  0, false
            flatCrossing,           0, 0, 4, 0,   -1,   -1,  2,  2, true
            flatTouchingEnd,        0, 0, 4, 0,    4,   -1,  2,  2, false
            flatAlongEdge,          0, 0, 4, 0,    0,    0,  2,  2, false
            """)
    void ellipseRect(String scenario, float x, float y, float rx, float ry, float qx, float qy, float qw, float qh, boolean expected) {
        check(expected, new Ellipse(x, y, rx, ry), new Rect(qx, qy, qw, qh));
    }

    // ellipse x, y, rx, ry, segment x1, y1, x2, y2
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            tangentAtEnd,           0, 0, 4, 2,    4, -5,   4, 5, false
            crossing,               0, 0, 4, 2,  3.9, -5, 3.9, 5, true
            inside,                 0, 0, 4, 2,    0,  0,   1, 0, true
            endingOnOutline,        0, 0, 4, 2,    4,  0,   8, 0, false
            tangentAtTop,           0, 0, 4, 2,   -9,  2,   9, 2, false
            apartOblique,           0, 0, 4, 2,    0,  4,   8, 0, false
            pointInside,            0, 0, 4, 2,    1,  1,   1, 1, true
            flatNeverCollides,      0, 0, 4, 0,    0, -5,   0, 5, false
            """)
    void ellipseLine(String scenario, float x, float y, float rx, float ry, float x1, float y1, float x2, float y2, boolean expected) {
        check(expected, new Ellipse(x, y, rx, ry), new Segment(x1, y1, x2, y2));
    }

    // ellipse 1, ellipse 2
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingSideBySide,    0, 0, 4, 2,    8,   0, 4, 2, false
            reachingSideBySide,    0, 0, 4, 2,  7.9,   0, 4, 2, true
            touchingStacked,       0, 0, 4, 2,    0,   4, 4, 2, false
            reachingStacked,       0, 0, 4, 2,    0, 3.9, 4, 2, true
            touchingUnequal,       0, 0, 3, 1,    5,   0, 2, 7, false
            reachingUnequal,       0, 0, 3, 1,  4.9,   0, 2, 7, true
            apartDiagonal,         0, 0, 4, 2,    6,   3, 2, 1, false
            same,                  0, 0, 4, 2,    0,   0, 4, 2, true
            contained,             0, 0, 4, 2,    0,   0, 1, 1, true
            plusSign,              0, 0, 4, 1,    0,   0, 1, 4, true
            flatPlusSign,          0, 0, 4, 0,    0,   0, 0, 3, true
            flatAlongFlat,         0, 0, 4, 0,    2,   0, 4, 0, false
            flatThroughReal,       0, 0, 4, 0,    3,   0, 2, 2, true
            flatTangentToReal,     0, 2, 4, 0,    0,   0, 4, 2, false
            """)
    void ellipseEllipse(String scenario, float x1, float y1, float a1, float b1, float x2, float y2, float a2, float b2, boolean expected) {
        check(expected, new Ellipse(x1, y1, a1, b1), new Ellipse(x2, y2, a2, b2));
    }

    @Test
    void flatCrossingFlat_isAPlusSignOnlyWhenTheyCross() {
        // (0,0,4,0) is the open segment from (-4,0) to (4,0); (0,0,0,4) from (0,-4) to (0,4): a plus sign.
        assertTrue(new Ellipse(0, 0, 4, 0).overlaps(new Ellipse(0, 0, 0, 4)));
        assertFalse(new Ellipse(0, 0, 4, 0).overlaps(new Ellipse(4, 0, 0, 4)), "meeting at an end");
    }

    @Test
    void polygonEllipse_table() {
        Ellipse e = new Ellipse(0, 0, 4, 2);
        Object[][] rows = {
                {Polygon.of(4, 0, 8, -2, 8, 2), false, "vertex on the right end"},
                {Polygon.of(3.9f, 0, 8, -2, 8, 2), true, "vertex reaching in"},
                {Polygon.of(-9, 2, 9, 2, 0, 9), false, "edge along the tangent at the top"},
                {Polygon.of(-20, -20, 20, -20, 0, 20), true, "polygon holding the ellipse"},
                {Polygon.of(-1, 0, 1, 0, 0, 1), true, "polygon inside"},
                {Polygon.of(-10, -10, 10, -10, 0, -2, -10, 10), true, "concave: the notch's tip reaches in"},
                {Polygon.of(-10, -10, 10, -10, 0, -2.5f, 10, 10, -10, 10), true, "concave around it"},
        };
        for (Object[] row : rows) {
            Polygon p = (Polygon) row[0];
            boolean expected = (Boolean) row[1];
            check(expected, p, e);
        }
        Polygon square = Polygon.of(-1, -1, 1, -1, 1, 1, -1, 1);
        check(true, square, new Ellipse(0, 0, 4, 0));
        check(false, square, new Ellipse(0, 1, 4, 0));
    }

    // ellipse, capsule x1, y1, x2, y2, r
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingAtRightEnd,     0, 0, 4, 2,    6, -5,  6, 5, 2, false
            reachingAtRightEnd,     0, 0, 4, 2,    6, -5,  6, 5, 2.1, true
            touchingAtTop,          0, 0, 4, 2,   -9,  5,  9, 5, 3, false
            reachingAtTop,          0, 0, 4, 2,   -9,  5,  9, 5, 3.1, true
            segmentOnOutline,       0, 0, 4, 2,    4,  0,  9, 0, 1, true
            pointCapsuleTouching,   0, 0, 4, 2,    0,  5,  0, 5, 3, false
            pointCapsuleReaching,   0, 0, 4, 2,    0, 4.9, 0, 4.9, 3, true
            zeroRadiusThrough,      0, 0, 4, 2,    0, -5,  0, 5, 0, true
            zeroRadiusTangent,      0, 0, 4, 2,    4, -5,  4, 5, 0, false
            flatEllipseInCapsule,   0, 0, 4, 0,    0, -5,  0, 5, 1, true
            flatEllipseTouching,    0, 0, 4, 0,    0,  2,  9, 2, 2, false
            apartOblique,           0, 0, 4, 2,    8,  0,  0, 8, 1, false
            """)
    void ellipseCapsule(String scenario, float x, float y, float rx, float ry,
                        float x1, float y1, float x2, float y2, float r, boolean expected) {
        check(expected, new Ellipse(x, y, rx, ry), new Capsule(x1, y1, x2, y2, r));
    }

    @Test
    void rawBodies_nanAndNegativeSizes_giveFalse_andNeverThrow() {
        // The shapes refuse such values (constructor_namesTheBadParameter); the plain-float
        // bodies the browser's Collide exports call answer false instead.
        float n = Float.NaN;
        assertFalse(RawTests.ellipsePoint(n, 0, 4, 2, 0, 0));
        assertFalse(RawTests.ellipsePoint(0, 0, 4, 2, 0, n));
        assertFalse(RawTests.ellipseCircle(0, 0, 4, 2, 0, 0, n));
        assertFalse(RawTests.ellipseCircle(0, 0, -4, 2, 0, 0, 1));
        assertFalse(RawTests.ellipseRect(0, 0, 4, 2, 0, 0, -1, 1));
        assertFalse(RawTests.ellipseRect(0, 0, 4, n, 0, 0, 1, 1));
        assertFalse(RawTests.ellipseLine(0, 0, 4, 2, n, 0, 1, 1));
        assertFalse(RawTests.ellipseEllipse(0, 0, 4, 2, 0, 0, 1, n));
        assertFalse(RawTests.ellipseEllipse(0, 0, 4, 2, 0, 0, 1, -1));
        assertFalse(RawTests.polygonEllipse(new float[] {0, 0, 9, 0, 0, 9}, 1, 1, n, 1));
        assertFalse(RawTests.ellipseCapsule(0, 0, 4, 2, 0, 0, 1, 1, n));
        assertFalse(RawTests.ellipseCapsule(0, 0, 4, 2, 0, 0, 1, 1, -1));
        float inf = Float.POSITIVE_INFINITY;
        // Infinite values never throw nor hang.
        RawTests.ellipseCircle(0, 0, inf, 2, 3, 3, 1);
        RawTests.ellipseEllipse(0, 0, inf, 2, inf, 3, 1, inf);
        RawTests.ellipseCapsule(0, 0, 4, 2, -inf, 0, inf, 1, 1);
        RawTests.ellipseCapsule(0, 0, Float.MAX_VALUE, Float.MIN_VALUE, 3, 0, 9, 1, Float.MAX_VALUE);
    }

    @Test
    void constructor_namesTheBadParameter() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Ellipse(0, 0, -1, 2)).getMessage().contains("rx"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Ellipse(0, 0, 1, Float.NaN)).getMessage().contains("ry"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Ellipse(Float.NaN, 0, 1, 1)).getMessage().contains("x"));
    }

    @Test
    void boundsHoldTheOutline_andTranslatedMoves() {
        Random rnd = new Random(7);
        for (int i = 0; i < 200; i++) {
            Ellipse e = new Ellipse(rnd.nextFloat() * 1000 - 500, rnd.nextFloat() * 1000 - 500, rnd.nextFloat() * 50, rnd.nextFloat() * 50);
            Rect b = e.bounds();
            assertTrue(b.x() <= (double) e.x() - e.rx() && (double) b.x() + b.w() >= (double) e.x() + e.rx(), e + " " + b);
            assertTrue(b.y() <= (double) e.y() - e.ry() && (double) b.y() + b.h() >= (double) e.y() + e.ry(), e + " " + b);
        }
        assertEquals(new Ellipse(3, 4, 5, 6), new Ellipse(1, 1, 5, 6).translated(2, 3));
        assertThrows(IllegalArgumentException.class, () -> new Ellipse(1, 1, 5, 6).translated(Float.NaN, 0));
    }

    /** Random ellipses against random shapes of every kind, both orders, against the sampled oracle. */
    @Test
    void agreesWithTheSampledOracle_everyKind() {
        Sampled.assertAgreesWithOracle(20261124L, 3000, Sampled::ellipse);
    }

    /**
     * Ellipse and circle against a second, tighter oracle: the distance from the circle's
     * centre to the outline by dense sampling of the outline refined by golden-section search,
     * compared with the radius outside a band of 1e-6.
     */
    @Test
    void ellipseCircle_agreesWithRefinedDistance() {
        Random rnd = new Random(11);
        int decided = 0;
        for (int i = 0; i < 3000; i++) {
            Ellipse e = Sampled.ellipse(rnd);
            float cx = Sampled.coord(rnd), cy = Sampled.coord(rnd);
            double u = (cx - e.x()) / (double) e.rx(), v = (cy - e.y()) / (double) e.ry();
            if (u * u + v * v <= 1) {
                continue; // centre inside: the table covers it
            }
            double d = outlineDistance(e, cx, cy);
            float r = (float) (d * (0.9 + 0.2 * rnd.nextDouble()));
            if (Math.abs(d - r) < 1e-6) {
                continue;
            }
            decided++;
            assertEquals(d < r, e.overlaps(new Circle(cx, cy, r)), e + " centre " + cx + "," + cy + " r " + r + " d " + d);
        }
        assertTrue(decided > 2000, decided + " decided");
    }

    static double outlineDistance(Ellipse e, double px, double py) {
        int n = 4096;
        int best = 0;
        double bestD = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            double d = at(e, 2 * Math.PI * i / n, px, py);
            if (d < bestD) {
                bestD = d;
                best = i;
            }
        }
        double lo = 2 * Math.PI * (best - 1) / n, hi = 2 * Math.PI * (best + 1) / n;
        double g = (Math.sqrt(5) - 1) / 2;
        for (int k = 0; k < 200; k++) {
            double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            if (at(e, m1, px, py) < at(e, m2, px, py)) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        return Math.min(bestD, at(e, (lo + hi) / 2, px, py));
    }

    private static double at(Ellipse e, double t, double px, double py) {
        return Math.hypot(e.x() + e.rx() * Math.cos(t) - px, e.y() + e.ry() * Math.sin(t) - py);
    }
}
