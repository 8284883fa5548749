package hitbox.internal;

import java.util.function.DoubleUnaryOperator;

/**
 * Golden-section search, the one home for the curved shapes' searches over an angle
 * ({@link Supports}, {@link ConvexSweep}, {@link CurvedClearance}): the least value of a
 * function that has one least value in [lo, hi], each step shrinking the bracket by 0.618
 * for one new evaluation.
 */
public final class Golden {
    private Golden() {
    }

    private static final double G = (Math.sqrt(5) - 1) / 2;

    /**
     * Where in [lo, hi] f is least, after at most {@code steps} steps or once the bracket is
     * narrower than {@code width}: {argument, value} of the better of the last two points.
     */
    public static double[] least(DoubleUnaryOperator f, double lo, double hi, int steps, double width) {
        double m1 = hi - G * (hi - lo), m2 = lo + G * (hi - lo);
        double f1 = f.applyAsDouble(m1), f2 = f.applyAsDouble(m2);
        for (int i = 0; i < steps && hi - lo > width; i++) {
            if (f1 < f2) {
                hi = m2;
                m2 = m1;
                f2 = f1;
                m1 = hi - G * (hi - lo);
                f1 = f.applyAsDouble(m1);
            } else {
                lo = m1;
                m1 = m2;
                f1 = f2;
                m2 = lo + G * (hi - lo);
                f2 = f.applyAsDouble(m2);
            }
        }
        return f1 < f2 ? new double[] {m1, f1} : new double[] {m2, f2};
    }
}
