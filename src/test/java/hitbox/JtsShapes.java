package hitbox;

import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * Hitbox's straight shapes as JTS geometry, for the tests that use JTS as their oracle: one
 * conversion, so the oracles agree on what a shape is. Coordinates are taken in double, so a
 * rectangle's far corner is {@code x + w} without float rounding.
 */
final class JtsShapes {
    static final GeometryFactory GF = new GeometryFactory();

    private JtsShapes() {
    }

    /** A segment, or the point it is when its ends are the same. */
    static Geometry segment(double x1, double y1, double x2, double y2) {
        if (x1 == x2 && y1 == y2) {
            return GF.createPoint(new Coordinate(x1, y1));
        }
        return GF.createLineString(new Coordinate[] {new Coordinate(x1, y1), new Coordinate(x2, y2)});
    }

    /** A polygon from its vertices {@code x0, y0, x1, y1, ...}, closed here. */
    static Geometry polygon(double... xy) {
        Coordinate[] c = new Coordinate[xy.length / 2 + 1];
        for (int i = 0; i < xy.length / 2; i++) {
            c[i] = new Coordinate(xy[2 * i], xy[2 * i + 1]);
        }
        c[c.length - 1] = c[0];
        return GF.createPolygon(c);
    }

    /**
     * A straight shape with its outline: a rectangle (a segment when flat), a segment, a polygon.
     *
     * @throws IllegalArgumentException for a round shape
     */
    static Geometry straight(Shape s) {
        if (s instanceof Rect r) {
            double x = r.x(), y = r.y(), x2 = x + (double) r.w(), y2 = y + (double) r.h();
            if (r.w() == 0 || r.h() == 0) {
                return segment(x, y, x2, y2);
            }
            return polygon(x, y, x2, y, x2, y2, x, y2);
        }
        if (s instanceof Segment g) {
            return segment(g.x1(), g.y1(), g.x2(), g.y2());
        }
        if (s instanceof Polygon p) {
            double[] xy = new double[2 * p.size()];
            for (int i = 0; i < p.size(); i++) {
                xy[2 * i] = p.x(i);
                xy[2 * i + 1] = p.y(i);
            }
            return polygon(xy);
        }
        throw new IllegalArgumentException("not a straight shape: " + s);
    }

    /**
     * A shape's core: a circle as its centre and a capsule as its segment (their radius is then
     * the reach around it), a straight shape as itself.
     *
     * @throws IllegalArgumentException for an ellipse
     */
    static Geometry core(Shape s) {
        if (s instanceof Circle c) {
            return GF.createPoint(new Coordinate(c.x(), c.y()));
        }
        if (s instanceof Capsule k) {
            return segment(k.x1(), k.y1(), k.x2(), k.y2());
        }
        return straight(s);
    }

    /** A round shape's reach around its {@link #core}: a circle's or capsule's radius, else 0. */
    static double radius(Shape s) {
        return s instanceof Circle c ? c.r() : s instanceof Capsule k ? k.r() : 0;
    }
}
