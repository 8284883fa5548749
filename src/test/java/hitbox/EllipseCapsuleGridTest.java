package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;

/**
 * Ellipses and capsules on a small whole-number grid, zero radii and point segments included,
 * where touching is the common case: every pair answers the same in both orders and moved by
 * up to a million pixels (the decisions work on differences, exactly); capsules against
 * circles and capsules match distances computed exactly in integers.
 */
class EllipseCapsuleGridTest {

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Integer> c = Arbitraries.integers().between(0, 6);
        Arbitrary<Integer> r = Arbitraries.integers().between(0, 3);
        Arbitrary<Shape> ellipses = Combinators.combine(c, c, r, r).as((x, y, a, b) -> new Ellipse(x, y, a, b));
        Arbitrary<Shape> capsules = Combinators.combine(c, c, c, c, r).as((x1, y1, x2, y2, k) -> new Capsule(x1, y1, x2, y2, k));
        Arbitrary<Shape> circles = Combinators.combine(c, c, r).as((x, y, k) -> new Circle(x, y, k));
        Arbitrary<Shape> rects = Combinators.combine(c, c, r, r).as((x, y, w, h) -> new Rect(x, y, w, h));
        Arbitrary<Shape> segments = Combinators.combine(c, c, c, c).as((x1, y1, x2, y2) -> new Segment(x1, y1, x2, y2));
        Arbitrary<Shape> triangles = Combinators.combine(c, c).as((x, y) -> Polygon.of(x, y, x + 3, y, x, y + 2));
        return Arbitraries.oneOf(ellipses, capsules, ellipses, capsules, circles, rects, segments, triangles);
    }

    @Property(tries = 3000)
    void symmetricAndTranslationInvariant(@ForAll("shapes") Shape a, @ForAll("shapes") Shape b,
                                          @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                          @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean ab = a.overlaps(b);
        assertEquals(ab, b.overlaps(a), () -> "symmetric: " + a + " and " + b);
        assertEquals(ab, a.translated(dx, dy).overlaps(b.translated(dx, dy)), () -> a + " and " + b + " moved by " + dx + ", " + dy);
    }

    /** Capsule against circle and capsule against capsule on whole numbers, against exact integer arithmetic. */
    @Property(tries = 3000)
    void capsules_matchExactIntegerDistances(@ForAll @IntRange(min = 0, max = 8) int x1, @ForAll @IntRange(min = 0, max = 8) int y1,
                                             @ForAll @IntRange(min = 0, max = 8) int x2, @ForAll @IntRange(min = 0, max = 8) int y2,
                                             @ForAll @IntRange(min = 0, max = 8) int x3, @ForAll @IntRange(min = 0, max = 8) int y3,
                                             @ForAll @IntRange(min = 0, max = 8) int x4, @ForAll @IntRange(min = 0, max = 8) int y4,
                                             @ForAll @IntRange(min = 0, max = 4) int r1, @ForAll @IntRange(min = 0, max = 4) int r2) {
        long reach = r1 + r2;
        assertEquals(within(x1, y1, x2, y2, x3, y3, reach), new Capsule(x1, y1, x2, y2, r1).overlaps(new Circle(x3, y3, r2)),
                () -> "capsuleCircle " + x1 + "," + y1 + " " + x2 + "," + y2 + " r " + r1 + " circle " + x3 + "," + y3 + " r " + r2);
        boolean meet = meet(x1, y1, x2, y2, x3, y3, x4, y4);
        boolean expected = reach > 0 && (meet || within(x1, y1, x2, y2, x3, y3, reach) || within(x1, y1, x2, y2, x4, y4, reach)
                || within(x3, y3, x4, y4, x1, y1, reach) || within(x3, y3, x4, y4, x2, y2, reach));
        assertEquals(expected, new Capsule(x1, y1, x2, y2, r1).overlaps(new Capsule(x3, y3, x4, y4, r2)), "capsuleCapsule");
    }

    /** Is (px, py) closer than reach to segment AB? In longs: exact. */
    private static boolean within(long ax, long ay, long bx, long by, long px, long py, long reach) {
        long ex = bx - ax, ey = by - ay, fx = px - ax, fy = py - ay;
        long len2 = ex * ex + ey * ey, along = fx * ex + fy * ey;
        if (len2 == 0 || along <= 0) {
            return fx * fx + fy * fy < reach * reach;
        }
        if (along >= len2) {
            long gx = px - bx, gy = py - by;
            return gx * gx + gy * gy < reach * reach;
        }
        long cross = ex * fy - ey * fx;
        return cross * cross < reach * reach * len2;
    }

    private static long orient(long ax, long ay, long bx, long by, long cx, long cy) {
        return Long.signum((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
    }

    private static boolean on(long ax, long ay, long bx, long by, long px, long py) {
        return orient(ax, ay, bx, by, px, py) == 0 && Math.min(ax, bx) <= px && px <= Math.max(ax, bx)
                && Math.min(ay, by) <= py && py <= Math.max(ay, by);
    }

    private static boolean meet(long ax, long ay, long bx, long by, long cx, long cy, long dx, long dy) {
        long o1 = orient(ax, ay, bx, by, cx, cy), o2 = orient(ax, ay, bx, by, dx, dy);
        long o3 = orient(cx, cy, dx, dy, ax, ay), o4 = orient(cx, cy, dx, dy, bx, by);
        return (o1 * o2 < 0 && o3 * o4 < 0) || on(ax, ay, bx, by, cx, cy) || on(ax, ay, bx, by, dx, dy)
                || on(cx, cy, dx, dy, ax, ay) || on(cx, cy, dx, dy, bx, by);
    }
}
