package hitbox.web;

import java.math.BigDecimal;

/**
 * {@code Math.fma(double, double, double)} for the browser build, where TeaVM's class library
 * lacks it: the exact product plus the addend, rounded once to the nearest double (ties to
 * even), as the JVM's intrinsic answers. The browser build points every call of
 * {@code Math.fma} at {@link #fma} (hitbox.web.tools.JvmMathOnWasm); the JVM keeps its intrinsic.
 *
 * <p>The library asks for one thing of fma: the rounding error of a product,
 * {@code fma(a, b, -(a * b))}. That case is answered by Dekker's exact product (Veltkamp's
 * split), exact while nothing overflows or underflows, which the guards check; every other
 * case, and those outside the guards, by exact decimal arithmetic ({@link BigDecimal}) and a
 * rounding checked against the neighbours of the candidate.
 *
 * <p>Reference: T. J. Dekker, "A floating-point technique for extending the available
 * precision", Numerische Mathematik 18 (1971); IEEE 754-2019, 5.4.1 (fusedMultiplyAdd) and
 * 6.3 (the sign of an exact zero sum).
 */
public final class ExactFma {
    /** Veltkamp's splitter for doubles: 2^27 + 1. */
    private static final double SPLIT = 0x1p27 + 1;
    /**
     * Half an ulp above {@code Double.MAX_VALUE}, 2^1024 - 2^970: from here on, a sum rounds to
     * infinity. Made from integers, not from {@code Math.ulp}, whose TeaVM version is not trusted here.
     */
    private static final BigDecimal OVERFLOW = BigDecimal.valueOf(2).pow(1024).subtract(BigDecimal.valueOf(2).pow(970));

    private ExactFma() {
    }

    /**
     * Returns {@code a * b + c} with one rounding, bit for bit what {@link Math#fma(double, double, double)}
     * returns.
     *
     * @param a the first factor
     * @param b the second factor
     * @param c the addend
     * @return the exact {@code a * b + c} rounded to the nearest double, ties to even
     */
    public static double fma(double a, double b, double c) {
        double p = a * b;
        if (c == -p && Math.abs(p) >= 0x1p-960 && Math.abs(p) <= Double.MAX_VALUE
                && Math.abs(a) < 0x1p995 && Math.abs(b) < 0x1p995) {
            double e = productError(a, b, p);
            // An exact zero sum of two non-zero terms is +0 when rounding to nearest.
            return e == 0 ? 0.0 : e;
        }
        return slow(a, b, c);
    }

    /** The exact {@code a * b - p} for {@code p = a * b}, within the guards of {@link #fma}. */
    private static double productError(double a, double b, double p) {
        double t = SPLIT * a;
        double ah = t - (t - a);
        double al = a - ah;
        t = SPLIT * b;
        double bh = t - (t - b);
        double bl = b - bh;
        return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    }

    private static double slow(double a, double b, double c) {
        if (Double.isNaN(a) || Double.isNaN(b) || Double.isNaN(c) || Double.isInfinite(a) || Double.isInfinite(b)) {
            return a * b + c;
        }
        if (Double.isInfinite(c)) {
            return c;    // a finite exact product never overflows
        }
        if (a == 0 || b == 0) {
            return a * b + c;    // the product is an exact signed zero: one rounding, the sum's
        }
        BigDecimal v = new BigDecimal(a).multiply(new BigDecimal(b)).add(new BigDecimal(c));
        int sign = v.signum();
        if (sign == 0) {
            return 0.0;
        }
        if (v.abs().compareTo(OVERFLOW) >= 0) {
            return sign > 0 ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        }
        double d = v.doubleValue();
        if (Double.isInfinite(d)) {
            d = Math.copySign(Double.MAX_VALUE, d);
        }
        double best = d;
        BigDecimal bestGap = gap(v, d);
        for (double n : new double[] {Math.nextUp(d), Math.nextDown(d)}) {
            if (Double.isInfinite(n)) {
                continue;
            }
            BigDecimal g = gap(v, n);
            int cmp = g.compareTo(bestGap);
            if (cmp < 0 || (cmp == 0 && (Double.doubleToRawLongBits(n) & 1) == 0)) {
                best = n;
                bestGap = g;
            }
        }
        // A result rounded to zero keeps the sign of the exact sum.
        return best == 0 ? (sign > 0 ? 0.0 : -0.0) : best;
    }

    private static BigDecimal gap(BigDecimal v, double d) {
        return v.subtract(new BigDecimal(d)).abs();
    }
}
