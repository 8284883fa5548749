package hitbox;

import hitbox.internal.*;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The routing of {@link Shape#overlaps} for all 36 ordered pairs of the six kinds: each
 * class calls its own kind's method of {@link Overlaps}, which hands earlier kinds the pair
 * swapped. Whichever shape is asked, and whether through {@code overlaps} or the library's
 * own {@link Overlaps#test}, the answer is the raw test for the pair (the Collide method, or
 * for an ellipse or a capsule its {@link RawTests} body, which Collide no longer names), written
 * out again here independently of Overlaps (a turned ellipse: the same answer both ways round).
 */
class OverlapsRoutingTest {

    private static final int KINDS = 6;

    /** A random shape of kind k (0 circle, 1 rect, 2 segment, 3 polygon, 4 ellipse, 5 capsule) near the origin. */
    private static Shape shape(int k, Random rnd) {
        switch (k) {
            case 0:
                return new Circle(c(rnd), c(rnd), size(rnd));
            case 1:
                return new Rect(c(rnd), c(rnd), size(rnd), size(rnd));
            case 2:
                return new Segment(c(rnd), c(rnd), c(rnd), c(rnd));
            case 3:
                return polygon(rnd);
            case 4:
                // one in three turned; radii sometimes equal (a circle) or 0 (flat)
                float angle = rnd.nextInt(3) == 0 ? rnd.nextInt(7) * 0.5f : 0;
                float rx = size(rnd);
                return new Ellipse(c(rnd), c(rnd), rx, rnd.nextInt(5) == 0 ? rx : size(rnd), angle);
            default:
                return new Capsule(c(rnd), c(rnd), c(rnd), c(rnd), size(rnd));
        }
    }

    /** A coordinate in [-6, 6], in halves, so touching cases come up. */
    private static float c(Random rnd) {
        return rnd.nextInt(25) * 0.5f - 6;
    }

    /** A size in [0, 5], in halves, 0 included. */
    private static float size(Random rnd) {
        return rnd.nextInt(11) * 0.5f;
    }

    /** A triangle, a convex quadrilateral or a concave arrow, moved about. */
    private static Polygon polygon(Random rnd) {
        float x = c(rnd), y = c(rnd);
        float[][] outlines = {
                {0, 0, 4, 1, 1, 3},
                {0, 0, 4, 0, 5, 3, -1, 4},
                {0, 0, 6, 0, 3, 2, 6, 5, 0, 5},
        };
        float[] xy = outlines[rnd.nextInt(outlines.length)].clone();
        for (int i = 0; i < xy.length; i += 2) {
            xy[i] += x;
            xy[i + 1] += y;
        }
        return Polygon.of(xy);
    }

    /** The raw test for the pair, or null for a pair with a turned ellipse (decided in its frame). */
    private static Boolean collide(Shape a, Shape b) {
        if (a instanceof Ellipse e) {
            if (!TurnedEllipses.aligned(e) || b instanceof Ellipse f && !TurnedEllipses.aligned(f)) {
                return null;
            }
            float x = e.x(), y = e.y(), rx = e.rx(), ry = e.ry();
            if (b instanceof Ellipse f) {
                return RawTests.ellipseEllipse(x, y, rx, ry, f.x(), f.y(), f.rx(), f.ry());
            } else if (b instanceof Capsule k) {
                return RawTests.ellipseCapsule(x, y, rx, ry, k.x1(), k.y1(), k.x2(), k.y2(), k.r());
            } else if (b instanceof Circle c) {
                return RawTests.ellipseCircle(x, y, rx, ry, c.x(), c.y(), c.r());
            } else if (b instanceof Rect r) {
                return RawTests.ellipseRect(x, y, rx, ry, r.x(), r.y(), r.w(), r.h());
            } else if (b instanceof Segment s) {
                return RawTests.ellipseLine(x, y, rx, ry, s.x1(), s.y1(), s.x2(), s.y2());
            }
            return RawTests.polygonEllipse(((Polygon) b).coordinates(), x, y, rx, ry);
        }
        if (b instanceof Ellipse) {
            return collide(b, a);
        }
        if (a instanceof Capsule k) {
            float x1 = k.x1(), y1 = k.y1(), x2 = k.x2(), y2 = k.y2(), r = k.r();
            if (b instanceof Capsule o) {
                return RawTests.capsuleCapsule(x1, y1, x2, y2, r, o.x1(), o.y1(), o.x2(), o.y2(), o.r());
            } else if (b instanceof Circle c) {
                return RawTests.capsuleCircle(x1, y1, x2, y2, r, c.x(), c.y(), c.r());
            } else if (b instanceof Rect q) {
                return RawTests.capsuleRect(x1, y1, x2, y2, r, q.x(), q.y(), q.w(), q.h());
            } else if (b instanceof Segment s) {
                return RawTests.capsuleLine(x1, y1, x2, y2, r, s.x1(), s.y1(), s.x2(), s.y2());
            }
            return RawTests.polygonCapsule(((Polygon) b).coordinates(), x1, y1, x2, y2, r);
        }
        if (b instanceof Capsule) {
            return collide(b, a);
        }
        return OverlapsTableTest.collide(a, b);
    }

    @Test
    void everyOrderedPair_routesToItsRawTest_andAnswersTheSameBothWays() {
        Random rnd = new Random(12);
        int[][] yes = new int[KINDS][KINDS], no = new int[KINDS][KINDS];
        for (int i = 0; i < 60_000; i++) {
            int ka = rnd.nextInt(KINDS), kb = rnd.nextInt(KINDS);
            Shape a = shape(ka, rnd), b = shape(kb, rnd);
            boolean ab = a.overlaps(b);
            String what = a + " vs " + b;
            assertEquals(ab, b.overlaps(a), () -> "b.overlaps(a): " + what);
            assertEquals(ab, Overlaps.test(a, b), () -> "Overlaps.test(a, b): " + what);
            assertEquals(ab, Overlaps.test(b, a), () -> "Overlaps.test(b, a): " + what);
            Boolean expected = collide(a, b);
            if (expected != null) {
                assertEquals(expected, ab, () -> "the raw test for the pair: " + what);
            }
            if (ab) {
                yes[ka][kb]++;
            } else {
                no[ka][kb]++;
            }
        }
        // Every ordered pair met both answers, so none of the 36 routes went untried.
        for (int ka = 0; ka < KINDS; ka++) {
            for (int kb = 0; kb < KINDS; kb++) {
                assertTrue(yes[ka][kb] > 20 && no[ka][kb] > 20, "kinds " + ka + ", " + kb + ": " + yes[ka][kb] + " yes, " + no[ka][kb] + " no");
            }
        }
    }
}
