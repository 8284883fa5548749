package hitbox.web;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Separation;
import hitbox.Sweep;
import org.teavm.jso.JSExport;
import org.teavm.jso.JSExportClasses;

/**
 * The browser module's entry: what JavaScript may call (web/js/hitbox.js wraps it). The shapes
 * are made here; the classes listed below bring their own methods: Collide (the tutorial's
 * tests), Shape, World, Body and Grid.
 */
@JSExportClasses({CollideJs.class, SnapJs.class, ShapeJs.class, WorldJs.class, BodyJs.class, GridJs.class,
    CharacterJs.class})
public final class HitboxJs {
    private HitboxJs() {
    }

    /**
     * A circle.
     *
     * @param x its centre's x
     * @param y its centre's y
     * @param r its radius
     * @return the shape
     */
    @JSExport
    public static ShapeJs circle(float x, float y, float r) {
        return new ShapeJs(new Circle(x, y, r));
    }

    /**
     * A rectangle from its top-left corner (p5's rectMode(CORNER)).
     *
     * @param x its left
     * @param y its top
     * @param w its width
     * @param h its height
     * @return the shape
     */
    @JSExport
    public static ShapeJs rect(float x, float y, float w, float h) {
        return new ShapeJs(new Rect(x, y, w, h));
    }

    /**
     * A segment between two points.
     *
     * @param x1 one end's x
     * @param y1 its y
     * @param x2 the other end's x
     * @param y2 its y
     * @return the shape
     */
    @JSExport
    public static ShapeJs segment(float x1, float y1, float x2, float y2) {
        return new ShapeJs(new Segment(x1, y1, x2, y2));
    }

    /**
     * A polygon from its corners [x0, y0, x1, y1, ...], convex or not, never crossing itself.
     *
     * @param xy the corners
     * @return the shape
     */
    @JSExport
    public static ShapeJs polygon(float[] xy) {
        return new ShapeJs(Polygon.of(xy));
    }

    /**
     * An ellipse from its centre and radii, turned by an angle (radians).
     *
     * @param x     its centre's x
     * @param y     its centre's y
     * @param rx    its radius along x
     * @param ry    its radius along y
     * @param angle its turn, radians
     * @return the shape
     */
    @JSExport
    public static ShapeJs ellipse(float x, float y, float rx, float ry, float angle) {
        return new ShapeJs(new Ellipse(x, y, rx, ry, angle));
    }

    /**
     * A capsule: the points within r of a segment.
     *
     * @param x1 one end's x
     * @param y1 its y
     * @param x2 the other end's x
     * @param y2 its y
     * @param r  the radius
     * @return the shape
     */
    @JSExport
    public static ShapeJs capsule(float x1, float y1, float x2, float y2, float r) {
        return new ShapeJs(new Capsule(x1, y1, x2, y2, r));
    }

    /**
     * The gap between two circles ({@link Separation#circleCircle}).
     *
     * @param x1 the first centre's x
     * @param y1 its y
     * @param r1 its radius
     * @param x2 the second centre's x
     * @param y2 its y
     * @param r2 its radius
     * @return the distance between their edges, negative when they overlap
     */
    @JSExport
    public static float separationCircleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return Separation.circleCircle(x1, y1, r1, x2, y2, r2);
    }

    /**
     * When a moving rectangle first touches another ({@link Sweep#rectRect}).
     *
     * @param x  the mover's left
     * @param y  its top
     * @param w  its width
     * @param h  its height
     * @param vx its move, x part
     * @param vy its move, y part
     * @param ox the obstacle's left
     * @param oy its top
     * @param ow its width
     * @param oh its height
     * @return t in [0, 1], or Infinity when it does not within the move
     */
    @JSExport
    public static float sweepRectRect(float x, float y, float w, float h, float vx, float vy,
                                      float ox, float oy, float ow, float oh) {
        return Sweep.rectRect(x, y, w, h, vx, vy, ox, oy, ow, oh);
    }

    /**
     * The test vectors' records (Vectors.run), for the bit-for-bit test.
     *
     * @param seed  the seed
     * @param count how many cases
     * @return the records
     */
    @JSExport
    public static int[] vectors(int seed, int count) {
        return Vectors.run(seed, count);
    }

    /**
     * The exact products' records (Vectors.fmaCases), for the bit-for-bit test.
     *
     * @param seed  the seed
     * @param count how many triples
     * @return the records
     */
    @JSExport
    public static int[] fmaVectors(int seed, int count) {
        return Vectors.fmaCases(seed, count);
    }

    /**
     * The sines' and cosines' records (Vectors.trigCases), for the bit-for-bit test.
     *
     * @param seed  the seed
     * @param count how many angles
     * @return the records
     */
    @JSExport
    public static int[] trigVectors(int seed, int count) {
        return Vectors.trigCases(seed, count);
    }

    /**
     * The platform methods' records (Vectors.mathCases), for the bit-for-bit test.
     *
     * @param seed  the seed
     * @param count how many calls
     * @return the records
     */
    @JSExport
    public static int[] mathVectors(int seed, int count) {
        return Vectors.mathCases(seed, count);
    }
}
