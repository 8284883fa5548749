package hitbox.internal;

import hitbox.*;

/**
 * Contacts for the curved shapes ({@link Ellipse}, {@link Capsule}) against any convex shape
 * with area, by support functions. For convex A and B the shortest push that separates them
 * is, over all unit directions n, the least of {@code h_A(n) + h_B(-n)} (h the support
 * function: how far the shape reaches along n): the Minkowski difference's distance from the
 * origin to its outline, the quantity EPA converges to. Here it is minimised over the angle
 * of n directly: every edge normal of a rectangle, polygon or capsule (where a flat side
 * makes the least exact), the four axis directions, and 72 directions whose local least
 * values are refined by golden-section search (one near an axis and as short taken on it).
 * The depth is found to about 1e-12 of the shapes' size; a normal, where the least is
 * flat, to about 1e-6 radians. All candidates are gathered, then chosen among at one place
 * by the tie rule of {@link Contact}, those within {@link Tolerance#SUPPORT_TIE} of the least
 * tying.
 *
 * <p>Reference: G. van den Bergen, <i>Collision Detection in Interactive 3D Environments</i>
 * (2004), 4.3 (penetration depth as the Minkowski difference's distance to its boundary).
 */
public final class Supports {
    private Supports() {
    }

    private static final int STEPS = 72;

    /**
     * How far the shape reaches along (nx, ny): the largest dot product of its points with it
     * (for a concave polygon, of its outline's, as for its convex hull).
     */
    public static double support(Shape s, double nx, double ny) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> TurnedEllipses.support((Ellipse) s, nx, ny);
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.max(k.x1() * nx + k.y1() * ny, k.x2() * nx + k.y2() * ny) + k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield c.x() * nx + c.y() * ny + c.r();
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.max(g.x1() * nx + g.y1() * ny, g.x2() * nx + g.y2() * ny);
            }
            case RECT -> reach(Polygons.corners((Rect) s, new double[8]), nx, ny);
            case POLYGON -> reach(HiddenParts.corners((Polygon) s), nx, ny); // cached, only read
        };
    }

    /** The largest dot product of the vertices with (nx, ny). */
    private static double reach(double[] xy, double nx, double ny) {
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < xy.length; i += 2) {
            best = Math.max(best, xy[i] * nx + xy[i + 1] * ny);
        }
        return best;
    }

    /**
     * The straight edges whose normals the search tries, as a closed outline of vertices:
     * a rectangle's or polygon's corners, a capsule's segment (its two sides), none for a
     * round shape; a segment, as a capsule's.
     */
    public static double[] straightEdges(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE, CIRCLE -> new double[0];
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield new double[] {k.x1(), k.y1(), k.x2(), k.y2()};
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield new double[] {g.x1(), g.y1(), g.x2(), g.y2()};
            }
            case RECT, POLYGON -> Polygons.corners(s);
        };
    }

    /** The push for direction angle t: how far b must move along (cos t, sin t) to clear a. */
    private static double push(Shape a, Shape b, double t) {
        double[] n = unit(t);
        return support(a, n[0], n[1]) + support(b, -n[0], -n[1]);
    }

    /**
     * The unit direction at angle t, exact where it is an axis direction: cos and sin of such
     * an angle round to about 6e-17, not 0, and the exact axis keeps a box's support exact.
     */
    private static double[] unit(double t) {
        double nx = StrictMath.cos(t), ny = StrictMath.sin(t);
        if (Math.abs(nx) < Tolerance.AXIS_SNAP) {
            return new double[] {0, Math.signum(ny)};
        }
        if (Math.abs(ny) < Tolerance.AXIS_SNAP) {
            return new double[] {Math.signum(nx), 0};
        }
        return new double[] {nx, ny};
    }

    /**
     * The contact of two overlapping convex shapes, normal from a to b. Every candidate
     * direction is gathered first and only then chosen among, at this one place: those
     * within the tie slack of the least push (see {@link Tolerance#SUPPORT_TIE}) all tie, and
     * the rule of {@link Contact} ({@link Contacts.Shortest}) picks among them, so the pick
     * does not depend on the order they were found in (a chain of candidates, each within
     * the slack of the one before, can no longer lead away from the least), and a pair's
     * mirror image, whose candidates are the mirrored ones, picks the mirrored direction.
     */
    public static Contact contact(Shape a, Shape b) {
        double[] found = new double[3 * 96];
        int n = 0;
        // The straight edges' normals first, exact where the least is flat. A cone of equally
        // short directions (a circle or a capsule's end centred on a corner) has such normals
        // for its ends: for convex shapes it is a corner of the one shape taken off the
        // other's segment or point, whose sides are straight edges of the two.
        for (Shape s : new Shape[] {a, b}) {
            double[] xy = straightEdges(s);
            int corners = xy.length / 2;
            for (int i = 0; i < corners; i++) {
                int j = (i + 1) % corners;
                double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
                if (ex != 0 || ey != 0) {
                    found = candidate(found, n++, a, b, unit(Math.atan2(ex, -ey)));
                    found = candidate(found, n++, a, b, unit(Math.atan2(-ex, ey)));
                }
            }
        }
        // Then the four axis directions, exact: the rule's pick from a cone of equally short
        // directions can be an axis inside it.
        for (double[] axis : new double[][] {{0, 1}, {0, -1}, {1, 0}, {-1, 0}}) {
            found = candidate(found, n++, a, b, axis);
        }
        // Then each local least of 72 samples, refined by golden-section search. Where the
        // least is flat to the fourth order (an ellipse's end with a capsule's end at its
        // centre of curvature) the search stops anywhere within about 1e-4 radians, all
        // equally short to a double's resolution; one that near an axis, and as short there
        // to the support sums' rounding, is taken on the axis (Golden.onAxis).
        double size = size(a, b);
        double[] f = new double[STEPS];
        for (int i = 0; i < STEPS; i++) {
            f[i] = push(a, b, 2 * Math.PI * i / STEPS);
        }
        for (int i = 0; i < STEPS; i++) {
            double prev = f[(i + STEPS - 1) % STEPS], next = f[(i + 1) % STEPS];
            if (f[i] <= prev && f[i] <= next) {
                double[] least = Golden.least(t -> push(a, b, t), 2 * Math.PI * (i - 1) / STEPS,
                        2 * Math.PI * (i + 1) / STEPS, 80, Tolerance.SUPPORT_ANGLE);
                least = Golden.onAxis(t -> push(a, b, t), least, 1e-12 * size);
                found = candidate(found, n++, a, b, unit(least[0]));
            }
        }
        // The one place a direction is chosen: everything within the slack of the least.
        double least = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            least = Math.min(least, found[3 * i + 2]);
        }
        double slack = Tolerance.SUPPORT_TIE * size;
        Contacts.Shortest best = new Contacts.Shortest(slack);
        for (int i = 0; i < n; i++) {
            if (found[3 * i + 2] <= least + slack) {
                best.offer(found[3 * i], found[3 * i + 1], found[3 * i + 2]);
            }
        }
        return best.contact();
    }

    /** Stores direction u and its push as candidate i of found (grown if full); returns found. */
    private static double[] candidate(double[] found, int i, Shape a, Shape b, double[] u) {
        if (3 * i + 3 > found.length) {
            found = java.util.Arrays.copyOf(found, 2 * found.length);
        }
        found[3 * i] = u[0];
        found[3 * i + 1] = u[1];
        found[3 * i + 2] = support(a, u[0], u[1]) + support(b, -u[0], -u[1]);
        return found;
    }

    /**
     * The scene's size for the tie slack: the largest coordinate of either shape's box (at
     * least 1). The float inputs are rounded to about 6e-8 of their coordinates, so pushes
     * meant to be equal (the edge normals of a regular polygon placed by cos and sin) differ
     * by that much of the coordinates, not of the shapes' own size.
     */
    private static double size(Shape a, Shape b) {
        double most = 1;
        for (Shape s : new Shape[] {a, b}) {
            most = Math.max(most, Math.max(Math.max(Math.abs(s.minX()), Math.abs(s.maxX())),
                    Math.max(Math.abs(s.minY()), Math.abs(s.maxY()))));
        }
        return most;
    }
}
