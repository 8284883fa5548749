package hitbox.bench;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.jbox2d.collision.shapes.CircleShape;
import org.jbox2d.collision.shapes.EdgeShape;
import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.common.Vec2;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * Hitbox shapes as the peers' own shapes, built once before timing so that every contender
 * starts from its own ready data. Each peer gets the shape where it is: dyn4j and JBox2D as a
 * shape about its centre plus a transform (dyn4j) or in world coordinates (JBox2D), libGDX in
 * its float fields.
 */
final class NarrowPeers {
    private NarrowPeers() {
    }

    /** The shape as a dyn4j convex about its own centre; {@link #dyn4jAt} places it. */
    static Convex dyn4j(Shape s) {
        if (s instanceof Circle c) return new org.dyn4j.geometry.Circle(c.r());
        if (s instanceof Rect r) return new org.dyn4j.geometry.Rectangle(r.w(), r.h());
        if (s instanceof Ellipse e) return new org.dyn4j.geometry.Ellipse(2.0 * e.rx(), 2.0 * e.ry());
        if (s instanceof Capsule k) return new org.dyn4j.geometry.Capsule(Math.hypot(k.x2() - k.x1(), k.y2() - k.y1()) + 2.0 * k.r(), 2.0 * k.r());
        if (s instanceof Segment g) return new org.dyn4j.geometry.Segment(new Vector2(g.x1(), g.y1()), new Vector2(g.x2(), g.y2()));
        float[] xy = ((Polygon) s).coordinates();
        int n = xy.length / 2;
        boolean counterClockwise = signedArea(xy) > 0;
        Vector2[] v = new Vector2[n];
        for (int k = 0; k < n; k++) {
            int j = counterClockwise ? k : n - 1 - k;
            v[k] = new Vector2(xy[2 * j], xy[2 * j + 1]);
        }
        return new org.dyn4j.geometry.Polygon(v);
    }

    /** Where {@link #dyn4j} puts the shape: segments and polygons are already in place. */
    static Transform dyn4jAt(Shape s) {
        Transform t = new Transform();
        if (s instanceof Capsule k) {
            t.rotate(Math.atan2(k.y2() - k.y1(), k.x2() - k.x1()));
            t.translate((k.x1() + (double) k.x2()) / 2, (k.y1() + (double) k.y2()) / 2);
        } else if (s instanceof Circle || s instanceof Rect || s instanceof Ellipse) {
            Rect box = s instanceof Rect r ? r : s.bounds();
            t.translate(box.x() + box.w() / 2.0, box.y() + box.h() / 2.0);
        }
        return t;
    }

    /** The shape in JBox2D, in world coordinates (JBox2D's polygons keep their 0.01 skin). */
    static org.jbox2d.collision.shapes.Shape jbox2d(Shape s) {
        if (s instanceof Circle c) {
            CircleShape shape = new CircleShape();
            shape.m_radius = c.r();
            shape.m_p.set(c.x(), c.y());
            return shape;
        }
        if (s instanceof Segment g) {
            EdgeShape edge = new EdgeShape();
            edge.set(new Vec2(g.x1(), g.y1()), new Vec2(g.x2(), g.y2()));
            return edge;
        }
        float[] xy = s instanceof Rect r ? Polygon.of(r).coordinates() : ((Polygon) s).coordinates();
        Vec2[] v = new Vec2[xy.length / 2];
        for (int k = 0; k < v.length; k++) {
            v[k] = new Vec2(xy[2 * k], xy[2 * k + 1]);
        }
        PolygonShape polygon = new PolygonShape();
        polygon.set(v, v.length);
        return polygon;
    }

    /** The shape's outline for libGDX's polygon tests (a rectangle as its four corners). */
    static com.badlogic.gdx.math.Polygon gdxPolygon(Shape s) {
        return new com.badlogic.gdx.math.Polygon(s instanceof Rect r ? Polygon.of(r).coordinates() : ((Polygon) s).coordinates());
    }

    /**
     * A polygon as a dyn4j convex about (px, py): its vertices less the point, in double, so
     * that a transform at (px, py) puts it back where it is and dyn4j turns it about that point
     * (the origin of its own frame).
     */
    static Convex dyn4jAbout(Polygon p, double px, double py) {
        float[] xy = p.coordinates();
        int n = xy.length / 2;
        boolean counterClockwise = signedArea(xy) > 0;
        Vector2[] v = new Vector2[n];
        for (int k = 0; k < n; k++) {
            int j = counterClockwise ? k : n - 1 - k;
            v[k] = new Vector2(xy[2 * j] - px, xy[2 * j + 1] - py);
        }
        return new org.dyn4j.geometry.Polygon(v);
    }

    /** A polygon in JBox2D about (px, py), its vertices less the point rounded to float: a sweep's body frame. */
    static PolygonShape jbox2dAbout(Polygon p, double px, double py) {
        float[] xy = p.coordinates();
        Vec2[] v = new Vec2[xy.length / 2];
        for (int k = 0; k < v.length; k++) {
            v[k] = new Vec2((float) (xy[2 * k] - px), (float) (xy[2 * k + 1] - py));
        }
        PolygonShape polygon = new PolygonShape();
        polygon.set(v, v.length);
        return polygon;
    }

    private static final GeometryFactory JTS = new GeometryFactory();

    /** The shape in JTS: a polygon or rectangle as its ring, a circle as its centre (see {@link #jtsRadius}). */
    static Geometry jts(Shape s) {
        if (s instanceof Circle c) return JTS.createPoint(new Coordinate(c.x(), c.y()));
        float[] xy = s instanceof Rect r ? Polygon.of(r).coordinates() : ((Polygon) s).coordinates();
        Coordinate[] ring = new Coordinate[xy.length / 2 + 1];
        for (int k = 0; k <= xy.length / 2; k++) {
            int j = k % (xy.length / 2);
            ring[k] = new Coordinate(xy[2 * j], xy[2 * j + 1]);
        }
        return JTS.createPolygon(ring);
    }

    /** What JTS's distance to {@link #jts}'s geometry leaves out: a circle's radius, else 0. */
    static double jtsRadius(Shape s) {
        return s instanceof Circle c ? c.r() : 0;
    }

    /** Twice the signed area, positive when the corners turn counter-clockwise with y up. */
    static double signedArea(float[] xy) {
        double sum = 0;
        for (int k = 0, n = xy.length / 2; k < n; k++) {
            int j = (k + 1) % n;
            sum += (double) xy[2 * k] * xy[2 * j + 1] - (double) xy[2 * j] * xy[2 * k + 1];
        }
        return sum;
    }
}
