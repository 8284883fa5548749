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
     * Are the centres closer than {@code r1 + r2}, decided exactly for every float (radii
     * already checked to be 0 or more)? In double first: each of the two sides, the distance
     * squared and the reach squared, is two float sums rounded once, squared and (for the
     * distance) added, so off by under 2^-50 of itself; outside a band of 2^-48 either way
     * the double comparison is the exact one. Inside it (nearly touching, or sizes so far
     * apart that the double sums rounded: a radius of 0.01 beside one of 3.4e38), the exact
     * comparison in {@link BigDecimal}. Infinite values are compared as the formula compares
     * them; NaN answers false.
     */
    public static boolean centresCloser(float x1, float y1, float r1, float x2, float y2, float r2) {
        double dx = (double) x2 - x1, dy = (double) y2 - y1, reach = (double) r1 + r2;
        double d2 = dx * dx + dy * dy, rr = reach * reach;
        if (d2 < rr * (1 - 0x1p-48) || d2 > rr * (1 + 0x1p-48) || !(Math.abs(d2) + rr < Double.POSITIVE_INFINITY)) {
            return d2 < rr;
        }
        // Inside the band: if every sum and square above was exact (whole and half pixels
        // touching exactly, the common case here), the comparison already is; the rest in
        // BigDecimal.
        if (exactSum(x2, -(double) x1, dx) && exactSum(y2, -(double) y1, dy) && exactSum(r1, r2, reach)
                && Math.fma(dx, dx, -(dx * dx)) == 0 && Math.fma(dy, dy, -(dy * dy)) == 0
                && Math.fma(reach, reach, -rr) == 0 && exactSum(dx * dx, dy * dy, d2)) {
            return d2 < rr;
        }
        BigDecimal ex = new BigDecimal(x2).subtract(new BigDecimal(x1)), ey = new BigDecimal(y2).subtract(new BigDecimal(y1));
        BigDecimal er = new BigDecimal(r1).add(new BigDecimal(r2));
        return ex.multiply(ex).add(ey.multiply(ey)).compareTo(er.multiply(er)) < 0;
    }

    /** Is s, the double sum of a and b, exact? Knuth's TwoSum: its rounding error, exactly, is 0. */
    private static boolean exactSum(double a, double b, double s) {
        double bb = s - a;
        return (a - (s - bb)) + (b - bb) == 0;
    }

    /** Are both parts finite (not NaN, not infinite)? */
    public static boolean finite(double vx, double vy) {
        return Math.abs(vx) < Slabs.INF && Math.abs(vy) < Slabs.INF;
    }
}
