package hitbox.internal;

import hitbox.*;

/**
 * The straight time of impact into a polygon where it has a closed form, for
 * {@link Sweep#timeOfImpact(Shape, float, float, Shape)}: two convex polygons, a rectangle
 * into a convex polygon ({@link #rectTimeOfImpact}) and a circle into any polygon
 * ({@link #circleTimeOfImpact}); every other pair with a polygon goes by convex pieces,
 * {@link ConvexSweep}. For two convex polygons: the entry as a ray cast against their
 * Minkowski difference, exact up to the rounding of double, then the promised float t, each
 * moved position tested with no polygon made (see
 * {@link #movedOverlaps(Polygon, float, float, Polygon, float[], boolean, boolean)}). Nothing is allocated but the
 * hit.
 *
 * <p>Mover a, moved by {@code t v}, overlaps b exactly when {@code t v} is inside the
 * convex polygon {@code b - a} (every point of b minus every point of a), whose edges are
 * the edges of b and of a turned round: each edge gives a half-plane, and the point
 * {@code t v} is inside all of them during an open interval of time (Cyrus-Beck, as for
 * boxes in {@link Slabs}), which starts at the entry, through the face entered last.
 * {@code n + m} faces, each placed by one support point of the other polygon: no
 * iteration and no tolerance.
 *
 * <p>This class is longer than most (about 500 lines): its three sweeps are one idea, a
 * polygon's faces clipping a ray in the thread's clip and the float positions walked from
 * the entry, and the two convex polygons' look-back; apart, each would carry a copy of the
 * clip, the faces' placing and the scratch.
 *
 * <p>Reference: C. Ericson, <i>Real-Time Collision Detection</i> (2005), 5.5 (moving
 * objects as a ray against their Minkowski sum); M. de Berg et al., <i>Computational
 * Geometry: Algorithms and Applications</i> (3rd ed., 2008), 13.3 (the Minkowski sum of two
 * convex polygons, edge by edge); G. Toussaint, "Solving geometric problems with the
 * rotating calipers" (1983).
 */
public final class ConvexPolygonSweep {
    private ConvexPolygonSweep() {
    }

    /**
     * The rounding of a corner's projection onto the sweep's direction, relative to the size of
     * the coordinates and the move: two products and a sum, each off by a unit of 2^-53, and
     * {@code |ux| + |uy| <= 1.5}; 2^-48 leaves a factor of ten to spare.
     */
    private static final double PROJECTION_ROUNDING = 0x1p-48;

    /** The hit of convex mover moving by (vx, vy) into convex obstacle, the two apart at the start; or null. */
    public static Hit timeOfImpact(Polygon mover, float vx, float vy, Polygon obstacle) {
        Scratch scratch = SCRATCH.get();
        Slabs.Clip clip = scratch.clip.reset();
        // A miss often shows in the first faces: the interval, once empty, stays empty.
        if (!faces(HiddenParts.corners(obstacle), HiddenParts.convexWinding(obstacle), HiddenParts.corners(mover), false, vx, vy, 0, 0, clip)) {
            return null;
        }
        double obstacleEntry = clip.enter;
        if (!faces(HiddenParts.corners(mover), HiddenParts.convexWinding(mover), HiddenParts.corners(obstacle), true, vx, vy, 0, 0, clip)) {
            return null;
        }
        // Entered last through one of the mover's own faces? Near the entry a clear position is
        // most often told apart by that face, so the probes try that polygon's edges first.
        boolean moverFace = clip.enter != obstacleEntry;
        double te = clip.firstTime(1);
        float[] moved = scratch.moved(HiddenParts.raw(mover).length);
        boolean keeps = keepsConvex(mover, Math.max(Math.abs(vx), Math.abs(vy)));
        SweptPairs.Search s = scratch.search.reset(te, true);
        while (s.searching()) {
            float t = s.t();
            s.answer(movedOverlaps(mover, t * vx, t * vy, obstacle, moved, keeps, moverFace));
        }
        // 1 means no float position up to the end overlaps (1 itself was found clear): a graze.
        float t = s.t();
        return t < 1 ? SweptPairs.hit(t, -clip.nx, -clip.ny) : null;
    }

    /**
     * The hit of a rectangle with area moving by (vx, vy) into a convex polygon, the two apart
     * at the start; or null. The same Minkowski difference as {@link #timeOfImpact}, whose
     * faces are here the rectangle's (two slabs, across and down) and the polygon's edges, the
     * rectangle's reach along each read from its corners with no array made; then the promised
     * float t as {@link Sweep} finds it for a rectangle and a segment ({@link SweptPairs#answer}):
     * the float positions {@code x + t * vx}, {@code y + t * vy} visited from the entry of the
     * faces pushed out by the rounding slack of those two coordinates, each tested with
     * {@link Polygons#convexRectOverlap}, no rectangle made. A character's box on a slope or
     * against a turned box asks this at every step, where conservative advancement took a
     * search of directions and of float positions. Where rounding in double puts the start
     * inside (the shapes touch), the general way ({@link ConvexSweep#byPieces}) answers.
     */
    public static Hit rectTimeOfImpact(Rect mover, float vx, float vy, Polygon obstacle) {
        return rectTimeOfImpact(mover, mover.x(), mover.y(), mover.w(), mover.h(), vx, vy, obstacle);
    }

    /**
     * {@link #rectTimeOfImpact(Rect, float, float, Polygon)} for the box (x, y, w, h), its
     * {@code Rect} given if made (else null: made only where the general way answers).
     */
    public static Hit rectTimeOfImpact(Rect made, float x, float y, float w, float h, float vx, float vy, Polygon obstacle) {
        double[] q = HiddenParts.corners(obstacle);
        int winding = HiddenParts.convexWinding(obstacle);
        Earliest e = rectEntry(SweptPairs.exactEntry(), x, y, w, h, vx, vy, q, winding, 0, 0);
        if (e.inside) {
            // Touching, and rounding put the start inside.
            return ConvexSweep.byPieces(made != null ? made : new Rect(x, y, w, h), vx, vy, obstacle);
        }
        Earliest grown = SweptPairs.decided(e) ? e
                : rectEntry(SweptPairs.grownEntry(), x, y, w, h, vx, vy, q, winding,
                SweptPairs.slack(x, vx) + ConvexSweep.TOUCH, SweptPairs.slack(y, vy) + ConvexSweep.TOUCH);
        float t = SweptPairs.answer(e, grown,
                SweptPairs.rectConvexAt(x, y, w, h, vx, vy, HiddenParts.raw(obstacle), winding), x, vx, y, vy);
        return SweptPairs.hit(t, e, grown, false);
    }

    /**
     * Can {@link #rectTimeOfImpact} answer this pair: a rectangle with area against a convex
     * polygon? (The caller has answered a mover that does not move.)
     */
    public static boolean rectAgainstConvex(Shape mover, Shape obstacle) {
        return ShapeKind.of(mover) == ShapeKind.RECT && ((Rect) mover).w() > 0 && ((Rect) mover).h() > 0
                && ShapeKind.of(obstacle) == ShapeKind.POLYGON && HiddenParts.convexWinding((Polygon) obstacle) != 0;
    }

    /**
     * The hit of a circle with area moving by (vx, vy) into a polygon (convex or not), the two
     * apart at the start; or null: the circle against each edge as {@link Sweep} sweeps a circle
     * against a segment, the earliest of those entries
     * ({@link SweptPairs#circlePolygonEntry}), then the promised float t by visiting the float
     * positions of the centre from the entry grown by their rounding slack
     * ({@link SweptPairs#answer}), each tested by {@link RawTests#polygonCircle}. Where
     * rounding in double puts the start inside (the shapes touch), the general way
     * ({@link ConvexSweep#byPieces}) answers.
     */
    public static Hit circleTimeOfImpact(Circle mover, float vx, float vy, Polygon obstacle) {
        return circleTimeOfImpact(mover, mover.x(), mover.y(), mover.r(), vx, vy, obstacle);
    }

    /**
     * {@link #circleTimeOfImpact(Circle, float, float, Polygon)} for the circle at (cx, cy)
     * of radius r, its {@code Circle} given if made (else null: made only where the general
     * way answers).
     */
    public static Hit circleTimeOfImpact(Circle made, float cx, float cy, float r, float vx, float vy, Polygon obstacle) {
        float[] xy = HiddenParts.raw(obstacle);
        Earliest e = SweptPairs.circlePolygonEntry(SweptPairs.exactEntry(), cx, cy, r, vx, vy, xy, 0, 0);
        if (e.inside) {
            // Touching, and rounding put the start inside.
            return ConvexSweep.byPieces(made != null ? made : new Circle(cx, cy, r), vx, vy, obstacle);
        }
        Earliest grown = SweptPairs.decided(e) ? e
                : SweptPairs.circlePolygonEntry(SweptPairs.grownEntry(), cx, cy, r, vx, vy, xy,
                SweptPairs.slack(cx, vx), SweptPairs.slack(cy, vy));
        float t = SweptPairs.answer(e, grown, SweptPairs.circlePolygonAt(cx, cy, r, vx, vy, xy), cx, vx, cy, vy);
        return SweptPairs.hit(t, e, grown, false);
    }

    /**
     * Can {@link #circleTimeOfImpact} answer this pair: a circle with area against a polygon?
     * Convex or not: a centre that starts outside the polygon, at least the radius from its
     * outline, can overlap it only by first coming within the radius of its outline. (The
     * caller has answered a mover that does not move.)
     */
    public static boolean circleAgainstPolygon(Shape mover, Shape obstacle) {
        return ShapeKind.of(mover) == ShapeKind.CIRCLE && ((Circle) mover).r() > 0
                && ShapeKind.of(obstacle) == ShapeKind.POLYGON;
    }

    /**
     * The entry of box (x, y, w, h), moving by (vx, vy), into convex q (corners in pairs,
     * winding w), with the box displaced by up to gx across and gy down (0, 0: the exact
     * entry), into e: the box's two slabs against q's extent, then for each edge of q the
     * slab {@code least + t v.n < edge}, least being the box's nearest corner along the
     * edge's outward normal n.
     */
    private static Earliest rectEntry(Earliest e, float x, float y, float w, float h, float vx, float vy,
                                      double[] q, int winding, double gx, double gy) {
        double left = x, right = (double) x + w, top = y, bottom = (double) y + h;
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < q.length; i += 2) {
            minX = Math.min(minX, q[i]);
            maxX = Math.max(maxX, q[i]);
            minY = Math.min(minY, q[i + 1]);
            maxY = Math.max(maxY, q[i + 1]);
        }
        Slabs.Clip clip = SCRATCH.get().clip.reset()
                .slab(minY - bottom - gy, maxY - top + gy, vy, 0, 1)
                .slab(minX - right - gx, maxX - left + gx, vx, 1, 0);
        for (int i = 0, j = q.length - 2; i < q.length && clip.firstTime(1) != Slabs.INF; j = i, i += 2) {
            double nx = winding * (q[i + 1] - q[j + 1]), ny = winding * (q[j] - q[i]);
            double edge = q[i] * nx + q[i + 1] * ny;
            double least = nx * left + ny * top + Math.min(0, nx * w) + Math.min(0, ny * h);
            double push = gx * Math.abs(nx) + gy * Math.abs(ny);
            clip.slab(Double.NEGATIVE_INFINITY, edge - least + push, vx * nx + vy * ny, nx, ny);
        }
        e.clip(clip, 1);
        return e;
    }

    /**
     * A time before which no copy of the mover with each vertex moved by up to {@code sx}
     * across and {@code sy} down (the rounding of its float positions) can overlap the
     * obstacle, the mover moving by (vx, vy): the entry with every face pushed out by the
     * reach of that box along its normal (a polygon that holds the Minkowski sum of the two
     * with the box), by the same faces as {@link #timeOfImpact}; 0 if that close at the
     * start, +infinity if not within the motion. {@link ConvexSweep}'s look-back starts its
     * walk over the float positions here (conservative advancement, which works for any
     * pieces, cost more than the sweep, and a disc of radius sx + sy started the walk so far
     * back, far from the origin, that the walk gave up).
     */
    public static double entryWithin(Polygon mover, float vx, float vy, Polygon obstacle, double sx, double sy) {
        Slabs.Clip clip = SCRATCH.get().clip.reset();
        if (!faces(HiddenParts.corners(obstacle), HiddenParts.convexWinding(obstacle), HiddenParts.corners(mover), false, vx, vy,
                sx, sy, clip)
                || !faces(HiddenParts.corners(mover), HiddenParts.convexWinding(mover), HiddenParts.corners(obstacle), true, vx, vy,
                sx, sy, clip)) {
            return Slabs.INF;
        }
        return clip.firstTime(1);
    }

    /**
     * The first float t in [from, until] at which the mover, moved by {@code t (vx, vy)} as a
     * sketch moves it (each coordinate {@code x + t * vx} rounded on its own), overlaps the
     * obstacle: +infinity if none does, NaN if the position at {@code from} overlaps already
     * (from was no bound) or more than {@link SweptPairs#MAX_POSITIONS} runs were visited.
     * {@link ConvexSweep}'s look-back, for two convex polygons, from the time before which no
     * float position can overlap ({@link #entryWithin}) up to the walk's answer.
     *
     * <p>Visiting every float position of every coordinate (16 for an 8-gon) cost several
     * times the sweep, so positions are certified clear in runs. (ux, uy) is the hit's normal
     * from the mover into the obstacle: a position whose moved corners all lie on the mover's
     * side of the obstacle's least reach along it is clear, whatever outline runs through them
     * (the margin covers the products' rounding in double). Corners that stay on that side
     * over the whole span, wherever rounding puts them (each coordinate moves monotonically,
     * so the box of its first and last float positions holds them all), are left out of the
     * certificate, so only the near corners' coordinates are walked. Where the certificate
     * fails, every coordinate's positions are visited with the exact test until it holds
     * again. The start and the answer are the first float t of their positions.
     */
    public static float firstOverlap(Polygon mover, float vx, float vy, Polygon obstacle, double from, float until,
                                     double ux, double uy) {
        float t = (float) Math.max(from, 0);
        if (t > from) {
            t = Math.max(Math.nextDown(t), 0f);
        }
        if (!(t <= until)) {
            return Float.POSITIVE_INFINITY;
        }
        float[] xy = HiddenParts.raw(mover);
        double[] q = HiddenParts.corners(obstacle);
        double least = Double.POSITIVE_INFINITY, size = Math.abs(vx) + Math.abs(vy);
        for (int i = 0; i < q.length; i += 2) {
            least = Math.min(least, q[i] * ux + q[i + 1] * uy);
            size = Math.max(size, Math.abs(q[i]) + Math.abs(q[i + 1]));
        }
        for (int i = 0; i < xy.length; i += 2) {
            size = Math.max(size, Math.abs(xy[i]) + Math.abs(xy[i + 1]) + Math.abs(vx) + Math.abs(vy));
        }
        // Each projection is two products and a sum of numbers up to size: off by a few units of
        // 2^-53 of size (|ux| + |uy| <= 1.5), the least and the corners' both.
        double below = least - PROJECTION_ROUNDING * size;
        float a0 = t * vx, b0 = t * vy, a1 = until * vx, b1 = until * vy;
        int n = xy.length / 2;
        Scratch scratch = SCRATCH.get();
        int[] near = scratch.near(n);
        int nearCount = 0;
        for (int k = 0; k < n; k++) {
            float x = xy[2 * k], y = xy[2 * k + 1];
            double most = Math.max(ux * (x + a0), ux * (x + a1)) + Math.max(uy * (y + b0), uy * (y + b1));
            if (!(most <= below)) {
                near[nearCount++] = k;
            }
        }
        if (nearCount == 0) {
            return Float.POSITIVE_INFINITY;  // every corner stays clear of the obstacle over the span
        }
        float[] moved = scratch.moved(xy.length);
        boolean keeps = keepsConvex(mover, Math.max(Math.abs(vx), Math.abs(vy)));
        // The next step of each near corner's x and y, worked out again only once reached
        // (the first 2 * nearCount of the scratch's array).
        float[] steps = scratch.steps(2 * nearCount);
        int stepCount = 2 * nearCount;
        for (int m = 0; m < nearCount; m++) {
            steps[2 * m] = SweptPairs.nextChange(t, xy[2 * near[m]], vx);
            steps[2 * m + 1] = SweptPairs.nextChange(t, xy[2 * near[m] + 1], vy);
        }
        boolean first = true;
        for (int visits = 0; visits < SweptPairs.MAX_POSITIONS; visits++) {
            float dx = t * vx, dy = t * vy;
            double most = Double.NEGATIVE_INFINITY;
            for (int m = 0; m < nearCount; m++) {
                int k = near[m];
                most = Math.max(most, (xy[2 * k] + dx) * ux + (xy[2 * k + 1] + dy) * uy);
            }
            float next;
            if (most <= below) {
                // Clear until a near corner moves: the far ones cannot make it overlap.
                next = Float.POSITIVE_INFINITY;
                for (int i = 0; i < stepCount; i++) {
                    next = Math.min(next, steps[i]);
                }
            } else {
                if (movedOverlaps(mover, dx, dy, obstacle, moved, keeps, true)) {
                    return first ? Float.NaN : t;
                }
                next = Float.POSITIVE_INFINITY;  // the next position of any corner
                for (int i = 0; i < xy.length; i += 2) {
                    next = Math.min(next, Math.min(SweptPairs.nextChange(t, xy[i], vx), SweptPairs.nextChange(t, xy[i + 1], vy)));
                }
            }
            if (next > until) {
                return Float.POSITIVE_INFINITY;
            }
            t = next;
            first = false;
            for (int i = 0; i < stepCount; i++) {
                if (steps[i] <= t) {
                    steps[i] = SweptPairs.nextChange(t, xy[2 * near[i / 2] + (i & 1)], (i & 1) == 0 ? vx : vy);
                }
            }
        }
        return Float.NaN;
    }

    /**
     * Adds to the clip the faces of the Minkowski difference {@code b - a} that come from
     * the edges of convex polygon p (winding {@code w}): b's own faces, or, for the mover a
     * ({@code mover}), a's faces turned round. Each is a half-plane of the point
     * {@code t (vx, vy)}: along p's outward edge normal n, b's face lies at the edge minus
     * a's least reach along n; a's face at b's least reach minus the edge, seen from the
     * other side. The normal is left unscaled, as the times do not depend on its length
     * (the hit's normal is made unit later). False, and the rest left out, as soon as the
     * time interval is empty (no entry within the motion).
     *
     * <p>The least reach of convex q along n is found by walking from where it was for the
     * previous edge to the neighbour that reaches less, until neither does: along a convex
     * outline the reach goes down to its least and up again, with no other dip, and from
     * one edge to the next the least moves on by a vertex or so (rotating calipers), so the
     * walk costs about two products an edge instead of one per vertex of q.
     */
    private static boolean faces(double[] p, int w, double[] q, boolean mover, double vx, double vy, double sx,
                                 double sy, Slabs.Clip clip) {
        int k = 0;
        for (int i = 0, j = p.length - 2; i < p.length; j = i, i += 2) {
            double nx = w * (p[i + 1] - p[j + 1]), ny = w * (p[j] - p[i]);
            k = least(q, k, nx, ny);
            double least = q[k] * nx + q[k + 1] * ny;
            double edge = p[i] * nx + p[i + 1] * ny;
            double push = sx * Math.abs(nx) + sy * Math.abs(ny);  // the box's reach along the unscaled normal
            if (mover) {
                clip.slab(least - edge - push, Slabs.INF, vx * nx + vy * ny, nx, ny);
            } else {
                clip.slab(Double.NEGATIVE_INFINITY, edge - least + push, vx * nx + vy * ny, nx, ny);
            }
            if (clip.firstTime(1) == Slabs.INF) {
                return false;
            }
        }
        return true;
    }

    /**
     * The vertex of convex q (coordinates in pairs) that reaches least along (nx, ny), found
     * by walking from vertex index {@code k} (of its x) the way the reach drops.
     */
    private static int least(double[] q, int k, double nx, double ny) {
        int m = q.length;
        double here = q[k] * nx + q[k + 1] * ny;
        int step = 2;
        int next = k + 2 == m ? 0 : k + 2;
        double there = q[next] * nx + q[next + 1] * ny;
        if (!(there < here)) {
            step = m - 2;  // one back, as indices go round
            next = k == 0 ? m - 2 : k - 2;
            there = q[next] * nx + q[next + 1] * ny;
        }
        for (int walked = 0; there < here && walked < m; walked += 2) {
            k = next;
            here = there;
            next = k + step >= m ? k + step - m : k + step;
            there = q[next] * nx + q[next + 1] * ny;
        }
        return k;
    }

    /**
     * {@link ConvexSweep#movedOverlaps(Shape, float, float, Shape)} for two convex polygons, the moved
     * vertices written into {@code moved} (as long as the mover's coordinates) instead of a
     * new polygon, with the same answer: the same float sums as {@link Polygon#translated};
     * when they are all exact the winding is the mover's, as there; when rounding moved a
     * vertex, a moved outline that is still convex with no vertex on its neighbour is one
     * {@link Polygon#of} accepts (a convex outline that goes round once is simple), and it is
     * convex with the winding {@link Polygons#convexWinding} finds, so the same
     * {@link Polygons#convexOverlap} answers. {@code keeps} ({@link #keepsConvex}) says the
     * rounding cannot have bent it, so that it need not be looked at; {@code moverFirst}
     * has that test try the mover's edges first (the answer is the same either way: no edge
     * of either polygon separates them). Any other outline
     * (rounding bent or squashed it) goes the general way. The bounds test
     * {@link Polygons#overlap} makes first is left out: it only ever says no where the exact
     * test says no too.
     */
    public static boolean movedOverlaps(Polygon mover, float dx, float dy, Polygon obstacle, float[] moved, boolean keeps,
                                 boolean moverFirst) {
        float[] xy = HiddenParts.raw(mover);
        boolean exact = true;
        boolean finite = true;
        for (int i = 0; i < xy.length; i += 2) {
            float x = xy[i] + dx, y = xy[i + 1] + dy;
            moved[i] = x;
            moved[i + 1] = y;
            exact &= x == (double) xy[i] + dx && y == (double) xy[i + 1] + dy;
            finite &= Float.isFinite(x) && Float.isFinite(y);
        }
        if (!finite) {
            return false; // moved past the float range: nothing is there
        }
        int w = keeps || exact ? HiddenParts.convexWinding(mover) : Polygons.convexWinding(moved);
        if (w == 0 || !keeps && !exact && repeatsNeighbour(moved)) {
            return ConvexSweep.movedOverlaps(mover, dx, dy, obstacle);
        }
        return moverFirst ? Polygons.convexOverlap(moved, w, HiddenParts.raw(obstacle), HiddenParts.convexWinding(obstacle))
                : Polygons.convexOverlap(HiddenParts.raw(obstacle), HiddenParts.convexWinding(obstacle), moved, w);
    }

    /**
     * Can no rounding of the mover's coordinates, moved by up to {@code reach} on each axis
     * (as {@code x + t * vx} in float, t in [0, 1]), bend a corner the other way? Then the
     * moved outline is convex with the mover's winding wherever the probes put it, and
     * {@link #movedOverlaps(Polygon, float, float, Polygon, float[], boolean, boolean)} need not check
     * it each time: asked once a sweep instead of once a probe.
     *
     * <p>A moved coordinate is the exact sum rounded to float, off by at most
     * {@code delta}, half a float step at the largest size M a moved coordinate can have, here
     * taken as {@code M * 2^-23}, twice that. The exact move keeps every orientation
     * {@code o = u x v} (u and v from a corner to its neighbours); moving each point by at
     * most delta on each axis moves u and v by at most {@code 2 delta} on each axis, so o by
     * at most {@code 2 delta (|u| + |v|) + 8 delta^2} (|.| the sum of the axes' sizes). A
     * corner that turns the mover's way by more than that, with room for double's rounding
     * of o, turns that way after any rounding, and so does every corner on the way there, so
     * the outline still goes round once: convex. False for a straight corner (a vertex
     * midway along a side), which any rounding may bend.
     */
    public static boolean keepsConvex(Polygon mover, double reach) {
        double[] c = HiddenParts.corners(mover);
        int w = HiddenParts.convexWinding(mover);
        double size = 0;
        for (double v : c) {
            size = Math.max(size, Math.abs(v));
        }
        double delta = Math.max((size + reach) * Tolerance.FLOAT_STEP, Float.MIN_VALUE);
        for (int i = 0, a = c.length - 2; i < c.length; a = i, i += 2) {
            int b = i + 2 == c.length ? 0 : i + 2;
            double ux = c[i] - c[a], uy = c[i + 1] - c[a + 1], vx = c[b] - c[a], vy = c[b + 1] - c[a + 1];
            double o = ux * vy - uy * vx;
            double bound = 2 * delta * (Math.abs(ux) + Math.abs(uy) + Math.abs(vx) + Math.abs(vy)) + 8 * delta * delta
                    + Tolerance.TURN_ROUNDING * (Math.abs(ux * vy) + Math.abs(uy * vx));
            if (!(w * o > bound)) {
                return false;
            }
        }
        return true;
    }

    /** Does some vertex sit on the next one (which {@link Polygon#of} refuses)? */
    private static boolean repeatsNeighbour(float[] xy) {
        for (int i = 0, j = xy.length - 2; i < xy.length; j = i, i += 2) {
            if (xy[i] == xy[j] && xy[i + 1] == xy[j + 1]) {
                return true;
            }
        }
        return false;
    }

    /**
     * Per thread, what a convex sweep works in: its clip, its walk, the look-back's near
     * corners and their next steps, and arrays for moved coordinates, one per length (a sweep
     * moves a polygon several times a call). Kept rather than made per call so that a sweep
     * allocates nothing but its hit, whatever the JIT inlines.
     */
    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    /** See {@link #SCRATCH}. */
    private static final class Scratch {
        public final Slabs.Clip clip = new Slabs.Clip();
        final SweptPairs.Search search = new SweptPairs.Search(Slabs.INF, true);
        private float[][] byLength = new float[0][];
        private int[] near = new int[16];
        private float[] steps = new float[32];

        /** An array of at least n ints, for the near corners. */
        int[] near(int n) {
            if (near.length < n) {
                near = new int[Math.max(n, 2 * near.length)];
            }
            return near;
        }

        /** An array of at least n floats, for the near corners' next steps. */
        float[] steps(int n) {
            if (steps.length < n) {
                steps = new float[Math.max(n, 2 * steps.length)];
            }
            return steps;
        }

        /** An array of exactly {@code length} floats (the polygon tests read the whole array). */
        public float[] moved(int length) {
            if (length >= byLength.length) {
                byLength = java.util.Arrays.copyOf(byLength, Math.max(length + 1, 2 * byLength.length));
            }
            if (byLength[length] == null) {
                byLength[length] = new float[length];
            }
            return byLength[length];
        }
    }
}
