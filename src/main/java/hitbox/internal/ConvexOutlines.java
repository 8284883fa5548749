package hitbox.internal;

/**
 * The distance between two convex outlines round an area (rectangles, polygons) that do not
 * overlap, in time in proportion to their corners: {@link Distances}' kernel for that pair,
 * beside its loop over every pair of edges, which takes time in proportion to their product.
 */
final class ConvexOutlines {
    private ConvexOutlines() {
    }

    /**
     * What a call works in, kept by a thread's {@code Distances} scratch so that a call makes
     * nothing: the two outlines walked from their lowest vertices, the vertices of their
     * difference with the vertex of each it is made of, and its edges' squared distances from
     * the origin; grown to the largest seen.
     */
    static final class Work {
        double[] walkAX = new double[0], walkAY = new double[0], walkBX = new double[0], walkBY = new double[0];
        double[] diffX = new double[0], diffY = new double[0], diffD2 = new double[0];
        int[] fromA = new int[0], fromB = new int[0];

        /** Grows the arrays for outlines of na and nb vertices. */
        void grow(int na, int nb) {
            if (walkAX.length <= na) {
                walkAX = new double[na + 1];
                walkAY = new double[na + 1];
            }
            if (walkBX.length <= nb) {
                walkBX = new double[nb + 1];
                walkBY = new double[nb + 1];
            }
            int m = na + nb;
            if (diffX.length <= m) {
                diffX = new double[m + 1];
                diffY = new double[m + 1];
                diffD2 = new double[m];
                fromA = new int[m];
                fromB = new int[m];
            }
        }
    }

    /**
     * The distance between two closed convex outlines that do not overlap, closest points in
     * q (a's, then b's).
     *
     * <p>The distance between A and B is the distance from the origin to their difference
     * {@code A - B = {p - q}}, a convex polygon whose edges are A's edges and B's reversed, in
     * the order of their directions: each of its vertices is {@code a_i - b_j} (a vertex of
     * each), and each of its edges pairs an edge of A with a vertex of B, a vertex of A with
     * an edge of B, or two edges with one direction (the merge of two sorted lists of
     * directions: de Berg et al., <i>Computational Geometry</i>, 3rd ed., section 13.3). The
     * edge of the difference nearest the origin names the features that hold the closest
     * points; their two edges are then measured by {@code Distances.segments}, as
     * {@code Distances.chains} measures every pair, so the answer and its exactness (exact
     * orientation signs where they touch) are those of the pairs' loop, and equally close
     * pairs are chosen by the same rule ({@code Distances.closer}). Every edge of the
     * difference within a rounding of the nearest is measured too: a near tie, or two
     * directions so nearly alike that rounding merged them in the other order (the difference
     * then differs from the true one by a sliver that thin), cannot hide the closest pair.
     * Directions are compared by half turn first (exact), then by the sign of their cross
     * product.
     *
     * <p>Both outlines are round an area (a polygon, a rectangle not flat): then, not
     * overlapping, they share no inside point, and the origin is not inside their difference.
     * Neither has an edge of length 0 (a polygon repeats no vertex; a rectangle with area has
     * none).
     *
     * @param a    a's vertices, x0, y0, x1, y1, ... (only read)
     * @param wa   a's winding, +1 or -1
     * @param b    b's vertices (only read)
     * @param wb   b's winding
     * @param q    receives the closest points
     * @param t    scratch for a candidate pair of points, four long
     * @param feet scratch for a foot, two long
     * @param s    the thread's working arrays
     * @return the distance, 0 when they touch
     */
    static double distance(double[] a, int wa, double[] b, int wb, double[] q, double[] t, double[] feet, Work s) {
        int na = a.length / 2, nb = b.length / 2;
        s.grow(na, nb);
        // Both walked the way their corners turn left (in raw coordinates), so that their
        // directions go round once from angle 0: A from its lowest vertex (least y, then least
        // x), -B from its own lowest, which is B's highest (greatest y, then greatest x).
        double[] ax = s.walkAX, ay = s.walkAY, bx = s.walkBX, by = s.walkBY;
        double scale = Math.max(walk(a, wa, 1, ax, ay), walk(b, wb, -1, bx, by));
        double[] dx = s.diffX, dy = s.diffY;
        int[] fa = s.fromA, fb = s.fromB;
        int count = 0;
        for (int i = 0, j = 0; i < na || j < nb; count++) {
            dx[count] = ax[i] - bx[j];
            dy[count] = ay[i] - by[j];
            fa[count] = i;
            fb[count] = j;
            // +1: A's edge comes first, -1: -B's, 0: one direction (once a walk is round, the other's).
            int first = i == na ? -1 : j == nb ? 1 : firstDirection(ax[i + 1] - ax[i], ay[i + 1] - ay[i],
                    bx[j] - bx[j + 1], by[j] - by[j + 1]);  // -B's edge
            i += first >= 0 ? 1 : 0;
            j += first <= 0 ? 1 : 0;
        }
        dx[count] = dx[0];
        dy[count] = dy[0];
        // The squared distance from the origin to each edge of the difference that faces it
        // (the origin on the edge's outer side or, to rounding, on its line: the nearest
        // point of a convex polygon lies on such an edge); the least.
        double[] d2 = s.diffD2;
        double least = Double.POSITIVE_INFINITY;
        for (int k = 0; k < count; k++) {
            double px = dx[k], py = dy[k], ex = dx[k + 1] - px, ey = dy[k + 1] - py;
            double tx = px * ey, ty = py * ex;
            if (tx - ty > Tolerance.ORIENTATION_ROUNDING * (Math.abs(tx) + Math.abs(ty))) {
                d2[k] = Double.POSITIVE_INFINITY;  // the origin lies inside this edge's line
            } else {
                least = Math.min(least, d2[k] = originToEdge2(px, py, dx[k + 1], dy[k + 1]));
            }
        }
        double reach = Math.sqrt(least) + Distances.PROJECTION_ROUNDING * scale;
        double within = reach * reach;
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < count; k++) {
            if (d2[k] > within) {
                continue;
            }
            // The edge of A from this vertex of the difference, and B's: their segments hold
            // the edge's features (an edge and the other's vertex at its start, or two edges).
            int i = fa[k] == na ? 0 : fa[k], j = fb[k] == nb ? 0 : fb[k];
            double d = Distances.segments(ax[i], ay[i], ax[i + 1], ay[i + 1],
                    bx[j], by[j], bx[j + 1], by[j + 1], t, feet);
            if (Distances.closer(d, best, t[0], t[1], t[2], t[3], q)) {
                best = d;
                System.arraycopy(t, 0, q, 0, 4);
                if (d == 0) {
                    return 0;
                }
            }
        }
        return best;
    }

    /**
     * Which of two directions, neither of length 0, comes first going round from angle 0 (the
     * direction (1, 0)) the way of increasing angle: +1 the first, -1 the second, 0 when they
     * are one direction. The half turn each lies in decides exactly; within one half turn, the
     * sign of the cross product.
     */
    private static int firstDirection(double ex, double ey, double fx, double fy) {
        int halfE = ey > 0 || ey == 0 && ex > 0 ? 0 : 2, halfF = fy > 0 || fy == 0 && fx > 0 ? 0 : 2;
        double cross = ex * fy - ey * fx;
        int turn = cross > 0 ? 1 : cross < 0 ? -1 : 0;
        return halfE == halfF ? turn : halfF - halfE >> 1;
    }

    /**
     * The closed outline's vertices into (x, y), the way its corners turn left (onwards if its
     * winding w is +1, backwards if -1), from its lowest vertex when {@code sign} is +1 (least
     * y, then least x) or its highest when -1 (greatest y, then greatest x), the first again
     * at the end.
     *
     * @return the largest size of a coordinate
     */
    private static double walk(double[] xy, int w, int sign, double[] x, double[] y) {
        int n = xy.length / 2;
        int start = 0;
        double size = 0, lx = sign * xy[0], ly = sign * xy[1];
        for (int k = 0; k < n; k++) {
            double vx = xy[2 * k], vy = xy[2 * k + 1], sx = sign * vx, sy = sign * vy;
            if (sy < ly || sy == ly && sx < lx) {
                start = k;
                lx = sx;
                ly = sy;
            }
            size = Math.max(size, Math.max(Math.abs(vx), Math.abs(vy)));
        }
        for (int k = 0, v = start; k < n; k++) {
            x[k] = xy[2 * v];
            y[k] = xy[2 * v + 1];
            v = w > 0 ? (v + 1 == n ? 0 : v + 1) : (v == 0 ? n - 1 : v - 1);
        }
        x[n] = x[0];
        y[n] = y[0];
        return size;
    }

    /** The squared distance from the origin to the segment from (px, py) to (qx, qy). */
    private static double originToEdge2(double px, double py, double qx, double qy) {
        double ex = qx - px, ey = qy - py;
        double len2 = ex * ex + ey * ey, along = -(px * ex + py * ey);
        if (along <= 0 || len2 == 0) {
            return px * px + py * py;
        }
        if (along >= len2) {
            return qx * qx + qy * qy;
        }
        double cross = px * ey - py * ex;
        return cross * cross / len2;
    }
}
