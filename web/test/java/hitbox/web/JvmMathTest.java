package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;

import hitbox.internal.Fdlibm;
import java.util.Random;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The browser build's stand-ins (ExactFma, JvmMath, Fdlibm) against the JVM's own methods, bit for bit,
 * on special values and millions of random arguments: here on the JVM, so a difference is the
 * stand-in's; the browser test then shows that the WebAssembly build computes them alike.
 */
class JvmMathTest {
    private static final double[] SPECIAL = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994,
        -0.49999999999999994, 1.0, -1.0, Double.MIN_VALUE, -Double.MIN_VALUE, Double.MIN_NORMAL, Double.MAX_VALUE,
        -Double.MAX_VALUE, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN, 0x1p52, 0x1p52 + 1,
        -0x1p52 - 1, 0x1p53, 0x1p-1022, 0x1p500, 0x1p-500, 3, 7, 1e300, 1e-300, 4503599627370495.5};

    /** Doubles over the whole range, with many near 1 and many with few mantissa bits (ties). */
    private static double any(SplittableRandom r) {
        long bits = r.nextLong();
        switch (r.nextInt(4)) {
            case 0:
                bits = (bits & 0x800FFFFFFFFFFFFFL) | ((long) (1023 - 30 + r.nextInt(60)) << 52);
                break;
            case 1:
                bits &= 0xFFFFFFF000000000L;
                break;
            case 2:
                return SPECIAL[r.nextInt(SPECIAL.length)] * (r.nextBoolean() ? 1 : -1);
            default:
                break;
        }
        return Double.longBitsToDouble(bits);
    }

    private static void same(double jvm, double standIn, String what) {
        if (Double.doubleToLongBits(jvm) != Double.doubleToLongBits(standIn)) {
            assertEquals(Double.toHexString(jvm), Double.toHexString(standIn), what);
        }
    }

    @Test
    void fma_sameBitsAsTheJvm() {
        SplittableRandom r = new SplittableRandom(1);
        for (int i = 0; i < 60_000; i++) {
            double a = any(r), b = any(r);
            double c = r.nextBoolean() ? -(a * b) : any(r);
            same(Math.fma(a, b, c), ExactFma.fma(a, b, c), "fma(" + a + ", " + b + ", " + c + ")");
        }
        for (double a : SPECIAL) {
            for (double b : SPECIAL) {
                for (double c : SPECIAL) {
                    same(Math.fma(a, b, c), ExactFma.fma(a, b, c), "fma(" + a + ", " + b + ", " + c + ")");
                }
            }
        }
    }

    @Test
    void ulpAndAtan2_sameBitsAsTheJvm() {
        SplittableRandom r = new SplittableRandom(7);
        for (int i = 0; i < 1_000_000; i++) {
            double y = any(r), x = r.nextInt(3) == 0 ? any(r) : (r.nextDouble() - 0.5) * 64;
            if (r.nextInt(4) == 0) {
                y = (r.nextDouble() - 0.5) * 64;
            }
            same(Math.ulp(y), JvmMath.ulp(y), "ulp(" + y + ")");
            same(Math.atan2(y, x), Fdlibm.atan2(y, x), "atan2(" + y + ", " + x + ")");
            same(Math.atan2(x, y), Fdlibm.atan2(x, y), "atan2(" + x + ", " + y + ")");
        }
        for (double y : SPECIAL) {
            same(Math.ulp(y), JvmMath.ulp(y), "ulp(" + y + ")");
            for (double x : SPECIAL) {
                same(Math.atan2(y, x), Fdlibm.atan2(y, x), "atan2(" + y + ", " + x + ")");
            }
        }
    }

    @Test
    void scalb_sameBitsAsTheJvm() {
        SplittableRandom r = new SplittableRandom(6);
        for (int i = 0; i < 1_000_000; i++) {
            double d = any(r);
            int n = r.nextInt(4) == 0 ? r.nextInt() : r.nextInt(-2200, 2200);
            same(Math.scalb(d, n), JvmMath.scalb(d, n), "scalb(" + d + ", " + n + ")");
        }
        for (double d : SPECIAL) {
            for (int n : new int[] {0, 1, -1, 511, 512, 513, -511, -512, -513, 1023, 1024, -1074, -1075, 2098, 2099, 2100,
                -2099, -2100, Integer.MAX_VALUE, Integer.MIN_VALUE}) {
                same(Math.scalb(d, n), JvmMath.scalb(d, n), "scalb(" + d + ", " + n + ")");
            }
        }
    }

    @Test
    void sinCos_sameBitsAsStrictMath() {
        SplittableRandom r = new SplittableRandom(5);
        for (int i = 0; i < 1_000_000; i++) {
            double x;
            switch (i % 6) {
                case 0:
                    x = (r.nextDouble() - 0.5) * 16;                       // the library's angles
                    break;
                case 1:
                    x = (float) ((r.nextDouble() - 0.5) * 4000);           // float angles
                    break;
                case 2:
                    x = (r.nextDouble() - 0.5) * 0x1p21;                   // medium: reduced by pi/2 in 33-bit pieces
                    break;
                case 3:
                    // near n * pi/2, where the reduction cancels: a second and third step
                    x = (1 + r.nextInt(1 << 20)) * (Math.PI / 2) + (r.nextInt(9) - 4) * Math.ulp((1 << 20) * Math.PI);
                    break;
                case 4:
                    x = Math.scalb(r.nextDouble() - 0.5, r.nextInt(-60, 1030));   // huge: the long reduction by 2/pi's bits
                    break;
                default:
                    x = any(r);
                    break;
            }
            same(StrictMath.sin(x), Fdlibm.sin(x), "sin(" + x + ")");
            same(StrictMath.cos(x), Fdlibm.cos(x), "cos(" + x + ")");
        }
        for (double x : SPECIAL) {
            for (double y : new double[] {x, -x, x * Math.PI, Math.PI / 2 * x}) {
                same(StrictMath.sin(y), Fdlibm.sin(y), "sin(" + y + ")");
                same(StrictMath.cos(y), Fdlibm.cos(y), "cos(" + y + ")");
            }
        }
    }

    @Test
    void hypot_sameBitsAsTheJvm() {
        SplittableRandom r = new SplittableRandom(2);
        for (int i = 0; i < 1_000_000; i++) {
            double a = any(r), b = r.nextInt(4) == 0 ? any(r) : a * (r.nextDouble() * 4);
            same(Math.hypot(a, b), JvmMath.hypot(a, b), "hypot(" + a + ", " + b + ")");
        }
        for (double a : SPECIAL) {
            for (double b : SPECIAL) {
                same(Math.hypot(a, b), JvmMath.hypot(a, b), "hypot(" + a + ", " + b + ")");
            }
        }
    }

    @Test
    void roundingAndRemainders_sameAsTheJvm() {
        SplittableRandom r = new SplittableRandom(3);
        for (int i = 0; i < 150_000; i++) {
            double a = i < SPECIAL.length ? SPECIAL[i] : any(r);
            double b = any(r);
            float f = (float) a;
            assertEquals(Math.round(f), JvmMath.round(f), "round(" + f + "f)");
            assertEquals(Math.round(a), JvmMath.round(a), "round(" + a + ")");
            same(Math.rint(a), JvmMath.rint(a), "rint(" + a + ")");
            same(Math.toRadians(a), JvmMath.toRadians(a), "toRadians(" + a + ")");
            same(Math.IEEEremainder(a, b), JvmMath.IEEEremainder(a, b), "IEEEremainder(" + a + ", " + b + ")");
            double small = (r.nextInt(2001) - 1000) / 4.0;
            same(Math.rint(small), JvmMath.rint(small), "rint(" + small + ")");
            assertEquals(Math.round(small), JvmMath.round(small), "round(" + small + ")");
            assertEquals(Math.round((float) small), JvmMath.round((float) small), "round(" + small + "f)");
        }
        for (float f = -3; f <= 3; f = Math.nextUp(f + Math.abs(f) * 0.0001f + 0.0001f)) {
            assertEquals(Math.round(f), JvmMath.round(f), "round(" + f + "f)");
        }
    }

    @Test
    void nextInt_sameDrawsAsJavaUtilRandom() {
        SplittableRandom r = new SplittableRandom(4);
        for (int i = 0; i < 2000; i++) {
            long seed = r.nextLong();
            Random jdk = new Random(seed);
            Random ours = new Random(seed);
            for (int k = 0; k < 200; k++) {
                int bound = r.nextInt(3) == 0 ? 1 << r.nextInt(31) : 1 + r.nextInt(Integer.MAX_VALUE);
                assertEquals(jdk.nextInt(bound), JvmMath.nextInt(ours, bound), "seed " + seed + " bound " + bound);
            }
        }
    }
}
