package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.operation.buffer.BufferParameters;
import org.locationtech.jts.operation.distance.DistanceOp;

/**
 * Capsules against JTS (LocationTech's Java Topology Suite 1.20), an oracle that shares no code
 * with Hitbox. A capsule is the open set of points closer than r to its segment, so against
 * a shape X that is the closure of its inside (circle, rectangle, polygon, capsule) or a
 * closed segment, they overlap exactly when {@code DistanceOp.distance(segment, X) < r} (plus
 * the other's radius for a circle or a capsule). A capsule of radius 0 is its segment: it
 * overlaps a shape with area when JTS's relate finds the segment's interior in the shape's
 * interior ({@code T********}), and nothing else. Checked in both orders, with touching
 * cases on whole numbers (where JTS's distance is exact) in a table, and random cases away
 * from a tie band of 1e-9 of the size. A second check uses JTS buffers: the buffer of the
 * segment with 64 segments a quarter circle lies inside the capsule (its vertices on the
 * round ends) and, grown by 1 / cos(pi / 256), holds it; the tolerance between the two is
 * {@code r (1 / cos(pi / 256) - 1)}, about 7.5e-5 r.
 */
class CapsuleJtsTest {

    private static final int QUADRANT = 64;

    private static boolean hasArea(Shape s) {
        return s instanceof Polygon || s instanceof Rect r && r.w() > 0 && r.h() > 0
                || s instanceof Circle c && c.r() > 0 || s instanceof Capsule k && k.r() > 0;
    }

    /** JTS's answer, or null inside the tie band. */
    private static Boolean oracle(Capsule k, Shape other, double band) {
        Geometry seg = JtsShapes.segment(k.x1(), k.y1(), k.x2(), k.y2());
        if (k.r() == 0) {
            if (!hasArea(other)) {
                return false;
            }
            if (other instanceof Circle || other instanceof Capsule) {
                // The segment reaches the open disc or capsule: closer than its radius.
                double d = DistanceOp.distance(seg, JtsShapes.core(other));
                return Math.abs(d - JtsShapes.radius(other)) < band * (1 + d) ? null : d < JtsShapes.radius(other);
            }
            return seg.relate(JtsShapes.core(other), "T********");
        }
        if (other instanceof Circle c && c.r() == 0 || other instanceof Capsule m && m.r() == 0) {
            if (other instanceof Capsule m && !(m.x1() == m.x2() && m.y1() == m.y2())) {
                return oracle(m, k, band); // a segment reaching into k: the other way round
            }
        }
        double reach = k.r() + JtsShapes.radius(other);
        double d = DistanceOp.distance(seg, JtsShapes.core(other));
        if (Math.abs(d - reach) < band * (1 + reach)) {
            return null;
        }
        if (other instanceof Polygon && d == 0) {
            return true; // the segment meets the closed polygon and r > 0
        }
        return d < reach;
    }

    private static void check(Capsule k, Shape other, boolean expected) {
        assertEquals(expected, k.overlaps(other), k + " and " + other);
        assertEquals(expected, other.overlaps(k), other + " and " + k);
    }

    // capsule x1, y1, x2, y2, r; other kind; its numbers; expected
    @ParameterizedTest(name = "{0}")
    @CsvSource(textBlock = """
            touchingCircleSide,       0, 0, 10, 0, 4, circle,  5, 7, 3, 0,        false
            reachingCircleSide,       0, 0, 10, 0, 4, circle,  5, 7, 4, 0,        true
            touchingCircleEnd,        0, 0, 10, 0, 3, circle, 15, 4, 2, 0,        false
            touchingRectAbove,        0, 0, 10, 0, 2, rect,    0, 2, 10, 5,       false
            reachingRectAbove,        0, 0, 10, 0, 2, rect,    0, 1, 10, 5,       true
            touchingRectCorner,       0, 0,  0, 0, 5, rect,    3, 4, 10, 10,      false
            segmentTouching,          0, 0, 10, 0, 3, segment, 0, 3, 10, 3,       false
            segmentReaching,          0, 0, 10, 0, 3, segment, 0, 2, 10, 9,       true
            capsulesTouching,         0, 0, 10, 0, 2, capsule, 0, 5, 10, 5,       false
            capsulesReaching,         0, 0, 10, 0, 2, capsule, 0, 4, 10, 5,       true
            pointSegmentCapsule,      5, 5,  5, 5, 5, circle, 13, 11, 5, 0,       false
            pointSegmentReaching,     5, 5,  5, 5, 5, circle, 13, 11, 5.5, 0,     true
            zeroRadiusIntoRect,       0, 0, 10, 0, 0, rect,    5, -1, 2, 2,       true
            zeroRadiusAlongEdge,      0, 0, 10, 0, 0, rect,    0, 0, 10, 5,       false
            zeroRadiusAndSegment,     0, 0, 10, 0, 0, segment, 5, -5, 5, 5,      false
            """)
    void table_agreesWithJts(String scenario, float x1, float y1, float x2, float y2, float r, String kind,
                             float a, float b, float c, float d, boolean expected) {
        Capsule k = new Capsule(x1, y1, x2, y2, r);
        Shape other = switch (kind) {
            case "circle" -> new Circle(a, b, c);
            case "rect" -> new Rect(a, b, c, d);
            case "segment" -> new Segment(a, b, c, d);
            default -> new Capsule(a, b, c, d, 3);
        };
        // Whole numbers: JTS's distances here are exact, so no tie band.
        Boolean jts = oracle(k, other, 0);
        assertEquals(expected, jts, "JTS on " + scenario);
        check(k, other, expected);
    }

    private static Shape other(Random rnd) {
        if (rnd.nextInt(10) == 0) {
            // Degenerate others: a point circle, a flat rectangle, a point-segment capsule.
            float x = Sampled.coord(rnd), y = Sampled.coord(rnd);
            return switch (rnd.nextInt(3)) {
                case 0 -> new Circle(x, y, 0);
                case 1 -> new Rect(x, y, rnd.nextInt(30), 0);
                default -> new Capsule(x, y, x, y, 1 + rnd.nextInt(10));
            };
        }
        Shape s;
        do {
            s = Sampled.any(rnd);
        } while (s instanceof Ellipse);
        return s;
    }

    private static Capsule capsule(Random rnd) {
        Capsule k = Sampled.capsule(rnd);
        return rnd.nextInt(8) == 0 ? new Capsule(k.x1(), k.y1(), k.x2(), k.y2(), 0) : k;
    }

    @Test
    void randomPairs_agreeWithJtsDistances_bothOrders() {
        Random rnd = new Random(20261124L);
        int yes = 0, no = 0;
        for (int i = 0; i < 5000; i++) {
            Capsule k = capsule(rnd);
            Shape other = other(rnd);
            Boolean jts = oracle(k, other, 1e-9);
            if (jts == null) {
                continue;
            }
            check(k, other, jts);
            if (jts) {
                yes++;
            } else {
                no++;
            }
        }
        assertTrue(yes > 800 && no > 800, yes + " overlapping, " + no + " apart");
    }

    /** The buffers: the inscribed buffer meeting the shape's inside proves an overlap, the circumscribed one missing it proves apart. */
    @Test
    void randomPairs_agreeWithJtsBuffers() {
        Random rnd = new Random(7);
        double grow = 1 / Math.cos(Math.PI / (4 * QUADRANT));
        int decided = 0;
        for (int i = 0; i < 1500; i++) {
            Capsule k = Sampled.capsule(rnd);
            Shape other;
            do {
                other = Sampled.any(rnd);
            } while (other instanceof Ellipse || other instanceof Circle || other instanceof Capsule || other instanceof Segment);
            Geometry seg = JtsShapes.segment(k.x1(), k.y1(), k.x2(), k.y2());
            Geometry g = JtsShapes.core(other);
            Geometry inner = seg.buffer(k.r(), QUADRANT, BufferParameters.CAP_ROUND);
            Geometry outer = seg.buffer(k.r() * grow, QUADRANT, BufferParameters.CAP_ROUND);
            if (inner.relate(g, "T********")) {
                decided++;
                check(k, other, true);
            } else if (!outer.relate(g, "T********")) {
                decided++;
                check(k, other, false);
            }
        }
        assertTrue(decided > 1400, decided + " decided");
    }
}
