package hitbox.internal;

import hitbox.*;

import java.math.BigDecimal;

/**
 * The one table behind {@link Shape#contains(Shape)}: does the first shape hold the second,
 * for every ordered pair of kinds (containment is not symmetric, so all 36 pairs have their
 * route, reached through {@link ShapeKind}'s exhaustive switches); and each kind's point
 * test behind {@link Shape#contains(float, float)} ({@link #point}).
 *
 * <p><b>What is asked.</b> The closure of b (b with its outline) lies in the closure of a: no
 * point of b is outside a, and touching a's outline from inside counts, so every shape holds
 * itself. A zero-size shape is read as what it behaves as (a circle of radius 0 a point, a
 * flat rectangle or ellipse its segment, a capsule of radius 0 its segment), ends included.
 *
 * <p><b>How, by the container's kind.</b>
 * <ul>
 *   <li>A rectangle (and an axis-aligned flat ellipse, its flat box): b's exact extents
 *       against the box's, each a comparison of sums of two floats decided exactly
 *       ({@link #atLeast}).</li>
 *   <li>A convex curved container (circle, capsule, ellipse) and a segment: convex, so b is
 *       held when the points and discs b is the hull of are: a polygon's or rectangle's
 *       corners, a segment's ends, a capsule's two end discs, a circle. Points and discs in a
 *       circle are decided exactly for every float ({@link #discWithin}); in a capsule by
 *       {@link Capsules#nearOrigin} (exact for whole numbers of modest size); points in an
 *       axis-aligned ellipse by {@link Ellipses#side} (exact). The rest, a disc or an ellipse
 *       in an ellipse, an ellipse in a circle or a capsule, and points in a turned ellipse,
 *       has no polynomial answer a float test can give: they are searched over the held
 *       shape's outline in double and answer true within {@link #CONTAINMENT} of touching
 *       from inside (the one tolerance here).</li>
 *   <li>A polygon, convex or concave: a held shape with area is inside when no edge of the
 *       polygon reaches into it (the pair tests of {@link Overlaps}, so as exact as they are)
 *       and one of its points is inside; a polygonal shape, a segment or a point when each
 *       of its edges lies in the closed polygon ({@link #segmentInside}), decided by exact
 *       orientation signs.</li>
 * </ul>
 *
 * <p>The class is longer than most: containment is not symmetric, so the table has all 36
 * ordered pairs rather than 21, and it keeps with them its two exact comparisons (sums of
 * floats, distances against a difference of radii) and the outline search for the curved
 * pairs, which nothing else in the library needs.
 */
public final class Containment {
    private Containment() {
    }

    /**
     * How far, relative to the container's size, a curved pair that is searched rather than
     * decided (see the class doc) may reach past the container and still count as held: far
     * above the double rounding of the search's sums (about 1e-15), far below a pixel. A
     * shape that touches from inside is always held; one that pokes out by less than this is
     * held too. Listed in {@link Tolerance}'s class doc.
     */
    public static final double CONTAINMENT = 1e-9;

    /**
     * A proven bound on the rounding of {@code (a1 - b1) + (a2 - b2)} in double, relative to
     * {@code |a1| + |a2| + |b1| + |b2|}: three additions, each off by at most a unit of 2^-53
     * of its size, with a unit to spare ({@code atLeast}). Beyond it the double sign is sure.
     */
    private static final double SUM_ROUNDING = 4 * 0x1p-53;

    /**
     * Where the golden-section search for how far a curved shape pokes out of its container
     * stops (radians of the outline's angle): the depth found is then as deep as it gets to
     * well within {@link #CONTAINMENT}.
     */
    private static final double SEARCH_STOP = 1e-9;

    /** How many points of the held outline the search samples before refining each peak. */
    private static final int SAMPLES = 64;

    /**
     * The point test behind {@link Shape#contains(float, float)}: is (px, py) in the shape's
     * open inside (a segment's closed line)? Each kind's case is its raw test, the one the
     * matching {@code Collide} method answers with; a NaN answers false in every case.
     *
     * @param s  the shape, not null
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is in the shape
     */
    public static boolean point(Shape s, float px, float py) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                // an aligned one is the raw test; a turned one takes the point into its own frame first
                yield TurnedEllipses.aligned(e) ? RawTests.ellipsePoint(e.x(), e.y(), e.rx(), e.ry(), px, py)
                        : TurnedEllipses.turnedPoint(e, px, py);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield RawTests.capsulePoint(k.x1(), k.y1(), k.x2(), k.y2(), k.r(), px, py);
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield RawTests.circlePoint(c.x(), c.y(), c.r(), px, py);
            }
            case RECT -> {
                Rect r = (Rect) s;
                yield RawTests.rectPoint(r.x(), r.y(), r.w(), r.h(), px, py);
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Lines.segmentPoint(g.x1(), g.y1(), g.x2(), g.y2(), px, py);
            }
            case POLYGON -> {
                float[] v = HiddenParts.raw((Polygon) s);
                if (v.length == 6) {
                    // Three orientation signs, not the crossing count's walk (1.9x slower). Both decide
                    // the open inside exactly, and a triangle has area (Polygon.of refuses a flat one);
                    // a NaN or infinite point is outside for both (TrianglePointTest).
                    yield RawTests.trianglePoint(v[0], v[1], v[2], v[3], v[4], v[5], px, py);
                }
                yield RawTests.polygonPoint(v, px, py);
            }
        };
    }

    /** Any two shapes: does a hold b? Routed on a's kind, then b's. */
    public static boolean test(Shape a, Shape b) {
        return switch (ShapeKind.of(a)) {
            case ELLIPSE -> ellipseContains((Ellipse) a, b);
            case CAPSULE -> capsuleContains((Capsule) a, b);
            case CIRCLE -> circleContains((Circle) a, b);
            case RECT -> rectContains((Rect) a, b);
            case SEGMENT -> segmentContains((Segment) a, b);
            case POLYGON -> polygonContains((Polygon) a, b);
        };
    }

    /** An ellipse, aligned or turned, flat or not, holding anything. */
    public static boolean ellipseContains(Ellipse e, Shape b) {
        if (e.rx() == 0 || e.ry() == 0) {
            if (TurnedEllipses.aligned(e)) {
                // its flat box (a point when both radii are 0)
                return box(e.x(), -e.rx(), e.rx(), e.y(), -e.ry(), e.ry(), b);
            }
            Segment s = TurnedEllipses.flatSegment(e);
            return convex(new Along(s.x1(), s.y1(), s.x2(), s.y2()), b);
        }
        return convex(new Oval(e), b);
    }

    /** A capsule holding anything. */
    public static boolean capsuleContains(Capsule k, Shape b) {
        return convex(new Stadium(k.x1(), k.y1(), k.x2(), k.y2(), k.r()), b);
    }

    /** A circle holding anything: the thread's disc, set to it (nothing the test calls sets it again). */
    public static boolean circleContains(Circle c, Shape b) {
        return convex(DISC.get().set(c.x(), c.y(), c.r()), b);
    }

    /** A thread's disc for {@link #circleContains}, so that the question makes nothing. */
    private static final ThreadLocal<Disc> DISC = ThreadLocal.withInitial(() -> new Disc(0, 0, 0));

    /** A rectangle holding anything. */
    public static boolean rectContains(Rect r, Shape b) {
        return box(r.x(), 0, r.w(), r.y(), 0, r.h(), b);
    }

    /** A segment holding anything: only segments and points on it. */
    public static boolean segmentContains(Segment s, Shape b) {
        return convex(new Along(s.x1(), s.y1(), s.x2(), s.y2()), b);
    }

    // ------------------------------------------------------------------ a box

    /**
     * Does the closed box [x + loX, x + hiX] x [y + loY, y + hiY] hold b? Each side is a sum of
     * two floats, and so is each of b's extents, so every comparison is exact.
     */
    static boolean box(float x, float loX, float hiX, float y, float loY, float hiY, Shape b) {
        return switch (ShapeKind.of(b)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) b;
                if (TurnedEllipses.aligned(e)) {
                    yield within(e.x(), -e.rx(), e.rx(), x, loX, hiX) && within(e.y(), -e.ry(), e.ry(), y, loY, hiY);
                }
                if (e.rx() == 0 || e.ry() == 0) {
                    yield box(x, loX, hiX, y, loY, hiY, TurnedEllipses.flatSegment(e));
                }
                // A turned ellipse's half-width is a square root: within the tolerance.
                double c = StrictMath.cos(e.angle()), s = StrictMath.sin(e.angle());
                double hw = Math.hypot(e.rx() * c, e.ry() * s), hh = Math.hypot(e.rx() * s, e.ry() * c);
                yield nearWithin(e.x(), hw, x, loX, hiX) && nearWithin(e.y(), hh, y, loY, hiY);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) b;
                float r = k.r();
                yield within(Math.min(k.x1(), k.x2()), -r, 0, x, loX, hiX) && within(Math.max(k.x1(), k.x2()), 0, r, x, loX, hiX)
                        && within(Math.min(k.y1(), k.y2()), -r, 0, y, loY, hiY) && within(Math.max(k.y1(), k.y2()), 0, r, y, loY, hiY);
            }
            case CIRCLE -> {
                Circle c = (Circle) b;
                yield within(c.x(), -c.r(), c.r(), x, loX, hiX) && within(c.y(), -c.r(), c.r(), y, loY, hiY);
            }
            case RECT -> {
                Rect r = (Rect) b;
                yield within(r.x(), 0, r.w(), x, loX, hiX) && within(r.y(), 0, r.h(), y, loY, hiY);
            }
            case SEGMENT -> {
                Segment s = (Segment) b;
                yield within(Math.min(s.x1(), s.x2()), 0, 0, x, loX, hiX) && within(Math.max(s.x1(), s.x2()), 0, 0, x, loX, hiX)
                        && within(Math.min(s.y1(), s.y2()), 0, 0, y, loY, hiY) && within(Math.max(s.y1(), s.y2()), 0, 0, y, loY, hiY);
            }
            case POLYGON -> {
                float[] xy = HiddenParts.raw((Polygon) b);
                boolean in = true;
                for (int i = 0; i < xy.length && in; i += 2) {
                    in = within(xy[i], 0, 0, x, loX, hiX) && within(xy[i + 1], 0, 0, y, loY, hiY);
                }
                yield in;
            }
        };
    }

    /** Does the first rectangle hold the second ({@code Rect.contains(Rect)}): finite values, sizes 0 or more. */
    public static boolean rectRect(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        return x2 >= x1 && y2 >= y1 && notPast(x2, w2, x1, w1) && notPast(y2, h2, y1, h1);
    }

    /**
     * Is {@code v + vs <= w + ws}, exactly, for finite floats? The sums in float decide when
     * they differ: rounding never reverses an order (a larger exact sum never rounds to a
     * smaller float, overflow included), so only sums that round to the same float, an edge
     * touching from inside among them, are compared exactly ({@link #atLeast}).
     */
    private static boolean notPast(float v, float vs, float w, float ws) {
        float a = v + vs, b = w + ws;
        return a != b ? a < b : atLeast(w, ws, v, vs);
    }

    /** Does the rectangle hold the circle ({@code Rect.contains(Circle)}): finite values, sizes 0 or more. */
    public static boolean rectCircle(float x, float y, float w, float h, float cx, float cy, float r) {
        return within(cx, -r, r, x, 0, w) && within(cy, -r, r, y, 0, h);
    }

    /** Does the first circle hold the second ({@code Circle.contains(Circle)}): finite values, sizes 0 or more. */
    public static boolean circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return new Disc(x1, y1, r1).holds(x2, y2, r2);
    }

    /** Does the circle hold the rectangle ({@code Circle.contains(Rect)}): finite values, sizes 0 or more. */
    public static boolean circleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        double right = (double) rectX + rectW, bottom = (double) rectY + rectH;
        return discWithin(rectX, rectY, cx, cy, r, 0) && discWithin(right, rectY, cx, cy, r, 0)
                && discWithin(right, bottom, cx, cy, r, 0) && discWithin(rectX, bottom, cx, cy, r, 0);
    }

    /** Are all four values finite (not NaN, not infinite)? */
    public static boolean finite(float a, float b, float c, float d) {
        return Math.abs(a) <= Float.MAX_VALUE && Math.abs(b) <= Float.MAX_VALUE
                && Math.abs(c) <= Float.MAX_VALUE && Math.abs(d) <= Float.MAX_VALUE;
    }

    /** Is the interval [v + lo, v + hi] inside [w + wLo, w + wHi]? Exact for floats. */
    private static boolean within(float v, float lo, float hi, float w, float wLo, float wHi) {
        return atLeast(v, lo, w, wLo) && atLeast(w, wHi, v, hi);
    }

    /** {@link #within} for [v - h, v + h] with h a rounded double: within the tolerance. */
    private static boolean nearWithin(float v, double h, float w, float wLo, float wHi) {
        double slack = CONTAINMENT * (h + Math.abs(wHi - (double) wLo));
        return ((double) v - w) - h - wLo >= -slack && ((double) w - v) + wHi - h >= -slack;
    }

    /**
     * Is {@code a1 + a2 >= b1 + b2}, exactly, for finite floats (any doubles that are exact,
     * in fact)? In double first, and exactly ({@link BigDecimal}) only within the rounding of
     * the three additions. A NaN answers false; an infinite value is compared in double.
     */
    static boolean atLeast(double a1, double a2, double b1, double b2) {
        double d1 = a1 - b1, d2 = a2 - b2, s = d1 + d2;
        double bound = SUM_ROUNDING * (Math.abs(a1) + Math.abs(a2) + Math.abs(b1) + Math.abs(b2));
        if (s > bound || -s > bound || !(bound < Double.POSITIVE_INFINITY)) {
            return s >= 0;
        }
        // Near a tie: whole numbers of modest size subtract and add without rounding, which
        // the error-free sums show, and then s is exact; otherwise exactly, allocating.
        if (Lines.twoSumError(a1, -b1, d1) == 0 && Lines.twoSumError(a2, -b2, d2) == 0 && Lines.twoSumError(d1, d2, s) == 0) {
            return s >= 0;
        }
        return new BigDecimal(a1).add(new BigDecimal(a2)).subtract(new BigDecimal(b1)).subtract(new BigDecimal(b2)).signum() >= 0;
    }

    // ------------------------------------------------------------------ convex containers

    /**
     * A closed convex container: it holds b when it holds the points and discs b is the hull
     * of ({@link #convex}).
     */
    private abstract static class Hull {
        /** Does it hold the point (closed)? */
        abstract boolean point(double x, double y);

        /** Does it hold the closed disc of radius r > 0? */
        abstract boolean disc(float x, float y, float r);

        /** Does it hold the ellipse (both radii above 0, not equal), its closure? */
        abstract boolean ellipse(Ellipse e);

        /**
         * The search's measure of a point at (x, y) from the container's reference point:
         * at most 1 when held, growing outwards (a distance over the radius, say).
         */
        double gauge(double x, double y) {
            return Double.POSITIVE_INFINITY;
        }

        /**
         * How much the gauge can grow per unit of distance, at most (1 over the container's
         * radius, or its smaller radius): a point within d of another has a gauge at most d
         * times this larger.
         */
        double outer() {
            return Double.POSITIVE_INFINITY;
        }

        /** The container's reference point, from which {@link #gauge} measures. */
        double refX() {
            return 0;
        }

        /** See {@link #refX()}. */
        double refY() {
            return 0;
        }

        /**
         * The search: is the outline of the ellipse centred at (cx, cy), radii a and b along
         * (cos, sin) and its perpendicular, held within {@link #CONTAINMENT}? The largest
         * gauge over the outline, from {@value #SAMPLES} samples and a golden-section search
         * about each sampled peak (the gauge along an ellipse's outline is a smooth function
         * of its angle with at most a few peaks).
         */
        final boolean outline(double cx, double cy, double a, double b, double cos, double sin) {
            double dx = cx - refX(), dy = cy - refY();
            // First the sure answers, from the gauge at the held shape's centre: every point of
            // it is within its larger radius of the centre, and the gauge grows by at most
            // outer() per unit of distance; and a container that holds it holds its centre.
            double centre = gauge(dx, dy);
            if (centre + Math.max(a, b) * outer() <= 1 - CONTAINMENT) {
                return true;
            }
            if (centre > 1 + CONTAINMENT) {
                return false;
            }
            java.util.function.DoubleUnaryOperator minus = t -> {
                double u = a * StrictMath.cos(t), v = b * StrictMath.sin(t);
                return -gauge(dx + u * cos - v * sin, dy + u * sin + v * cos);
            };
            double step = 2 * Math.PI / SAMPLES;
            double[] g = new double[SAMPLES];
            for (int i = 0; i < SAMPLES; i++) {
                g[i] = minus.applyAsDouble(i * step);
                if (-g[i] > 1 + CONTAINMENT) {
                    return false;
                }
            }
            for (int i = 0; i < SAMPLES; i++) {
                double here = g[i], before = g[(i + SAMPLES - 1) % SAMPLES], after = g[(i + 1) % SAMPLES];
                if (here <= before && here <= after) {
                    double[] best = Golden.least(minus, (i - 1) * step, (i + 1) * step, 60, SEARCH_STOP);
                    if (-best[1] > 1 + CONTAINMENT) {
                        return false;
                    }
                }
            }
            return true;
        }
    }

    /** A closed disc. */
    private static final class Disc extends Hull {
        float x, y, r;

        Disc(float x, float y, float r) {
            set(x, y, r);
        }

        Disc set(float x, float y, float r) {
            this.x = x;
            this.y = y;
            this.r = r;
            return this;
        }

        @Override
        boolean point(double px, double py) {
            return discWithin(px, py, x, y, r, 0);
        }

        @Override
        boolean disc(float cx, float cy, float cr) {
            return cr <= r && discWithin(cx, cy, x, y, r, cr);
        }

        /** The closed disc of radius cr (0 or more) at (cx, cy), a point for 0. */
        boolean holds(float cx, float cy, float cr) {
            return cr == 0 ? point(cx, cy) : disc(cx, cy, cr);
        }

        @Override
        boolean ellipse(Ellipse e) {
            return r > 0 && outline(e.x(), e.y(), e.rx(), e.ry(), StrictMath.cos(e.angle()), StrictMath.sin(e.angle()));
        }

        @Override
        double gauge(double px, double py) {
            return Math.hypot(px, py) / r;
        }

        @Override
        double outer() {
            return 1.0 / r;
        }

        @Override
        double refX() {
            return x;
        }

        @Override
        double refY() {
            return y;
        }
    }

    /** A closed capsule: the points at most r from the segment. */
    private static final class Stadium extends Hull {
        final float x1, y1, x2, y2, r;

        Stadium(float x1, float y1, float x2, float y2, float r) {
            this.x1 = x1;
            this.y1 = y1;
            this.x2 = x2;
            this.y2 = y2;
            this.r = r;
        }

        @Override
        boolean point(double px, double py) {
            return Capsules.nearOrigin(x1 - px, y1 - py, x2 - px, y2 - py, r, true);
        }

        @Override
        boolean disc(float cx, float cy, float cr) {
            return cr <= r && Capsules.nearOrigin((double) x1 - cx, (double) y1 - cy, (double) x2 - cx, (double) y2 - cy,
                    (double) r - cr, true);
        }

        @Override
        boolean ellipse(Ellipse e) {
            return r > 0 && outline(e.x(), e.y(), e.rx(), e.ry(), StrictMath.cos(e.angle()), StrictMath.sin(e.angle()));
        }

        @Override
        double gauge(double px, double py) {
            double ex = (double) x2 - x1, ey = (double) y2 - y1;
            double len2 = ex * ex + ey * ey;
            double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, (px * ex + py * ey) / len2));
            return Math.hypot(px - t * ex, py - t * ey) / r;
        }

        @Override
        double outer() {
            return 1.0 / r;
        }

        @Override
        double refX() {
            return x1;
        }

        @Override
        double refY() {
            return y1;
        }
    }

    /** A closed segment: it holds only points on it (and so segments on it). */
    private static final class Along extends Hull {
        final float x1, y1, x2, y2;

        Along(float x1, float y1, float x2, float y2) {
            this.x1 = x1;
            this.y1 = y1;
            this.x2 = x2;
            this.y2 = y2;
        }

        @Override
        boolean point(double px, double py) {
            return Lines.orient(x1, y1, x2, y2, px, py) == 0 && Lines.inBox(x1, y1, x2, y2, px, py);
        }

        @Override
        boolean disc(float cx, float cy, float r) {
            return false; // a disc with area never lies on a segment
        }

        @Override
        boolean ellipse(Ellipse e) {
            return false;
        }
    }

    /** A closed ellipse with area, aligned or turned. */
    private static final class Oval extends Hull {
        final Ellipse e;
        final double cos, sin;

        Oval(Ellipse e) {
            this.e = e;
            boolean aligned = TurnedEllipses.aligned(e);
            this.cos = aligned ? 1 : StrictMath.cos(e.angle());
            this.sin = aligned ? 0 : StrictMath.sin(e.angle());
        }

        @Override
        boolean point(double px, double py) {
            if (sin == 0 && cos == 1) {
                return Ellipses.side(px, py, e.x(), e.y(), e.rx(), e.ry()) <= 0; // exact
            }
            return gauge(px - e.x(), py - e.y()) <= 1 + CONTAINMENT;
        }

        @Override
        boolean disc(float cx, float cy, float r) {
            if (e.rx() == e.ry()) {
                return new Disc(e.x(), e.y(), e.rx()).disc(cx, cy, r); // a circle, exactly
            }
            return outline(cx, cy, r, r, 1, 0);
        }

        @Override
        boolean ellipse(Ellipse f) {
            return outline(f.x(), f.y(), f.rx(), f.ry(), StrictMath.cos(f.angle()), StrictMath.sin(f.angle()));
        }

        @Override
        double gauge(double px, double py) {
            double u = px * cos + py * sin, v = -px * sin + py * cos;
            return Math.hypot(u / e.rx(), v / e.ry());
        }

        @Override
        double outer() {
            return 1.0 / Math.min(e.rx(), e.ry());
        }

        @Override
        double refX() {
            return e.x();
        }

        @Override
        double refY() {
            return e.y();
        }
    }

    /** Does the convex container hold b? Through the points and discs b is the hull of. */
    private static boolean convex(Hull a, Shape b) {
        return switch (ShapeKind.of(b)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) b;
                if (e.rx() == 0 || e.ry() == 0) {
                    if (TurnedEllipses.aligned(e)) { // its flat box's two ends, or its point
                        yield a.point((double) e.x() - e.rx(), (double) e.y() - e.ry())
                                && a.point((double) e.x() + e.rx(), (double) e.y() + e.ry());
                    }
                    Segment s = TurnedEllipses.flatSegment(e);
                    yield a.point(s.x1(), s.y1()) && a.point(s.x2(), s.y2());
                }
                yield e.rx() == e.ry() ? a.disc(e.x(), e.y(), e.rx()) : a.ellipse(e);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) b;
                if (k.r() == 0) {
                    yield a.point(k.x1(), k.y1()) && a.point(k.x2(), k.y2());
                }
                yield a.disc(k.x1(), k.y1(), k.r()) && a.disc(k.x2(), k.y2(), k.r());
            }
            case CIRCLE -> {
                Circle c = (Circle) b;
                yield c.r() == 0 ? a.point(c.x(), c.y()) : a.disc(c.x(), c.y(), c.r());
            }
            case RECT -> {
                Rect r = (Rect) b;
                double right = (double) r.x() + r.w(), bottom = (double) r.y() + r.h();
                yield a.point(r.x(), r.y()) && a.point(right, bottom) && a.point(right, r.y()) && a.point(r.x(), bottom);
            }
            case SEGMENT -> {
                Segment s = (Segment) b;
                yield a.point(s.x1(), s.y1()) && a.point(s.x2(), s.y2());
            }
            case POLYGON -> {
                float[] xy = HiddenParts.raw((Polygon) b);
                boolean in = true;
                for (int i = 0; i < xy.length && in; i += 2) {
                    in = a.point(xy[i], xy[i + 1]);
                }
                yield in;
            }
        };
    }

    /**
     * Is the distance from p to q at most {@code reach - less} (reach at least less)? Exact for
     * every finite float input ({@link Discs#distanceSign}).
     */
    static boolean discWithin(double px, double py, double qx, double qy, double reach, double less) {
        return Discs.distanceSign(px, py, qx, qy, reach, less) <= 0;
    }

    // ------------------------------------------------------------------ a polygon

    /** A polygon, convex or concave, holding anything. */
    public static boolean polygonContains(Polygon p, Shape b) {
        float[] xy = HiddenParts.raw(p);
        Rect box = p.bounds();
        // Cheap first: b's box must lie in the polygon's (exact extents, as for a rectangle).
        if (!box(box.x(), 0, box.w(), box.y(), 0, box.h(), b.bounds())) {
            return false;
        }
        int convex = HiddenParts.convexWinding(p);
        int w = convex != 0 ? convex : Polygons.winding(xy);
        boolean quick = convex != 0;
        return switch (ShapeKind.of(b)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) b;
                if (e.rx() == 0 || e.ry() == 0) {
                    if (TurnedEllipses.aligned(e)) {
                        yield segmentInside(xy, w, quick, (double) e.x() - e.rx(), (double) e.y() - e.ry(),
                                (double) e.x() + e.rx(), (double) e.y() + e.ry());
                    }
                    Segment s = TurnedEllipses.flatSegment(e);
                    yield segmentInside(xy, w, quick, s.x1(), s.y1(), s.x2(), s.y2());
                }
                // With area: no edge reaches into it, and its centre is inside.
                if (!Polygons.contains(xy, e.x(), e.y())) {
                    yield false;
                }
                boolean aligned = TurnedEllipses.aligned(e);
                int n = xy.length / 2;
                for (int i = 0, h = n - 1; i < n; h = i++) {
                    boolean meets = aligned
                            ? Ellipses.segment(e.x(), e.y(), e.rx(), e.ry(), xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], false)
                            : TurnedEllipses.turned(e, new Segment(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1]));
                    if (meets) {
                        yield false;
                    }
                }
                yield true;
            }
            case CAPSULE -> {
                Capsule k = (Capsule) b;
                if (k.r() == 0) {
                    yield segmentInside(xy, w, quick, k.x1(), k.y1(), k.x2(), k.y2());
                }
                if (!Polygons.contains(xy, k.x1(), k.y1())) {
                    yield false;
                }
                int n = xy.length / 2;
                for (int i = 0, h = n - 1; i < n; h = i++) {
                    if (Capsules.segmentsWithin(k.x1(), k.y1(), k.x2(), k.y2(), xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], k.r())) {
                        yield false;
                    }
                }
                yield true;
            }
            case CIRCLE -> {
                Circle c = (Circle) b;
                if (c.r() == 0) {
                    yield closedContains(xy, c.x(), c.y());
                }
                if (!Polygons.contains(xy, c.x(), c.y())) {
                    yield false;
                }
                int n = xy.length / 2;
                for (int i = 0, h = n - 1; i < n; h = i++) {
                    if (RawTests.lineCircle(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], c.x(), c.y(), c.r())) {
                        yield false;
                    }
                }
                yield true;
            }
            case RECT -> outlineInside(xy, w, quick, Polygons.corners((Rect) b, new double[8]));
            case SEGMENT -> {
                Segment s = (Segment) b;
                yield segmentInside(xy, w, quick, s.x1(), s.y1(), s.x2(), s.y2());
            }
            case POLYGON -> outlineInside(xy, w, quick, HiddenParts.corners((Polygon) b));
        };
    }

    /** Does every edge of the closed outline (x0, y0, x1, y1, ...) lie in the closed polygon? */
    private static boolean outlineInside(float[] xy, int w, boolean convex, double[] outline) {
        int n = outline.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (!segmentInside(xy, w, convex, outline[2 * h], outline[2 * h + 1], outline[2 * i], outline[2 * i + 1])) {
                return false;
            }
        }
        return true;
    }

    /** Is the point in the closed polygon: inside, or on its outline? Exact. */
    static boolean closedContains(float[] xy, double px, double py) {
        return Polygons.contains(xy, px, py) || onOutline(xy, px, py);
    }

    /** Is the point on the polygon's outline? Exact orientation signs. */
    private static boolean onOutline(float[] xy, double px, double py) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (Lines.orient(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], px, py) == 0
                    && Lines.inBox(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], px, py)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Does the closed segment PQ lie in the closed polygon (winding w)? Exact orientation
     * signs. Both ends must be in it, and no edge may cross PQ properly (there the segment
     * would pass from inside to outside). Then PQ meets the outline only at its ends, at
     * polygon vertices on it, and along edges, so it is cut into pieces, each wholly inside,
     * wholly outside or along an edge; each piece starts at P or at a polygon vertex, and the
     * step from there towards Q tells which: into the corner's closed wedge at a vertex,
     * towards the inside side of an edge P lies on, or anywhere when P is inside. A concave
     * polygon whose notch PQ jumps (both ends inside, an edge leaving) fails at the notch's
     * vertices or crossings.
     */
    static boolean segmentInside(float[] xy, int w, boolean convex, double px, double py, double qx, double qy) {
        if (convex) {
            // A convex polygon holds the segment when it holds both ends.
            return onInnerSide(xy, w, px, py) && onInnerSide(xy, w, qx, qy);
        }
        if (!closedContains(xy, px, py) || !closedContains(xy, qx, qy)) {
            return false;
        }
        if (px == qx && py == qy) {
            return true;
        }
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int h = i == 0 ? n - 1 : i - 1, k = i + 1 == n ? 0 : i + 1;
            double ax = xy[2 * i], ay = xy[2 * i + 1], bx = xy[2 * k], by = xy[2 * k + 1];
            double o1 = Lines.orient(ax, ay, bx, by, px, py);
            double o2 = Lines.orient(ax, ay, bx, by, qx, qy);
            double oa = Lines.orient(px, py, qx, qy, ax, ay);
            double ob = Lines.orient(px, py, qx, qy, bx, by);
            if (Lines.opposite(o1, o2) && Lines.opposite(oa, ob)) {
                return false; // a proper crossing: one side of it is outside
            }
            // Vertex a on PQ (P itself included, Q not): the step from it towards Q.
            if (oa == 0 && Lines.inBox(px, py, qx, qy, ax, ay) && !(ax == qx && ay == qy)
                    && !intoClosedCorner(w, xy[2 * h], xy[2 * h + 1], ax, ay, bx, by, qx, qy)) {
                return false;
            }
            // P inside edge ab (not at a vertex): the step must go to the inside side or along.
            if (o1 == 0 && Lines.inBox(ax, ay, bx, by, px, py) && !(px == ax && py == ay) && !(px == bx && py == by)
                    && w * o2 < 0) {
                return false;
            }
        }
        return true;
    }

    /** Is the point on the inner side of every edge of the convex polygon (winding w), or on it? Exact. */
    private static boolean onInnerSide(float[] xy, int w, double px, double py) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (w * Lines.orient(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], px, py) < 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * At vertex v between prev and next, is the direction towards q into the closed wedge of
     * the inside (along an edge counts)? Exact: each cross product with the direction is an
     * orientation with q, since q lies along it.
     */
    private static boolean intoClosedCorner(int w, double prevX, double prevY, double vx, double vy,
                                            double nextX, double nextY, double qx, double qy) {
        double turn = w * Lines.orient(prevX, prevY, vx, vy, nextX, nextY);
        double in = w * Lines.orient(prevX, prevY, vx, vy, qx, qy);   // (v - prev) x (q - v)
        double out = w * Lines.orient(vx, vy, nextX, nextY, qx, qy);  // (next - v) x (q - v)
        if (turn > 0) {
            return in >= 0 && out >= 0;
        }
        if (turn < 0) {
            return in >= 0 || out >= 0;
        }
        return out >= 0; // a straight corner: the inside side of the line, or along it
    }
}
