package hitbox.internal;

import hitbox.*;

/**
 * Contacts for the curved shapes ({@link Ellipse}, {@link Capsule}) against any convex shape
 * with area, by support functions. For convex A and B the shortest push that separates them
 * is, over all unit directions n, the least of {@code h_A(n) + h_B(-n)} (h the support
 * function: how far the shape reaches along n): the Minkowski difference's distance from the
 * origin to its outline, the quantity EPA converges to. Here it is minimised over the angle
 * of n directly: 72 directions and every edge normal of a rectangle, polygon or capsule
 * (where a flat side makes the least exact), then each local least refined by golden-section
 * search. The depth is found to about 1e-12 of the shapes' size; a normal, where the least
 * is flat, to about 1e-6 radians.
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
        double nx = Math.cos(t), ny = Math.sin(t);
        return support(a, nx, ny) + support(b, -nx, -ny);
    }

    /** The contact of two overlapping convex shapes, normal from a to b. */
    public static Contact contact(Shape a, Shape b) {
        Contacts.Shortest best = new Contacts.Shortest(Tolerance.SUPPORT_TIE * scale(a, b));
        // The straight edges' normals first, exact where the least is flat.
        for (Shape s : new Shape[] {a, b}) {
            double[] xy = straightEdges(s);
            int n = xy.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
                if (ex != 0 || ey != 0) {
                    offer(best, a, b, Math.atan2(ex, -ey));
                    offer(best, a, b, Math.atan2(-ex, ey));
                }
            }
        }
        // Then the four axis directions, exact. Where the least is flat (an ellipse's flat
        // top against a circle) the search stops about 1e-8 radians off the axis, and where
        // a whole cone of directions is equally short (a circle centred on a corner) it stops
        // anywhere in it; the tie rule's pick from such a cone is one of its ends (an edge
        // normal, offered above) or an axis inside it, and a refined direction that ties with
        // one of these then leaves it in place.
        offerDirection(best, a, b, 0, 1);
        offerDirection(best, a, b, 0, -1);
        offerDirection(best, a, b, 1, 0);
        offerDirection(best, a, b, -1, 0);
        double[] f = new double[STEPS];
        for (int i = 0; i < STEPS; i++) {
            f[i] = push(a, b, 2 * Math.PI * i / STEPS);
        }
        for (int i = 0; i < STEPS; i++) {
            double prev = f[(i + STEPS - 1) % STEPS], next = f[(i + 1) % STEPS];
            if (f[i] <= prev && f[i] <= next) {
                double t = refine(a, b, 2 * Math.PI * (i - 1) / STEPS, 2 * Math.PI * (i + 1) / STEPS);
                offer(best, a, b, t);
            }
        }
        return best.contact();
    }

    private static void offer(Contacts.Shortest best, Shape a, Shape b, double t) {
        double nx = Math.cos(t), ny = Math.sin(t);
        // Exact axis directions where rounding of cos and sin would leave a hair.
        if (Math.abs(nx) < Tolerance.AXIS_SNAP) {
            nx = 0;
            ny = Math.signum(ny);
        } else if (Math.abs(ny) < Tolerance.AXIS_SNAP) {
            ny = 0;
            nx = Math.signum(nx);
        }
        offerDirection(best, a, b, nx, ny);
    }

    private static void offerDirection(Contacts.Shortest best, Shape a, Shape b, double nx, double ny) {
        best.offer(nx, ny, support(a, nx, ny) + support(b, -nx, -ny));
    }

    /** Golden-section search for the least push in [lo, hi]. */
    private static double refine(Shape a, Shape b, double lo, double hi) {
        return Golden.least(t -> push(a, b, t), lo, hi, 80, Tolerance.SUPPORT_ANGLE)[0];
    }

    /** The shapes' size, for the tie tolerance. */
    private static double scale(Shape a, Shape b) {
        Rect p = a.bounds(), q = b.bounds();
        return Math.max(1, Math.max(Math.max(p.w(), p.h()), Math.max(q.w(), q.h())));
    }
}
