package hitbox;

import hitbox.internal.*;

/**
 * A shape in the plane: an immutable value that can be tested against any other shape.
 *
 * <p>The family is sealed so that {@link #overlaps} can answer for every pair: circles,
 * rectangles, segments, polygons, ellipses and capsules. Each pair is decided by the same code as the matching
 * {@link Collide} method, and by the same <a href="package-summary.html#touching">touching
 * rule</a>, in either order: {@code a.overlaps(b) == b.overlaps(a)}.
 *
 * <p>Every question a shape answers is asked here, once for all six kinds; what is special
 * to a kind (what is open or closed, how a zero size behaves, what a transform makes of it)
 * is on that kind's class. A kind overrides {@link #translated}, and {@link #rotated} and
 * {@link #transformed} where it keeps its kind, only to answer with its own type:
 * {@code Circle c = circle.translated(5, 0)}.
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
    default boolean overlaps(Shape other) {
        // One switch on this shape's kind to its small part of the table (Overlaps.circleWith,
        // say, with its fast path): for a receiver of one kind the JIT keeps only that case.
        return Overlaps.test(this, Check.notNull("other", other));
    }

    /**
     * How this shape and {@code other} overlap: the unit normal from this shape to the other
     * and the depth that separates them, or null when they do not overlap (touching is not
     * overlapping).
     *
     * @param other the other shape, not null
     * @return the contact, or null when the shapes are apart or touching
     * @throws IllegalArgumentException if {@code other} is null, or either shape is a
     *                                  {@link Segment} (a segment has no area to push out of)
     */
    default Contact contact(Shape other) {
        return Contacts.between(this, Check.notNull("other", other));
    }

    /**
     * Is the point in this shape? For shapes with area the outline does not count; for a
     * segment, a point on it counts, end points included.
     *
     * <p>Each kind answers as its point test: {@link Collide#circlePoint},
     * {@link Collide#rectPoint}, {@link Collide#polygonPoint} (a triangle by
     * {@link Collide#trianglePoint}, which gives the same answer); a capsule by "closer than
     * {@code r} to its segment", compared exactly as its pairs are; an axis-aligned ellipse by
     * {@code (dx / rx)^2 + (dy / ry)^2 < 1} multiplied out so nothing is divided, decided
     * exactly for every float (a turned one takes the point into its own frame first).
     *
     * <p>A NaN in any argument answers false
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x the point's x
     * @param y the point's y
     * @return true if the point is in the shape
     */
    default boolean contains(float x, float y) {
        return Containment.point(this, x, y);
    }

    /**
     * Does this shape hold {@code other}: is no point of the other shape outside this one?
     * Touching this shape's outline from inside counts, so every shape contains itself (and
     * {@code a.contains(b) && b.contains(a)} means the two cover the same points).
     *
     * <p>With the <a href="package-summary.html#touching">touching rule</a>'s open shapes,
     * this is about closures: the other shape with its outline lies in this shape with its
     * outline. So {@code new Rect(0, 0, 10, 10)} contains {@code new Rect(0, 0, 5, 5)} (two
     * edges shared), {@code new Circle(0, 0, 10)} contains {@code new Circle(5, 0, 5)} (touching
     * inside at (10, 0)) and {@code new Segment(0, 0, 10, 0)} (an end on the outline), but not
     * {@code new Circle(5, 0, 5.5f)}. A zero-size shape is the set it behaves as, ends
     * included: a circle of radius 0 is its centre, so the rectangle above contains
     * {@code new Circle(0, 5, 0)} although {@code contains(0, 5)}, which asks about the open
     * inside, is false. A segment, a shape without area, contains only segments and zero-size
     * shapes that lie on it; a concave polygon does not contain a shape whose corners are all
     * inside it while an edge crosses its notch.
     *
     * <p>Exact, with no tolerance, for whole-number coordinates of modest size wherever the
     * answer is a polynomial sign: every pair of circles, rectangles, segments, polygons and
     * capsules, and points or straight shapes in an axis-aligned ellipse (rectangles and
     * circles against any float). The curved pairs that are not (an ellipse
     * holding a circle, capsule or ellipse, an ellipse inside a circle or capsule, and
     * anything in or around a turned ellipse) are searched in double and count as held when
     * within a relative 1e-9 of the container's size of touching from inside; a polygon
     * holding a turned ellipse is decided as {@link #overlaps} decides that pair.
     *
     * @param other the shape that may be inside, not null
     * @return true if every point of {@code other} is in this shape or on its outline
     * @throws IllegalArgumentException if {@code other} is null
     */
    default boolean contains(Shape other) {
        return Containment.test(this, Check.notNull("other", other));
    }

    /**
     * The smallest axis-aligned float rectangle that holds this shape: its hit box for a
     * cheap first test. Rounded outwards: its far edges, {@code x + w} and {@code y + h}
     * added in double as {@link Collide} adds them, are at or beyond the shape's, even when
     * the exact size is not a float. (Only a shape reaching past the float range, a circle
     * of radius near {@code Float.MAX_VALUE}, say, gets a box held back at the float range.)
     *
     * <p>A rectangle is its own bounds, and a polygon's box is made once, when first asked. A
     * circle's, a capsule's, a segment's and an aligned ellipse's box is its exact extent
     * rounded outwards (so it holds the shape even when {@code x - r} is not a float); a
     * turned ellipse's is {@code hypot(rx cos, ry sin)} either side of the centre, widened
     * by a few double roundings before it is rounded outwards. So the box is exact, its edges
     * the shape's, whenever those edges are floats.
     *
     * @return the bounding rectangle, never null
     */
    default Rect bounds() {
        return Bounds.of(this);
    }

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
     * This shape under the affine transform {@code t}: turned, scaled, mirrored, sheared and
     * moved as {@code t} moves each of its points (see {@link Transform}). What each kind
     * becomes (in detail on its class, or on its own {@code transformed}):
     * <ul>
     *   <li>{@link Circle}: a circle under a similarity (a turn, a mirror, a scale the same
     *       both ways, a move); under a scale that differs by direction, or a shear, a turned
     *       {@link Ellipse} (an ellipse whose two radii round to the same float is a circle
     *       again).</li>
     *   <li>{@link Rect}: a rect when the transform keeps the axes (a move, an axis scale or
     *       mirror, a quarter turn: exactly {@code m01 = m10 = 0} or {@code m00 = m11 = 0});
     *       otherwise a {@link Polygon} of its four corners.</li>
     *   <li>{@link Segment}, {@link Polygon}, {@link Ellipse}: the same kind (an ellipse's
     *       image is an ellipse, exactly, with new radii and angle).</li>
     *   <li>{@link Capsule}: a capsule under a similarity; a capsule stretched one way has
     *       elliptical ends, no exact result, and is refused.</li>
     * </ul>
     * Every point is transformed in double and rounded once to float.
     *
     * <p>A <em>singular</em> transform (determinant 0, such as {@code Transform.scaling(0, 1)})
     * squashes the plane onto a line or a point: a segment, a circle or an ellipse (flat: a
     * radius of 0), an axis-kept rect (width or height 0) and a capsule of radius 0 still have
     * an answer; a polygon, a rect turned off the axes and a capsule with a radius have none
     * and are refused.
     *
     * @param t the transform, not null
     * @return the transformed shape, never null
     * @throws IllegalArgumentException if {@code t} is null, a coordinate or size goes beyond
     *                                  the float range, or the kind has no exact result (see
     *                                  each kind)
     */
    default Shape transformed(Transform t) {
        return Transforms.apply(this, Transforms.affine(t));
    }

    /**
     * This shape turned by {@code angle} about the point (pivotX, pivotY): radians, clockwise
     * on screen for a positive angle, as Processing's {@code rotate()}. Same as
     * {@code transformed(Transform.rotation(angle, pivotX, pivotY))}: a turn keeps every kind
     * but a rectangle, which stays a rect for a whole number of quarter turns
     * ({@code HALF_PI}, {@code PI}...) and becomes a {@link Polygon} otherwise.
     *
     * @param angle  the turn, in radians
     * @param pivotX the x of the point it turns about
     * @param pivotY the y of the point it turns about
     * @return the turned shape, never null
     * @throws IllegalArgumentException if a value is NaN or infinite, or a coordinate goes
     *                                  beyond the float range
     */
    default Shape rotated(float angle, float pivotX, float pivotY) {
        return Transform.turn(this, angle, pivotX, pivotY);
    }
}
