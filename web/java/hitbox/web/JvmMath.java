package hitbox.web;

import java.util.Random;

/**
 * The JVM's answers for the few methods of the Java platform that TeaVM's class library
 * (0.16.0) lacks or answers otherwise, for the browser build only: there, every call of the
 * method on the left becomes a call of the one on the right (hitbox.web.tools.JvmMathOnWasm);
 * the JVM build never sees this class. Each is checked against the JVM's own on millions of
 * arguments by {@code JvmMathTest}, and the library's answers as a whole by the test vectors.
 *
 * <table>
 * <caption>What stands in for what, and why</caption>
 * <tr><th>the JVM's</th><th>TeaVM's</th><th>here</th></tr>
 * <tr><td>{@code Math.fma}</td><td>missing</td><td>{@link ExactFma#fma}</td></tr>
 * <tr><td>{@code Math.hypot}</td><td>{@code sqrt(x*x + y*y)}: rounds twice, overflows</td>
 *     <td>{@link #hypot}: fdlibm's algorithm, which {@code StrictMath.hypot} specifies</td></tr>
 * <tr><td>{@code Math.round(float)}, {@code Math.round(double)}</td>
 *     <td>adds {@code signum(a) * 0.5}: ties away from zero, and {@code 0.49999997f} rounds to 1</td>
 *     <td>{@link #round(float)}, {@link #round(double)}: the nearest, ties towards positive infinity</td></tr>
 * <tr><td>{@code Math.rint}</td><td>{@code round}: ties away from zero, loses -0.0</td>
 *     <td>{@link #rint}: ties to even</td></tr>
 * <tr><td>{@code Math.IEEEremainder}</td><td>truncates the quotient to an {@code int}</td>
 *     <td>{@link #IEEEremainder}: the quotient rounded to even, exactly</td></tr>
 * <tr><td>{@code Math.toRadians}</td><td>{@code deg * PI / 180}: two roundings</td>
 *     <td>{@link #toRadians}: one product, as the JDK</td></tr>
 * <tr><td>{@code -x} ({@code float}, {@code double})</td><td>{@code 0 - x}: +0.0 for -(+0.0)</td>
 *     <td>{@link #negate(float)}, {@link #negate(double)}: the sign bit flipped</td></tr>
 * <tr><td>{@code Math.ulp(double)}</td><td>{@code Double.MIN_VALUE} for every negative number</td>
 *     <td>{@link #ulp}</td></tr>
 * <tr><td>{@code Math.scalb(double, int)}</td><td>infinity for some large finite results</td>
 *     <td>{@link #scalb}: the JDK's steps</td></tr>
 * <tr><td>{@code Random.nextInt(int)}</td><td>another bounding method</td>
 *     <td>{@link #nextInt}: the one {@code java.util.Random} specifies</td></tr>
 * </table>
 *
 * <p>Reference: fdlibm 5.3 (Sun Microsystems, 1993), e_hypot.c and e_remainder.c, the algorithms
 * that {@code StrictMath}'s documentation names; the {@code java.util.Random} specification.
 */
public final class JvmMath {
    /** The JDK's {@code Math.toRadians} factor, pi / 180 rounded once. */
    private static final double DEGREES_TO_RADIANS = 0.017453292519943295;

    private JvmMath() {
    }

    /**
     * {@code Math.ulp(double)}: the gap from |d| to the next double away from zero. TeaVM's
     * answers {@code Double.MIN_VALUE} for every negative d.
     *
     * @param d the number
     * @return its ulp: NaN for NaN, infinity for the infinities
     */
    public static double ulp(double d) {
        int e = (int) (Double.doubleToRawLongBits(d) >>> 52) & 0x7ff;
        if (e == 0x7ff) {
            return Math.abs(d);
        }
        if (e <= 52) {   // the ulp is below the smallest normal: a subnormal power of two
            return Double.longBitsToDouble(1L << Math.max(0, e - 1));
        }
        return Double.longBitsToDouble((long) (e - 52) << 52);
    }

    /**
     * {@code Math.scalb(double, int)}: d times 2^n, in the JDK's steps (the remainder of n by 512
     * first, then 2^512 or 2^-512 at a time), so that a result near or below the smallest
     * normal rounds where the JVM's does. TeaVM's answers infinity for some large finite results
     * (scalb(-0.74, 1018) is -Infinity there).
     *
     * @param d the number
     * @param n the power of two
     * @return d * 2^n, rounded as the JVM rounds it
     */
    public static double scalb(double d, int n) {
        // Beyond this every finite non-zero d has gone to 0 or infinity, and the loop stays short.
        int limit = 2099;
        n = Math.max(-limit, Math.min(limit, n));
        int rest = n % 512;   // the sign of n, as the JDK's
        d *= Double.longBitsToDouble((long) (1023 + rest) << 52);
        n -= rest;
        double step = n < 0 ? 0x1p-512 : 0x1p512;
        while (n != 0) {
            d *= step;
            n -= n < 0 ? -512 : 512;
        }
        return d;
    }

    /**
     * {@code Math.hypot}: sqrt(x² + y²) without overflow or underflow in between, by fdlibm's
     * algorithm (an error below one ulp, the same bits as the JVM's).
     *
     * @param x a side
     * @param y the other side
     * @return the hypotenuse
     */
    public static double hypot(double x, double y) {
        double a = Math.abs(x);
        double b = Math.abs(y);
        int ha = high(a);
        int hb = high(b);
        if (hb > ha) {
            double t = a;
            a = b;
            b = t;
            int j = ha;
            ha = hb;
            hb = j;
        }
        if (ha - hb > 0x3c00000) {
            return a + b;    // a / b > 2^60
        }
        int k = 0;
        if (ha > 0x5f300000) {    // a > 2^500
            if (ha >= 0x7ff00000) {    // infinity or NaN
                double w = a + b;
                if (((ha & 0xfffff) | low(a)) == 0) {
                    w = a;
                }
                if (((hb ^ 0x7ff00000) | low(b)) == 0) {
                    w = b;
                }
                return w;
            }
            ha -= 0x25800000;    // scale both by 2^-600
            hb -= 0x25800000;
            k += 600;
            a = withHigh(a, ha);
            b = withHigh(b, hb);
        }
        if (hb < 0x20b00000) {    // b < 2^-500
            if (hb <= 0x000fffff) {    // b subnormal or zero
                if ((hb | low(b)) == 0) {
                    return a;
                }
                double t1 = Double.longBitsToDouble(0x7fd0000000000000L);    // 2^1022
                b *= t1;
                a *= t1;
                k -= 1022;
                // fdlibm keeps the old high words here, for the split below: so does the JVM's.
            } else {    // scale both by 2^600
                ha += 0x25800000;
                hb += 0x25800000;
                k -= 600;
                a = withHigh(a, ha);
                b = withHigh(b, hb);
            }
        }
        double w = a - b;
        if (w > b) {
            double t1 = withHighOnly(ha);
            double t2 = a - t1;
            w = Math.sqrt(t1 * t1 - (b * (-b) - t2 * (a + t1)));
        } else {
            a = a + a;
            double y1 = withHighOnly(hb);
            double y2 = b - y1;
            double t1 = withHighOnly(ha + 0x00100000);
            double t2 = a - t1;
            w = Math.sqrt(t1 * y1 - (w * (-w) - (t1 * y2 + t2 * b)));
        }
        if (k != 0) {
            return Double.longBitsToDouble(((long) (0x3ff00000 + (k << 20))) << 32) * w;
        }
        return w;
    }

    private static int high(double d) {
        return (int) (Double.doubleToRawLongBits(d) >>> 32);
    }

    private static int low(double d) {
        return (int) Double.doubleToRawLongBits(d);
    }

    private static double withHigh(double d, int high) {
        return Double.longBitsToDouble(((long) high << 32) | (Double.doubleToRawLongBits(d) & 0xffffffffL));
    }

    private static double withHighOnly(int high) {
        return Double.longBitsToDouble((long) high << 32);
    }

    /**
     * Java's {@code -x} for a float: the sign bit flipped, so {@code -(+0.0f)} is -0.0f.
     *
     * @param x the value
     * @return its negation
     */
    public static float negate(float x) {
        return Float.intBitsToFloat(Float.floatToRawIntBits(x) ^ 0x80000000);
    }

    /**
     * Java's {@code -x} for a double: the sign bit flipped, so {@code -(+0.0)} is -0.0.
     *
     * @param x the value
     * @return its negation
     */
    public static double negate(double x) {
        return Double.longBitsToDouble(Double.doubleToRawLongBits(x) ^ Long.MIN_VALUE);
    }

    /**
     * {@code Math.round(float)}: the nearest {@code int}, ties towards positive infinity, NaN to
     * 0, beyond the range to its ends.
     *
     * @param a the value
     * @return the rounded value
     */
    public static int round(float a) {
        // a + 0.5 is exact in double for every float (24 bits of mantissa).
        return (int) Math.floor((double) a + 0.5);
    }

    /**
     * {@code Math.round(double)}: the nearest {@code long}, ties towards positive infinity, NaN
     * to 0, beyond the range to its ends.
     *
     * @param a the value
     * @return the rounded value
     */
    public static long round(double a) {
        double f = Math.floor(a);
        // a - f is exact, or rounds on the right side of 1/2 (see the tests): no a + 0.5, which
        // rounds 0.49999999999999994 up.
        return (long) (a - f >= 0.5 ? f + 1 : f);
    }

    /**
     * {@code Math.rint}: the nearest integer value, ties to the even one, keeping the sign of zero.
     *
     * @param a the value
     * @return the rounded value
     */
    public static double rint(double a) {
        if (!(Math.abs(a) < 0x1p52)) {
            return a;    // NaN, infinite, or already an integer
        }
        double f = Math.floor(a);
        double d = a - f;
        double r = d > 0.5 ? f + 1 : d < 0.5 ? f : (f % 2 == 0 ? f : f + 1);
        return Math.copySign(r, a);
    }

    /**
     * {@code Math.IEEEremainder}: {@code x - n * y} for n the exact quotient rounded to the
     * nearest integer, ties to even; exact.
     *
     * @param x the dividend
     * @param y the divisor
     * @return the remainder
     */
    public static double IEEEremainder(double x, double y) {
        if (Double.isNaN(x) || Double.isNaN(y) || Double.isInfinite(x) || y == 0) {
            return Double.NaN;
        }
        if (Double.isInfinite(y)) {
            return x;
        }
        double p = Math.abs(y);
        double r = Math.abs(x);
        if (p <= Double.MAX_VALUE / 2) {
            r = r % (p + p);    // exact: now in [0, 2p)
        }
        if (r - p == 0) {
            r = 0;
        } else if (p < 0x1p-1021) {
            if (r + r > p) {
                r -= p;
                if (r + r >= p) {
                    r -= p;
                }
            }
        } else {
            double half = 0.5 * p;
            if (r > half) {
                r -= p;
                if (r >= half) {
                    r -= p;
                }
            }
        }
        return x < 0 || (x == 0 && 1 / x < 0) ? -r : r;
    }

    /**
     * {@code Math.toRadians}: the angle times pi / 180, one rounding.
     *
     * @param deg an angle in degrees
     * @return the angle in radians
     */
    public static double toRadians(double deg) {
        return deg * DEGREES_TO_RADIANS;
    }

    /**
     * {@code random.nextInt(bound)} as {@code java.util.Random} specifies it: the same draws from
     * the same seed. TeaVM's {@code Random} has the specified generator ({@code nextInt()}) but
     * bounds it another way.
     *
     * @param random the generator
     * @param bound  the bound, positive
     * @return a value in [0, bound)
     * @throws IllegalArgumentException if bound is not positive
     */
    public static int nextInt(Random random, int bound) {
        if (bound <= 0) {
            throw new IllegalArgumentException("bound must be positive");
        }
        int r = random.nextInt() >>> 1;    // next(31): the top 31 of the 48 bits
        int m = bound - 1;
        if ((bound & m) == 0) {
            return (int) ((bound * (long) r) >> 31);
        }
        for (int u = r; u - (r = u % bound) + m < 0; u = random.nextInt() >>> 1) {
            // rejected: draw again
        }
        return r;
    }
}
