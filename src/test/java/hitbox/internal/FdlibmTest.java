package hitbox.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * {@link Fdlibm#sinCos} against the JVM's {@code StrictMath.cos} and {@code sin}, bit for bit:
 * a turning body's pose takes its cosine and sine from it, and every other part of the
 * library from {@code StrictMath}, so the two must never differ. (The browser build's test,
 * {@code JvmMathTest}, holds {@code Fdlibm.sin}, {@code cos} and {@code atan2} to the JVM's.)
 */
class FdlibmTest {

    private static void same(double x, double[] out) {
        Fdlibm.sinCos(x, out);
        assertEquals(Double.doubleToRawLongBits(StrictMath.cos(x)), Double.doubleToRawLongBits(out[0]), "cos(" + x + ")");
        assertEquals(Double.doubleToRawLongBits(StrictMath.sin(x)), Double.doubleToRawLongBits(out[1]), "sin(" + x + ")");
    }

    @Test
    void sinCos_givesStrictMathsBits() {
        double[] out = new double[2];
        for (double x : new double[] {0.0, -0.0, Double.MIN_VALUE, -Double.MIN_VALUE, 1e-300, Math.PI / 4, -Math.PI / 4,
                Math.PI / 2, Math.PI, -Math.PI, 3 * Math.PI / 4, 2 * Math.PI, 1e6, 1e22, -1e300, Double.MAX_VALUE,
                Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
            same(x, out);
        }
        SplittableRandom r = new SplittableRandom(29);
        for (int i = 0; i < 1_000_000; i++) {
            double x = switch (i % 5) {
                case 0 -> (float) ((r.nextDouble() - 0.5) * 4 * Math.PI);  // a body's float angle
                case 1 -> (r.nextDouble() - 0.5) * 2e6;  // medium: a reduction by pi/2 in pieces
                case 2 -> (r.nextInt(64) - 32) * (Math.PI / 2) + (r.nextDouble() - 0.5) * 1e-9;  // near k pi/2
                case 3 -> Math.scalb(r.nextDouble(), r.nextInt(1100) - 60) * (r.nextBoolean() ? 1 : -1);  // huge
                default -> Double.longBitsToDouble(r.nextLong());  // any double
            };
            same(x, out);
        }
    }
}
