package hitbox;

import hitbox.internal.*;

/**
 * A shape in the plane: an immutable value that can be tested against any other shape.
 *
 * <p>The family is sealed so that {@link #overlaps} can answer for every pair: circles,
 * rectangles, segments, polygons, ellipses and capsules. Each pair is decided by the same code as the matching
 * {@link Collide} method, and by the same <a href="package-summary.html#touching">touching
 * rule</a>, in either order: {@code a.overlaps(b) == b.overlaps(a)}.
 */
public sealed interface Shape permits Circle, Rect, Segment, Polygon, Ellipse, Capsule {

    /**
     * Does this shape collide with {@code other}? Touching is not colliding for shapes with
     * area; segments are closed (see the package documentation).
     *
     * @param other the other shape, not null
     * @return true if the two shapes collide
     * @throws IllegalArgumentException if {@code other} is null
     */
    boolean overlaps(Shape other);

    /**
     * How this shape and {@code other} overlap: the unit normal from this shape to the other
     * and the depth that separates them, or null when they do not overlap (touching is not
     * overlapping). Same as {@link Contact#between Contact.between(this, other)}.
     *
     * @param other the other shape, not null
     * @return the contact, or null when the shapes are apart or touching
     * @throws IllegalArgumentException if {@code other} is null, or either shape is a
     *                                  {@link Segment} (a segment has no area to push out of)
     */
    default Contact contact(Shape other) {
        return Contact.between(this, Check.notNull("other", other));
    }

    /**
     * How far this shape is from {@code other}, and the closest point on each, or null when
     * they overlap (then use {@link #contact}). Same as
     * {@link Separation#between Separation.between(this, other)}: every pair of shapes,
     * segments too; touching shapes give distance 0.
     *
     * @param other the other shape, not null
     * @return the separation (this shape's point first), or null when the shapes overlap
     * @throws IllegalArgumentException if {@code other} is null
     */
    default Separation separation(Shape other) {
        return Separation.between(this, Check.notNull("other", other));
    }

    /**
     * Is the point in this shape? For shapes with area the outline does not count; for a
     * segment, a point on it counts.
     *
     * <p>A NaN in any argument answers false
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x the point's x
     * @param y the point's y
     * @return true if the point is in the shape
     */
    boolean contains(float x, float y);

    /**
     * The smallest axis-aligned float rectangle that holds this shape: its hit box for a
     * cheap first test. Rounded outwards: its far edges, {@code x + w} and {@code y + h}
     * added in double as {@link Collide} adds them, are at or beyond the shape's, even when
     * the exact size is not a float. (Only a shape reaching past the float range, a circle
     * of radius near {@code Float.MAX_VALUE}, say, gets a box held back at the float range.)
     *
     * @return the bounding rectangle, never null
     */
    Rect bounds();

    /**
     * This shape moved by (dx, dy).
     *
     * @param dx how far to move right
     * @param dy how far to move down
     * @return a new shape of the same kind, moved, never null
     * @throws IllegalArgumentException if the move gives a NaN or infinite coordinate
     */
    Shape translated(float dx, float dy);

    /**
     * The shape's smallest x, in double: exact for circles, rectangles, segments and capsules
     * (a sum of two floats is exact in double), a hair outside for a turned ellipse (widened
     * past its rounding) and a polygon (its {@link #bounds()} box's edge). {@link #bounds()}
     * is these four extents rounded outwards to floats.
     *
     * @return the smallest x, at or below every point of the shape
     */
    double minX();

    /**
     * The shape's smallest y, as {@link #minX()}.
     *
     * @return the smallest y, at or below every point of the shape
     */
    double minY();

    /**
     * The shape's largest x, as {@link #minX()}.
     *
     * @return the largest x, at or above every point of the shape
     */
    double maxX();

    /**
     * The shape's largest y, as {@link #minX()}.
     *
     * @return the largest y, at or above every point of the shape
     */
    double maxY();
}
