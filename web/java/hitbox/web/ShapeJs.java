package hitbox.web;

import hitbox.Ray;
import hitbox.Separation;
import hitbox.Shape;
import hitbox.Sweep;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;
import org.teavm.jso.JSObject;
import org.teavm.jso.JSProperty;

/**
 * One of the library's six shapes for JavaScript, made by {@code circle(...)}, {@code rect(...)}
 * and the others; it answers every question the Java shape does, in either order of a pair.
 */
@JSClass(name = "Shape")
public final class ShapeJs {
    final Shape shape;

    ShapeJs(Shape shape) {
        this.shape = shape;
    }

    /**
     * Does this shape overlap the other (touching is not overlapping)?
     *
     * @param other the other shape
     * @return whether they overlap
     */
    @JSExport
    public boolean overlaps(ShapeJs other) {
        return shape.overlaps(other.shape);
    }

    /**
     * How to push this shape out of the other: {nx, ny, depth}, the normal from this shape to
     * the other, or null when apart.
     *
     * @param other the other shape
     * @return the contact, or null
     */
    @JSExport
    public JSObject contact(ShapeJs other) {
        return Js.of(shape.contact(other.shape));
    }

    /**
     * The gap between the shapes and the nearest points: {distance, ax, ay, bx, by}.
     *
     * @param other the other shape
     * @return the separation
     */
    @JSExport
    public JSObject separation(ShapeJs other) {
        return Js.of(Separation.between(shape, other.shape));
    }

    /**
     * Is the point inside (the edge counts as inside)?
     *
     * @param x the point's x
     * @param y the point's y
     * @return whether it is inside
     */
    @JSExport
    public boolean contains(float x, float y) {
        return shape.contains(x, y);
    }

    /**
     * Is the other shape wholly inside this one?
     *
     * @param other the other shape
     * @return whether it is inside
     */
    @JSExport
    public boolean containsShape(ShapeJs other) {
        return shape.contains(other.shape);
    }

    /**
     * When this shape, moved by (vx, vy), first touches the obstacle: {t, nx, ny, side} with t
     * in [0, 1], or null if it does not within the move.
     *
     * @param vx       the move, x part
     * @param vy       the move, y part
     * @param obstacle the shape in the way
     * @return the hit, or null
     */
    @JSExport
    public JSObject sweep(float vx, float vy, ShapeJs obstacle) {
        return Js.of(Sweep.timeOfImpact(shape, vx, vy, obstacle.shape));
    }

    /**
     * Where a ray from (ox, oy) along (dx, dy) first meets this shape, within maxDistance:
     * {distance, x, y, nx, ny}, or null.
     *
     * @param ox          the origin's x
     * @param oy          the origin's y
     * @param dx          the direction's x part
     * @param dy          the direction's y part
     * @param maxDistance how far the ray reaches (Infinity for no end)
     * @return the hit, or null
     */
    @JSExport
    public JSObject raycast(float ox, float oy, float dx, float dy, float maxDistance) {
        return Js.of(new Ray(ox, oy, dx, dy, maxDistance).cast(shape));
    }

    /**
     * The same shape moved by (dx, dy).
     *
     * @param dx the move, x part
     * @param dy the move, y part
     * @return the moved shape
     */
    @JSExport
    public ShapeJs translated(float dx, float dy) {
        return new ShapeJs(shape.translated(dx, dy));
    }

    /**
     * The same shape turned by an angle (radians) about a pivot.
     *
     * @param angle  the angle, radians, clockwise on screen
     * @param pivotX the pivot's x
     * @param pivotY the pivot's y
     * @return the turned shape
     */
    @JSExport
    public ShapeJs rotated(float angle, float pivotX, float pivotY) {
        return new ShapeJs(shape.rotated(angle, pivotX, pivotY));
    }

    /**
     * The bounding box: {x, y, w, h}.
     *
     * @return the box
     */
    @JSExport
    @JSProperty
    public JSObject getBounds() {
        return Js.of(shape.bounds());
    }

    /**
     * The kind: "Circle", "Rect", "Segment", "Polygon", "Ellipse" or "Capsule".
     *
     * @return the kind's name
     */
    @JSExport
    @JSProperty
    public String getKind() {
        if (shape instanceof hitbox.Circle) {
            return "Circle";
        } else if (shape instanceof hitbox.Rect) {
            return "Rect";
        } else if (shape instanceof hitbox.Segment) {
            return "Segment";
        } else if (shape instanceof hitbox.Polygon) {
            return "Polygon";
        } else if (shape instanceof hitbox.Ellipse) {
            return "Ellipse";
        }
        return "Capsule";
    }

    /**
     * The shape as the library writes it, e.g. "Circle[x=1.0, y=2.0, r=3.0]".
     *
     * @return the text
     */
    @JSExport
    @Override
    public String toString() {
        return shape.toString();
    }
}
