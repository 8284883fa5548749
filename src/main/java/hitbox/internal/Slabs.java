package hitbox.internal;

/**
 * The slab maths that {@link Sweep} and {@link Ray} share: a point moving along
 * {@code t * v} through open intervals {@code lo < t * v < hi}, one per axis, and the time it
 * is inside all of them (Cyrus-Beck clipping). A moving box against a standing box is two
 * slabs (the Minkowski difference of two boxes is a box), a box against a segment three, and
 * a ray against a box is the same two slabs with the ray's direction as {@code v}.
 *
 * <p>Everything is in {@code double}, and every decision compares sums of floats, which are
 * exact in double: for whole-number coordinates, hit or miss and which face are exact.
 *
 * <p>Reference: C. Ericson, <i>Real-Time Collision Detection</i> (2005), 5.3.3
 * (intersecting a ray against a box by slabs); M. Cyrus, J. Beck, "Generalized two- and
 * three-dimensional clipping", 1978.
 */
public final class Slabs {
    private Slabs() {
    }

    /** "Never": the time or distance of no hit. */
    public static final double INF = Double.POSITIVE_INFINITY;

    /**
     * When does {@code t * v} enter the open interval (lo, hi)? -infinity if it is always
     * inside ({@code v = 0}), +infinity if never, NaN for NaN input.
     */
    public static double enter(double lo, double hi, double v) {
        if (v > 0) {
            return lo / v;
        }
        if (v < 0) {
            return hi / v;
        }
        if (v == 0) {
            return lo < 0 && 0 < hi ? Double.NEGATIVE_INFINITY : INF;
        }
        return Double.NaN;
    }

    /** When does {@code t * v} leave the open interval (lo, hi)? See {@link #enter}. */
    public static double exit(double lo, double hi, double v) {
        if (v > 0) {
            return hi / v;
        }
        if (v < 0) {
            return lo / v;
        }
        if (v == 0) {
            return lo < 0 && 0 < hi ? INF : Double.NEGATIVE_INFINITY;
        }
        return Double.NaN;
    }

    /**
     * The start of the open time interval (enter, exit) clipped to [0, limit): the time of
     * impact, or +infinity if the interval is empty, over before 0, or starts at the limit
     * or later (NaN gives +infinity).
     */
    public static double firstTime(double enter, double exit, double limit) {
        return enter < exit && exit > 0 && enter < limit ? Math.max(enter, 0) : INF;
    }

    /**
     * The first time in [0, limit) that {@code t * (vx, vy)} is inside the open box
     * (loX, hiX) x (loY, hiY), or +infinity: the time-only box test, allocating nothing. Same
     * answer as {@link #box}'s clip.
     */
    public static double boxTime(double loX, double hiX, double loY, double hiY, double vx, double vy, double limit) {
        double enter = Math.max(enter(loX, hiX, vx), enter(loY, hiY, vy));
        double exit = Math.min(exit(loX, hiX, vx), exit(loY, hiY, vy));
        return firstTime(enter, exit, limit);
    }

    /**
     * The box (loX, hiX) x (loY, hiY) as a clip, y first: entering both axes at the same
     * moment (a corner, exactly) counts as entering through a top or bottom face, so a
     * player landing exactly on a platform's corner lands.
     */
    public static Clip box(double loX, double hiX, double loY, double hiY, double vx, double vy) {
        return box(new Clip(), loX, hiX, loY, hiY, vx, vy);
    }

    /** {@link #box(double, double, double, double, double, double)} into an empty clip. */
    public static Clip box(Clip into, double loX, double hiX, double loY, double hiY, double vx, double vy) {
        return into.slab(loY, hiY, vy, 0, 1).slab(loX, hiX, vx, 1, 0);
    }

    /**
     * A point moving through the intersection of open slabs {@code lo < t * v < hi}: the time
     * it is inside all of them, and the outward normal of the face entered last.
     */
    public static final class Clip {
        public double enter = Double.NEGATIVE_INFINITY;
        public double exit = INF;
        public double nx;
        public double ny;

        /**
         * Adds the slab {@code lo < t * v < hi} across the unit axis (ax, ay). Entering it
         * from below means coming in against the axis, so the face's outward normal is -axis.
         */
        public Clip slab(double lo, double hi, double v, double ax, double ay) {
            double in = enter(lo, hi, v);
            double out = exit(lo, hi, v);
            if (in > enter || Double.isNaN(in)) {
                enter = in;
                nx = v > 0 ? -ax : ax;
                ny = v > 0 ? -ay : ay;
            }
            if (out < exit || Double.isNaN(out)) {
                exit = out;
            }
            return this;
        }

        /** Empties the clip of slabs (inside all of none, at every time), to be used again. */
        public Clip reset() {
            enter = Double.NEGATIVE_INFINITY;
            exit = INF;
            nx = 0;
            ny = 0;
            return this;
        }

        /** Is the point inside every slab at t = 0? */
        public boolean insideAtStart() {
            return enter < 0 && exit > 0;
        }

        /** The first time in [0, limit) inside every slab, or +infinity. */
        public double firstTime(double limit) {
            return Slabs.firstTime(enter, exit, limit);
        }
    }
}
