package hitbox;

import hitbox.internal.*;

import hitbox.internal.*;

import java.util.Arrays;

/**
 * A ray: a half-line from an origin in a direction, up to a greatest distance. Cast it at a
 * shape to find where it first meets it: line of sight, a laser, a bullet that must not pass
 * through walls, the mouse pointer's line.
 *
 * <p>The ray is closed, like a segment, and follows the <a
 * href="package-summary.html#touching">touching rule</a>: it hits a shape with area (circle,
 * rectangle, polygon) only where it goes into its inside, so a ray that runs along an edge,
 * or only touches a corner or a circle's outline, does not hit it. It hits a segment
 * wherever it touches it, end points included; running along a segment it hits the nearer
 * end. A ray that starts inside a shape with area hits it at distance 0 (what a game wants
 * from line of sight: the view is blocked), with the normal pointing along the ray. A ray of
 * length 0 ({@code maxDistance} 0) goes nowhere: it hits only a shape it starts inside, or a
 * segment it starts on.
 *
 * <p>A hit's normal follows the package's one convention, <em>from the mover into what it
 * hit</em>: here from the ray into the shape, the shape's inward surface normal, so a bullet
 * bounces off a wall with {@code Response.bounce(dx, dy, hit.nx(), hit.ny(), 1)}.
 *
 * <p>The direction need not be of unit length; distances are always in pixels. For
 * whole-number coordinates and directions, whether a ray hits is decided exactly.
 *
 * <p>{@link #cast(Shape)} answers for every shape. The distance alone on plain floats stays
 * for a circle, a rectangle and a segment ({@link #distanceToCircle}, {@link #distanceToRect},
 * {@link #distanceToSegment}), where the narrow-phase table (docs/narrow-phase.md) shows
 * {@code cast} more than 10% slower on the same question.
 *
 * <p>This class is longer than most (about 600 lines): the raw-float distances and the cast at
 * each of the six shape kinds, each with its normal, belong together.
 *
 * <p>Reference: Christer Ericson, <i>Real-Time Collision Detection</i> (2005), 5.3
 * "Intersecting Lines, Rays, and (Directed) Segments" (slabs for boxes, a quadratic for
 * spheres, orientation tests for segments).
 *
 * @param ox          the origin's x
 * @param oy          the origin's y
 * @param dx          the direction's x part
 * @param dy          the direction's y part
 * @param maxDistance how far the ray reaches, in pixels: 0 or more, and may be
 *                    {@link Float#POSITIVE_INFINITY}. When it is the direction's own length
 *                    (as {@link #between} makes it) the ray ends exactly at
 *                    {@code (ox + dx, oy + dy)}.
 */
public record Ray(float ox, float oy, float dx, float dy, float maxDistance) {

    /** Events on a polygon's outline closer than this fraction of the ray's length are one event. */
    static final double SAME_EVENT = 1e-12;

    /**
     * Makes a ray, checking its values.
     *
     * @param ox the origin's x
     * @param oy the origin's y
     * @param dx the direction's x part
     * @param dy the direction's y part
     * @param maxDistance how far the ray reaches, in pixels: 0 or more, and may be {@link Float#POSITIVE_INFINITY}. When it is the direction's own length (as {@link #between} makes it) the ray ends exactly at {@code (ox + dx, oy + dy)}.
     *
     * @throws IllegalArgumentException if a value is NaN, the origin or direction is
     *                                  infinite, the direction is (0, 0), or maxDistance is
     *                                  negative
     */
    public Ray {
        Check.finite("ox", ox);
        Check.finite("oy", oy);
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        if (dx == 0 && dy == 0) {
            throw new IllegalArgumentException("direction (dx, dy) must not be (0, 0): a ray needs a direction");
        }
        if (!(maxDistance >= 0)) {
            throw new IllegalArgumentException("maxDistance must be >= 0 (or infinite), was " + maxDistance);
        }
    }

    /**
     * Makes a ray with no end.
     *
     * @param ox the origin's x
     * @param oy the origin's y
     * @param dx the direction's x part
     * @param dy the direction's y part
     * @throws IllegalArgumentException if a value is NaN or infinite, or the direction is (0, 0)
     */
    public Ray(float ox, float oy, float dx, float dy) {
        this(ox, oy, dx, dy, Float.POSITIVE_INFINITY);
    }

    /**
     * The ray from one point that ends exactly at another: for line of sight, "can the enemy
     * at (x1, y1) see the player at (x2, y2)?" is {@code between(x1, y1, x2, y2).cast(wall) == null}.
     *
     * @param x1 the start's x
     * @param y1 the start's y
     * @param x2 the end's x
     * @param y2 the end's y
     * @return the ray from (x1, y1) towards (x2, y2), reaching it and no farther, never null
     * @throws IllegalArgumentException if a value is NaN or infinite, or the points are the same
     */
    public static Ray between(float x1, float y1, float x2, float y2) {
        Check.finite("x1", x1);
        Check.finite("y1", y1);
        Check.finite("x2", x2);
        Check.finite("y2", y2);
        if (x1 == x2 && y1 == y2) {
            throw new IllegalArgumentException("the two points must differ, both were (" + x1 + ", " + y1 + ")");
        }
        float dx = x2 - x1, dy = y2 - y1;
        return new Ray(x1, y1, dx, dy, (float) RayCast.length(dx, dy));
    }

    /**
     * Where does this ray first meet the shape?
     *
     * @param shape any shape, not null
     * @return the nearest hit, or null if the ray does not reach the shape (within
     *         {@link #maxDistance()})
     * @throws IllegalArgumentException if the shape is null
     */
    public RayHit cast(Shape shape) {
        Check.notNull("shape", shape);
        double limit = RayCast.limit(dx, dy, maxDistance);
        return switch (ShapeKind.of(shape)) {
            case ELLIPSE -> castEllipse((Ellipse) shape, limit);
            case CAPSULE -> castCapsule((Capsule) shape, limit);
            case CIRCLE -> castCircle((Circle) shape, limit);
            case RECT -> castRect((Rect) shape, limit);
            case SEGMENT -> castSegment((Segment) shape, limit);
            case POLYGON -> castPolygon((Polygon) shape, limit);
        };
    }

    // ---------------------------------------------------------------- raw floats, no allocation
    // Kept where the narrow-phase table (docs/narrow-phase.md) shows cast() more than 10%
    // slower on the same question (a circle 4.35x, a rect 2.06x, a segment 2.60x: cast makes a
    // RayHit with its point and normal); ellipses and capsules are asked through cast().

    /**
     * How far along a ray is the first point inside the circle? Allocates nothing and never
     * throws.
     *
     * @param ox          the ray's origin x
     * @param oy          the ray's origin y
     * @param dx          the ray's direction, x part
     * @param dy          the ray's direction, y part
     * @param maxDistance how far the ray reaches
     * @param cx          the circle's centre x
     * @param cy          the circle's centre y
     * @param r           the circle's radius
     * @return the distance in pixels, 0 if the origin is inside, or
     *         {@link Float#POSITIVE_INFINITY} if the ray does not go into the circle (also for
     *         NaN or infinite input, a direction of (0, 0), a negative maxDistance or a
     *         negative radius)
     */
    public static float distanceToCircle(float ox, float oy, float dx, float dy, float maxDistance,
                                         float cx, float cy, float r) {
        if (badRay(ox, oy, dx, dy, maxDistance) || Check.notFinite(cx, cy, r, 0, 0)) {
            return Float.POSITIVE_INFINITY;
        }
        return distance(circleParam(ox, oy, dx, dy, RayCast.limit(dx, dy, maxDistance), cx, cy, r), dx, dy);
    }

    /**
     * How far along a ray is the first point inside the rectangle? Allocates nothing and never
     * throws.
     *
     * @param ox          the ray's origin x
     * @param oy          the ray's origin y
     * @param dx          the ray's direction, x part
     * @param dy          the ray's direction, y part
     * @param maxDistance how far the ray reaches
     * @param rectX          the rectangle's left edge
     * @param rectY          the rectangle's top edge
     * @param rectW          the rectangle's width
     * @param rectH          the rectangle's height
     * @return the distance in pixels, 0 if the origin is inside, or
     *         {@link Float#POSITIVE_INFINITY} if the ray does not go into the rectangle
     *         (also for NaN or infinite input, a direction of (0, 0), a negative
     *         maxDistance or a negative size)
     */
    public static float distanceToRect(float ox, float oy, float dx, float dy, float maxDistance,
                                       float rectX, float rectY, float rectW, float rectH) {
        if (badRay(ox, oy, dx, dy, maxDistance) || Check.notFinite(rectX, rectY, rectW, rectH, 0)) {
            return Float.POSITIVE_INFINITY;
        }
        return RayCast.rectDistance(ox, oy, dx, dy, maxDistance, rectX, rectY, rectW, rectH);
    }

    /**
     * How far along a ray is the first point of the segment? Allocates nothing and never
     * throws.
     *
     * @param ox          the ray's origin x
     * @param oy          the ray's origin y
     * @param dx          the ray's direction, x part
     * @param dy          the ray's direction, y part
     * @param maxDistance how far the ray reaches
     * @param x1          the segment's first end, x
     * @param y1          the segment's first end, y
     * @param x2          the segment's second end, x
     * @param y2          the segment's second end, y
     * @return the distance in pixels, or {@link Float#POSITIVE_INFINITY} if the ray does not
     *         reach the segment (also for NaN or infinite input, a direction of (0, 0) or a
     *         negative maxDistance)
     */
    public static float distanceToSegment(float ox, float oy, float dx, float dy, float maxDistance,
                                          float x1, float y1, float x2, float y2) {
        if (badRay(ox, oy, dx, dy, maxDistance) || Check.notFinite(x1, y1, x2, y2, 0)) {
            return Float.POSITIVE_INFINITY;
        }
        return distance(segmentParam(ox, oy, dx, dy, RayCast.limit(dx, dy, maxDistance), x1, y1, x2, y2), dx, dy);
    }

    // ---------------------------------------------------------------- the maths, in units of (dx, dy)

    /**
     * A ray the raw-float methods answer "no hit" for: a NaN or infinite origin or direction,
     * a direction of (0, 0), or a NaN or negative reach.
     */
    private static boolean badRay(float ox, float oy, float dx, float dy, float maxDistance) {
        return Check.notFinite(ox, oy, dx, dy, 0) || (dx == 0 && dy == 0) || !(maxDistance >= 0);
    }

    private static float distance(double s, float dx, float dy) {
        return RayCast.distance(s, dx, dy);
    }

    /**
     * The ray's parameter where it enters the aligned ellipse: scaled by ry along x and rx
     * along y the ellipse is a circle of radius rx ry, and the parameter is the same in both
     * planes. Negative if the origin is inside; {@link Slabs#INF} if it never enters.
     */
    private static double ellipseParam(float ox, float oy, double dx, double dy, double limit, float x, float y, float a, float b) {
        return Discs.entry(((double) ox - x) * b, ((double) oy - y) * a, dx * b, dy * a, (double) a * b, limit);
    }

    /**
     * The ray's parameter where it enters the capsule: the first entry into either end's disc
     * or the rectangle between them (in the segment's own frame); 0 if the origin is inside,
     * {@link Slabs#INF} if it never enters.
     */
    private static double capsuleParam(float ox, float oy, double dx, double dy, double limit,
                                       float x1, float y1, float x2, float y2, float r) {
        if (RawTests.capsulePoint(x1, y1, x2, y2, r, ox, oy)) {
            return 0;
        }
        double s = Math.min(Discs.entry((double) ox - x1, (double) oy - y1, dx, dy, r, limit),
                Discs.entry((double) ox - x2, (double) oy - y2, dx, dy, r, limit));
        double ex = (double) x2 - x1, ey = (double) y2 - y1, len = Math.hypot(ex, ey);
        if (len > 0) {
            double ux = ex / len, uy = ey / len;
            double px = (double) ox - x1, py = (double) oy - y1;
            double along = px * ux + py * uy, across = -px * uy + py * ux;
            double va = dx * ux + dy * uy, vc = -dx * uy + dy * ux;
            s = Math.min(s, Slabs.boxTime(-along, len - along, -r - across, r - across, va, vc, limit));
        }
        return s == Slabs.INF ? s : Math.max(s, 0);
    }

    private static double circleParam(float ox, float oy, float dx, float dy, double limit, float cx, float cy, float r) {
        double s = Discs.entry((double) ox - cx, (double) oy - cy, dx, dy, r, limit);
        return s < 0 ? 0 : s;
    }

    /**
     * The first s in [0, limit] where o + s d is on the closed segment, or +infinity. Solves
     * o + s d = a + u e with cross products; the decisions (s >= 0, u in [0, 1]) compare the
     * numerators with the denominator, exact for whole numbers.
     */
    private static double segmentParam(float ox, float oy, float dx, float dy, double limit,
                                       float x1, float y1, float x2, float y2) {
        double ex = (double) x2 - x1, ey = (double) y2 - y1;
        double wx = (double) x1 - ox, wy = (double) y1 - oy;
        double denom = dx * ey - dy * ex;
        double sNum = wx * ey - wy * ex;
        double uNum = wx * dy - wy * dx;
        if (denom != 0) {
            if (denom < 0) {
                denom = -denom;
                sNum = -sNum;
                uNum = -uNum;
            }
            if (!(sNum >= 0 && uNum >= 0 && uNum <= denom)) {
                return Slabs.INF;
            }
            double s = sNum / denom;
            return s <= limit ? s : Slabs.INF;
        }
        if (uNum != 0) {
            return Slabs.INF;  // parallel, on another line (or NaN: uNum != 0 is true, so no hit)
        }
        // On the same line: the ray meets the part of the segment between its ends' projections.
        double dd = (double) dx * dx + (double) dy * dy;
        double s1 = (wx * dx + wy * dy) / dd;
        double s2 = (((double) x2 - ox) * dx + ((double) y2 - oy) * dy) / dd;
        double lo = Math.min(s1, s2), hi = Math.max(s1, s2);
        return hi >= 0 && lo <= limit ? Math.max(lo, 0) : Slabs.INF;
    }

    // ---------------------------------------------------------------- shapes, with normals

    private RayHit castCircle(Circle c, double limit) {
        double s = circleParam(ox, oy, dx, dy, limit, c.x(), c.y(), c.r());
        if (s == Slabs.INF) {
            return null;
        }
        if (s == 0 && Collide.circlePoint(c.x(), c.y(), c.r(), ox, oy)) {
            return inside();
        }
        return hitAt(s, ox + s * dx - c.x(), oy + s * dy - c.y());
    }

    /**
     * An ellipse: scaled by ry along x and rx along y it is a circle of radius rx ry, and the
     * ray's parameter is the same in both planes. The normal is the outline's gradient.
     */
    private RayHit castEllipse(Ellipse e, double limit) {
        double a = e.rx(), b = e.ry();
        if (!TurnedEllipses.aligned(e)) {
            return castTurnedEllipse(e, a, b, limit);
        }
        double s = ellipseParam(ox, oy, dx, dy, limit, e.x(), e.y(), e.rx(), e.ry());
        if (s == Slabs.INF) {
            return null;
        }
        if (s < 0) {
            return inside();
        }
        double hx = ox + s * dx - e.x(), hy = oy + s * dy - e.y();
        return hitAt(s, hx / (a * a), hy / (b * b));
    }

    /**
     * A turned ellipse: the ray taken into its frame (the turn undone about the centre), cast
     * as for an aligned one, and the normal turned back.
     */
    private RayHit castTurnedEllipse(Ellipse e, double a, double b, double limit) {
        TurnedEllipses.Frame f = new TurnedEllipses.Frame(e);
        double u = f.u(ox, oy), v = f.v(ox, oy);
        double du = dx * f.c() + dy * f.s(), dv = -dx * f.s() + dy * f.c();
        double s = Discs.entry(u * b, v * a, du * b, dv * a, a * b, limit);
        if (s == Slabs.INF) {
            return null;
        }
        if (s < 0) {
            return inside();
        }
        double gu = (u + s * du) / (a * a), gv = (v + s * dv) / (b * b);
        return hitAt(s, gu * f.c() - gv * f.s(), gu * f.s() + gv * f.c());
    }

    /**
     * A capsule: the first entry into either end's disc or the rectangle between them (in the
     * segment's own frame); the normal points from the segment's nearest point to the hit.
     */
    private RayHit castCapsule(Capsule k, double limit) {
        if (RawTests.capsulePoint(k.x1(), k.y1(), k.x2(), k.y2(), k.r(), ox, oy)) {
            return inside();
        }
        double s = capsuleParam(ox, oy, dx, dy, limit, k.x1(), k.y1(), k.x2(), k.y2(), k.r());
        if (s == Slabs.INF) {
            return null;
        }
        double ex = (double) k.x2() - k.x1(), ey = (double) k.y2() - k.y1(), len = Math.hypot(ex, ey);
        double hx = ox + s * dx, hy = oy + s * dy;
        double t = len == 0 ? 0 : Lines.clamp(((hx - k.x1()) * ex + (hy - k.y1()) * ey) / (len * len), 0, 1);
        double nx = hx - (k.x1() + t * ex), ny = hy - (k.y1() + t * ey);
        return nx == 0 && ny == 0 ? hitAt(s, -dx, -dy) : hitAt(s, nx, ny);
    }

    private RayHit castRect(Rect r, double limit) {
        if (Collide.rectPoint(r.x(), r.y(), r.w(), r.h(), ox, oy)) {
            return inside();
        }
        // y first, as in Sweep: a ray into a corner exactly counts as hitting top or bottom.
        Slabs.Clip clip = Slabs.box((double) r.x() - ox, (double) r.x() + r.w() - ox,
                (double) r.y() - oy, (double) r.y() + r.h() - oy, dx, dy);
        double s = clip.firstTime(limit);
        return s == Slabs.INF ? null : hitAt(s, clip.nx, clip.ny);
    }

    private RayHit castSegment(Segment g, double limit) {
        double s = segmentParam(ox, oy, dx, dy, limit, g.x1(), g.y1(), g.x2(), g.y2());
        if (s == Slabs.INF) {
            return null;
        }
        double nx = -((double) g.y2() - g.y1()), ny = (double) g.x2() - g.x1();
        double facing = nx * dx + ny * dy;
        if (facing == 0) {
            return hitAt(s, -dx, -dy);  // along the segment: its end faces the ray
        }
        return facing < 0 ? hitAt(s, nx, ny) : hitAt(s, -nx, -ny);
    }

    /**
     * A polygon, convex or not: the ray's parameter at every point where it meets the
     * outline, in order; between two such events the ray is wholly inside or wholly outside,
     * so the first event followed by an inside stretch is where the ray goes in. Inside is
     * asked of {@link Polygon#contains} only at points off the outline (a stretch's middle,
     * never one that runs along an edge, and the origin only when it is off the outline), so
     * the answer does not lean on how points on edges are treated.
     */
    private RayHit castPolygon(Polygon p, double limit) {
        if (p.isConvex()) {
            return castConvex(p, limit);
        }
        int n = p.size();
        double[] events = new double[2 * n];
        double[] alongFrom = new double[n], alongTo = new double[n];
        int count = 0, along = 0;
        boolean onOutline = false;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double s = segmentParam(ox, oy, dx, dy, Slabs.INF, p.x(i), p.y(i), p.x(j), p.y(j));
            if (s == Slabs.INF) {
                continue;
            }
            onOutline |= s == 0;
            events[count++] = s;
            double ex = (double) p.x(j) - p.x(i), ey = (double) p.y(j) - p.y(i);
            if (dx * ey - dy * ex == 0) {
                // Along the edge: its far end is an event too, and the stretch between is on the outline.
                double dd = (double) dx * dx + (double) dy * dy;
                double si = (((double) p.x(i) - ox) * dx + ((double) p.y(i) - oy) * dy) / dd;
                double sj = (((double) p.x(j) - ox) * dx + ((double) p.y(j) - oy) * dy) / dd;
                events[count++] = Math.max(si, sj);
                alongFrom[along] = s;
                alongTo[along++] = Math.max(si, sj);
            }
        }
        if (!onOutline && p.contains(ox, oy)) {
            return inside();
        }
        Arrays.sort(events, 0, count);
        double scale = Math.max(1, Math.abs(events[Math.max(count - 1, 0)]));
        for (int k = 0; k + 1 < count; k++) {
            double s = events[k];
            if (!(s < limit)) {
                break;  // reaching the outline at the very end does not get inside
            }
            int next = k + 1;
            while (next < count && events[next] - s <= SAME_EVENT * scale) {
                next++;
            }
            if (next == count) {
                break;  // past the last event the ray is outside
            }
            double to = events[next];
            boolean onEdge = false;
            for (int a = 0; a < along && !onEdge; a++) {
                onEdge = alongFrom[a] <= s && to <= alongTo[a];
            }
            // The middle in double, not rounded to float: a stretch that passes a hair from a
            // corner has its middle a hair from the outline, where float rounding could cross it.
            double mid = (s + to) / 2;
            if (!onEdge && Polygons.contains(p.raw(), ox + mid * dx, oy + mid * dy)) {
                return hitPolygon(p, Polygons.winding(p.raw()), s + 0.0, SAME_EVENT * scale); // (not -0)
            }
            k = next - 1;
        }
        return null;
    }

    /**
     * A convex polygon, in one pass over its edges (Cyrus-Beck clipping): the open polygon is
     * the part strictly inside every edge's line, so the ray is inside between the last line it
     * crosses going in and the first it crosses going out. Each crossing is the parameter
     * {@link #segmentParam} gives at the edge, {@code orient(edge, origin) / cross(d, edge)};
     * a way in and a way out closer than {@link #SAME_EVENT} (a corner only touched) are one
     * event, as for any polygon. Which side of each edge's line the origin is on is decided
     * exactly (in double, and where that is within rounding of 0 by {@link Lines#orient}), so
     * a start inside, on the outline, or outside an edge the ray runs parallel to is told
     * exactly for any floats. Allocates nothing but the hit.
     *
     * <p>Reference: M. Cyrus and J. Beck, "Generalized two- and three-dimensional clipping",
     * Computers &amp; Graphics 3 (1978).
     */
    private RayHit castConvex(Polygon p, double limit) {
        double[] c = p.corners();
        int w = p.convexWinding(), n = c.length / 2;
        // A bound on the rounding of every orientation below: each is two products of
        // differences, each off by a few units of 2^-53 of its size, and the polygon's box
        // (which holds it, rounded outwards) bounds every difference.
        Rect box = p.bounds();
        double left = box.x(), top = box.y(), right = left + box.w(), bottom = top + box.h();
        double farX = Math.max(Math.abs(left - ox), Math.abs(right - ox));
        double farY = Math.max(Math.abs(top - oy), Math.abs(bottom - oy));
        double rounding = Tolerance.ORIENTATION_ROUNDING * (farX * box.h() + farY * box.w());
        // The crossings kept as fractions num / den with den > 0, compared by cross
        // multiplication, so that only the answer is divided; and the origin's least depth
        // inside an edge's line (times its length), to tell whether it starts inside.
        double inNum = 0, inDen = 0, outNum = 0, outDen = 0, least = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            int j = i + 1 == n ? 0 : i + 1;
            double ex = c[2 * j] - c[2 * i], ey = c[2 * j + 1] - c[2 * i + 1];
            double denom = dx * ey - dy * ex;
            // orient(vertex i, vertex j, origin), as Lines.orient computes it when not near 0,
            // and by Lines.orient when it is: every sign below is exact.
            double num = (c[2 * i] - ox) * ey - (c[2 * i + 1] - oy) * ex;
            if (Math.abs(num) <= rounding) {
                num = Lines.orient(c[2 * i], c[2 * i + 1], c[2 * j], c[2 * j + 1], ox, oy);
            }
            least = Math.min(least, w * num);
            if (denom == 0) {
                if (w * num <= 0) {
                    return null; // along the edge's line, on or outside it: never strictly inside
                }
                continue;
            }
            // Going in across this edge when the direction points against its outward normal.
            boolean goingIn = w * denom < 0;
            if (denom < 0) {
                denom = -denom;
                num = -num;
            }
            if (goingIn) {
                if (inDen == 0 || num * inDen > inNum * denom) {
                    inNum = num;
                    inDen = denom;
                }
            } else if (outDen == 0 || num * outDen < outNum * denom) {
                outNum = num;
                outDen = denom;
            }
        }
        if (least > 0) {
            return inside(); // strictly inside every edge's line
        }
        // Some edge is crossed going in and some going out: a bounded polygon is.
        double in = inNum / inDen, out = outNum / outDen;
        double near = SAME_EVENT * Math.max(1, Math.abs(out));
        if (!(in >= 0 && in < limit && out - in > near)) {
            return null;
        }
        return hitPolygon(p, w, in + 0.0, near); // (+ 0.0: a start on the outline is at 0, not -0)
    }

    /**
     * The hit at s on the outline of a polygon of winding {@code turn}: its normal is the
     * outward normals of the edges met within {@code near} of s and facing the ray, summed (two
     * at a corner), else straight back. Allocates nothing but the hit.
     */
    private RayHit hitPolygon(Polygon p, int turn, double s, double near) {
        float[] xy = p.raw();
        int n = xy.length / 2;
        double sx = 0, sy = 0;
        for (int i = 0; i < n; i++) {
            int j = i + 1 == n ? 0 : i + 1;
            double ex = (double) xy[2 * j] - xy[2 * i], ey = (double) xy[2 * j + 1] - xy[2 * i + 1];
            double ahead = turn * (dx * ey - dy * ex);
            if (ahead > Tolerance.NEAR_TIE * (Math.abs(dx * ey) + Math.abs(dy * ex))) {
                continue; // clearly facing away (the test below would say so too): skip its crossing
            }
            double at = segmentParam(ox, oy, dx, dy, Slabs.INF, xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]);
            if (at != Slabs.INF && Math.abs(at - s) <= near) {
                // The outward normal (edges of a Polygon have length). A plain square root, not
                // Math.hypot (several times dearer): the squares of float differences neither
                // overflow nor underflow in double.
                // Facing the ray: ahead < 0, the sign of out . d without the unit normal's
                // rounding, so an edge the ray runs along is not counted by a rounding error.
                double len = Math.sqrt(ex * ex + ey * ey), outX = turn * ey / len, outY = -turn * ex / len;
                if (ahead < 0) {
                    sx += outX;
                    sy += outY;
                }
            }
        }
        return sx == 0 && sy == 0 ? hitAt(s, -dx, -dy) : hitAt(s, sx, sy);
    }

    /** The hit of a ray that starts inside: distance 0, the normal along the ray. */
    private RayHit inside() {
        return hitAt(0, -dx, -dy);
    }

    /**
     * The hit at parameter s, given the shape's <em>outward</em> normal there (facing the
     * ray); the hit carries it turned round, from the ray into the shape.
     */
    private RayHit hitAt(double s, double outX, double outY) {
        double len = Math.hypot(outX, outY);
        // Held in the float range: a ray across a polygon wider than it cannot say more.
        return new RayHit(Check.held(s * RayCast.length(dx, dy)), Check.held(ox + s * dx), Check.held(oy + s * dy),
                (float) (-outX / len), (float) (-outY / len));
    }
}
