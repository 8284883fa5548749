package hitbox;

import java.math.BigDecimal;

/**
 * The slow reference for the collision tests: each pair written the most obvious way, in
 * exact arithmetic, so that a test can say "the library agrees with the maths".
 *
 * <p>Every float is turned into a {@link BigDecimal} without rounding ({@code new
 * BigDecimal(double)} is exact, and a float widens to a double exactly), and sums, differences
 * and squares of BigDecimals are exact too. So every answer here is the true answer for the
 * given floats, by the <a href="package-summary.html#touching">touching rule</a>: shapes with
 * area are open, a zero-size shape has no inside and collides only by reaching into the inside
 * of a shape that has one. Nothing here is tuned for speed or shares code with the library.
 *
 * <p>This is a test-side utility for the whole package: test classes for other pairs may add
 * their own reference methods here, in the same style (obvious formulation, exact maths).
 * All arguments must be finite; sizes must be 0 or more.
 */
final class Reference {
    private Reference() {
    }

    /**
     * Whole-number offsets of up to 1e6, by which a test moves every shape of a case: the
     * library promises the same answer, touching cases included, after any of them.
     */
    static final float[][] WHOLE_OFFSETS = {
            {1_000_000, 1_000_000}, {-1_000_000, -1_000_000}, {1_000_000, -1_000_000},
            {-999_999, 654_321}, {0, 1_000_000}, {-1_000_000, 0},
    };

    /** The float's exact value. */
    static BigDecimal exact(float v) {
        return new BigDecimal(v);
    }

    /** The exact square of the distance between two points. */
    static BigDecimal distanceSquared(float x1, float y1, float x2, float y2) {
        BigDecimal dx = exact(x2).subtract(exact(x1));
        BigDecimal dy = exact(y2).subtract(exact(y1));
        return dx.multiply(dx).add(dy.multiply(dy));
    }

    /** Is {@code a < b}? */
    static boolean less(BigDecimal a, BigDecimal b) {
        return a.compareTo(b) < 0;
    }

    /** Is the point strictly inside the circle: closer to the centre than the radius? */
    static boolean circlePoint(float cx, float cy, float r, float px, float py) {
        BigDecimal radius = exact(r);
        return less(distanceSquared(cx, cy, px, py), radius.multiply(radius));
    }

    /**
     * Do the circles overlap: are the centres closer than the sum of the radii? With one radius
     * 0 this is the other circle containing a point; with both 0 it is never true.
     */
    static boolean circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        BigDecimal reach = exact(r1).add(exact(r2));
        return less(distanceSquared(x1, y1, x2, y2), reach.multiply(reach));
    }

    /** Is the point strictly between the left and right edges, and the top and bottom edges? */
    static boolean rectPoint(float rx, float ry, float rw, float rh, float px, float py) {
        return openIntervalHas(rx, rw, px) && openIntervalHas(ry, rh, py);
    }

    /**
     * Do the rectangles overlap? A rectangle with area is open; one of width or height 0 is a
     * segment (without its ends) or a point that must reach into the other's inside. Two of
     * them meet only when they cross like a plus sign, as the tutorial's comparisons say.
     */
    static boolean rectRect(float x1, float y1, float w1, float h1,
                            float x2, float y2, float w2, float h2) {
        // Boxes meet when they meet along each axis. An open interval (a, b) and a closed one
        // [c, d] share a point when c < b and a < d; two open ones, likewise.
        return openMeetsClosed(x1, w1, x2, w2) && openMeetsClosed(y1, h1, y2, h2);
    }

    /**
     * Does the circle overlap the rectangle? A circle of radius 0 is a point, which must be
     * strictly inside. Otherwise the circle's open inside meets the rectangle when the
     * rectangle's nearest point (clamping the centre into the closed rectangle) is closer to
     * the centre than the radius.
     */
    static boolean circleRect(float cx, float cy, float r, float rx, float ry, float rw, float rh) {
        if (r == 0) {
            return rectPoint(rx, ry, rw, rh, cx, cy);
        }
        BigDecimal nearestX = exact(cx).max(exact(rx)).min(exact(rx).add(exact(rw)));
        BigDecimal nearestY = exact(cy).max(exact(ry)).min(exact(ry).add(exact(rh)));
        BigDecimal dx = exact(cx).subtract(nearestX);
        BigDecimal dy = exact(cy).subtract(nearestY);
        BigDecimal radius = exact(r);
        return less(dx.multiply(dx).add(dy.multiply(dy)), radius.multiply(radius));
    }

    /** Is v in the open interval (start, start + length)? */
    private static boolean openIntervalHas(float start, float length, float v) {
        return less(exact(start), exact(v)) && less(exact(v), exact(start).add(exact(length)));
    }

    /** Do [s1, s1 + l1] and [s2, s2 + l2] share a point, with at least one of them open? */
    private static boolean openMeetsClosed(float s1, float l1, float s2, float l2) {
        return less(exact(s2), exact(s1).add(exact(l1))) && less(exact(s1), exact(s2).add(exact(l2)));
    }
}
