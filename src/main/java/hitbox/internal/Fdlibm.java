package hitbox.internal;

/**
 * {@code StrictMath.sin}, {@code StrictMath.cos} and {@code Math.atan2} in Java, for the
 * browser build and for a turning body's pose ({@link #sinCos}: both from one reduction, where
 * the JVM's {@code StrictMath} makes two native calls): fdlibm 5.3's algorithms (s_sin.c, s_cos.c, k_sin.c, k_cos.c, e_rem_pio2.c, k_rem_pio2.c,
 * e_atan2.c, s_atan.c), which {@code StrictMath}'s documentation names, so the same bits as
 * every JVM's ({@code Math.atan2} is {@code StrictMath.atan2} on the JVM). The library calls
 * {@code StrictMath.sin}/{@code cos} and {@code Math.atan2}; on the browser build
 * hitbox.web.tools.JvmMathOnWasm points those calls here, where TeaVM's class library answers
 * otherwise (its atan2 differs in the last bit for about one argument in six).
 * {@code JvmMathTest} compares them with the JVM's on a million arguments each, huge ones
 * included.
 *
 * <p>The argument is first reduced to {@code r = x - n * pi/2}, |r| at most about pi/4, as a
 * sum of two doubles {@code r0 + r1}; then a polynomial of degree 13 (sine) or 14 (cosine)
 * answers for r and n mod 4 picks the sign and which one. Reduction by pi/2 split in 33-bit
 * pieces serves up to 2^19 * pi/2; beyond that, the bits of 2/pi that matter for x are
 * multiplied out in 24-bit pieces ({@link #reduceLarge}). The tables were checked against 2/pi
 * and pi/2 computed to 2,400 bits.
 *
 * <p>This class is longer than most (about 630 lines): fdlibm's sine, cosine and arc tangent
 * with their reductions, constants and tables, kept together as fdlibm keeps them.
 */
public final class Fdlibm {
    private Fdlibm() {
    }

    // The sine's polynomial: sin(x) ~ x + S1 x^3 + ... + S6 x^13 on [-pi/4, pi/4].
    private static final double S1 = Double.longBitsToDouble(0xBFC5555555555549L);
    private static final double S2 = Double.longBitsToDouble(0x3F8111111110F8A6L);
    private static final double S3 = Double.longBitsToDouble(0xBF2A01A019C161D5L);
    private static final double S4 = Double.longBitsToDouble(0x3EC71DE357B1FE7DL);
    private static final double S5 = Double.longBitsToDouble(0xBE5AE5E68A2B9CEBL);
    private static final double S6 = Double.longBitsToDouble(0x3DE5D93A5ACFD57CL);
    // The cosine's: cos(x) ~ 1 - x^2/2 + C1 x^4 + ... + C6 x^14.
    private static final double C1 = Double.longBitsToDouble(0x3FA555555555554CL);
    private static final double C2 = Double.longBitsToDouble(0xBF56C16C16C15177L);
    private static final double C3 = Double.longBitsToDouble(0x3EFA01A019CB1590L);
    private static final double C4 = Double.longBitsToDouble(0xBE927E4F809C52ADL);
    private static final double C5 = Double.longBitsToDouble(0x3E21EE9EBDB4B1C4L);
    private static final double C6 = Double.longBitsToDouble(0xBDA8FAE9BE8838D4L);

    /** 2/pi rounded, for n. */
    private static final double INV_PIO2 = Double.longBitsToDouble(0x3FE45F306DC9C883L);
    /** pi/2 in pieces: PIO2_1 its first 33 bits, PIO2_1T the rest; then the rest split again, twice. */
    private static final double PIO2_1 = Double.longBitsToDouble(0x3FF921FB54400000L);
    private static final double PIO2_1T = Double.longBitsToDouble(0x3DD0B4611A626331L);
    private static final double PIO2_2 = Double.longBitsToDouble(0x3DD0B4611A600000L);
    private static final double PIO2_2T = Double.longBitsToDouble(0x3BA3198A2E037073L);
    private static final double PIO2_3 = Double.longBitsToDouble(0x3BA3198A2E000000L);
    private static final double PIO2_3T = Double.longBitsToDouble(0x397B839A252049C1L);
    private static final double TWO24 = 16777216.0;
    private static final double TWON24 = 5.9604644775390625E-8;

    /** The high words of n * pi/2 for n = 1 to 32: an x near one of them loses bits to cancellation. */
    private static final int[] NPIO2_HW = {
        0x3FF921FB, 0x400921FB, 0x4012D97C, 0x401921FB, 0x401F6A7A, 0x4022D97C,
        0x4025FDBB, 0x402921FB, 0x402C463A, 0x402F6A7A, 0x4031475C, 0x4032D97C,
        0x40346B9C, 0x4035FDBB, 0x40378FDB, 0x403921FB, 0x403AB41B, 0x403C463A,
        0x403DD85A, 0x403F6A7A, 0x40407E4C, 0x4041475C, 0x4042106C, 0x4042D97C,
        0x4043A28C, 0x40446B9C, 0x404534AC, 0x4045FDBB, 0x4046C6CB, 0x40478FDB,
        0x404858EB, 0x404921FB,
    };

    /** 2/pi in 24-bit pieces, 1584 bits: enough for any double. */
    private static final int[] TWO_OVER_PI = {
        0xA2F983, 0x6E4E44, 0x1529FC, 0x2757D1, 0xF534DD, 0xC0DB62, 0x95993C, 0x439041,
        0xFE5163, 0xABDEBB, 0xC561B7, 0x246E3A, 0x424DD2, 0xE00649, 0x2EEA09, 0xD1921C,
        0xFE1DEB, 0x1CB129, 0xA73EE8, 0x8235F5, 0x2EBB44, 0x84E99C, 0x7026B4, 0x5F7E41,
        0x3991D6, 0x398353, 0x39F49C, 0x845F8B, 0xBDF928, 0x3B1FF8, 0x97FFDE, 0x05980F,
        0xEF2F11, 0x8B5A0A, 0x6D1F6D, 0x367ECF, 0x27CB09, 0xB74F46, 0x3F669E, 0x5FEA2D,
        0x7527BA, 0xC7EBE5, 0xF17B3D, 0x0739F7, 0x8A5292, 0xEA6BFB, 0x5FB11F, 0x8D5D08,
        0x560330, 0x46FC7B, 0x6BABF0, 0xCFBC20, 0x9AF436, 0x1DA9E3, 0x91615E, 0xE61B08,
        0x659985, 0x5F14A0, 0x68408D, 0xFFD880, 0x4D7327, 0x310606, 0x1556CA, 0x73A8C9,
        0x60E27B, 0xC08C6B,
    };

    /** pi/2 in 24-bit pieces. */
    private static final double[] PIO2 = {
        Double.longBitsToDouble(0x3FF921FB40000000L), Double.longBitsToDouble(0x3E74442D00000000L),
        Double.longBitsToDouble(0x3CF8469880000000L), Double.longBitsToDouble(0x3B78CC5160000000L),
        Double.longBitsToDouble(0x39F01B8380000000L), Double.longBitsToDouble(0x387A252040000000L),
        Double.longBitsToDouble(0x36E3822280000000L), Double.longBitsToDouble(0x3569F31D00000000L),
    };

    /**
     * {@code StrictMath.sin}.
     *
     * @param x an angle, radians
     * @return its sine, the bits StrictMath gives
     */
    public static double sin(double x) {
        int ix = high(x) & 0x7fffffff;
        if (ix <= 0x3fe921fb) {
            return kernelSin(x, 0, false);
        }
        if (ix >= 0x7ff00000) {
            return x - x;   // NaN for NaN and the infinities
        }
        double[] y = new double[2];
        int n = reduce(x, y);
        switch (n & 3) {
            case 0:
                return kernelSin(y[0], y[1], true);
            case 1:
                return kernelCos(y[0], y[1]);
            case 2:
                return -kernelSin(y[0], y[1], true);
            default:
                return -kernelCos(y[0], y[1]);
        }
    }

    /**
     * {@code StrictMath.cos}.
     *
     * @param x an angle, radians
     * @return its cosine, the bits StrictMath gives
     */
    public static double cos(double x) {
        int ix = high(x) & 0x7fffffff;
        if (ix <= 0x3fe921fb) {
            return kernelCos(x, 0);
        }
        if (ix >= 0x7ff00000) {
            return x - x;
        }
        double[] y = new double[2];
        int n = reduce(x, y);
        switch (n & 3) {
            case 0:
                return kernelCos(y[0], y[1]);
            case 1:
                return -kernelSin(y[0], y[1], true);
            case 2:
                return -kernelCos(y[0], y[1]);
            default:
                return kernelSin(y[0], y[1], true);
        }
    }

    /**
     * {@code StrictMath.cos(x)} and {@code StrictMath.sin(x)} at once, the same bits as each:
     * {@link #cos} and {@link #sin} share their reduction of x, so this reduces once and runs
     * both polynomials. A turning body's pose asks for both each frame; on the JVM, where
     * {@code StrictMath} makes a native call for each, this is about twice as fast.
     *
     * @param x   an angle, radians
     * @param out where the answers go: out[0] the cosine, out[1] the sine (length 2 at least)
     */
    public static void sinCos(double x, double[] out) {
        int ix = high(x) & 0x7fffffff;
        if (ix <= 0x3fe921fb) {
            out[0] = kernelCos(x, 0);
            out[1] = kernelSin(x, 0, false);
            return;
        }
        if (ix >= 0x7ff00000) {
            out[0] = x - x;   // NaN for NaN and the infinities
            out[1] = x - x;
            return;
        }
        int n = reduce(x, out);   // out holds the reduced angle's two parts for now
        double y0 = out[0], y1 = out[1];
        double s = kernelSin(y0, y1, true), c = kernelCos(y0, y1);
        switch (n & 3) {
            case 0 -> {
                out[0] = c;
                out[1] = s;
            }
            case 1 -> {
                out[0] = -s;
                out[1] = c;
            }
            case 2 -> {
                out[0] = -c;
                out[1] = -s;
            }
            default -> {
                out[0] = s;
                out[1] = -c;
            }
        }
    }

    // ---------------------------------------------------------------- atan2

    /** atan(0.5), atan(1), atan(1.5), atan(inf), each as a double and the rest. */
    private static final double[] ATAN_HI = {Double.longBitsToDouble(0x3FDDAC670561BB4FL),
        Double.longBitsToDouble(0x3FE921FB54442D18L), Double.longBitsToDouble(0x3FEF730BD281F69BL),
        Double.longBitsToDouble(0x3FF921FB54442D18L)};
    private static final double[] ATAN_LO = {Double.longBitsToDouble(0x3C7A2B7F222F65E2L),
        Double.longBitsToDouble(0x3C81A62633145C07L), Double.longBitsToDouble(0x3C7007887AF0CBBDL),
        Double.longBitsToDouble(0x3C91A62633145C07L)};
    /** atan's polynomial on [-7/16, 7/16]: atan(x) ~ x - x (AT[0] x^2 + AT[1] x^4 + ...). */
    private static final double[] AT = {Double.longBitsToDouble(0x3FD555555555550DL),
        Double.longBitsToDouble(0xBFC999999998EBC4L), Double.longBitsToDouble(0x3FC24924920083FFL),
        Double.longBitsToDouble(0xBFBC71C6FE231671L), Double.longBitsToDouble(0x3FB745CDC54C206EL),
        Double.longBitsToDouble(0xBFB3B0F2AF749A6DL), Double.longBitsToDouble(0x3FB10D66A0D03D51L),
        Double.longBitsToDouble(0xBFADDE2D52DEFD9AL), Double.longBitsToDouble(0x3FA97B4B24760DEBL),
        Double.longBitsToDouble(0xBFA2B4442C6A6C2FL), Double.longBitsToDouble(0x3F90AD3AE322DA11L)};
    private static final double PI_O_4 = Double.longBitsToDouble(0x3FE921FB54442D18L);
    private static final double PI_O_2 = Double.longBitsToDouble(0x3FF921FB54442D18L);
    private static final double PI = Double.longBitsToDouble(0x400921FB54442D18L);
    /** pi - PI. */
    private static final double PI_LO = Double.longBitsToDouble(0x3CA1A62633145C07L);
    /** Added to the answers that are not exact, as fdlibm does (to raise "inexact"); it never changes them. */
    private static final double TINY = 1.0e-300;

    /**
     * {@code Math.atan2} (and {@code StrictMath.atan2}): the angle of the point (x, y).
     *
     * @param y the point's y
     * @param x the point's x
     * @return the angle, radians, from -pi to pi, the bits the JVM gives
     */
    public static double atan2(double y, double x) {
        int hx = high(x);
        int ix = hx & 0x7fffffff;
        int lx = (int) Double.doubleToRawLongBits(x);
        int hy = high(y);
        int iy = hy & 0x7fffffff;
        int ly = (int) Double.doubleToRawLongBits(y);
        if (Double.isNaN(x) || Double.isNaN(y)) {
            return x + y;
        }
        if (x == 1.0) {
            return atan(y);
        }
        int m = ((hy >> 31) & 1) | ((hx >> 30) & 2);   // 2 * sign(x) + sign(y)
        if ((iy | ly) == 0) {   // y is 0
            switch (m) {
                case 0:
                case 1:
                    return y;
                case 2:
                    return PI + TINY;
                default:
                    return -PI - TINY;
            }
        }
        if ((ix | lx) == 0) {   // x is 0
            return hy < 0 ? -PI_O_2 - TINY : PI_O_2 + TINY;
        }
        if (ix == 0x7ff00000) {   // x is infinite
            if (iy == 0x7ff00000) {
                switch (m) {
                    case 0:
                        return PI_O_4 + TINY;
                    case 1:
                        return -PI_O_4 - TINY;
                    case 2:
                        return 3.0 * PI_O_4 + TINY;
                    default:
                        return -3.0 * PI_O_4 - TINY;
                }
            }
            switch (m) {
                case 0:
                    return 0.0;
                case 1:
                    return -0.0;
                case 2:
                    return PI + TINY;
                default:
                    return -PI - TINY;
            }
        }
        if (iy == 0x7ff00000) {   // y is infinite
            return hy < 0 ? -PI_O_2 - TINY : PI_O_2 + TINY;
        }
        int k = (iy - ix) >> 20;
        double z;
        if (k > 60) {   // |y/x| > 2^60
            z = PI_O_2 + 0.5 * PI_LO;
        } else if (hx < 0 && k < -60) {   // |y|/x < -2^60
            z = 0.0;
        } else {
            z = atan(Math.abs(y / x));
        }
        switch (m) {
            case 0:
                return z;
            case 1:
                return Double.longBitsToDouble(Double.doubleToRawLongBits(z) ^ Long.MIN_VALUE);
            case 2:
                return PI - (z - PI_LO);
            default:
                return (z - PI_LO) - PI;
        }
    }

    /** fdlibm's atan (s_atan.c), for atan2. */
    private static double atan(double x) {
        int hx = high(x);
        int ix = hx & 0x7fffffff;
        if (ix >= 0x44100000) {   // |x| >= 2^66, or NaN
            if (Double.isNaN(x)) {
                return x + x;
            }
            return hx > 0 ? ATAN_HI[3] + ATAN_LO[3] : -ATAN_HI[3] - ATAN_LO[3];
        }
        int id;
        if (ix < 0x3fdc0000) {   // |x| < 0.4375
            if (ix < 0x3e200000) {   // |x| < 2^-29: atan x is x
                return x;
            }
            id = -1;
        } else {
            x = Math.abs(x);
            if (ix < 0x3ff30000) {   // |x| < 1.1875
                if (ix < 0x3fe60000) {   // 7/16 <= |x| < 11/16
                    id = 0;
                    x = (2.0 * x - 1.0) / (2.0 + x);
                } else {                 // 11/16 <= |x| < 19/16
                    id = 1;
                    x = (x - 1.0) / (x + 1.0);
                }
            } else if (ix < 0x40038000) {   // |x| < 2.4375
                id = 2;
                x = (x - 1.5) / (1.0 + 1.5 * x);
            } else {                        // 2.4375 <= |x| < 2^66
                id = 3;
                x = -1.0 / x;
            }
        }
        double z = x * x;
        double w = z * z;
        double s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
        double s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
        if (id < 0) {
            return x - x * (s1 + s2);
        }
        z = ATAN_HI[id] - ((x * (s1 + s2) - ATAN_LO[id]) - x);
        return hx < 0 ? -z : z;
    }

    // ---------------------------------------------------------------- sin and cos

    /** sin(x + y) for |x| at most about pi/4, y the tail of x (used only when hasTail). */
    private static double kernelSin(double x, double y, boolean hasTail) {
        int ix = high(x) & 0x7fffffff;
        if (ix < 0x3e400000) {
            return x;   // |x| < 2^-27: sin x is x to the last bit
        }
        double z = x * x;
        double v = z * x;
        double r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
        if (!hasTail) {
            return x + v * (S1 + z * r);
        }
        return x - ((z * (0.5 * y - v * r) - y) - v * S1);
    }

    /** cos(x + y) for |x| at most about pi/4, y the tail of x. */
    private static double kernelCos(double x, double y) {
        int ix = high(x) & 0x7fffffff;
        if (ix < 0x3e400000) {
            return 1.0;   // |x| < 2^-27
        }
        double z = x * x;
        double r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
        if (ix < 0x3FD33333) {   // |x| < 0.3
            return 1.0 - (0.5 * z - (z * r - x * y));
        }
        // 1 - x^2/2 loses bits for larger x: take qx (about x^2/4, cut to its high word) out first.
        double qx = ix > 0x3fe90000 ? 0.28125 : Double.longBitsToDouble((long) (ix - 0x00200000) << 32);
        double hz = 0.5 * z - qx;
        double a = 1.0 - qx;
        return a - (hz - (z * r - x * y));
    }

    /**
     * x - n * pi/2 as y[0] + y[1], |y[0]| at most about pi/4.
     *
     * @return n (its low bits are what the callers need)
     */
    private static int reduce(double x, double[] y) {
        int hx = high(x);
        int ix = hx & 0x7fffffff;
        if (ix < 0x4002d97c) {   // |x| < 3pi/4: n is 1 or -1
            double z;
            if (hx > 0) {
                z = x - PIO2_1;
                if (ix != 0x3ff921fb) {   // 33 + 53 bits of pi/2 are enough
                    y[0] = z - PIO2_1T;
                    y[1] = (z - y[0]) - PIO2_1T;
                } else {                  // near pi/2: 33 + 33 + 53 bits
                    z -= PIO2_2;
                    y[0] = z - PIO2_2T;
                    y[1] = (z - y[0]) - PIO2_2T;
                }
                return 1;
            }
            z = x + PIO2_1;
            if (ix != 0x3ff921fb) {
                y[0] = z + PIO2_1T;
                y[1] = (z - y[0]) + PIO2_1T;
            } else {
                z += PIO2_2;
                y[0] = z + PIO2_2T;
                y[1] = (z - y[0]) + PIO2_2T;
            }
            return -1;
        }
        if (ix <= 0x413921fb) {   // |x| up to about 2^19 * pi/2
            double t = Math.abs(x);
            int n = (int) (t * INV_PIO2 + 0.5);
            double fn = n;
            double r = t - fn * PIO2_1;
            double w = fn * PIO2_1T;   // good to 85 bits
            if (n < 32 && ix != NPIO2_HW[n - 1]) {
                y[0] = r - w;   // no cancellation
            } else {
                int j = ix >> 20;
                y[0] = r - w;
                int i = j - ((high(y[0]) >> 20) & 0x7ff);
                if (i > 16) {   // a second step, good to 118 bits
                    t = r;
                    w = fn * PIO2_2;
                    r = t - w;
                    w = fn * PIO2_2T - ((t - r) - w);
                    y[0] = r - w;
                    i = j - ((high(y[0]) >> 20) & 0x7ff);
                    if (i > 49) {   // a third, 151 bits: enough for every double here
                        t = r;
                        w = fn * PIO2_3;
                        r = t - w;
                        w = fn * PIO2_3T - ((t - r) - w);
                        y[0] = r - w;
                    }
                }
            }
            y[1] = (r - y[0]) - w;
            if (hx < 0) {
                y[0] = -y[0];
                y[1] = -y[1];
                return -n;
            }
            return n;
        }
        // Large: |x| as three 24-bit pieces times 2^e0, then the bits of 2/pi that matter.
        int e0 = (ix >> 20) - 1046;   // ilogb(x) - 23
        double z = Double.longBitsToDouble(((long) (ix - (e0 << 20)) << 32) | (Double.doubleToRawLongBits(x) & 0xffffffffL));
        double[] tx = new double[3];
        for (int i = 0; i < 2; i++) {
            tx[i] = (int) z;
            z = (z - tx[i]) * TWO24;
        }
        tx[2] = z;
        int nx = 3;
        while (tx[nx - 1] == 0.0) {
            nx--;
        }
        int n = reduceLarge(tx, y, e0, nx);
        if (hx < 0) {
            y[0] = -y[0];
            y[1] = -y[1];
            return -n;
        }
        return n;
    }

    /**
     * fdlibm's __kernel_rem_pio2 for double precision (prec 2, jk 4): x (nx 24-bit pieces,
     * scaled by 2^e0) times 2/pi, its integer part mod 8 returned and its fraction times pi/2
     * in y[0] + y[1].
     */
    private static int reduceLarge(double[] x, double[] y, int e0, int nx) {
        final int jk = 4;
        final int jp = jk;
        int[] iq = new int[20];
        double[] f = new double[20];
        double[] fq = new double[20];
        double[] q = new double[20];
        int jx = nx - 1;
        int jv = Math.max(0, (e0 - 3) / 24);
        int q0 = e0 - 24 * (jv + 1);

        // f[0..jx+jk]: the pieces of 2/pi that meet x's pieces
        int j = jv - jx;
        int m = jx + jk;
        for (int i = 0; i <= m; i++, j++) {
            f[i] = j < 0 ? 0.0 : (double) TWO_OVER_PI[j];
        }
        for (int i = 0; i <= jk; i++) {
            double fw = 0.0;
            for (j = 0; j <= jx; j++) {
                fw += x[j] * f[jx + i - j];
            }
            q[i] = fw;
        }
        int jz = jk;
        int n;
        int ih;
        double z;
        while (true) {
            // distill q[] into iq[], highest last
            int i = 0;
            j = jz;
            z = q[jz];
            for (; j > 0; i++, j--) {
                double fw = (int) (TWON24 * z);
                iq[i] = (int) (z - TWO24 * fw);
                z = q[j - 1] + fw;
            }
            z = scalbn(z, q0);
            z -= 8.0 * Math.floor(z * 0.125);   // the integer part mod 8 is all that is needed
            n = (int) z;
            z -= n;
            ih = 0;
            if (q0 > 0) {   // iq[jz-1] holds bits of n
                i = iq[jz - 1] >> (24 - q0);
                n += i;
                iq[jz - 1] -= i << (24 - q0);
                ih = iq[jz - 1] >> (23 - q0);
            } else if (q0 == 0) {
                ih = iq[jz - 1] >> 23;
            } else if (z >= 0.5) {
                ih = 2;
            }
            if (ih > 0) {   // the fraction is more than 1/2: take 1 - it, and n + 1
                n += 1;
                int carry = 0;
                for (i = 0; i < jz; i++) {
                    j = iq[i];
                    if (carry == 0) {
                        if (j != 0) {
                            carry = 1;
                            iq[i] = 0x1000000 - j;
                        }
                    } else {
                        iq[i] = 0xffffff - j;
                    }
                }
                if (q0 > 0) {
                    if (q0 == 1) {
                        iq[jz - 1] &= 0x7fffff;
                    } else if (q0 == 2) {
                        iq[jz - 1] &= 0x3fffff;
                    }
                }
                if (ih == 2) {
                    z = 1.0 - z;
                    if (carry != 0) {
                        z -= scalbn(1.0, q0);
                    }
                }
            }
            // all the bits so far cancelled: take more pieces of 2/pi and start again
            if (z == 0.0) {
                j = 0;
                for (i = jz - 1; i >= jk; i--) {
                    j |= iq[i];
                }
                if (j == 0) {
                    int k = 1;
                    while (iq[jk - k] == 0) {
                        k++;
                    }
                    for (i = jz + 1; i <= jz + k; i++) {
                        f[jx + i] = TWO_OVER_PI[jv + i];
                        double fw = 0.0;
                        for (j = 0; j <= jx; j++) {
                            fw += x[j] * f[jx + i - j];
                        }
                        q[i] = fw;
                    }
                    jz += k;
                    continue;
                }
            }
            break;
        }
        // chop off zero pieces, or split z into 24-bit pieces
        if (z == 0.0) {
            jz -= 1;
            q0 -= 24;
            while (iq[jz] == 0) {
                jz--;
                q0 -= 24;
            }
        } else {
            z = scalbn(z, -q0);
            if (z >= TWO24) {
                double fw = (int) (TWON24 * z);
                iq[jz] = (int) (z - TWO24 * fw);
                jz += 1;
                q0 += 24;
                iq[jz] = (int) fw;
            } else {
                iq[jz] = (int) z;
            }
        }
        // the fraction's pieces as doubles, then times pi/2
        double fw = scalbn(1.0, q0);
        for (int i = jz; i >= 0; i--) {
            q[i] = fw * iq[i];
            fw *= TWON24;
        }
        for (int i = jz; i >= 0; i--) {
            fw = 0.0;
            for (int k = 0; k <= jp && k <= jz - i; k++) {
                fw += PIO2[k] * q[i + k];
            }
            fq[jz - i] = fw;
        }
        // compress fq[] into y[0] + y[1]
        fw = 0.0;
        for (int i = jz; i >= 0; i--) {
            fw += fq[i];
        }
        y[0] = ih == 0 ? fw : -fw;
        fw = fq[0] - fw;
        for (int i = 1; i <= jz; i++) {
            fw += fq[i];
        }
        y[1] = ih == 0 ? fw : -fw;
        return n & 7;
    }

    /** x * 2^n for the small n here (|n| well inside the normal range): exact. */
    private static double scalbn(double x, int n) {
        return x * Double.longBitsToDouble((long) (1023 + n) << 52);
    }

    private static int high(double x) {
        return (int) (Double.doubleToRawLongBits(x) >>> 32);
    }
}
