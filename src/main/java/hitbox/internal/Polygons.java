package hitbox.internal;

import hitbox.*;

import java.math.BigDecimal;

/**
 * Polygon maths behind {@link Collide} and {@link Polygon}; {@code xy} is x0, y0, x1, y1, ....
 *
 * <p>Edge i runs from vertex i to vertex i + 1, and the last edge closes the polygon back to
 * vertex 0. Every decision is an exact orientation sign ({@link Lines#orient}), never a
 * computed crossing point, so the answers on whole-number coordinates are exact.
 *
 * <p>The collision tests rest on one fact about open sets. The inside of a simple polygon is
 * connected, so if no point of a polygon's outline lies inside another shape S (itself
 * connected), then S is wholly inside the polygon or wholly outside it, and one point of S
 * settles which. Hence "polygon meets S" is "an edge reaches into S, or a point of S is
 * inside the polygon"; the edge tests and the one-point test below are exact, so the whole
 * answer is.
 *
 * <p>This class is longer than most (about 750 lines) because every piece of it is one idea
 * used by many pairs (the even-odd test, an edge reaching into a polygon, the convex fast
 * path, the exact areas and corners), kept in one home so that {@link Collide}, {@link Polygon}, {@link Contact} and
 * the sweeps never copy it.
 */
public final class Polygons {
    private Polygons() {
    }

    /**
     * How much a distance from a point to an edge, found in double with a square root, may be
     * off relative to the coordinates' size: a few units of 2^-53 of it, with room to spare.
     * Subtracted so that the distance returned is never more than the true one.
     */
    private static final double DISTANCE_ROUNDING = 1e-13;

    /**
     * Throws with a learner's message if {@code xy} is not a valid simple polygon: pairs of
     * finite coordinates, at least 3 vertices, no vertex repeating its neighbour, some area,
     * and no two edges meeting anywhere but at the corner they share.
     */
    public static void validate(float[] xy) {
        if (xy.length % 2 != 0) {
            throw new IllegalArgumentException("a polygon needs x, y pairs, but got an odd number of coordinates ("
                    + xy.length + ")");
        }
        int n = xy.length / 2;
        if (n < 3) {
            throw new IllegalArgumentException("a polygon needs at least 3 vertices, got " + n);
        }
        for (int i = 0; i < xy.length; i++) {
            // The name is built only for a refusal: a polygon made every frame (a turned body's
            // shape) would otherwise spend most of its checking on strings no one reads.
            if (!Float.isFinite(xy[i])) {
                Check.finite((i % 2 == 0 ? "x" : "y") + (i / 2), xy[i]);
            }
        }
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            if (xy[2 * i] == xy[2 * k] && xy[2 * i + 1] == xy[2 * k + 1]) {
                String point = "(" + xy[2 * i] + ", " + xy[2 * i + 1] + ")";
                throw new IllegalArgumentException(k == 0
                        ? "vertices " + i + " and 0 are the same point " + point
                        + ": a polygon closes itself, so do not repeat the first vertex at the end"
                        : "vertices " + i + " and " + k + " are the same point " + point
                        + ": remove the repeated vertex");
            }
        }
        boolean flat = true;
        for (int i = 2; i < n && flat; i++) {
            flat = orient(xy, 0, 1, i) == 0; // vertex 1 differs from vertex 0, checked above
        }
        if (flat) {
            throw new IllegalArgumentException("the polygon has no area: all its vertices lie on one line");
        }
        for (int i = 0; i < n; i++) {
            // Neighbouring edges i and i + 1 share vertex i + 1; they may not fold back over
            // each other (the third vertex going back along the same line).
            int b = (i + 1) % n;
            int c = (i + 2) % n;
            if (orient(xy, i, b, c) == 0 && dot(xy, b, i, c) > 0) {
                throw new IllegalArgumentException("edges " + i + " and " + b + " overlap (the outline folds back on"
                        + " itself at vertex " + b + "): a polygon's edges may only meet at the corner they share");
            }
            for (int j = i + 2; j < n; j++) {
                if (i == 0 && j == n - 1) {
                    continue; // edges n-1 and 0 are neighbours: checked above
                }
                int d = (j + 1) % n;
                if (segmentsMeet(xy, i, b, j, d)) {
                    boolean cross = Lines.opposite(orient(xy, i, b, j), orient(xy, i, b, d))
                            && Lines.opposite(orient(xy, j, d, i), orient(xy, j, d, b));
                    throw new IllegalArgumentException("edges " + i + " and " + j + (cross ? " cross" : " touch")
                            + ": a polygon's edges may only meet at the corner they share"
                            + " (edge i runs from vertex i to vertex i + 1)");
                }
            }
        }
    }

    /** The bounding rectangle of the vertices, rounded outwards ({@link Bounds#enclosing}). */
    public static Rect bounds(float[] xy) {
        float minX = xy[0], maxX = xy[0], minY = xy[1], maxY = xy[1];
        for (int i = 2; i < xy.length; i += 2) {
            minX = Math.min(minX, xy[i]);
            maxX = Math.max(maxX, xy[i]);
            minY = Math.min(minY, xy[i + 1]);
            maxY = Math.max(maxY, xy[i + 1]);
        }
        return Bounds.enclosing(minX, minY, maxX, maxY);
    }

    /**
     * Is the point strictly inside? On an edge or at a vertex is not. Even-odd crossing count
     * along a ray to the right, with the half-open rule: an edge counts when one end is below
     * the point's y and the other is at or above it (the comparison {@code y > py} differs at
     * its ends), so a ray through a vertex counts that vertex exactly once, or not at all at
     * a spike, by rule and not by luck. Which side of the edge the point is on is an exact
     * orientation sign, with no crossing x computed. Fewer than 3 vertices: false.
     *
     * <p>Reference: E. Haines, "Point in Polygon Strategies", Graphics Gems IV (1994), and
     * W. R. Franklin's PNPOLY, made exact with an orientation test.
     */
    /**
     * The crossing rule of {@link #contains}, one edge at a time: 1 if the ray from (px, py)
     * to the right crosses the edge from a to b, 0 if not, -1 if the point lies on the edge.
     * An edge counts only when one end is below the point's level and the other at or above
     * it (half-open), so a corner the ray passes through is counted once and a corner it
     * only touches twice or not at all.
     */
    public static int rayCrossing(double ax, double ay, double bx, double by, double px, double py) {
        if ((ay > py) == (by > py)) {
            return 0;
        }
        double o = Lines.orient(ax, ay, bx, by, px, py);
        if (o == 0) {
            return -1;
        }
        // The ray to the right crosses the edge when the point is left of the crossing; which
        // sign of o that is depends on whether the edge goes up or down.
        return (by > ay ? o > 0 : o < 0) ? 1 : 0;
    }

    public static boolean contains(float[] xy, double px, double py) {
        int n = xy.length / 2;
        if (n < 3) {
            return false;
        }
        boolean inside = false;
        double ax = xy[2 * n - 2];
        double ay = xy[2 * n - 1];
        for (int i = 0; i < n; i++) {
            double bx = xy[2 * i];
            double by = xy[2 * i + 1];
            if ((ay > py) != (by > py)) {
                // The edge crosses the point's level somewhere in its own x range, so a point
                // left of that whole range is left of the crossing (counts, and is not on the
                // edge) and a point right of it is right of it (does not count, not on the
                // edge): plain comparisons, exact. Only a point within the range needs the sign.
                if (px < ax && px < bx) {
                    inside = !inside;
                    ax = bx;
                    ay = by;
                    continue;
                }
                if (px > ax && px > bx) {
                    ax = bx;
                    ay = by;
                    continue;
                }
                int crossing = rayCrossing(ax, ay, bx, by, px, py);
                if (crossing < 0) {
                    return false; // on the edge: its y range holds py, and it is on the line
                }
                if (crossing > 0) {
                    inside = !inside;
                }
            } else if (ay == py && (by == py ? px >= Math.min(ax, bx) && px <= Math.max(ax, bx) : ax == px)) {
                return false; // on a horizontal edge at the point's level, or on vertex a
            }
            ax = bx;
            ay = by;
        }
        return inside;
    }

    /**
     * Which way the vertices go: +1 or -1 (the sign of {@link Lines#orient} for a point inside
     * next to any edge, when walking from vertex i to vertex i + 1), or 0 for no area. Read at
     * the leftmost (then topmost) vertex, which is always a convex corner, so one exact
     * orientation decides it, with no area sum that could round.
     */
    public static int winding(float[] xy) {
        int n = xy.length / 2;
        if (n < 3) {
            return 0;
        }
        int m = leftmost(xy);
        int prev = distinctNeighbour(xy, m, n - 1);
        int next = distinctNeighbour(xy, m, 1);
        double o = orient(xy, prev, m, next);
        // 0 only for input Polygon.of refuses (all on one line, or folding back on itself).
        return o > 0 ? 1 : (o < 0 ? -1 : 0);
    }

    /** The index of the leftmost vertex (the topmost of those, then the first). */
    public static int leftmost(float[] xy) {
        int m = 0;
        for (int i = 1; i < xy.length / 2; i++) {
            if (xy[2 * i] < xy[2 * m] || (xy[2 * i] == xy[2 * m] && xy[2 * i + 1] < xy[2 * m + 1])) {
                m = i;
            }
        }
        return m;
    }

    /** The first vertex from m, stepping by {@code step} (1 or n - 1), that is not at m's place. */
    public static int distinctNeighbour(float[] xy, int m, int step) {
        int n = xy.length / 2;
        int k = (m + step) % n;
        while (k != m && xy[2 * k] == xy[2 * m] && xy[2 * k + 1] == xy[2 * m + 1]) {
            k = (k + step) % n;
        }
        return k;
    }

    /**
     * The winding (+1 or -1, as {@link #winding}) of a convex outline, or 0 if it is not
     * convex or has no area. Convex here means: every corner turns the same way (a straight
     * corner, a vertex in the middle of a side, is allowed; folding back along the same line
     * is not), and the edge directions go round once: their x parts change sign exactly twice
     * around the outline, and so do their y parts. An outline that turns the same way at every
     * corner but winds round twice (a pentagram) changes sign at least four times, since the
     * direction's angle then passes each vertical and each horizontal direction twice.
     * Repeated vertices (zero-length edges) are skipped, so a raw array with the first vertex
     * again at the end answers as without it. Exact orientation signs; n orientations in all,
     * the price of the convex fast path on a raw array.
     *
     * <p>Reference: the convexity test of P. Schorn and F. Fisher, "Testing the Convexity of
     * a Polygon", Graphics Gems IV (1994).
     */
    public static int convexWinding(float[] xy) {
        int n = xy.length / 2;
        if (n < 3) {
            return 0;
        }
        // The last edge with length, and the signs of the last edges with a nonzero x and y
        // part: where the walk round starts, so that the sign changes are counted cyclically.
        int last = n - 1;
        while (last >= 0 && sameVertex(xy, last, last + 1 == n ? 0 : last + 1)) {
            last--;
        }
        if (last < 0) {
            return 0;
        }
        int signX = 0, signY = 0;
        for (int i = last; i >= 0 && (signX == 0 || signY == 0); i--) {
            int k = i + 1 == n ? 0 : i + 1;
            if (signX == 0) {
                signX = sign(xy[2 * k] - (double) xy[2 * i]);
            }
            if (signY == 0) {
                signY = sign(xy[2 * k + 1] - (double) xy[2 * i + 1]);
            }
        }
        double ax = xy[2 * last], ay = xy[2 * last + 1];
        int turn = 0, flipsX = 0, flipsY = 0;
        for (int i = 0; i < n; i++) {
            int k = i + 1 == n ? 0 : i + 1;
            double bx = xy[2 * i], by = xy[2 * i + 1], cx = xy[2 * k], cy = xy[2 * k + 1];
            if (bx == cx && by == cy) {
                continue;
            }
            // (ax, ay) starts the edge with length before this one, which ends at (bx, by).
            double o = Lines.orient(ax, ay, bx, by, cx, cy);
            if (o == 0) {
                if ((bx - ax) * (cx - bx) + (by - ay) * (cy - by) <= 0) {
                    return 0; // folds back along the same line
                }
            } else if (turn == 0) {
                turn = o > 0 ? 1 : -1;
            } else if ((o > 0 ? 1 : -1) != turn) {
                return 0; // a corner turning the other way: concave (or crossing itself)
            }
            int sx = sign(cx - bx), sy = sign(cy - by);
            if (sx != 0 && sx != signX) {
                flipsX++;
                signX = sx;
            }
            if (sy != 0 && sy != signY) {
                flipsY++;
                signY = sy;
            }
            ax = bx;
            ay = by;
        }
        return flipsX <= 2 && flipsY <= 2 ? turn : 0;
    }

    /** +1, -1 or 0 (for 0, -0 and NaN). */
    private static int sign(double v) {
        return v > 0 ? 1 : (v < 0 ? -1 : 0);
    }

    private static boolean sameVertex(float[] xy, int i, int k) {
        return xy[2 * i] == xy[2 * k] && xy[2 * i + 1] == xy[2 * k + 1];
    }

    /**
     * Do two convex outlines overlap (their open insides meet)? {@code wa} and {@code wb} are
     * their windings from {@link #convexWinding}, not 0.
     *
     * <p>The separating axis theorem asked with orientation signs instead of projections: two
     * convex polygons have disjoint insides exactly when some edge's line has the other polygon
     * wholly on or outside it (the edges of their Minkowski difference are the edges of the
     * two, so if no edge line separates them the origin is inside the difference). On or
     * outside edge ab is {@code w * orient(a, b, q) <= 0} for every vertex q, an exact sign
     * ({@link Lines#orient}), so touching is decided exactly for every float, not only for
     * whole numbers, with no projection rounded and nothing allocated. An edge is given up at
     * the first vertex strictly inside it, and the search for that vertex starts where the
     * previous edge found one, so overlapping pairs cost about one orientation per edge.
     *
     * <p>Reference: C. Ericson, <i>Real-Time Collision Detection</i> (2005), 5.2.1 (separating
     * axis test); S. Gottschalk, "Separating axis theorem", 1996.
     */
    public static boolean convexOverlap(float[] a, int wa, float[] b, int wb) {
        return !edgeSeparates(a, wa, b) && !edgeSeparates(b, wb, a);
    }

    /**
     * Do convex polygon p (a {@code Polygon}'s outline: winding w, no NaN) and the open rectangle (x, y, w, h), w and h
     * above 0, overlap? {@link #convexOverlap} with the rectangle as the other polygon, its
     * corners summed in double (as {@link RawTests#rectRect} sums them), so no array is made:
     * the rectangle's own edges separate when p's box is on or past one of them, and an edge of
     * p separates when every corner of the rectangle is on or outside its line (exact
     * orientations). A sweep asks this at every float position it looks at.
     */
    public static boolean convexRectOverlap(float[] p, int w, float x, float y, float width, float height) {
        double right = (double) x + width, bottom = (double) y + height;
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
        int n = p.length / 2;
        for (int i = 0; i < p.length; i += 2) {
            minX = Math.min(minX, p[i]);
            maxX = Math.max(maxX, p[i]);
            minY = Math.min(minY, p[i + 1]);
            maxY = Math.max(maxY, p[i + 1]);
        }
        if (maxX <= x || minX >= right || maxY <= y || minY >= bottom) {
            return false;
        }
        double ax = p[2 * n - 2], ay = p[2 * n - 1];
        for (int i = 0; i < n; i++) {
            double bx = p[2 * i], by = p[2 * i + 1];
            if ((ax != bx || ay != by)
                    && !(w * Lines.orient(ax, ay, bx, by, x, y) > 0)
                    && !(w * Lines.orient(ax, ay, bx, by, right, y) > 0)
                    && !(w * Lines.orient(ax, ay, bx, by, right, bottom) > 0)
                    && !(w * Lines.orient(ax, ay, bx, by, x, bottom) > 0)) {
                return false;
            }
            ax = bx;
            ay = by;
        }
        return true;
    }

    /** Does the line of some edge of convex p (winding w) have every vertex of q on or outside it? */
    public static boolean edgeSeparates(float[] p, int w, float[] q) {
        int n = p.length / 2, m = q.length / 2;
        int start = 0;
        double ax = p[2 * n - 2], ay = p[2 * n - 1];
        for (int i = 0; i < n; i++) {
            double bx = p[2 * i], by = p[2 * i + 1];
            if (ax != bx || ay != by) {
                int k = start;
                boolean inside = false;
                for (int c = 0; c < m; c++) {
                    if (w * Lines.orient(ax, ay, bx, by, q[2 * k], q[2 * k + 1]) > 0) {
                        inside = true;
                        break;
                    }
                    k = k + 1 == m ? 0 : k + 1;
                }
                if (!inside) {
                    return true;
                }
                start = k;
            }
            ax = bx;
            ay = by;
        }
        return false;
    }

    /**
     * Do two polygon shapes overlap? Their cached bounds first (touching boxes are apart,
     * since the boxes hold the open polygons), then the convex fast path when both are
     * convex, else {@link Collide#polygonPolygon}.
     */
    public static boolean overlap(Polygon p, Polygon q) {
        Rect r = p.bounds(), s = q.bounds();
        if (!RawTests.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h())) {
            return false;
        }
        int wp = HiddenParts.convexWinding(p), wq = HiddenParts.convexWinding(q);
        if (wp != 0 && wq != 0) {
            return convexOverlap(HiddenParts.raw(p), wp, HiddenParts.raw(q), wq);
        }
        return RawTests.polygonPolygon(HiddenParts.raw(p), HiddenParts.raw(q));
    }

    /**
     * Are the two polygons' bounding boxes apart (touching counts as apart, since polygons
     * are open)? A cheap first test; false means "maybe".
     */
    public static boolean boundsApart(float[] a, float[] b) {
        return max(a, 0) <= min(b, 0) || max(b, 0) <= min(a, 0)
                || max(a, 1) <= min(b, 1) || max(b, 1) <= min(a, 1);
    }

    /** Is every vertex of {@code inner} in the closed bounding box of {@code outer}'s vertices? */
    public static boolean boxWithin(float[] inner, float[] outer) {
        return min(inner, 0) >= min(outer, 0) && max(inner, 0) <= max(outer, 0)
                && min(inner, 1) >= min(outer, 1) && max(inner, 1) <= max(outer, 1);
    }

    /** The largest x ({@code axis} 0) or y (1) of the vertices. */
    private static float max(float[] xy, int axis) {
        float m = xy[axis];
        for (int i = axis + 2; i < xy.length - 1 + axis; i += 2) {
            m = Math.max(m, xy[i]);
        }
        return m;
    }

    /** The smallest x ({@code axis} 0) or y (1) of the vertices. */
    private static float min(float[] xy, int axis) {
        float m = xy[axis];
        for (int i = axis + 2; i < xy.length - 1 + axis; i += 2) {
            m = Math.min(m, xy[i]);
        }
        return m;
    }

    /**
     * Standing at vertex v, does a small step in direction d go strictly inside? The inside
     * next to v is the open wedge between the edges prev-v and v-next: at a convex corner the
     * directions inside both edges, at a reflex corner those inside either. Directions along
     * an edge are on the outline, so not inside.
     *
     * @param w the polygon's {@link #winding}
     */
    public static boolean cornerContains(int w, double prevX, double prevY, double vx, double vy,
                                  double nextX, double nextY, double dx, double dy) {
        double inX = vx - prevX;
        double inY = vy - prevY;
        double outX = nextX - vx;
        double outY = nextY - vy;
        double turn = w * (inX * outY - inY * outX);
        boolean insideIn = w * (inX * dy - inY * dx) > 0;
        boolean insideOut = w * (outX * dy - outY * dx) > 0;
        return turn >= 0 ? insideIn && insideOut : insideIn || insideOut;
    }

    /**
     * {@link #cornerContains} at vertex i, between its neighbours; a neighbour at the same
     * place (a repeated vertex, such as the first vertex repeated at the end) is skipped, so
     * raw arrays with repeats answer as they would without them.
     */
    public static boolean cornerContains(int w, float[] xy, int i, double dx, double dy) {
        int n = xy.length / 2;
        int h = distinctNeighbour(xy, i, n - 1);
        int k = distinctNeighbour(xy, i, 1);
        return cornerContains(w, xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], xy[2 * k], xy[2 * k + 1], dx, dy);
    }

    /**
     * Standing at point p (anywhere), does a small step in direction d land strictly inside
     * the polygon? Inside already: yes. On a vertex: the corner's wedge decides. Inside an
     * edge: the side of the edge decides. Elsewhere outside: no. Exact.
     *
     * @param w the polygon's {@link #winding}, not 0
     */
    public static boolean stepsInside(float[] xy, int w, double px, double py, double dx, double dy) {
        int at = locate(xy, px, py);
        if (at >= 0) {
            return cornerContains(w, xy, at, dx, dy);
        }
        if (at < -1) {
            int i = -at - 2, k = (i + 1) % (xy.length / 2);
            return w * (((double) xy[2 * k] - xy[2 * i]) * dy - ((double) xy[2 * k + 1] - xy[2 * i + 1]) * dx) > 0;
        }
        return contains(xy, px, py);
    }

    /**
     * Where the point is on the outline: the index of the vertex it is on, or
     * {@code -(i + 2)} if it is inside edge i (on it, not at its far end), or -1 if it is not
     * on the outline. Exact.
     */
    private static int locate(float[] xy, double px, double py) {
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            double ax = xy[2 * i];
            double ay = xy[2 * i + 1];
            int k = (i + 1) % n;
            double bx = xy[2 * k];
            double by = xy[2 * k + 1];
            if (ax == px && ay == py) {
                return i;
            }
            if (Lines.orient(ax, ay, bx, by, px, py) == 0 && Lines.inBox(ax, ay, bx, by, px, py)
                    && !(bx == px && by == py)) {
                return -(i + 2);
            }
        }
        return -1;
    }

    /**
     * {@link #stepsInside} from vertex v of another polygon, in the direction
     * {@code (p - v) + (q - v)} between its neighbours p and q, decided in exact arithmetic
     * (the direction and every cross product in {@link BigDecimal}): a corner can be far
     * thinner than a double's rounding (coordinates of 1e38 next to 1e-45), and a rounded
     * direction would fall out of it. Runs once per polygon pair.
     */
    public static boolean stepsInsideExact(float[] xy, int w, float vx, float vy, float px, float py, float qx, float qy) {
        BigDecimal bvx = new BigDecimal(vx), bvy = new BigDecimal(vy);
        BigDecimal dx = new BigDecimal(px).subtract(bvx).add(new BigDecimal(qx).subtract(bvx));
        BigDecimal dy = new BigDecimal(py).subtract(bvy).add(new BigDecimal(qy).subtract(bvy));
        int n = xy.length / 2;
        int at = locate(xy, vx, vy);
        if (at >= 0) {
            int h = distinctNeighbour(xy, at, n - 1);
            int j = distinctNeighbour(xy, at, 1);
            double ax = xy[2 * at], ay = xy[2 * at + 1];
            int turn = w * Double.compare(Lines.orient(xy[2 * h], xy[2 * h + 1], ax, ay, xy[2 * j], xy[2 * j + 1]), 0);
            boolean insideIn = w * crossSign(xy[2 * h], xy[2 * h + 1], ax, ay, dx, dy) > 0;
            boolean insideOut = w * crossSign(ax, ay, xy[2 * j], xy[2 * j + 1], dx, dy) > 0;
            return turn >= 0 ? insideIn && insideOut : insideIn || insideOut;
        }
        if (at < -1) {
            int i = -at - 2, k = (i + 1) % n;
            return w * crossSign(xy[2 * i], xy[2 * i + 1], xy[2 * k], xy[2 * k + 1], dx, dy) > 0;
        }
        return contains(xy, vx, vy);
    }

    /** The exact sign of (b - a) x d. */
    private static int crossSign(double ax, double ay, double bx, double by, BigDecimal dx, BigDecimal dy) {
        BigDecimal ex = new BigDecimal(bx).subtract(new BigDecimal(ax));
        BigDecimal ey = new BigDecimal(by).subtract(new BigDecimal(ay));
        return ex.multiply(dy).subtract(ey.multiply(dx)).signum();
    }

    /**
     * Walking the segment from (x1, y1) to (x2, y2), does it step into the polygon's inside
     * somewhere before its far end? Together with "is (x1, y1) inside", that decides whether
     * the closed segment reaches the inside: if it does, take the first point of the walk
     * that is inside; unless it is (x1, y1) itself, the walk steps in just there, from a
     * point of the outline that is not the far end. That point is inside an edge, and the
     * segment crosses the edge properly, or starts on it and heads for the inside side; or it
     * is a vertex, and the walking direction points into the corner's wedge. Touching the
     * outline, running along an edge, or slipping through a notch past its corners is none
     * of these.
     *
     * @param w the polygon's {@link #winding}, not 0
     */
    public static boolean segmentCrossesInto(float[] xy, int w, double x1, double y1, double x2, double y2) {
        int n = xy.length / 2;
        double dx = x2 - x1;
        double dy = y2 - y1;
        for (int i = 0; i < n; i++) {
            double ax = xy[2 * i];
            double ay = xy[2 * i + 1];
            int k = (i + 1) % n;
            double bx = xy[2 * k];
            double by = xy[2 * k + 1];
            double o1 = Lines.orient(ax, ay, bx, by, x1, y1);
            double o2 = Lines.orient(ax, ay, bx, by, x2, y2);
            double oa = Lines.orient(x1, y1, x2, y2, ax, ay);
            double ob = Lines.orient(x1, y1, x2, y2, bx, by);
            if (Lines.opposite(o1, o2) && Lines.opposite(oa, ob)) {
                return true; // a proper crossing, away from every vertex: one way is in
            }
            if (o1 == 0 && o2 != 0 && strictlyBetween(ax, ay, bx, by, x1, y1) && w * o2 > 0) {
                return true; // starts inside edge ab and heads for the inside side
            }
            if (oa == 0 && Lines.inBox(x1, y1, x2, y2, ax, ay) && !(ax == x2 && ay == y2)
                    && cornerContains(w, xy, i, dx, dy)) {
                return true; // passes vertex a (or starts there) heading into its corner
            }
        }
        return false;
    }

    /** Is p, known to be on the line ab, on the segment ab but at neither end? */
    private static boolean strictlyBetween(double ax, double ay, double bx, double by, double px, double py) {
        return Lines.inBox(ax, ay, bx, by, px, py) && !(px == ax && py == ay) && !(px == bx && py == by);
    }

    /** Orientation of vertices i, j, k. */
    private static double orient(float[] xy, int i, int j, int k) {
        return Lines.orient(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1], xy[2 * k], xy[2 * k + 1]);
    }

    /** Dot product of (vertex i - vertex o) and (vertex j - vertex o). */
    private static double dot(float[] xy, int o, int i, int j) {
        double ox = xy[2 * o];
        double oy = xy[2 * o + 1];
        return ((double) xy[2 * i] - ox) * ((double) xy[2 * j] - ox) + ((double) xy[2 * i + 1] - oy) * ((double) xy[2 * j + 1] - oy);
    }

    /** Do the closed edges a-b and c-d (given by vertex indices) have a point in common? */
    private static boolean segmentsMeet(float[] xy, int a, int b, int c, int d) {
        return RawTests.lineLine(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1],
                xy[2 * c], xy[2 * c + 1], xy[2 * d], xy[2 * d + 1]);
    }

    /**
     * Twice the signed area, exactly (the shoelace formula in {@link BigDecimal}): no
     * rounding, no overflow, whatever the coordinates. Its sign follows {@link Lines#orient}.
     */
    public static BigDecimal exactDoubleSignedArea(double[] xy) {
        int n = xy.length / 2;
        BigDecimal sum = BigDecimal.ZERO;
        for (int i = 1; i + 1 < n; i++) {
            sum = sum.add(Lines.exactOrient(xy[0], xy[1], xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3]));
        }
        return sum;
    }

    /** The winding as the sign of the exact area: +1, -1, or 0 for none. */
    public static int areaSign(double[] xy) {
        return exactDoubleSignedArea(xy).signum();
    }

    /**
     * Twice the signed area (shoelace formula), measured from vertex 0 so that large but
     * nearby coordinates keep their precision; a double, rounded (see
     * {@link #exactDoubleSignedArea} for the exact one). Its sign follows {@link Lines#orient}.
     */
    public static double doubleSignedArea(double[] xy) {
        return doubleSignedArea(xy, xy.length / 2);
    }

    /** {@link #doubleSignedArea(double[])} of the first n vertices of xy. */
    public static double doubleSignedArea(double[] xy, int n) {
        double ox = xy[0];
        double oy = xy[1];
        double sum = 0;
        for (int i = 1; i + 1 < n; i++) {
            sum += Lines.orient(ox, oy, xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3]);
        }
        return sum;
    }

    /**
     * Does any vertex equal the next one (the last the first)? {@link #validate} refuses that;
     * {@link #convexWinding} skips it.
     */
    public static boolean repeatsNeighbour(float[] xy) {
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int k = i + 1 == n ? 0 : i + 1;
            if (sameVertex(xy, i, k)) {
                return true;
            }
        }
        return false;
    }

    /**
     * A lower bound on the polygon's margin: the shortest distance from a vertex to an edge
     * that does not end at it, less a bound on its double rounding (so 0 or less for an
     * outline that is not valid, or too small for its coordinates to tell). O(n<sup>2</sup>).
     *
     * <p>Why it matters: move the vertices, each by at most d, along straight paths. The
     * distance from a point to a segment changes by at most the point's move plus the larger
     * move of the segment's ends, so no vertex-to-edge distance drops by more than 2d. Two
     * edges that do not meet can only come to cross by first touching, and touching puts an
     * end of one on the other (a distance 0); neighbouring edges fold over each other only
     * when a vertex reaches its neighbour's edge, and a vertex reaches its neighbour only
     * along that same edge. So a valid outline with margin m stays valid (simple, no repeated
     * vertex, with area) under every move of at most d &lt; m / 2 per vertex; an affine map
     * scales every distance by at least its smaller singular value s, so its image has margin
     * at least s m before rounding.
     */
    public static double margin(float[] xy) {
        int n = xy.length / 2;
        double min = Double.POSITIVE_INFINITY;
        double big = 0;
        for (float v : xy) {
            big = Math.max(big, Math.abs(v));
        }
        for (int j = 0; j < n; j++) {
            int k = j + 1 == n ? 0 : j + 1;
            double ax = xy[2 * j], ay = xy[2 * j + 1];
            double ex = xy[2 * k] - ax, ey = xy[2 * k + 1] - ay;
            double len2 = ex * ex + ey * ey;
            for (int i = 0; i < n; i++) {
                if (i == j || i == k) {
                    continue;
                }
                double px = xy[2 * i] - ax, py = xy[2 * i + 1] - ay;
                double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, (px * ex + py * ey) / len2));
                double d = Math.hypot(px - t * ex, py - t * ey);
                if (d < min) {
                    min = d;
                }
            }
        }
        // Each distance above is off by a few units of 2^-53 of the coordinates' size.
        return min - DISTANCE_ROUNDING * big;
    }

    /**
     * The first vertex where the polygon bends inwards (turns against its {@link #winding}),
     * or -1 if it is convex. Straight vertices (on the line between their neighbours) do not
     * count. Exact orientation signs; assumes a simple polygon, as {@link Polygon#of} makes.
     */
    public static int concaveVertex(float[] xy) {
        int w = winding(xy);
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            if (w * orient(xy, (i + n - 1) % n, i, (i + 1) % n) < 0) {
                return i;
            }
        }
        return -1;
    }

    /**
     * A rectangle's or polygon's vertices in double, x0, y0, x1, y1, .... A rectangle's are
     * its corners top-left, top-right, bottom-right, bottom-left, with the far edges
     * {@code x + w} and {@code y + h} exact in double (rounded to float they are
     * {@link Rect#right()} and {@link Rect#bottom()}); a rectangle of width or height 0 gives
     * four corners that lie on a segment or at a point.
     */
    public static double[] corners(Shape s) {
        return switch (ShapeKind.of(s)) {
            case RECT -> corners((Rect) s, new double[8]);
            case POLYGON -> toDouble(HiddenParts.raw((Polygon) s));
            case ELLIPSE, CAPSULE, CIRCLE, SEGMENT -> throw notStraight(s);
        };
    }

    /** The refusal of a shape that has no corners, for the library's own callers (a bug if it happens). */
    public static IllegalArgumentException notStraight(Shape s) {
        return new IllegalArgumentException("a rectangle or a polygon was expected, not " + s);
    }

    /** A rectangle's corners as {@link #corners(Shape)} gives them, written into {@code into} (length 8). */
    public static double[] corners(Rect r, double[] into) {
        double x = r.x(), y = r.y(), right = x + r.w(), bottom = y + r.h();
        into[0] = x;
        into[1] = y;
        into[2] = right;
        into[3] = y;
        into[4] = right;
        into[5] = bottom;
        into[6] = x;
        into[7] = bottom;
        return into;
    }

    /** The coordinates widened to double (exactly). */
    public static double[] toDouble(float[] xy) {
        double[] d = new double[xy.length];
        for (int i = 0; i < xy.length; i++) {
            d[i] = xy[i];
        }
        return d;
    }

    /**
     * The unit normal of edge i (vertex i to i + 1) pointing out of the polygon, or null for a
     * zero-length edge. {@code turn} is the polygon's {@link Polygons#winding}: the inside is
     * on the side where the orientation has that sign.
     */
    public static double[] outwardNormal(float[] xy, int i, double turn) {
        int n = xy.length / 2;
        int j = (i + 1) % n;
        double ex = (double) xy[2 * j] - xy[2 * i];
        double ey = (double) xy[2 * j + 1] - xy[2 * i + 1];
        double len = Math.hypot(ex, ey);
        if (len == 0) {
            return null;
        }
        // (-ey, ex) is on the positive-orientation side; outward is the other side of the inside.
        return new double[] {turn * ey / len, -turn * ex / len};
    }
}
