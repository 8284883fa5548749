package hitbox.internal;

import hitbox.*;

import java.util.List;
import java.util.function.DoubleUnaryOperator;

/**
 * The contact of a curved shape ({@link Ellipse}, {@link Capsule}) with a concave polygon:
 * the shortest push that clears the whole polygon, not just its nearest convex piece (pushing
 * out of one piece can land the shape in another).
 *
 * <p>The translations of the curved shape K that overlap the polygon are the union of the
 * regions {@code C_i (+) -K} over the polygon's convex pieces C_i. Along a direction n, each
 * region is an open interval of push lengths (lo_i, hi_i); the shortest push along n that
 * clears them all, f(n), is the least d &gt;= 0 in no interval. The shortest push overall is
 * the least f(n) over n: the union's boundary point nearest the origin is reached along a
 * straight push that stays inside the union. Each interval end is the entry time of the
 * shape moving along the line towards the piece ({@link ConvexSweep#entry}, never late, so a
 * push is never short); f is sampled at 48 directions (the four axis directions exact), at
 * every edge normal of the pieces and at a capsule's side normals, and its local least values
 * refined by golden-section search, then placed again on the support functions of the piece
 * whose region the push leaves ({@code polish}). The depth is found to about 1e-6 pixels
 * (the entries' tolerance) where the least is smooth, exactly where it is a single region's
 * nearest boundary point; a least value in a gap narrower than the sampling between
 * directions can be missed, giving a longer push that still clears.
 *
 * <p>Every candidate goes through {@link Contacts.Shortest}, the tie rule of {@link Contact}:
 * depths within {@code SLACK} tie, and the keys of normals found by this search within
 * {@link Tolerance#SEARCH_KEY_TIE}. Costs a few thousand support evaluations per direction:
 * a rare pair.
 */
public final class CurvedClearance {
    private CurvedClearance() {
    }

    private static final int STEPS = 48;

    /**
     * Depths this close (pixels) tie for the rule of {@link Contact}: each interval end is an
     * entry found to within {@link ConvexSweep#TOUCH}, so the same push reached along two
     * directions (or through two different pieces) can come out that far apart.
     */
    private static final double SLACK = 2 * ConvexSweep.TOUCH;

    /**
     * How far past a cone's end (radians) f must have risen by ten times {@link #SLACK} for
     * the end to be offered ({@code coneEnd}): a steep rise, not the slow one past a side.
     */
    private static final double CONE_STEP = 1e-4;

    /**
     * The contact of curved k and concave polygon p (they overlap); normal from the first
     * shape to the second: from k to p unless {@code polygonFirst}.
     */
    public static Contact contact(Shape k, Polygon p, boolean polygonFirst) {
        List<Object> pieces = ConvexSweep.pieces(p);
        Object round = ConvexSweep.pieces(k).get(0);
        Rect a = k.bounds(), b = p.bounds();
        // Farther than any push can need: both boxes' sizes and the gap between them.
        double far = 2 * (Math.max(a.w(), a.h()) + Math.max(b.w(), b.h()))
                + Math.hypot((double) a.x() - b.x(), (double) a.y() - b.y()) + 1;
        // The push moves k along n: k is the second shape, or the normal turns round; the
        // tie rule reads the normals as they will be reported (flip).
        Contacts.Shortest best = new Contacts.Shortest(SLACK, !polygonFirst);
        // Every candidate, however found, goes through the one tie rule (it used to be the
        // first found of the least depths, so an equally short direction the rule prefers
        // could be dropped): the samples first, the four axis directions among them exact,
        // then the refined least values, then the edge normals. A refined direction that
        // ties with an exact one in every key leaves the exact one in place.
        double[] f = new double[STEPS];
        for (int i = 0; i < STEPS; i++) {
            double[] n = unit(2 * Math.PI * i / STEPS);
            f[i] = push(round, pieces, n[0], n[1], far, null);
            best.offer(n[0], n[1], f[i]);
        }
        int[] last = new int[1];
        for (int i = 0; i < STEPS; i++) {
            double prev = f[(i + STEPS - 1) % STEPS], next = f[(i + 1) % STEPS];
            if (f[i] <= prev && f[i] <= next) {
                double[] r = refine(round, pieces, 2 * Math.PI * (i - 1) / STEPS, 2 * Math.PI * (i + 1) / STEPS, far);
                if (!polish(best, round, pieces, r[0], far, last)) {
                    double[] n = unit(r[0]);
                    best.offer(n[0], n[1], r[1]);
                }
            }
        }
        for (Object piece : pieces) {
            offerEdgeNormals(best, round, pieces, (double[]) piece, far);
        }
        // A capsule's sides: where a whole cone of directions is equally short (a corner of
        // the polygon on the capsule's segment), a side's normal can be the cone's end.
        offerEdgeNormals(best, round, pieces, Supports.straightEdges(k), far);
        coneEnds(best, round, pieces, f, far);
        return best.contact();
    }

    /**
     * The ends of a cone of equally short pushes where another region starts. When k is
     * round at its ends with one radius (a capsule, or an ellipse with equal radii) and the
     * best push is that radius, the origin can be a corner of a region (a polygon corner on
     * the capsule's segment): every direction of a cone then pushes exactly that far, and the
     * rule's pick is one of the cone's ends or an axis direction inside it (sampled). An end
     * bounded by a straight side is an edge normal, offered already; an end where the push's
     * end point enters another region is found here, by bisection between a direction in the
     * cone (a sample, or the best so far) and a neighbouring sample outside it, and offered
     * when f rises steeply past it (beyond a straight side it rises only as the square of the
     * angle, and the bisection would stop about 1e-3 radians past the exact normal).
     */
    private static void coneEnds(Contacts.Shortest best, Object round, List<Object> pieces, double[] f, double far) {
        ConvexSweep.Round k = (ConvexSweep.Round) round;
        double d = best.depth, limit = d + SLACK, step = 2 * Math.PI / STEPS;
        if (k.a != k.b || !(Math.abs(d - k.a) <= SLACK)) {
            return;
        }
        double bestAngle = Math.atan2(best.ny, best.nx);
        for (int i = 0; i < STEPS; i++) {
            if (f[i] <= limit) {
                for (int j : new int[] {i - 1, i + 1}) {
                    if (f[Math.floorMod(j, STEPS)] > limit) {
                        coneEnd(best, round, pieces, step * i, step * j, limit, far);
                    }
                }
            }
        }
        int below = (int) Math.floor(bestAngle / step);
        for (int j : new int[] {below, below + 1}) {
            if (f[Math.floorMod(j, STEPS)] > limit) {
                coneEnd(best, round, pieces, bestAngle, step * j, limit, far);
            }
        }
    }

    /** Bisection between angle in (f at most limit) and angle out (f above it); see {@link #coneEnds}. */
    private static void coneEnd(Contacts.Shortest best, Object round, List<Object> pieces, double in, double out,
                                double limit, double far) {
        for (int s = 0; s < 60 && Math.abs(out - in) > Tolerance.CLEARANCE_ANGLE; s++) {
            double mid = (in + out) / 2;
            double[] u = unit(mid);
            // Closer to the cone's flat depth than the tie slack, so that the end offered
            // pushes as far as the cone, not up to the slack farther.
            if (push(round, pieces, u[0], u[1], far, null) <= limit - SLACK * 63 / 64) {
                in = mid;
            } else {
                out = mid;
            }
        }
        double[] past = unit(in + Math.signum(out - in) * CONE_STEP);
        if (push(round, pieces, past[0], past[1], far, null) > limit + 10 * SLACK) {
            double[] u = unit(in);
            best.offer(u[0], u[1], push(round, pieces, u[0], u[1], far, null));
        }
    }

    /** Offers the push along both normals of every edge of the corners xy. */
    private static void offerEdgeNormals(Contacts.Shortest best, Object round, List<Object> pieces, double[] xy,
                                         double far) {
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
            if (ex == 0 && ey == 0) {
                continue;
            }
            for (double angle : new double[] {Math.atan2(ex, -ey), Math.atan2(-ex, ey)}) {
                double[] u = unit(angle);
                best.offer(u[0], u[1], push(round, pieces, u[0], u[1], far, null));
            }
        }
    }

    /**
     * A least value of f found near the angle, placed again without the entries' noise: f
     * there is the push out of one piece's region (the piece whose interval ended last), and
     * where that region's boundary is nearest the origin, the ray's way out of it is as long
     * as the two shapes' support functions say ({@code reach(piece, n) + reach(k, -n)},
     * exact and smooth, its least found to a double's resolution). The entries stop anywhere
     * within {@link ConvexSweep#TOUCH}, so f wobbles by up to about 1e-6 and its golden search
     * ends up to 1e-3 radians off a flat least, where it ties (within the slack) with the
     * exact least and the rule could prefer it, so that mirror images disagree. Offered, in
     * place of the search's, only when f there agrees (a least at a corner of the union,
     * where two regions meet, is not one of these and is left as found): was it?
     */
    private static boolean polish(Contacts.Shortest best, Object round, List<Object> pieces, double angle, double far,
                                  int[] last) {
        double[] n = unit(angle);
        push(round, pieces, n[0], n[1], far, last);
        if (last[0] < 0) {
            return false;
        }
        Object piece = pieces.get(last[0]);
        DoubleUnaryOperator out = t -> {
            double[] u = unit(t);
            return reach(piece, u[0], u[1]) + ((ConvexSweep.Round) round).reach(-u[0], -u[1]);
        };
        double[] s = Golden.least(out, angle - Math.PI / STEPS, angle + Math.PI / STEPS, 80, Tolerance.SUPPORT_ANGLE);
        // A least flat to the fourth order (a polygon corner at the centre of curvature of an
        // ellipse's end) taken on the axis when it is as short, to within the rounding of the
        // support sums (far is the scene's size), so that mirror images agree.
        s = Golden.onAxis(out, s, Tolerance.SUPPORT_SUM_ROUNDING * far);
        double[] m = unit(s[0]);
        if (!(Math.abs(push(round, pieces, m[0], m[1], far, null) - s[1]) <= SLACK)) {
            return false;
        }
        best.offer(m[0], m[1], s[1]);
        return true;
    }

    /** How far a convex piece's corners reach along (nx, ny). */
    private static double reach(Object piece, double nx, double ny) {
        double[] xy = (double[]) piece;
        double most = Double.NEGATIVE_INFINITY;
        for (int i = 0; i + 1 < xy.length; i += 2) {
            most = Math.max(most, xy[i] * nx + xy[i + 1] * ny);
        }
        return most;
    }

    /**
     * The unit direction at the angle, exact where it is an axis direction: cos and sin of
     * such an angle round to about 6e-17, not 0 (as in {@link Supports}).
     */
    private static double[] unit(double angle) {
        double nx = StrictMath.cos(angle), ny = StrictMath.sin(angle);
        if (Math.abs(nx) < Tolerance.AXIS_SNAP) {
            return new double[] {0, Math.signum(ny)};
        }
        if (Math.abs(ny) < Tolerance.AXIS_SNAP) {
            return new double[] {Math.signum(nx), 0};
        }
        return new double[] {nx, ny};
    }

    /**
     * f along unit direction (nx, ny): the shortest push of k along it that clears every
     * piece; the index of the piece whose interval it ends goes into {@code last[0]} (-1 for
     * no push), unless last is null.
     */
    private static double push(Object k, List<Object> pieces, double nx, double ny, double far, int[] last) {
        double[] lo = new double[pieces.size()], hi = new double[pieces.size()];
        double[] normal = new double[2];
        for (int i = 0; i < pieces.size(); i++) {
            Object c = pieces.get(i);
            // Coming back from far along n: hi (entered at time te of the way back).
            double te = ConvexSweep.entry(k, c, far * nx, far * ny, -far * nx, -far * ny, normal);
            if (te > 1) {
                lo[i] = hi[i] = Double.NEGATIVE_INFINITY; // the line misses the piece
                continue;
            }
            hi[i] = far * (1 - te);
            if (hi[i] <= 0) {
                lo[i] = hi[i]; // wholly behind the start: no push along n meets it
                continue;
            }
            double ts = ConvexSweep.entry(k, c, -far * nx, -far * ny, far * nx, far * ny, normal);
            lo[i] = -far + (ts > 1 ? far : far * ts);
        }
        double d = 0;
        int ended = -1;
        for (boolean moved = true; moved; ) {
            moved = false;
            for (int i = 0; i < lo.length; i++) {
                if (lo[i] < d && d < hi[i]) {
                    d = hi[i];
                    ended = i;
                    moved = true;
                }
            }
        }
        if (last != null) {
            last[0] = ended;
        }
        return d;
    }

    /** Golden-section search for the least f in [lo, hi]: {angle, f}. */
    private static double[] refine(Object k, List<Object> pieces, double lo, double hi, double far) {
        return Golden.least(t -> {
            double[] n = unit(t);
            return push(k, pieces, n[0], n[1], far, null);
        }, lo, hi, 32, Tolerance.CLEARANCE_ANGLE);
    }
}
