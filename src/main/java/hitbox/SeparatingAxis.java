package hitbox;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * The separating axis theorem (SAT) for convex polygons, with the axes laid open so that a
 * sketch can draw them.
 *
 * <p>The idea: shine a light across each edge of both polygons, along the edge's normal,
 * and look at the two shadows on a line. If on some axis the shadows do not overlap, a line
 * fits between the polygons and they are apart. If the shadows overlap on every axis, the
 * polygons overlap, and the axis with the least overlap tells the shortest way to push them
 * apart. For two convex polygons, the edge normals of both are the only axes that need
 * checking. Rotated rectangles are convex polygons with four vertices.
 *
 * <p>The touching rule holds: shadows that only touch (overlap 0) separate, so polygons
 * sharing an edge or a corner do not overlap. The test is exact for whole-number
 * coordinates up to about a million: projections are taken on the un-normalized edge
 * normal in double, where each product of two coordinate differences is exact.
 *
 * <p>Every method here needs convex polygons and throws for a concave one, naming the vertex
 * where it bends inwards; {@link Contact#between} handles concave polygons too.
 *
 * <p>Reference: S. Gottschalk, "Separating axis theorem", 1996; C. Ericson, <i>Real-Time
 * Collision Detection</i>, 2005, section 5.2.1.
 */
public final class SeparatingAxis {
    private SeparatingAxis() {
    }

    /**
     * One axis of the test: a unit direction and the two polygons' shadows on it.
     *
     * <p>The shadows are the polygons' vertices projected onto the line through the origin
     * along (nx, ny): a point (x, y) lands at {@code x * nx + y * ny}. Draw the axis as a
     * line in that direction, and each shadow from {@code min * (nx, ny)} to
     * {@code max * (nx, ny)}.
     *
     * <p>The values are rounded to float for drawing. {@link SeparatingAxis#overlaps} decides
     * with exact arithmetic, so at very large coordinates an axis can show an overlap of 0
     * where the exact test sees a hair's-width overlap; for whole-number coordinates up to a
     * few thousand the two always agree.
     *
     * @param nx   the axis direction's x, a unit vector: an edge normal, pointing out of the
     *             polygon that owns the edge
     * @param ny   the axis direction's y
     * @param minA where polygon a's shadow starts
     * @param maxA where polygon a's shadow ends
     * @param minB where polygon b's shadow starts
     * @param maxB where polygon b's shadow ends
     */
    public record Axis(float nx, float ny, float minA, float maxA, float minB, float maxB) {

        /**
         * Makes an axis, checking its values.
         *
         * @param nx   the direction's x (unit length)
         * @param ny   the direction's y
         * @param minA where a's shadow starts
         * @param maxA where a's shadow ends
         * @param minB where b's shadow starts
         * @param maxB where b's shadow ends
         * @throws IllegalArgumentException if a value is NaN or infinite, a shadow ends
         *                                  before it starts, or (nx, ny) does not have length 1
         *                                  (within {@link Contact#UNIT_TOLERANCE})
         */
        public Axis {
            // -0 becomes 0, so that computed axes equal ones written by hand.
            nx += 0.0f;
            ny += 0.0f;
            minA += 0.0f;
            maxA += 0.0f;
            minB += 0.0f;
            maxB += 0.0f;
            Check.finite("nx", nx);
            Check.finite("ny", ny);
            Check.finite("minA", minA);
            Check.finite("maxA", maxA);
            Check.finite("minB", minB);
            Check.finite("maxB", maxB);
            if (minA > maxA || minB > maxB) {
                throw new IllegalArgumentException("a shadow must not end before it starts (minA <= maxA,"
                        + " minB <= maxB), but a is [" + minA + ", " + maxA + "] and b is [" + minB + ", " + maxB + "]");
            }
            double length = Math.hypot(nx, ny);
            if (Math.abs(length - 1) > Contact.UNIT_TOLERANCE) {
                throw new IllegalArgumentException("the axis (nx, ny) must have length 1, but ("
                        + nx + ", " + ny + ") has length " + (float) length);
            }
        }

        /**
         * How much the two shadows overlap: the length they share, or minus the gap between
         * them.
         *
         * @return the overlap, greater than 0 when the shadows overlap, 0 when they touch,
         *         negative when there is a gap
         */
        public float overlap() {
            return Math.min(maxA, maxB) - Math.max(minA, minB);
        }

        /**
         * Does this axis separate the polygons? Yes when the shadows do not overlap, touching
         * included.
         *
         * @return true if {@code overlap() <= 0}
         */
        public boolean separates() {
            return overlap() <= 0;
        }
    }

    /**
     * The axes SAT checks for two convex polygons, for drawing: one per edge of nonzero
     * length, a's edges first, then b's, each in vertex order (the axis of edge i, from vertex
     * i to vertex i + 1, is the edge's outward normal).
     *
     * @param a the first polygon, convex
     * @param b the second polygon, convex
     * @return the axes, an unmodifiable list; the polygons overlap when no axis
     *         {@link Axis#separates() separates} them, never null
     * @throws IllegalArgumentException if a polygon is null or concave
     */
    public static List<Axis> axes(Polygon a, Polygon b) {
        double[] pa = convexCorners("a", a);
        double[] pb = convexCorners("b", b);
        List<Axis> axes = new ArrayList<>(pa.length / 2 + pb.length / 2);
        for (double[] owner : new double[][] {pa, pb}) {
            double turn = Polygons.areaSign(owner);
            int n = owner.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ex = owner[2 * j] - owner[2 * i];
                double ey = owner[2 * j + 1] - owner[2 * i + 1];
                double len = Math.hypot(ex, ey);
                if (len == 0) {
                    continue;
                }
                // The outward normal, un-normalized, so the projections below are exact.
                double mx = turn * ey, my = -turn * ex;
                axes.add(new Axis((float) (mx / len), (float) (my / len),
                        (float) (min(pa, mx, my) / len), (float) (max(pa, mx, my) / len),
                        (float) (min(pb, mx, my) / len), (float) (max(pb, mx, my) / len)));
            }
        }
        return Collections.unmodifiableList(axes);
    }

    /**
     * Do two convex polygons overlap? Polygons that only touch (share an edge or a corner) do
     * not: the shadows must overlap by more than 0 on every axis.
     *
     * @param a the first polygon, convex
     * @param b the second polygon, convex
     * @return true if no axis separates them
     * @throws IllegalArgumentException if a polygon is null or concave
     */
    public static boolean overlaps(Polygon a, Polygon b) {
        convexCorners("a", a);
        convexCorners("b", b);
        // The same axes, asked with exact orientation signs (Polygons.convexOverlap).
        return Polygons.convexOverlap(a.raw(), a.convexWinding(), b.raw(), b.convexWinding());
    }

    /**
     * The contact between two convex polygons, or null when they do not overlap: the axis
     * with the least overlap, oriented from a to b. Moving b along the normal by the depth
     * makes the shadows on that axis just touch, and no shorter move separates the polygons.
     * Ties follow the rule of {@link Contact}.
     *
     * @param a the first polygon, convex
     * @param b the second polygon, convex
     * @return the contact, normal from a to b, or null when apart
     * @throws IllegalArgumentException if a polygon is null or concave
     */
    public static Contact contact(Polygon a, Polygon b) {
        return contact(convexCorners("a", a), a.convexWinding(), a.bounds(), convexCorners("b", b), b.convexWinding(), b.bounds());
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
    static Contact contact(double[] a, int wa, Rect boxA, double[] b, int wb, Rect boxB) {
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
                // How far the other polygon reaches in behind the edge's line: the most any
                // vertex of it lies inside, measured from the edge's own vertex so that large
                // coordinates do not cancel.
                double reach = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < other.length - 1; k += 2) {
                    reach = Math.max(reach, (ox - other[k]) * mx + (oy - other[k + 1]) * my);
                }
                // Each term has a relative rounding error of a few units of 2^-53 in its
                // differences and products; far below this bound.
                if (reach <= Tolerance.ORIENTATION_ROUNDING * (spreadX * Math.abs(mx) + spreadY * Math.abs(my))) {
                    // Within rounding of touching: decide with exact orientation signs. A
                    // polygon thinner than a double's rounding of its size (found by
                    // fuzzing) would otherwise look flat, and apart from itself.
                    reach = exactReach(owner, i, j, w, other);
                    if (reach <= 0) {
                        return null;
                    }
                }
                double len2 = mx * mx + my * my;
                // A push longer than the best by more than the tie rule's slack cannot win:
                // asked on squares (the factor 2 covers their rounding many times over), so
                // that only the few pushes that can win pay for a square root and a division.
                double reachable = best * (1 + 2 * Contact.TIE);
                if (reach * reach > reachable * reachable * len2) {
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
        return best == Double.POSITIVE_INFINITY ? null : Contact.of(bestX, bestY, best);
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

    private static double min(double[] p, double mx, double my) {
        double m = Double.POSITIVE_INFINITY;
        for (int i = 0; i < p.length; i += 2) {
            m = Math.min(m, p[i] * mx + p[i + 1] * my);
        }
        return m;
    }

    private static double max(double[] p, double mx, double my) {
        double m = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < p.length; i += 2) {
            m = Math.max(m, p[i] * mx + p[i + 1] * my);
        }
        return m;
    }

    /** The polygon's vertices in double (its own, not a copy), after checking it is there and convex. */
    private static double[] convexCorners(String name, Polygon p) {
        Check.notNull(name, p);
        int v = p.concaveVertex();
        if (v >= 0) {
            throw new IllegalArgumentException("SAT needs convex polygons; polygon " + name
                    + " is concave at vertex " + v + " (" + p.x(v) + ", " + p.y(v) + ")");
        }
        return p.corners();
    }
}
