package hitbox.internal;

import java.math.BigDecimal;

/**
 * Segment maths behind {@link Collide} and {@link Segment}, built on exact orientation tests.
 *
 * <p>Nothing here divides: every decision is the sign of a sum of products, so vertical and
 * parallel lines are ordinary cases, and for whole-number coordinates up to about a million
 * every sign is exact.
 */
public final class Lines {
    private Lines() {
    }

    /**
     * Products at least this large (in magnitude) are far enough from underflow that an
     * {@code fma} error term of 0 means the product is exact: a residual below about 2^-1074
     * could itself have rounded to 0. Floats' differences and their squares never come near it.
     */
    static final double UNDERFLOW_GUARD = 0x1p-900;

    /**
     * The orientation of c seen from the line a to b: positive for one turn, negative for the
     * other, 0 when the three points are collinear. It is the cross product (b - a) x (c - a),
     * twice the signed area of the triangle abc.
     *
     * <p>Its sign is exact for every finite input, however large or mixed in size the
     * coordinates (1e16 next to 1, say, where the differences themselves round): the value is
     * computed in double, and when it is within the rounding error of 0 (Shewchuk's error
     * bound), it is computed again exactly, in {@link BigDecimal}. The slow path runs only
     * for points within rounding of a line; its value is then the exact one, rounded.
     *
     * <p>Reference: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
     * Robust Geometric Predicates", Discrete &amp; Computational Geometry 18 (1997): the
     * error bound of orient2d's first stage.
     */
    public static double orient(double ax, double ay, double bx, double by, double cx, double cy) {
        double left = (bx - ax) * (cy - ay);
        double right = (by - ay) * (cx - ax);
        double det = left - right;
        double bound = ORIENT_ERROR * (Math.abs(left) + Math.abs(right));
        if (det > bound || -det > bound || Double.isNaN(det) || Double.isInfinite(bound)) {
            return det;
        }
        if (exactTerms(ax, ay, bx, by, cx, cy, left, right)) {
            return det;
        }
        return exactOrient(ax, ay, bx, by, cx, cy).doubleValue();
    }

    /**
     * Were the two products of {@link #orient} computed without rounding? Then their
     * difference, rounded once, is the exact value rounded, with the exact sign (a difference
     * of two doubles is 0 only when they are equal). This is the usual case near 0: points
     * exactly on a line with coordinates of modest size (whole numbers, say), where the
     * differences and products of floats are all exact in double; it answers them without
     * {@link BigDecimal}, so without allocating. Each difference is checked with Knuth's
     * Two-Sum and each product with a fused multiply-add.
     */
    private static boolean exactTerms(double ax, double ay, double bx, double by, double cx, double cy,
                                      double left, double right) {
        double ex = bx - ax, ey = by - ay, fx = cx - ax, fy = cy - ay;
        return exactDifference(bx, ax, ex) && exactDifference(cy, ay, fy)
                && exactDifference(by, ay, ey) && exactDifference(cx, ax, fx)
                && exactProduct(ex, fy, left) && exactProduct(ey, fx, right);
    }

    /**
     * Is p the exact product of x and y? The fused multiply-add's error term is 0, and the
     * product is far enough from underflow (or an exact 0) that an error term could not
     * itself have underflowed to 0: floats' differences never come near that.
     */
    private static boolean exactProduct(double x, double y, double p) {
        return p == 0 ? x == 0 || y == 0 : Math.abs(p) >= UNDERFLOW_GUARD && Math.fma(x, y, -p) == 0;
    }

    /** Is {@code d}, the rounded {@code b - a}, exact? (Knuth's Two-Sum error term is 0.) */
    private static boolean exactDifference(double b, double a, double d) {
        double bv = d - b;
        double av = d - bv;
        return (b - av) + (-a - bv) == 0;
    }

    /** Shewchuk's ccwerrboundA, (3 + 16 eps) eps with eps = 2^-53. */
    private static final double ORIENT_ERROR = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;

    /** The orientation in exact arithmetic. */
    public static BigDecimal exactOrient(double ax, double ay, double bx, double by, double cx, double cy) {
        BigDecimal x = new BigDecimal(ax), y = new BigDecimal(ay);
        BigDecimal ex = new BigDecimal(bx).subtract(x), ey = new BigDecimal(by).subtract(y);
        BigDecimal fx = new BigDecimal(cx).subtract(x), fy = new BigDecimal(cy).subtract(y);
        return ex.multiply(fy).subtract(ey.multiply(fx));
    }

    /** Is the point in the closed axis-aligned box spanned by a and b? */
    public static boolean inBox(double ax, double ay, double bx, double by, double px, double py) {
        return px >= Math.min(ax, bx) && px <= Math.max(ax, bx)
                && py >= Math.min(ay, by) && py <= Math.max(ay, by);
    }

    /** Does the point lie on the closed segment? */
    public static boolean segmentPoint(float x1, float y1, float x2, float y2, float px, float py) {
        return orient(x1, y1, x2, y2, px, py) == 0 && inBox(x1, y1, x2, y2, px, py);
    }

    /** Are a and b non-zero with the same sign? (False if either is 0 or NaN.) */
    public static boolean sameSide(double a, double b) {
        return (a > 0 && b > 0) || (a < 0 && b < 0);
    }

    /** Are a and b non-zero with opposite signs? (False if either is 0 or NaN.) */
    public static boolean opposite(double a, double b) {
        return (a > 0 && b < 0) || (a < 0 && b > 0);
    }

    /**
     * A number with the exact sign of {@code a * b - c * d} (positive, negative or zero; NaN
     * if an argument is NaN). Plain double arithmetic would round the two products, and near
     * a tie (a point exactly on a circle) the rounding could flip the sign; here each product
     * is split into its rounded value and its exact rounding error with {@link Math#fma}, and
     * the four parts are added without error. Exact unless a product overflows or
     * underflows, which whole-number inputs up to 2^26 never do.
     *
     * <p>Reference: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
     * Robust Geometric Predicates", Discrete &amp; Computational Geometry 18 (1997): Two-Sum
     * and Two-Two-Sum; the error of a product from a fused multiply-add.
     */
    public static double signOfProductDifference(double a, double b, double c, double d) {
        double p = a * b;
        double pe = Math.fma(a, b, -p);       // a * b == p + pe exactly
        double q = -(c * d);
        double qe = Math.fma(-c, d, -q);      // -(c * d) == q + qe exactly
        // Two-Two-Sum of the expansions (p, pe) and (q, qe): x3 + x2 + x1 + x0 is the exact
        // sum, in components that do not overlap, largest last; the largest non-zero
        // component has the sign of the whole.
        double s = pe + qe;
        double bv = s - pe;
        double av = s - bv;
        double x0 = (pe - av) + (qe - bv);
        double i = s;
        s = p + i;
        bv = s - p;
        av = s - bv;
        double r0 = (p - av) + (i - bv);
        double j = s;
        s = r0 + q;
        bv = s - r0;
        av = s - bv;
        double x1 = (r0 - av) + (q - bv);
        i = s;
        s = j + i;
        bv = s - j;
        av = s - bv;
        double x2 = (j - av) + (i - bv);
        double x3 = s;
        return x3 != 0 ? x3 : x2 != 0 ? x2 : x1 != 0 ? x1 : x0;
    }

    /** Do the closed segments AB and CD meet? Exact orientation signs. */
    public static boolean segmentsMeet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        double o1 = Lines.orient(ax, ay, bx, by, cx, cy);
        double o2 = Lines.orient(ax, ay, bx, by, dx, dy);
        // Both ends strictly on one side of the other's line: apart, and no end can lie on
        // the other segment (a segment through a point of a line, not along it, has its ends
        // on both sides), so the two orientations left are not needed. The usual miss.
        if (sameSide(o1, o2)) {
            return false;
        }
        double o3 = Lines.orient(cx, cy, dx, dy, ax, ay);
        double o4 = Lines.orient(cx, cy, dx, dy, bx, by);
        if (sameSide(o3, o4)) {
            return false;
        }
        if (Lines.opposite(o1, o2) && Lines.opposite(o3, o4)) {
            return true;
        }
        return (o1 == 0 && Lines.inBox(ax, ay, bx, by, cx, cy))
                || (o2 == 0 && Lines.inBox(ax, ay, bx, by, dx, dy))
                || (o3 == 0 && Lines.inBox(cx, cy, dx, dy, ax, ay))
                || (o4 == 0 && Lines.inBox(cx, cy, dx, dy, bx, by));
    }

    /** Knuth's two-sum: the rounding error of {@code sum = x + y}, exactly (0 when the sum is exact). */
    public static double twoSumError(double x, double y, double sum) {
        double yv = sum - x;
        double xv = sum - yv;
        return (x - xv) + (y - yv);
    }

    /**
     * Clamps {@code v} into [lo, hi] (lo <= hi); used for the closest point of a rectangle.
     * NaN in any argument gives NaN, so a NaN rectangle edge cannot be clamped away into a
     * false "collision": a NaN fails both comparisons and lands on {@code lo + v}, or on hi
     * when hi is the NaN. Written with comparisons rather than {@code Math.max(lo,
     * Math.min(v, hi))}, which gives the same values (a zero's sign aside) but which the JIT
     * here compiles to branches that mispredict on mixed inputs: {@code RawTests.circleRect}
     * took 7.8 ns a case with it and 3.3 without (a scratch loop on the table's kind of cases).
     */
    public static double clamp(double v, double lo, double hi) {
        return v >= lo ? (v <= hi ? v : hi) : (v < lo ? lo : lo + v);
    }
}
