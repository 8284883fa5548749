package hitbox;

import hitbox.internal.*;

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
 * <p>This class lays the test open for drawing; it does not answer it. To ask whether two
 * polygons overlap, ask them: {@code a.overlaps(b)} (these axes, decided with exact
 * orientation signs), and {@code a.contact(b)} for the shortest push that parts them (the
 * axis whose shadows need the least move apart), oriented from a to b, as the normal and depth
 * of a {@link Contact}; both take concave polygons too.
 * {@link #axes} needs convex polygons and throws for a concave one, naming the vertex where it
 * bends inwards.
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
     * <p>The values are rounded to float for drawing. {@link Polygon#overlaps} decides
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
