package hitbox.internal;

import java.math.BigDecimal;

/**
 * The disc maths that {@link Sweep} and {@link Ray} share: when does a point moving along
 * {@code d + t v} enter an open disc around the origin? A moving circle against a standing
 * one is a point against a disc of the summed radius; so are the rounded corners of a circle
 * against a box, the ends of a capsule, and a ray against a circle.
 *
 * <p>Reference: C. Ericson, <i>Real-Time Collision Detection</i> (2005), 5.3.2
 * (intersecting a ray or segment against a sphere).
 */
public final class Discs {
    private Discs() {
    }

    /**
     * When does the point {@code d + t v} enter the open disc of radius {@code reach} around
     * the origin, for t in [0, limit)? -infinity if it starts inside, +infinity if it never
     * enters (a path that only touches the outline does not; NaN, an infinite velocity or a
     * reach of 0 or less do not either). A point that starts on the outline and moves in
     * enters at 0.
     */
    public static double entry(double dx, double dy, double vx, double vy, double reach, double limit) {
        if (!(reach > 0) || !finite(vx, vy)) {
            return Slabs.INF;  // a point has no inside to enter
        }
        double c = dx * dx + dy * dy - reach * reach;
        if (c < 0) {
            return Double.NEGATIVE_INFINITY;
        }
        double b = dx * vx + dy * vy;
        if (!(b < 0)) {
            return Slabs.INF;  // moving away, sideways along the outline, not at all, or NaN
        }
        double a = vx * vx + vy * vy;
        double disc = b * b - a * c;
        if (!(disc > 0)) {
            return Slabs.INF;  // the path misses the disc or only touches it
        }
        if (c == 0) {
            // Touching and moving in: inside at once, but only if the motion goes anywhere.
            return limit > 0 ? 0 : Slabs.INF;
        }
        // The entry t1 is before the limit when the point is inside at the limit, or when
        // the closest approach (-b / a) comes before it; decided without the square root.
        boolean beforeLimit = limit == Slabs.INF || a * limit * limit + 2 * b * limit + c < 0 || -b < a * limit;
        if (!beforeLimit) {
            return Slabs.INF;
        }
        // t1 = (-b - sqrt(disc)) / a, written without cancellation.
        return Math.min(c / (Math.sqrt(disc) - b), limit);
    }

    /**
     * Are the centres closer than {@code r1 + r2} (radii already checked to be 0 or more)?
     * {@link #distanceSign} with {@code less = -r2}, so exact for every float.
     */
    public static boolean centresCloser(float x1, float y1, float r1, float x2, float y2, float r2) {
        return distanceSign(x2, y2, x1, y1, r1, -(double) r2) < 0;
    }

    /**
     * The sign of {@code |p - q|^2 - (reach - less)^2}: -1, 0 or 1, exact for every finite
     * float input (given as doubles). In double first, trusted outside a band of
     * {@link Tolerance#NEAR_TIE} of the two sides, well wider than their rounding; near a tie,
     * the double values when every difference, square and sum was exact (checked by
     * error-free transformations, so whole and half pixels touching exactly allocate
     * nothing), else in {@link BigDecimal} (sizes far apart in magnitude, or fractions with
     * many bits). Infinite input is compared as the double formula compares it; NaN gives 1.
     */
    public static int distanceSign(double px, double py, double qx, double qy, double reach, double less) {
        double dx = px - qx, dy = py - qy, m = reach - less;
        double xx = dx * dx, yy = dy * dy, d2 = xx + yy, m2 = m * m;
        if (!(d2 + m2 < Double.POSITIVE_INFINITY) || Math.abs(d2 - m2) > Tolerance.NEAR_TIE * (d2 + m2)) {
            return d2 < m2 ? -1 : d2 == m2 ? 0 : 1;
        }
        if (Lines.twoSumError(px, -qx, dx) == 0 && Lines.twoSumError(py, -qy, dy) == 0 && Lines.twoSumError(reach, -less, m) == 0
                && Math.fma(dx, dx, -xx) == 0 && Math.fma(dy, dy, -yy) == 0 && Math.fma(m, m, -m2) == 0
                && Lines.twoSumError(xx, yy, d2) == 0
                && (xx == 0 || xx >= Lines.UNDERFLOW_GUARD) && (yy == 0 || yy >= Lines.UNDERFLOW_GUARD)
                && (m2 == 0 || m2 >= Lines.UNDERFLOW_GUARD)) {
            return Double.compare(d2, m2);  // all exact (the subnormal guard: an fma residual there can round)
        }
        BigDecimal ex = new BigDecimal(px).subtract(new BigDecimal(qx));
        BigDecimal ey = new BigDecimal(py).subtract(new BigDecimal(qy));
        BigDecimal em = new BigDecimal(reach).subtract(new BigDecimal(less));
        return Integer.signum(ex.multiply(ex).add(ey.multiply(ey)).compareTo(em.multiply(em)));
    }

    /** Are both parts finite (not NaN, not infinite)? */
    public static boolean finite(double vx, double vy) {
        return Math.abs(vx) < Slabs.INF && Math.abs(vy) < Slabs.INF;
    }
}
