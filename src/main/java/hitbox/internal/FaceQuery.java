package hitbox.internal;

import hitbox.*;

/**
 * The contact of two convex polygons by the face query of their Minkowski difference: the
 * separating axis test that also finds the shortest push, on the polygons' corners in
 * double. Behind the convex polygon pairs of {@link Shape#contact} (and so of
 * {@code a.contact(b)}).
 */
public final class FaceQuery {
    private FaceQuery() {
    }

    /**
     * SAT contact on raw vertices, x0, y0, x1, y1, ...; convex, with their windings
     * ({@link Polygons#winding}: +1 or -1). A side may be flat (a rectangle of width or height
     * 0: a segment or a point; give it either winding): its zero-length edges have no axis and
     * are skipped, and its two opposite edges give both directions, so the test is still
     * complete.
     *
     * <p>Only the faces of the Minkowski difference a - b are asked: on a's edges, b pushed out
     * through the edge (along a's outward normal); on b's edges, b pushed back through its own
     * edge (against b's outward normal). Those are all the directions in which the
     * difference's boundary is nearest the origin, so the least of them is the minimum
     * translation, and the polygons are apart exactly when one of them is 0 or less. The other
     * way along each axis never goes below that minimum (it is a separating move too), and
     * where it equals it, the same direction is also a face of the difference; so leaving it
     * out changes no answer.
     *
     * <p>Reference: E. Catto, Box2D's {@code b2FindMaxSeparation} (the same face query);
     * C. Ericson, <i>Real-Time Collision Detection</i> (2005), 5.2.1.
     */
    public static Contact convexPolygons(double[] a, int wa, Rect boxA, double[] b, int wb, Rect boxB) {
        // How far the coordinates spread, for the rounding bound below: every vertex of both
        // is in the two boxes (which enclose their shapes, rounded outwards).
        double spreadX = Math.max((double) boxA.x() + boxA.w(), (double) boxB.x() + boxB.w()) - Math.min(boxA.x(), boxB.x());
        double spreadY = Math.max((double) boxA.y() + boxA.h(), (double) boxB.y() + boxB.h()) - Math.min(boxA.y(), boxB.y());
        // The best push so far, in locals (the tie rule of Contacts.Shortest), so that the
        // search allocates nothing but its answer.
        double bestX = 0, bestY = 0, best = Double.POSITIVE_INFINITY;
        for (int pass = 0; pass < 2; pass++) {
            double[] owner = pass == 0 ? a : b, other = pass == 0 ? b : a;
            int w = pass == 0 ? wa : wb;
            // b goes along a's outward normals, and against b's own.
            double toward = pass == 0 ? 1 : -1;
            int n = owner.length / 2;
            for (int i = 0; i < n; i++) {
                int j = i + 1 == n ? 0 : i + 1;
                double ox = owner[2 * i], oy = owner[2 * i + 1];
                double ex = owner[2 * j] - ox, ey = owner[2 * j + 1] - oy;
                if (ex == 0 && ey == 0) {
                    continue;
                }
                // The outward normal, un-normalized: (ey, -ex) is on the outside of a
                // polygon of winding +1.
                double mx = w * ey, my = -w * ex;
                // Each term has a relative rounding error of a few units of 2^-53 in its
                // differences and products; far below this bound.
                double rounding = Tolerance.ORIENTATION_ROUNDING * (spreadX * Math.abs(mx) + spreadY * Math.abs(my));
                double len2 = mx * mx + my * my;
                // A push longer than the best by more than the tie rule's slack cannot win:
                // asked on squares (the factor 2 covers their rounding many times over), so
                // that only the few pushes that can win pay for a square root and a division.
                double reachable = best * (1 + 2 * Contact.TIE), beyond = reachable * reachable * len2;
                // How far the other polygon reaches in behind the edge's line: the most any
                // vertex of it lies inside, measured from the edge's own vertex so that large
                // coordinates do not cancel.
                double reach = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < other.length - 1; k += 2) {
                    reach = Math.max(reach, (ox - other[k]) * mx + (oy - other[k + 1]) * my);
                    if (reach > rounding && reach * reach > beyond) {
                        // Already too long to win, and clear of the rounding: the rest of
                        // the vertices can only make it longer.
                        break;
                    }
                }
                if (reach <= rounding) {
                    // Within rounding of touching: decide with exact orientation signs. A
                    // polygon thinner than a double's rounding of its size (found by
                    // fuzzing) would otherwise look flat, and apart from itself.
                    reach = exactReach(owner, i, j, w, other);
                    if (reach <= 0) {
                        return null;
                    }
                }
                if (reach * reach > beyond) {
                    continue;
                }
                double len = Math.sqrt(len2);
                double ux = toward * mx / len, uy = toward * my / len, d = reach / len;
                if (Contacts.Shortest.beats(ux, uy, d, bestX, bestY, best, 0, false)) {
                    bestX = ux;
                    bestY = uy;
                    best = d;
                }
            }
        }
        return best == Double.POSITIVE_INFINITY ? null : Contacts.of(bestX, bestY, best);
    }

    /**
     * How far the other polygon reaches in behind edge i-j of {@code owner} (winding w), times
     * the edge's length: the largest {@code w * orient(i, j, q)} over its vertices q,
     * each of exact sign ({@link Lines#orient}), so 0 or less exactly when the edge's line
     * separates the two.
     */
    private static double exactReach(double[] owner, int i, int j, int w, double[] other) {
        double reach = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < other.length - 1; k += 2) {
            reach = Math.max(reach, w * Lines.orient(owner[2 * i], owner[2 * i + 1], owner[2 * j], owner[2 * j + 1],
                    other[k], other[k + 1]));
        }
        return reach;
    }
}
