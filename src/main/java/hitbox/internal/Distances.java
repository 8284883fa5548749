package hitbox.internal;

import hitbox.*;

/**
 * The distance between two shapes that do not overlap, and the closest points: the kernel
 * behind {@link Separation}.
 *
 * <p>When two shapes do not overlap (by the touching rule, decided exactly by
 * {@link Overlaps}), neither reaches into the other's inside, so the distance between them
 * is the distance between their outlines (for a segment, the segment itself; for a shape of
 * size 0, what is left of it). Every shape is reduced to its <em>core</em> and a radius: a
 * circle is its centre and r, a capsule its segment and r, an ellipse with equal radii a
 * circle and a flat one its segment, a rectangle or polygon its closed outline (convex or
 * concave alike), a segment itself; only an ellipse with two different radii stays curved.
 * The distance is the cores' distance less the two radii (held at 0), and each closest point
 * is its core's closest point moved by its radius towards the other. So every ordered pair of
 * the six kinds is answered by one of three kernels, each written once (two convex outlines
 * round an area, by a faster form of the first):
 *
 * <table>
 *   <caption>Which kernel answers each pair</caption>
 *   <tr><th></th><th>Circle, Capsule, Rect, Segment, Polygon; a flat or round Ellipse</th><th>an Ellipse</th></tr>
 *   <tr><th>Circle, Capsule, Rect, Segment, Polygon; a flat or round Ellipse</th><td>{@link #chains}</td><td>{@link #ellipseChain}</td></tr>
 *   <tr><th>an Ellipse</th><td>{@link #ellipseChain}, swapped</td><td>{@link #ellipses}</td></tr>
 * </table>
 *
 * <p><b>Straight cores</b> ({@link #chains}): the least distance over every pair of edges
 * (for a convex outline, only over the pairs that can hold the closest points: {@link #facing}),
 * each pair closest-point by exact orientation signs ({@link Lines#segmentsMeet}: edges that
 * meet are 0 apart), else the least of the four end-to-edge distances, worked in double from
 * differences of the floats. For whole-number coordinates of modest size this is exact
 * wherever the distance is a rational number that a float holds: an axis-aligned gap (the
 * cross product over the edge's length, both exact), a corner-to-corner distance that is a
 * whole number (a square root of an exact sum of squares is correctly rounded). Two convex
 * outlines round an area (rectangles, convex polygons) go by {@link ConvexOutlines}, which
 * walks their difference to find the pair of edges that holds the closest points, in time in
 * proportion to their corners, then measures that pair the same way. A circle and a convex
 * outline round an area go by {@link #pointAndOutline}, which measures only the edges nearest
 * the centre, as the loop over the pairs would, and settles most pairs apart without asking
 * {@link Overlaps}. Where several pairs of points are equally close, the one given has the
 * first midpoint ({@code closer}), in every kernel of straight cores.
 *
 * <p><b>Ellipses</b> ({@link #ellipseChain}, {@link #ellipses}): the distance from a point to
 * the ellipse is Eberly's ({@link Ellipses#distance}, to double precision). Along an edge the
 * distance to the ellipse is a convex function, whose least is found by bisection on the
 * sign of its slope; around a second ellipse's outline it may have several local least
 * values, so {@value #ELLIPSE_SAMPLES} points are sampled and each local least is refined the
 * same way. The distance is then right to about {@link Tolerance#SEPARATION_CURVED} of the
 * shapes' size (the searches stop at a double's resolution of the slope; see there).
 *
 * <p>A separation makes nothing but its answer: the cores, the closest points and what the
 * kernels work in are a thread's {@code Scratch}, fetched once per call.
 *
 * <p>This class is longer than most (about 925 lines): the three kernels, the pruning that
 * keeps two polygons and a circle with a polygon fast (the facing marks of convex outlines, the sorted loops of many
 * sides), the scratch they work in, and their small helpers, kept in one place.
 */
public final class Distances {
    private Distances() {
    }

    /**
     * The relative rounding of an edge's reach along the direction between the chains' boxes
     * (two products and a sum in double, of coordinates up to the largest seen): a few units
     * of 2^-53 of it, with room to spare. {@code chains} stops its sorted loops only when the
     * gap along that direction beats the best distance by more than this.
     */
    static final double PROJECTION_ROUNDING = 1e-12;

    /** How many points of a second ellipse's outline are sampled before refining (see the class doc). */
    static final int ELLIPSE_SAMPLES = 128;

    /** Steps of the slope bisections: more than a double's 53 bits of a parameter. */
    private static final int BISECTIONS = 100;

    /**
     * A shape's core: a chain of straight edges (one vertex for a point, two for a segment,
     * a closed outline for a rectangle or polygon) or an ellipse with two different radii,
     * and the radius around it. Mutable, so that a thread's {@link Scratch} keeps two and
     * {@link #between} makes none: {@link #core} sets one to a shape's, its vertices in the
     * core's own arrays (a polygon's are its cached corners, only read).
     */
    public static final class Core {
        /** The chain's vertices, x0, y0, x1, y1, ...; null for an ellipse (only read). */
        private double[] xy;
        /** Does the chain close back to its first vertex (an outline)? */
        private boolean closed;
        /** The ellipse, or null for a chain. */
        private Ellipse ellipse;
        /** The radius around the core, 0 or more. */
        private double r;
        /**
         * A closed outline's winding (+1 or -1) when it is convex, else 0: a convex outline's
         * edges that face away from the other shape are skipped ({@link #facing}).
         */
        private int winding;
        /**
         * Is it a convex outline round an area (not a flat rectangle)? Two such that do not
         * overlap share no inside point, which {@link ConvexOutlines} takes as given; a flat
         * one can cross another's outline without overlapping it.
         */
        private boolean solid;
        /** The arrays this core's own vertices are written into: a point's, two ends', four corners. */
        private final double[] point = new double[2], ends = new double[4], corners = new double[8];

        /**
         * A core of the given parts.
         *
         * @param xy      the chain's vertices, x0, y0, x1, y1, ...; null for an ellipse (only read)
         * @param closed  does the chain close back to its first vertex (an outline)?
         * @param ellipse the ellipse, or null for a chain
         * @param r       the radius around the core, 0 or more
         */
        public Core(double[] xy, boolean closed, Ellipse ellipse, double r) {
            set(xy, closed, ellipse, r);
        }

        private Core set(double[] xy, boolean closed, Ellipse ellipse, double r) {
            this.xy = xy;
            this.closed = closed;
            this.ellipse = ellipse;
            this.r = r;
            this.winding = 0;
            this.solid = false;
            return this;
        }

        /**
         * This core, a closed outline, marked convex with the given winding (+1 or -1; 0: not
         * known convex), and whether it is round an area.
         */
        private Core convex(int winding, boolean solid) {
            this.winding = winding;
            this.solid = solid && winding != 0;
            return this;
        }

        private Core point(double x, double y, double r) {
            point[0] = x;
            point[1] = y;
            return set(point, false, null, r);
        }

        private Core ends(double x1, double y1, double x2, double y2, double r) {
            ends[0] = x1;
            ends[1] = y1;
            ends[2] = x2;
            ends[3] = y2;
            return set(ends, false, null, r);
        }

        /** @return the chain's vertices; null for an ellipse */
        public double[] xy() {
            return xy;
        }

        /** @return does the chain close back to its first vertex? */
        public boolean closed() {
            return closed;
        }

        /** @return the ellipse, or null for a chain */
        public Ellipse ellipse() {
            return ellipse;
        }

        /** @return the radius around the core */
        public double r() {
            return r;
        }

        /** @return is the core a single point (a circle's centre)? */
        private boolean isPoint() {
            return xy != null && xy.length == 2;
        }
    }

    /**
     * A thread's working arrays, so that a separation makes nothing but its answer: the two
     * cores, the closest points, and what the kernels below write into as they go. Fetched
     * once per {@link #between} or {@link #apart} and handed down; no kernel here calls
     * another that fetches it again.
     */
    private static final class Scratch {
        final Core a = new Core(null, false, null, 0), b = new Core(null, false, null, 0);
        /** The closest points, and a candidate pair of them. */
        final double[] q = new double[4], t = new double[4];
        /** A segment's foot, an ellipse's nearest point, an outline point with its tangent. */
        final double[] feet = new double[2], near = new double[2], p = new double[4];
        /** The sampled distances around a second ellipse. */
        final double[] g = new double[ELLIPSE_SAMPLES];
        /** The sorted chains' boxes, reaches and orders, grown to the largest chains seen. */
        final double[] boxA = new double[4], boxB = new double[4];
        double[] hiA = new double[0], loB = new double[0];
        int[] oa = new int[0], ob = new int[0], merge = new int[0];
        /** Which vertices of the other shape each edge of a convex outline faces ({@link #facing}), grown to the largest seen. */
        long[] frontA = new long[8], frontB = new long[8];
        /** An outline's edges' squared distances from a point ({@code pointAndOutline}), grown to the largest seen. */
        double[] edgeD2 = new double[8];
        /** Did the last {@code pointAndOutline} find its two shapes surely apart? */
        boolean surelyApart;
        /** What {@link ConvexOutlines} works in. */
        final ConvexOutlines.Work convex = new ConvexOutlines.Work();
    }

    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    /** The shape's core, written into {@code c}: the one switch over the kinds here. */
    private static Core core(Shape s, Core c) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> ellipseCore((Ellipse) s, c);
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield c.ends(k.x1(), k.y1(), k.x2(), k.y2(), k.r());
            }
            case CIRCLE -> {
                Circle o = (Circle) s;
                yield c.point(o.x(), o.y(), o.r());
            }
            // A rectangle's corners go top-left, top-right, bottom-right, bottom-left: winding +1
            // (a flat one either way: its two long edges face both ways).
            case RECT -> {
                Rect r = (Rect) s;
                yield c.set(Polygons.corners(r, c.corners), true, null, 0).convex(1, r.w() > 0 && r.h() > 0);
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield c.ends(g.x1(), g.y1(), g.x2(), g.y2(), 0);
            }
            case POLYGON -> c.set(HiddenParts.corners((Polygon) s), true, null, 0) // cached, only read
                    .convex(HiddenParts.convexWinding((Polygon) s), true);
        };
    }

    /**
     * An ellipse's core: a circle's (its centre and radius) when its radii are equal, its
     * segment when it is flat (as {@link TurnedEllipses#flatSegment} when turned, as the
     * overlap test reads it), else the ellipse itself.
     */
    private static Core ellipseCore(Ellipse e, Core c) {
        if (e.rx() == e.ry()) {
            return c.point(e.x(), e.y(), e.rx());
        }
        if (e.rx() == 0 || e.ry() == 0) {
            if (e.angle() == 0) {
                return c.ends((double) e.x() - e.rx(), (double) e.y() - e.ry(),
                        (double) e.x() + e.rx(), (double) e.y() + e.ry(), 0);
            }
            TurnedEllipses.flatEnds(e, c.ends);
            return c.set(c.ends, false, null, 0);
        }
        return c.set(null, false, e, 0);
    }

    /**
     * The separation of two shapes, or null when they overlap.
     *
     * @param a the first shape, not null
     * @param b the second shape, not null
     * @return the separation, points on a then b, or null when they overlap
     */
    public static Separation between(Shape a, Shape b) {
        Scratch s = SCRATCH.get();
        double[] q = s.q;
        Core ca = core(a, s.a), cb = core(b, s.b);
        double gap;
        if (ca.solid && cb.isPoint() || cb.solid && ca.isPoint()) {
            double d = pointAndOutline(ca, cb, q, s);
            if (!s.surelyApart) {
                if (Overlaps.test(a, b)) {
                    return null;
                }
                if (d == Double.POSITIVE_INFINITY) {
                    d = cores(ca, cb, q, s);  // not reached: a point surely inside overlaps
                }
            }
            gap = withRadii(d, ca.r, cb.r, q);
        } else {
            if (Overlaps.test(a, b)) {
                return null;
            }
            gap = apart(ca, cb, q, s);
        }
        return new Separation(Check.held(gap), Check.held(q[0]), Check.held(q[1]), Check.held(q[2]), Check.held(q[3]));
    }

    /**
     * The distance between a point core (a circle's centre) and a convex outline round an
     * area (a polygon's, a rectangle's), either first, without their radii, and the closest
     * points in q, as {@link #cores} gives them when the two do not overlap; and into
     * {@code s.surelyApart}, whether the shapes with their radii are surely apart. One pass
     * over the outline's edges finds each one's squared distance from the point, leaving out
     * those the point is surely behind; the edges within rounding of the nearest are then
     * measured as {@link #chains} measures them (the same {@link #segments} and
     * {@link #closer}: the edges left out cannot be closer). Surely apart: the point lies
     * strictly outside one of the outline's edge lines (an exact sign: then it is outside
     * the outline) and the distance beats the radii by more than its rounding. That settles
     * most pairs without the overlap test, which would look at every edge again (a third of
     * the call's time, issue 29's narrow table, "separation, circle vs convex 8-gon"); the
     * rest are asked of it. Infinite when the point is surely inside.
     */
    private static double pointAndOutline(Core ca, Core cb, double[] q, Scratch s) {
        boolean pointFirst = ca.isPoint();
        Core outline = pointFirst ? cb : ca, point = pointFirst ? ca : cb;
        double[] o = outline.xy, d2 = s.edgeD2.length >= o.length / 2 ? s.edgeD2 : (s.edgeD2 = new double[o.length / 2]);
        double px = point.xy[0], py = point.xy[1];
        int n = o.length / 2;
        // Each edge's squared distance from the point, without its foot or a square root;
        // an edge the point is surely behind cannot hold the closest point of a point outside
        // (a corner it shares is its neighbour's too), and counts as infinitely far.
        double least = Double.POSITIVE_INFINITY, size = Math.max(Math.abs(px), Math.abs(py));
        int w = outline.winding;
        for (int i = 0; i < n; i++) {
            int i2 = i + 1 == n ? 0 : i + 1;
            double x1 = o[2 * i], y1 = o[2 * i + 1];
            size = Math.max(size, Math.max(Math.abs(x1), Math.abs(y1)));
            double ex = o[2 * i2] - x1, ey = o[2 * i2 + 1] - y1, fx = px - x1, fy = py - y1;
            double ta = fx * ey, tb = fy * ex, cross = ta - tb;
            if (w * cross < -Tolerance.ORIENTATION_ROUNDING * (Math.abs(ta) + Math.abs(tb))) {
                d2[i] = Double.POSITIVE_INFINITY;
                continue;
            }
            double len2 = ex * ex + ey * ey, dot = fx * ex + fy * ey, e2;
            if (dot <= 0) {
                e2 = fx * fx + fy * fy;
            } else if (dot >= len2) {
                double gx = fx - ex, gy = fy - ey;
                e2 = gx * gx + gy * gy;
            } else {
                e2 = cross * cross / len2;
            }
            d2[i] = e2;
            least = Math.min(least, e2);
        }
        s.surelyApart = false;
        if (least == Double.POSITIVE_INFINITY) {
            return least;  // surely inside
        }
        // The edges within rounding of the nearest, measured as chains measures them.
        double reach = point.r + outline.r, slack = PROJECTION_ROUNDING * (size + reach);
        double within = Math.sqrt(least) + slack;
        within *= within;
        double best = Double.POSITIVE_INFINITY;
        int bestEdge = -1;
        double[] t = s.t, feet = s.feet;
        for (int i = 0; i < n; i++) {
            if (d2[i] > within) {
                continue;
            }
            int i2 = i + 1 == n ? 0 : i + 1;
            double x1 = o[2 * i], y1 = o[2 * i + 1], x2 = o[2 * i2], y2 = o[2 * i2 + 1];
            double d = pointFirst ? segments(px, py, px, py, x1, y1, x2, y2, t, feet)
                    : segments(x1, y1, x2, y2, px, py, px, py, t, feet);
            if (closer(d, best, t[0], t[1], t[2], t[3], q)) {
                best = d;
                bestEdge = i;
                System.arraycopy(t, 0, q, 0, 4);
            }
        }
        if (best - reach > 2 * slack) {
            // Outside the outline: strictly beyond the line of the edge that holds the
            // closest point, or of one of its neighbours (where that point is a corner, the
            // point lies beyond one of the corner's two edges).
            for (int k = -1; k <= 1 && !s.surelyApart; k++) {
                int i = (bestEdge + k + n) % n, i2 = i + 1 == n ? 0 : i + 1;
                s.surelyApart = Lines.orient(o[2 * i], o[2 * i + 1], o[2 * i2], o[2 * i2 + 1], px, py) * w < 0;
            }
        }
        return best;
    }

    /**
     * The distance between two cores with their radii, held at 0, and the closest points
     * (moved out by the radii) in {@code q}: a's x, y, then b's.
     */
    public static double apart(Core a, Core b, double[] q) {
        return apart(a, b, q, SCRATCH.get());
    }

    /** {@link #apart(Core, Core, double[])} with the thread's scratch. */
    private static double apart(Core a, Core b, double[] q, Scratch s) {
        return withRadii(cores(a, b, q, s), a.r(), b.r(), q);
    }

    /**
     * The distance d between two cores less their radii ra and rb, held at 0, and their
     * closest points in q moved out by the radii.
     */
    private static double withRadii(double d, double ra, double rb, double[] q) {
        if (ra == 0 && rb == 0) {
            return d;
        }
        double gap = less(d, ra, rb);
        if (d > 0) {
            double ux = (q[2] - q[0]) / d, uy = (q[3] - q[1]) / d;
            q[0] += ra * ux;
            q[1] += ra * uy;
            q[2] -= rb * ux;
            q[3] -= rb * uy;
        }
        if (gap == 0) {
            // Touching: one point, on both outlines. The one on a core without a radius is
            // exactly on its outline; else a's, moved out by its radius.
            if (rb == 0) {
                q[0] = q[2];
                q[1] = q[3];
            } else {
                q[2] = q[0];
                q[3] = q[1];
            }
            return 0;
        }
        return gap;
    }

    /** The distance d between two cores less their radii, held at 0 (touching or overlapping). */
    private static double less(double d, double ra, double rb) {
        double gap = d - (ra + rb);
        return gap > 0 ? gap : 0;
    }

    /**
     * The distance between two discs (centre and radius; a point has radius 0), held at 0:
     * {@link #apart} for two point cores, without making them, for the raw-float forms. The
     * squares of two floats' differences cannot overflow or vanish in a double, so a plain
     * square root serves; it is correctly rounded, so exact when the distance is a whole
     * number.
     */
    public static double discs(float x1, float y1, float r1, float x2, float y2, float r2) {
        double dx = (double) x2 - x1, dy = (double) y2 - y1;
        return less(Math.sqrt(dx * dx + dy * dy), r1, r2);
    }

    /** The distance between two cores (without their radii), closest points in q. */
    private static double cores(Core a, Core b, double[] q, Scratch s) {
        if (a.ellipse() == null && b.ellipse() == null) {
            if (a.solid && b.solid) {
                return ConvexOutlines.distance(a.xy(), a.winding, b.xy(), b.winding, q, s.t, s.feet, s.convex);
            }
            // Small outlines only: the marks take every edge against every vertex, and a
            // long's bits (beyond, the sorted loops of chains prune as well).
            boolean small = a.xy().length <= 2 * FACING_UP_TO && b.xy().length <= 2 * FACING_UP_TO;
            long[] frontA = a.winding == 0 || !small ? null : (s.frontA = facing(a.xy(), a.winding, b.xy(), s.frontA));
            long[] frontB = b.winding == 0 || !small ? null : (s.frontB = facing(b.xy(), b.winding, a.xy(), s.frontB));
            return chains(a.xy(), a.closed(), frontA, b.xy(), b.closed(), frontB, q, s);
        }
        if (a.ellipse() != null && b.ellipse() != null) {
            return ellipses(a.ellipse(), b.ellipse(), q, s);
        }
        if (a.ellipse() != null) {
            return ellipseChain(a.ellipse(), b.xy(), b.closed(), q, false, s);
        }
        return ellipseChain(b.ellipse(), a.xy(), a.closed(), q, true, s);
    }

    // ---------------------------------------------------------------- straight cores

    /** How many edges a chain of n vertices has: a point counts as one edge of length 0. */
    private static int edges(int n, boolean closed) {
        return n <= 1 ? 1 : closed ? n : n - 1;
    }

    /**
     * Above how many edge pairs {@link #chains} takes them in order of their reach towards
     * each other, which lets it stop early: below, the plain double loop is cheaper.
     */
    private static final int SORT_ABOVE = 64;

    /**
     * The least distance between two chains of straight edges (a point, a segment, or a
     * closed outline), and the closest points in q: a's, then b's. Edge pairs whose boxes
     * are further apart than the best so far are skipped. For many pairs (two polygons of
     * many sides) the edges are taken in order of their reach along the direction from a's
     * box centre to b's: a's from the furthest-reaching, b's from the least, and a loop
     * stops once the gap along that direction (a lower bound of the distance, as a
     * projection) exceeds the best so far, with a slack of {@link #PROJECTION_ROUNDING} of the
     * coordinates over its rounding. The least is the same; only pairs that cannot beat it are skipped.
     */
    private static double chains(double[] a, boolean closedA, long[] frontA, double[] b, boolean closedB, long[] frontB,
                                 double[] q, Scratch s) {
        int na = a.length / 2, nb = b.length / 2;
        int ea = edges(na, closedA), eb = edges(nb, closedB);
        boolean sorted = (long) ea * eb > SORT_ABOVE;
        double[] hiA = null, loB = null;
        int[] oa = null, ob = null;
        double slack = 0;
        if (sorted) {
            double[] ba = box(a, s.boxA), bb = box(b, s.boxB);
            double ux = (bb[0] + bb[2]) / 2 - (ba[0] + ba[2]) / 2, uy = (bb[1] + bb[3]) / 2 - (ba[1] + ba[3]) / 2;
            double len = Math.hypot(ux, uy);
            ux = len > 0 ? ux / len : 1;
            uy = len > 0 ? uy / len : 0;
            if (s.hiA.length < ea) {
                s.hiA = new double[ea];
                s.oa = new int[ea];
            }
            if (s.loB.length < eb) {
                s.loB = new double[eb];
                s.ob = new int[eb];
            }
            if (s.merge.length < Math.max(ea, eb)) {
                s.merge = new int[Math.max(ea, eb)];
            }
            hiA = reach(a, na, ea, ux, uy, true, s.hiA);
            loB = reach(b, nb, eb, ux, uy, false, s.loB);
            oa = order(hiA, ea, true, s.oa, s.merge);
            ob = order(loB, eb, false, s.ob, s.merge);
            for (double v : ba) {
                slack = Math.max(slack, Math.abs(v));
            }
            for (double v : bb) {
                slack = Math.max(slack, Math.abs(v));
            }
            slack *= PROJECTION_ROUNDING;
        }
        double best = Double.POSITIVE_INFINITY;
        double[] t = s.t, feet = s.feet;
        for (int k = 0; k < ea; k++) {
            int i = sorted ? oa[k] : k;
            if (sorted && loB[ob[0]] - hiA[i] > best + slack) {
                break;
            }
            if (frontA != null && frontA[i] == 0) {
                continue;
            }
            int i2 = na <= 1 ? i : (i + 1) % na;
            double ax1 = a[2 * i], ay1 = a[2 * i + 1], ax2 = a[2 * i2], ay2 = a[2 * i2 + 1];
            for (int m = 0; m < eb; m++) {
                int j = sorted ? ob[m] : m;
                if (sorted && loB[j] - hiA[i] > best + slack) {
                    break;
                }
                int j2 = nb <= 1 ? j : (j + 1) % nb;
                if (frontA != null && (frontA[i] >>> j & 1) == 0 && (frontA[i] >>> j2 & 1) == 0
                        || frontB != null && (frontB[j] >>> i & 1) == 0 && (frontB[j] >>> i2 & 1) == 0) {
                    // Neither end of one edge lies in front of the other's line: not the closest pair.
                    continue;
                }
                double bx1 = b[2 * j], by1 = b[2 * j + 1], bx2 = b[2 * j2], by2 = b[2 * j2 + 1];
                double gx = Math.max(0, Math.max(Math.min(bx1, bx2) - Math.max(ax1, ax2), Math.min(ax1, ax2) - Math.max(bx1, bx2)));
                double gy = Math.max(0, Math.max(Math.min(by1, by2) - Math.max(ay1, ay2), Math.min(ay1, ay2) - Math.max(by1, by2)));
                if (gx > best || gy > best) {
                    continue;
                }
                double d = segments(ax1, ay1, ax2, ay2, bx1, by1, bx2, by2, t, feet);
                if (closer(d, best, t[0], t[1], t[2], t[3], q)) {
                    best = d;
                    System.arraycopy(t, 0, q, 0, 4);
                    if (d == 0) {
                        return 0;
                    }
                }
            }
        }
        return best;
    }



    /**
     * For each edge of a closed convex outline {@code xy} (winding w, at most
     * {@value #FACING_UP_TO} vertices), which vertices of the other chain (at most as many)
     * lie in front of the edge's line or on it, as bits, into {@code front} (grown if short;
     * returned); to the rounding of the products, in front when in doubt. An edge of length 0
     * has no normal, and every vertex is in front of it. {@link #chains} skips a pair of
     * edges when neither end of one lies in front of the other's line (an edge with nothing in
     * front, every pair it is in). The closest point p of the outline, towards the other's q, lies on an
     * edge whose outward normal has a positive part along q - p (an edge's own, or at a
     * corner one of the two edges' normals, since their cone holds q - p), so q is in front of
     * that edge's line, and so is an end of q's edge; touching, q is p itself, on both edges.
     * (Only this outline need be convex.) The same holds from the other side when the other
     * is a convex outline too, for the same pair of edges.
     */
    private static long[] facing(double[] xy, int w, double[] other, long[] front) {
        int n = xy.length / 2;
        if (front.length < n) {
            front = new long[n];
        }
        for (int i = 0; i < n; i++) {
            int j = i + 1 == n ? 0 : i + 1;
            double ox = xy[2 * i], oy = xy[2 * i + 1];
            double mx = w * (xy[2 * j + 1] - oy), my = -w * (xy[2 * j] - ox);
            long bits = 0;
            for (int k = 0; k < other.length - 1; k += 2) {
                double tx = (other[k] - ox) * mx, ty = (other[k + 1] - oy) * my;
                // In front (or on the line, to rounding) exactly when this is not negative:
                // its sign bit, so that the loop has no branch to mispredict.
                double ahead = tx + ty + Tolerance.ORIENTATION_ROUNDING * (Math.abs(tx) + Math.abs(ty));
                bits |= (~Double.doubleToRawLongBits(ahead) >>> 63) << (k >> 1);
            }
            front[i] = bits;
        }
        return front;
    }

    /** The most vertices of a convex outline, and of the other shape, for which {@link #facing} marks its edges. */
    private static final int FACING_UP_TO = 64;

    /** The chain's box into r: min x, min y, max x, max y. */
    private static double[] box(double[] xy, double[] r) {
        r[0] = Double.POSITIVE_INFINITY;
        r[1] = Double.POSITIVE_INFINITY;
        r[2] = Double.NEGATIVE_INFINITY;
        r[3] = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < xy.length - 1; i += 2) {
            r[0] = Math.min(r[0], xy[i]);
            r[1] = Math.min(r[1], xy[i + 1]);
            r[2] = Math.max(r[2], xy[i]);
            r[3] = Math.max(r[3], xy[i + 1]);
        }
        return r;
    }

    /** Each edge's reach along (ux, uy) into r: the larger of its ends' if {@code high}, else the smaller. */
    private static double[] reach(double[] xy, int n, int edges, double ux, double uy, boolean high, double[] r) {
        for (int i = 0; i < edges; i++) {
            int i2 = n <= 1 ? i : (i + 1) % n;
            double p = ux * xy[2 * i] + uy * xy[2 * i + 1], p2 = ux * xy[2 * i2] + uy * xy[2 * i2 + 1];
            r[i] = high ? Math.max(p, p2) : Math.min(p, p2);
        }
        return r;
    }

    /**
     * The indices of the first n keys into {@code out}, in descending order of key if
     * {@code descending}, else ascending; equal keys in the order of their indices (a stable
     * merge sort, bottom up, through {@code tmp}: the order a stable sort of the indices gives).
     */
    private static int[] order(double[] keys, int n, boolean descending, int[] out, int[] tmp) {
        for (int i = 0; i < n; i++) {
            out[i] = i;
        }
        int[] from = out, to = tmp;
        for (int width = 1; width < n; width *= 2) {
            for (int lo = 0; lo < n; lo += 2 * width) {
                int mid = Math.min(lo + width, n), hi = Math.min(lo + 2 * width, n);
                int i = lo, j = mid, k = lo;
                while (i < mid && j < hi) {
                    // The left run's first wins ties: stable.
                    to[k++] = after(keys, from[i], from[j], descending) ? from[j++] : from[i++];
                }
                while (i < mid) {
                    to[k++] = from[i++];
                }
                while (j < hi) {
                    to[k++] = from[j++];
                }
            }
            int[] swap = from;
            from = to;
            to = swap;
        }
        if (from != out) {
            System.arraycopy(from, 0, out, 0, n);
        }
        return out;
    }

    /** Does index x's key come strictly after index y's in the order? */
    private static boolean after(double[] keys, int x, int y, boolean descending) {
        return (descending ? Double.compare(keys[y], keys[x]) : Double.compare(keys[x], keys[y])) > 0;
    }

    /**
     * The distance between closed segments AB and CD (either may be a point), closest points
     * in q (on AB, then on CD): 0 where they meet, by exact orientation signs.
     */
    public static double segments(double ax, double ay, double bx, double by,
                                  double cx, double cy, double dx, double dy, double[] q) {
        return segments(ax, ay, bx, by, cx, cy, dx, dy, q, new double[2]);
    }

    /** {@link #segments} with a scratch array of two for the feet, so a loop allocates once. */
    static double segments(double ax, double ay, double bx, double by,
                                   double cx, double cy, double dx, double dy, double[] q, double[] f) {
        double best = pointSegment(ax, ay, cx, cy, dx, dy, f);
        put(q, ax, ay, f[0], f[1]);
        // When AB is a point (a circle's centre), its distance to CD is the answer; when CD
        // is one, its end d is its end c: the skipped distances cannot be smaller.
        if (ax != bx || ay != by) {
            double d = pointSegment(bx, by, cx, cy, dx, dy, f);
            if (closer(d, best, bx, by, f[0], f[1], q)) {
                best = put(q, bx, by, f[0], f[1]) + d;
            }
            d = pointSegment(cx, cy, ax, ay, bx, by, f);
            if (closer(d, best, f[0], f[1], cx, cy, q)) {
                best = put(q, f[0], f[1], cx, cy) + d;
            }
            if (cx != dx || cy != dy) {
                d = pointSegment(dx, dy, ax, ay, bx, by, f);
                if (closer(d, best, f[0], f[1], dx, dy, q)) {
                    best = put(q, f[0], f[1], dx, dy) + d;
                }
            }
        }
        // Segments that meet have boxes that meet: the box test skips the four exact
        // orientations for most pairs (the end-to-edge distances above were all > 0).
        if (best > 0 && boxesMeet(ax, ay, bx, by, cx, cy, dx, dy) && Lines.segmentsMeet(ax, ay, bx, by, cx, cy, dx, dy)) {
            // They cross (no end lies on the other, or rounding hid it): at the crossing.
            double o1 = Lines.orient(cx, cy, dx, dy, ax, ay), o2 = Lines.orient(cx, cy, dx, dy, bx, by);
            double s = o1 == o2 ? 0 : o1 / (o1 - o2);
            double x = ax + s * (bx - ax), y = ay + s * (by - ay);
            return put(q, x, y, x, y);
        }
        return best;
    }

    /**
     * Is the pair of points (x1, y1), (x2, y2), d apart, closer than the pair in q, best
     * apart, or as close with its midpoint first (the least x, then the least y)? The one rule
     * for equally close pairs (two parallel edges give many), so that the pair given is the
     * same whichever shape comes first, and whichever kernel finds it.
     */
    static boolean closer(double d, double best, double x1, double y1, double x2, double y2, double[] q) {
        if (d != best) {
            return d < best;
        }
        double sx = x1 + x2, bx = q[0] + q[2];
        return sx < bx || sx == bx && y1 + y2 < q[1] + q[3];
    }

    /** Do the closed boxes of segments AB and CD have a point in common? */
    private static boolean boxesMeet(double ax, double ay, double bx, double by,
                                     double cx, double cy, double dx, double dy) {
        return Math.max(ax, bx) >= Math.min(cx, dx) && Math.max(cx, dx) >= Math.min(ax, bx)
                && Math.max(ay, by) >= Math.min(cy, dy) && Math.max(cy, dy) >= Math.min(ay, by);
    }

    /** Writes the two points into q; returns 0, for a caller to add its distance to. */
    private static double put(double[] q, double x1, double y1, double x2, double y2) {
        q[0] = x1;
        q[1] = y1;
        q[2] = x2;
        q[3] = y2;
        return 0;
    }

    /**
     * The distance from point P to the closed segment AB (a point if A = B), and the
     * segment's closest point in {@code foot}. In the segment's interior, the gap across an
     * axis-aligned edge (exact), else the cross product over the length.
     */
    public static double pointSegment(double px, double py, double ax, double ay, double bx, double by, double[] foot) {
        double ex = bx - ax, ey = by - ay, fx = px - ax, fy = py - ay;
        double len2 = ex * ex + ey * ey;
        double dot = fx * ex + fy * ey;
        if (len2 == 0 || dot <= 0) {
            foot[0] = ax;
            foot[1] = ay;
            return Math.sqrt(fx * fx + fy * fy);
        }
        if (dot >= len2) {
            foot[0] = bx;
            foot[1] = by;
            double gx = px - bx, gy = py - by;
            return Math.sqrt(gx * gx + gy * gy);
        }
        // An axis-aligned edge: the gap across it, exact whatever the sizes.
        if (ex == 0) {
            foot[0] = ax;
            foot[1] = py;
            return Math.abs(fx);
        }
        if (ey == 0) {
            foot[0] = px;
            foot[1] = ay;
            return Math.abs(fy);
        }
        double s = dot / len2;
        foot[0] = ax + s * ex;
        foot[1] = ay + s * ey;
        return Math.abs(ex * fy - ey * fx) / Math.sqrt(len2);
    }

    // ---------------------------------------------------------------- ellipses

    /**
     * The distance from a point to an ellipse's outline (two different radii, both above 0;
     * the point not inside), and the outline's closest point in {@code near}: the point taken
     * into the ellipse's frame, Eberly's closest point there, and back.
     */
    public static double ellipsePoint(Ellipse e, double px, double py, double[] near) {
        double c = e.angle() == 0 ? 1 : StrictMath.cos(e.angle()), s = e.angle() == 0 ? 0 : StrictMath.sin(e.angle());
        double dx = px - e.x(), dy = py - e.y();
        double u = dx * c + dy * s, v = -dx * s + dy * c;
        double d = Ellipses.distance(e.rx(), e.ry(), u, v, near);
        double nu = near[0], nv = near[1];
        near[0] = e.x() + (nu * c - nv * s);
        near[1] = e.y() + (nu * s + nv * c);
        return d;
    }

    /**
     * The distance from an ellipse to a chain of straight edges, closest points in q: the
     * ellipse's first, or the chain's first if {@code chainFirst}.
     */
    private static double ellipseChain(Ellipse e, double[] xy, boolean closed, double[] q, boolean chainFirst, Scratch s) {
        int n = xy.length / 2, edges = edges(n, closed);
        double best = Double.POSITIVE_INFINITY;
        double[] t = s.t;
        for (int i = 0; i < edges; i++) {
            int i2 = n <= 1 ? i : (i + 1) % n;
            double d = ellipseSegment(e, xy[2 * i], xy[2 * i + 1], xy[2 * i2], xy[2 * i2 + 1], t, s.near);
            if (d < best) {
                best = d;
                System.arraycopy(t, 0, q, 0, 4);
            }
        }
        if (chainFirst) {
            swap(q);
        }
        return best;
    }

    /** Exchanges the two points of q. */
    private static void swap(double[] q) {
        double x = q[0], y = q[1];
        q[0] = q[2];
        q[1] = q[3];
        q[2] = x;
        q[3] = y;
    }

    /**
     * The distance from an ellipse to the closed segment AB outside it, closest points in q
     * (the ellipse's, then the segment's). The distance to a convex set is convex along the
     * segment, so its least is where its slope, {@code (P - near) . (B - A)}, changes sign:
     * found by bisection.
     */
    private static double ellipseSegment(Ellipse e, double ax, double ay, double bx, double by, double[] q, double[] near) {
        double ex = bx - ax, ey = by - ay;
        double s;
        if (ex == 0 && ey == 0 || slope(e, ax, ay, ex, ey, near) >= 0) {
            s = 0;
        } else if (slope(e, bx, by, ex, ey, near) <= 0) {
            s = 1;
        } else {
            double lo = 0, hi = 1;
            s = 0.5;
            for (int i = 0; i < BISECTIONS; i++) {
                s = (lo + hi) / 2;
                if (s == lo || s == hi) {
                    break;
                }
                double m = slope(e, ax + s * ex, ay + s * ey, ex, ey, near);
                if (m == 0) {
                    break;
                }
                if (m < 0) {
                    lo = s;
                } else {
                    hi = s;
                }
            }
        }
        double px = s == 0 ? ax : s == 1 ? bx : ax + s * ex, py = s == 0 ? ay : s == 1 ? by : ay + s * ey;
        double d = ellipsePoint(e, px, py, near);
        return put(q, near[0], near[1], px, py) + d;
    }

    /** The sign of the distance's slope along (dx, dy) at (px, py), outside the ellipse. */
    private static double slope(Ellipse e, double px, double py, double dx, double dy, double[] near) {
        ellipsePoint(e, px, py, near);
        return (px - near[0]) * dx + (py - near[1]) * dy;
    }

    /** A point of ellipse f's outline, at eccentric angle t, into {@code p}; its tangent into p[2], p[3]. */
    private static void onOutline(Ellipse f, double t, double[] p) {
        double c = f.angle() == 0 ? 1 : StrictMath.cos(f.angle()), s = f.angle() == 0 ? 0 : StrictMath.sin(f.angle());
        double u = f.rx() * StrictMath.cos(t), v = f.ry() * StrictMath.sin(t);
        double du = -f.rx() * StrictMath.sin(t), dv = f.ry() * StrictMath.cos(t);
        p[0] = f.x() + (u * c - v * s);
        p[1] = f.y() + (u * s + v * c);
        p[2] = du * c - dv * s;
        p[3] = du * s + dv * c;
    }

    /**
     * The distance between two ellipses that do not overlap, closest points in q (e's, then
     * f's): f's outline sampled at {@value #ELLIPSE_SAMPLES} eccentric angles, the distance
     * of each point to e by {@link #ellipsePoint}, and each local least refined by bisection
     * on the sign of the slope along f's outline.
     */
    private static double ellipses(Ellipse e, Ellipse f, double[] q, Scratch s) {
        int n = ELLIPSE_SAMPLES;
        double[] g = s.g;
        double[] p = s.p, near = s.near;
        for (int i = 0; i < n; i++) {
            onOutline(f, 2 * Math.PI * i / n, p);
            g[i] = ellipsePoint(e, p[0], p[1], near);
        }
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            if (!(g[i] <= g[(i + n - 1) % n] && g[i] <= g[(i + 1) % n])) {
                continue;
            }
            double lo = 2 * Math.PI * (i - 1) / n, hi = 2 * Math.PI * (i + 1) / n;
            for (int k = 0; k < BISECTIONS; k++) {
                double m = (lo + hi) / 2;
                if (m == lo || m == hi) {
                    break;
                }
                onOutline(f, m, p);
                ellipsePoint(e, p[0], p[1], near);
                double sl = (p[0] - near[0]) * p[2] + (p[1] - near[1]) * p[3];
                if (sl < 0) {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            // The sampled point, in case the bracket held no change of sign, and the refined one.
            for (int k = 0; k < 2; k++) {
                onOutline(f, k == 0 ? 2 * Math.PI * i / n : (lo + hi) / 2, p);
                double d = ellipsePoint(e, p[0], p[1], near);
                if (d < best) {
                    best = put(q, near[0], near[1], p[0], p[1]) + d;
                }
            }
        }
        return best;
    }
}
