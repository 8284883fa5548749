package hitbox;

import hitbox.internal.RawTests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@link Capsule} against every shape, both argument orders: exact tables (touching, 3-4-5
 * corners, zero radii, a capsule whose segment is a point) and a random comparison with
 * {@link Sampled} and with a distance computed by sampling the segment, neither sharing code
 * with the library; and the plain-float bodies behind them ({@code RawTests}, which the
 * browser's {@code Collide.capsule...} exports call) for bad values.
 */
class CapsuleTest {

    private static void check(boolean expected, Shape a, Shape b) {
        EllipseTest.check(expected, a, b);
    }

    // capsule x1, y1, x2, y2, r, point px, py
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            insideSide,          0, 0, 10, 0, 2,    5, 1.9, true
            onSide,              0, 0, 10, 0, 2,    5,   2, false
            onEnd,               0, 0, 10, 0, 2,   12,   0, false
            insideEnd,           0, 0, 10, 0, 2, 11.9,   0, true
            onEnd345,            0, 0, 10, 0, 5,   13,   4, false
            onBackEnd,           0, 0, 10, 0, 2,   -2,   0, false
            onSegment,           0, 0, 10, 0, 2,    3,   0, true
            zeroRadius,          0, 0, 10, 0, 0,    5,   0, false
            pointCapsule,        3, 3,  3, 3, 2,    4,   3, true
            pointCapsuleOutline, 3, 3,  3, 3, 5,    6,   7, false
            """)
    void capsulePoint(String scenario, float x1, float y1, float x2, float y2, float r, float px, float py, boolean expected) {
        Capsule k = new Capsule(x1, y1, x2, y2, r);
        assertEquals(expected, k.contains(px, py));
        check(expected, k, new Circle(px, py, 0));
    }

    // capsule, circle cx, cy, r
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingSide,        0, 0, 10, 0, 2,    5,   5, 3, false
            reachingSide,        0, 0, 10, 0, 2,    5, 4.9, 3, true
            touchingEnd,         0, 0, 10, 0, 2,   15,   0, 3, false
            touchingEnd345,      0, 0, 10, 0, 2,   13,   4, 3, false
            reachingEnd345,      0, 0, 10, 0, 2,   13, 3.9, 3, true
            circleHoldsIt,       0, 0, 10, 0, 2,    5,   0, 50, true
            zeroRadiusCapsule,   0, 0, 10, 0, 0,    5,   1, 2, true
            zeroRadiusTangent,   0, 0, 10, 0, 0,    5,   2, 2, false
            zeroRadiusCircle,    0, 0, 10, 0, 2,    5,   1, 0, true
            bothZero,            0, 0, 10, 0, 0,    5,   0, 0, false
            pointCapsuleTouch,   0, 0,  0, 0, 2,    3,   4, 3, false
            pointCapsuleReach,   0, 0,  0, 0, 2,    3,   4, 3.5, true
            hugeTouching,  1000000, 0, 1000010, 0, 2, 1000013, 4, 3, false
            """)
    void capsuleCircle(String scenario, float x1, float y1, float x2, float y2, float r, float cx, float cy, float cr, boolean expected) {
        check(expected, new Capsule(x1, y1, x2, y2, r), new Circle(cx, cy, cr));
    }

    // capsule, rect
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingTop,         0, 0, 10, 0, 2,    0,   2, 10, 5, false
            reachingTop,         0, 0, 10, 0, 2,    0, 1.9, 10, 5, true
            touchingCorner345,   0, 0, 10, 0, 5,   13,   4,  5, 5, false
            reachingCorner,      0, 0, 10, 0, 5,   13, 3.9,  5, 5, true
            rectInside,          0, 0, 10, 0, 2,    4,  -1,  1, 1, true
            capsuleInside,       0, 0, 10, 0, 2,  -10, -10, 30, 30, true
            segmentCrossesRect,  0, 0, 10, 0, 1,    4,  -5,  1, 10, true
            flatRectTouching,    0, 0, 10, 0, 2,    0,   2, 10, 0, false
            flatRectReaching,    0, 0, 10, 0, 2,    0,   1, 10, 0, true
            pointRectOnOutline,  0, 0, 10, 0, 2,    5,   2,  0, 0, false
            zeroRadiusAlongEdge, 0, 0, 10, 0, 0,    0,   0, 10, 5, false
            zeroRadiusInto,      0, 1, 10, 1, 0,    0,   0, 10, 5, true
            pointCapsule,        5, 5,  5, 5, 2,    0,   0,  4, 9, true
            """)
    void capsuleRect(String scenario, float x1, float y1, float x2, float y2, float r,
                     float rx, float ry, float rw, float rh, boolean expected) {
        check(expected, new Capsule(x1, y1, x2, y2, r), new Rect(rx, ry, rw, rh));
    }

    // capsule, segment
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingParallel,    0, 0, 10, 0, 2,    0,   2, 10, 2, false
            reachingParallel,    0, 0, 10, 0, 2,    0, 1.9, 10, 1.9, true
            crossing,            0, 0, 10, 0, 2,    5,  -5,  5, 5, true
            endTouching345,      0, 0, 10, 0, 5,   13,   4, 20, 4, false
            collinearApart,      0, 0, 10, 0, 2,   12,   0, 20, 0, false
            collinearReaching,   0, 0, 10, 0, 2, 11.5,   0, 20, 0, true
            zeroRadiusCrossing,  0, 0, 10, 0, 0,    5,  -5,  5, 5, false
            pointSegment,        0, 0, 10, 0, 2,    5,   1,  5, 1, true
            """)
    void capsuleLine(String scenario, float x1, float y1, float x2, float y2, float r,
                     float x3, float y3, float x4, float y4, boolean expected) {
        check(expected, new Capsule(x1, y1, x2, y2, r), new Segment(x3, y3, x4, y4));
    }

    // capsule, capsule
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingParallel,    0, 0, 10, 0, 2,    0,   4, 10,   4, 2, false
            reachingParallel,    0, 0, 10, 0, 2,    0,   4, 10,   4, 2.5, true
            crossing,            0, 0, 10, 0, 1,    5,  -5,  5,   5, 1, true
            endsTouching345,     0, 0, 10, 0, 2,   13,   4, 20,   4, 3, false
            endsReaching,        0, 0, 10, 0, 2,   13,   4, 20,   4, 3.1, true
            zeroAndZeroCrossing, 0, 0, 10, 0, 0,    5,  -5,  5,   5, 0, false
            zeroIntoReal,        0, 0, 10, 0, 0,    5,  -5,  5,  -1, 2, true
            pointCapsules,       0, 0,  0, 0, 2,    3,   4,  3,   4, 3, false
            """)
    void capsuleCapsule(String scenario, float x1, float y1, float x2, float y2, float r1,
                        float x3, float y3, float x4, float y4, float r2, boolean expected) {
        check(expected,
                new Capsule(x1, y1, x2, y2, r1), new Capsule(x3, y3, x4, y4, r2));
    }

    @Test
    void polygonCapsule_table() {
        Capsule k = new Capsule(0, 0, 10, 0, 2);
        Object[][] rows = {
                {Polygon.of(0, 2, 10, 2, 10, 5, 0, 5), false, "touching along a side"},
                {Polygon.of(0, 1.9f, 10, 1.9f, 10, 5, 0, 5), true, "reaching the side"},
                {Polygon.of(-20, -20, 40, -20, 10, 30), true, "holding the capsule"},
                {Polygon.of(4, -1, 6, -1, 5, 1), true, "inside the capsule"},
                {Polygon.of(13, 4, 20, 4, 20, 10), false, "vertex 5 from the end, r 2: apart"},
                {Polygon.of(-10, -10, 20, -10, 5, -1.9f, 20, 10, -10, 10), true, "concave, notch tip reaching in"},
        };
        for (Object[] row : rows) {
            Polygon p = (Polygon) row[0];
            check((Boolean) row[1], p, k);
        }
        Polygon square = Polygon.of(0, 0, 10, 0, 10, 10, 0, 10);
        check(true, square, new Capsule(2, 5, 8, 5, 0));
        check(false, square, new Capsule(0, 0, 10, 0, 0));
        check(false, square, new Capsule(13, 14, 13, 14, 5));
    }

    @Test
    void rawBodies_nanAndNegativeSizes_giveFalse() {
        // The shapes refuse such values (constructor_boundsAndTranslated); the plain-float
        // bodies the browser's Collide exports call answer false instead.
        float n = Float.NaN;
        assertFalse(RawTests.capsulePoint(0, 0, 10, 0, n, 5, 0));
        assertFalse(RawTests.capsulePoint(0, 0, 10, 0, 2, 5, n));
        assertFalse(RawTests.capsuleCircle(0, 0, 10, 0, -2, 5, 0, 3));
        assertFalse(RawTests.capsuleCircle(n, 0, 10, 0, 2, 5, 0, 3));
        assertFalse(RawTests.capsuleRect(0, 0, 10, 0, 2, 0, 0, -1, 5));
        assertFalse(RawTests.capsuleRect(0, 0, 10, 0, 2, 0, 0, n, 5));
        assertFalse(RawTests.capsuleLine(0, 0, 10, 0, 2, 5, n, 5, 5));
        assertFalse(RawTests.capsuleLine(0, 0, 10, 0, -2, 5, -5, 5, 5));
        assertFalse(RawTests.capsuleCapsule(0, 0, 10, 0, 2, 5, 0, 5, 5, n));
        assertFalse(RawTests.polygonCapsule(new float[] {0, 0, 9, 0, 0, 9}, 1, 1, 2, 2, n));
        assertFalse(RawTests.polygonCapsule(new float[] {0, 0, 9, 0, 0, 9}, 1, 1, 2, 2, -1));
    }

    @Test
    void constructor_boundsAndTranslated() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Capsule(0, 0, 1, 1, -1)).getMessage().contains("r"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Capsule(0, 0, Float.NaN, 1, 1)).getMessage().contains("x2"));
        Random rnd = new Random(3);
        for (int i = 0; i < 200; i++) {
            Capsule k = new Capsule(rnd.nextFloat() * 999, rnd.nextFloat() * 999, rnd.nextFloat() * 999, rnd.nextFloat() * 999, rnd.nextFloat() * 40);
            Rect b = k.bounds();
            for (double[] p : Sampled.outline(k)) {
                assertTrue(p[0] >= b.x() - 1e-9 && p[0] <= (double) b.x() + b.w() + 1e-9
                        && p[1] >= b.y() - 1e-9 && p[1] <= (double) b.y() + b.h() + 1e-9, k + " " + b);
            }
            assertTrue(b.x() <= Math.min(k.x1(), k.x2()) - (double) k.r());
            assertTrue((double) b.y() + b.h() >= Math.max(k.y1(), k.y2()) + (double) k.r());
        }
        assertEquals(new Capsule(3, 4, 5, 6, 1), new Capsule(1, 1, 3, 3, 1).translated(2, 3));
        assertEquals(new Segment(1, 1, 3, 3), new Capsule(1, 1, 3, 3, 1).segment());
    }

    /** Random capsules against random shapes of every kind, both orders, against the sampled oracle. */
    @Test
    void agreesWithTheSampledOracle_everyKind() {
        Sampled.assertAgreesWithOracle(20261125L, 3000, Sampled::capsule);
    }

    /**
     * Capsule against capsule and circle by distance: the distance between the segments from
     * 2001 samples of each parameter refined by ternary search (the distance is convex along a
     * segment), compared with the sum of radii outside a band of 1e-6.
     */
    @Test
    void capsuleCapsule_agreesWithSampledDistance() {
        Random rnd = new Random(5);
        int decided = 0;
        for (int i = 0; i < 2000; i++) {
            float[] a = {Sampled.coord(rnd), Sampled.coord(rnd), Sampled.coord(rnd), Sampled.coord(rnd)};
            float[] b = {Sampled.coord(rnd), Sampled.coord(rnd), Sampled.coord(rnd), Sampled.coord(rnd)};
            double d = segmentDistance(a, b);
            float r1 = (float) (d * rnd.nextDouble()), r2 = (float) (d * (0.8 + 0.4 * rnd.nextDouble())) - r1;
            if (!(r2 >= 0) || Math.abs(d - ((double) r1 + r2)) < 1e-6) {
                continue;
            }
            decided++;
            boolean expected = d < (double) r1 + r2;
            Capsule ka = new Capsule(a[0], a[1], a[2], a[3], r1), kb = new Capsule(b[0], b[1], b[2], b[3], r2);
            assertEquals(expected, ka.overlaps(kb));
            assertEquals(expected, kb.overlaps(ka));
        }
        assertTrue(decided > 1000, decided + " decided");
    }

    private static double segmentDistance(float[] a, float[] b) {
        double lo = 0, hi = 1;
        for (int k = 0; k < 200; k++) {
            double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (toSegment(a, m1, b) < toSegment(a, m2, b)) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        double best = toSegment(a, (lo + hi) / 2, b);
        return Math.min(best, Math.min(toSegment(a, 0, b), toSegment(a, 1, b)));
    }

    private static double toSegment(float[] a, double t, float[] b) {
        double px = a[0] + t * (a[2] - a[0]), py = a[1] + t * (a[3] - a[1]);
        return Sampled.segmentDistance(b[0], b[1], b[2], b[3], px, py);
    }
}
