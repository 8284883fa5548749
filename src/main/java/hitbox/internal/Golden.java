package hitbox.internal;

import java.util.function.DoubleUnaryOperator;

/**
 * Golden-section search, the one home for the curved shapes' searches over an angle
 * ({@link Supports}, {@link ConvexSweep}, {@link CurvedClearance}): the least value of a
 * function that has one least value in [lo, hi], each step shrinking the bracket by 0.618
 * for one new evaluation; and the one step that takes a least found near an axis direction
 * onto the axis ({@link #onAxis}).
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
        return least(f, lo, hi, steps, width, new double[2]);
    }

    /** {@link #least(DoubleUnaryOperator, double, double, int, double)} into {@code out}; returns it. */
    public static double[] least(DoubleUnaryOperator f, double lo, double hi, int steps, double width, double[] out) {
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
        out[0] = f1 < f2 ? m1 : m2;
        out[1] = f1 < f2 ? f1 : f2;
        return out;
    }

    /** How near an axis direction (radians) a searched least is taken to lie on it, if as short ({@link #onAxis}). */
    private static final double AXIS_NEAR = 1e-3;

    /**
     * A least value of a push over the angle, {angle, push} as a golden search found it
     * ({@link Supports}, {@link CurvedClearance}), taken on the nearest axis direction when
     * that lies within 1e-3 radians and pushes as short, to within {@code slack} (the rounding
     * of the push's sums). A least flat to the fourth order (a corner, or a capsule's end, at
     * the centre of curvature of an ellipse's end) is placed by no search closer than about
     * 1e-4 radians, all those directions equally short to a double's resolution; at an
     * unturned ellipse's end it is an axis direction, and taken there, mirror images agree.
     * The push f must be exact at the axis angles (the unit direction snapped to 0 and 1).
     */
    public static double[] onAxis(DoubleUnaryOperator f, double[] least, double slack) {
        return onAxis(f, least, slack, new double[2]);
    }

    /**
     * {@link #onAxis(DoubleUnaryOperator, double[], double)} into {@code out} (which may be
     * {@code least} itself): {axis, push} if taken on the axis, else least's values.
     */
    public static double[] onAxis(DoubleUnaryOperator f, double[] least, double slack, double[] out) {
        double axis = Math.rint(least[0] / (Math.PI / 2)) * (Math.PI / 2);
        double x = least[0], v = least[1];
        if (Math.abs(axis - x) < AXIS_NEAR) {
            double along = f.applyAsDouble(axis);
            if (along <= v + slack) {
                x = axis;
                v = along;
            }
        }
        out[0] = x;
        out[1] = v;
        return out;
    }
}
