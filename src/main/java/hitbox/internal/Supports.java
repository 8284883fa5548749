package hitbox.internal;

import hitbox.*;

/**
 * Contacts for the curved shapes ({@link Ellipse}, {@link Capsule}) against any convex shape
 * with area, by support functions. For convex A and B the shortest push that separates them
 * is, over all unit directions n, the least of {@code h_A(n) + h_B(-n)} (h the support
 * function: how far the shape reaches along n): the Minkowski difference's distance from the
 * origin to its outline, the quantity EPA converges to. Here it is minimised over the angle
 * of n directly: every edge normal of a rectangle, polygon or capsule (where a flat side
 * makes the least exact), the four axis directions, and 72 directions whose local least
 * values are refined by golden-section search (one near an axis and as short taken on it).
 * The depth is found to about 1e-12 of the shapes' size; a normal, where the least is
 * flat, to about 1e-6 radians. All candidates are gathered, then chosen among at one place
 * by the tie rule of {@link Contact}, those within {@link Tolerance#SUPPORT_TIE} of the least
 * tying.
 *
 * <p>Reference: G. van den Bergen, <i>Collision Detection in Interactive 3D Environments</i>
 * (2004), 4.3 (penetration depth as the Minkowski difference's distance to its boundary).
 */
public final class Supports {
    private Supports() {
    }

    private static final int STEPS = 72;

    /**
     * How far the shape reaches along (nx, ny): the largest dot product of its points with it
     * (for a concave polygon, of its outline's, as for its convex hull).
     */
    public static double support(Shape s, double nx, double ny) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> TurnedEllipses.support((Ellipse) s, nx, ny);
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.max(k.x1() * nx + k.y1() * ny, k.x2() * nx + k.y2() * ny) + k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield c.x() * nx + c.y() * ny + c.r();
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.max(g.x1() * nx + g.y1() * ny, g.x2() * nx + g.y2() * ny);
            }
            case RECT -> rectReach((Rect) s, nx, ny);
            case POLYGON -> reach(HiddenParts.corners((Polygon) s), nx, ny); // cached, only read
        };
    }

    /** The largest dot product of the vertices with (nx, ny). */
    private static double reach(double[] xy, double nx, double ny) {
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < xy.length; i += 2) {
            best = Math.max(best, xy[i] * nx + xy[i + 1] * ny);
        }
        return best;
    }

    /**
     * {@link #reach} of the rectangle's corners ({@link Polygons#corners(Rect, double[])}'s,
     * in its order), without making them: the same products, maxima and order, so the same
     * value to the last bit.
     */
    private static double rectReach(Rect r, double nx, double ny) {
        double x = r.x(), y = r.y(), right = x + r.w(), bottom = y + r.h();
        double best = Math.max(Double.NEGATIVE_INFINITY, x * nx + y * ny);
        best = Math.max(best, right * nx + y * ny);
        best = Math.max(best, right * nx + bottom * ny);
        return Math.max(best, x * nx + bottom * ny);
    }

    /**
     * The straight edges whose normals the search tries, as a closed outline of vertices:
     * a rectangle's or polygon's corners, a capsule's segment (its two sides), none for a
     * round shape; a segment, as a capsule's.
     */
    public static double[] straightEdges(Shape s) {
        return straightEdges(s, new double[4], new double[8]).clone();
    }

    /** No straight edges. */
    private static final double[] NONE = {};

    /**
     * {@link #straightEdges(Shape)} written into {@code ends} (a capsule's or segment's) or
     * {@code corners} (a rectangle's), or a polygon's cached corners; only read.
     */
    private static double[] straightEdges(Shape s, double[] ends, double[] corners) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE, CIRCLE -> NONE;
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield ends(ends, k.x1(), k.y1(), k.x2(), k.y2());
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield ends(ends, g.x1(), g.y1(), g.x2(), g.y2());
            }
            case RECT -> Polygons.corners((Rect) s, corners);
            case POLYGON -> HiddenParts.corners((Polygon) s);
        };
    }

    private static double[] ends(double[] e, double x1, double y1, double x2, double y2) {
        e[0] = x1;
        e[1] = y1;
        e[2] = x2;
        e[3] = y2;
        return e;
    }

    /**
     * The push for direction angle t, how far b must move along (cos t, sin t) to clear a, as
     * the function a golden search asks: one per thread, set to a pair for a search (a
     * lambda taking the pair along was made per search).
     */
    private static final class Push implements java.util.function.DoubleUnaryOperator {
        private Shape a, b;
        private final double[] n = new double[2];

        Push of(Shape a, Shape b) {
            this.a = a;
            this.b = b;
            return this;
        }

        @Override
        public double applyAsDouble(double t) {
            unit(t, n);
            return support(a, n[0], n[1]) + support(b, -n[0], -n[1]);
        }
    }

    /**
     * The unit direction at angle t into {@code out}, exact where it is an axis direction: cos
     * and sin of such an angle round to about 6e-17, not 0, and the exact axis keeps a box's
     * support exact.
     */
    private static double[] unit(double t, double[] out) {
        double nx = StrictMath.cos(t), ny = StrictMath.sin(t);
        if (Math.abs(nx) < Tolerance.AXIS_SNAP) {
            out[0] = 0;
            out[1] = Math.signum(ny);
        } else if (Math.abs(ny) < Tolerance.AXIS_SNAP) {
            out[0] = Math.signum(nx);
            out[1] = 0;
        } else {
            out[0] = nx;
            out[1] = ny;
        }
        return out;
    }

    /** The four axis directions, exact. */
    private static final double[][] AXES = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};

    /**
     * A thread's working objects for {@link #contact}: the candidates, the samples, a
     * direction, a search's answer, the search's function, and the straight edges' ends.
     */
    private static final class Scratch {
        double[] found = new double[3 * 96];
        final double[] f = new double[STEPS], u = new double[2], least = new double[2];
        final double[] ends = new double[4], corners = new double[8];
        final Push push = new Push();
    }

    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    /**
     * The contact of two overlapping convex shapes, normal from a to b. Every candidate
     * direction is gathered first and only then chosen among, at this one place: those
     * within the tie slack of the least push (see {@link Tolerance#SUPPORT_TIE}) all tie, and
     * the rule of {@link Contact} ({@link Contacts.Shortest}) picks among them, so the pick
     * does not depend on the order they were found in (a chain of candidates, each within
     * the slack of the one before, can no longer lead away from the least), and a pair's
     * mirror image, whose candidates are the mirrored ones, picks the mirrored direction.
     */
    public static Contact contact(Shape a, Shape b) {
        Scratch sc = SCRATCH.get();
        double[] found = sc.found, u = sc.u;
        int n = 0;
        // The straight edges' normals first, exact where the least is flat. A cone of equally
        // short directions (a circle or a capsule's end centred on a corner) has such normals
        // for its ends: for convex shapes it is a corner of the one shape taken off the
        // other's segment or point, whose sides are straight edges of the two.
        for (int k = 0; k < 2; k++) {
            double[] xy = straightEdges(k == 0 ? a : b, sc.ends, sc.corners);
            int corners = xy.length / 2;
            for (int i = 0; i < corners; i++) {
                int j = (i + 1) % corners;
                double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
                if (ex != 0 || ey != 0) {
                    found = candidate(found, n++, a, b, unit(Math.atan2(ex, -ey), u));
                    found = candidate(found, n++, a, b, unit(Math.atan2(-ex, ey), u));
                }
            }
        }
        // Then the four axis directions, exact: the rule's pick from a cone of equally short
        // directions can be an axis inside it.
        for (double[] axis : AXES) {
            found = candidate(found, n++, a, b, axis);
        }
        // Then each local least of 72 samples, refined by golden-section search. Where the
        // least is flat to the fourth order (an ellipse's end with a capsule's end at its
        // centre of curvature) the search stops anywhere within about 1e-4 radians, all
        // equally short to a double's resolution; one that near an axis, and as short there
        // to the support sums' rounding, is taken on the axis (Golden.onAxis).
        double size = size(a, b);
        double[] f = sc.f;
        Push push = sc.push.of(a, b);
        for (int i = 0; i < STEPS; i++) {
            f[i] = push.applyAsDouble(2 * Math.PI * i / STEPS);
        }
        for (int i = 0; i < STEPS; i++) {
            double prev = f[(i + STEPS - 1) % STEPS], next = f[(i + 1) % STEPS];
            if (f[i] <= prev && f[i] <= next) {
                double[] least = Golden.least(push, 2 * Math.PI * (i - 1) / STEPS,
                        2 * Math.PI * (i + 1) / STEPS, 80, Tolerance.SUPPORT_ANGLE, sc.least);
                Golden.onAxis(push, least, Tolerance.SUPPORT_SUM_ROUNDING * size, least);
                found = candidate(found, n++, a, b, unit(least[0], u));
            }
        }
        sc.found = found;
        // The one place a direction is chosen: everything within the slack of the least.
        double least = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            least = Math.min(least, found[3 * i + 2]);
        }
        double slack = Tolerance.SUPPORT_TIE * size;
        // The rule of Contacts.Shortest on locals: a Shortest made here was not always
        // scalar-replaced once the shapes' calls became one switch each (issue 30), and a
        // manifold with a capsule then made 40 bytes a call (NarrowAllocationTest).
        double bx = 0, by = 0, best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            double nx = found[3 * i], ny = found[3 * i + 1], depth = found[3 * i + 2];
            if (depth <= least + slack && Contacts.Shortest.beats(nx, ny, depth, bx, by, best, slack, false)) {
                bx = nx;
                by = ny;
                best = depth;
            }
        }
        return best != Double.POSITIVE_INFINITY ? Contacts.of(bx, by, best) : null;
    }

    /** Stores direction u and its push as candidate i of found (grown if full); returns found. */
    private static double[] candidate(double[] found, int i, Shape a, Shape b, double[] u) {
        if (3 * i + 3 > found.length) {
            found = java.util.Arrays.copyOf(found, 2 * found.length);
        }
        found[3 * i] = u[0];
        found[3 * i + 1] = u[1];
        found[3 * i + 2] = support(a, u[0], u[1]) + support(b, -u[0], -u[1]);
        return found;
    }

    /**
     * The scene's size for the tie slack: the largest coordinate of either shape's box (at
     * least 1). The float inputs are rounded to about 6e-8 of their coordinates, so pushes
     * meant to be equal (the edge normals of a regular polygon placed by cos and sin) differ
     * by that much of the coordinates, not of the shapes' own size.
     */
    private static double size(Shape a, Shape b) {
        double most = 1;
        for (int k = 0; k < 2; k++) {
            Shape s = k == 0 ? a : b;
            most = Math.max(most, Extents.reach(s));
        }
        return most;
    }
}
