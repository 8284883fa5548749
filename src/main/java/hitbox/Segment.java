package hitbox;

import hitbox.internal.*;

/**
 * A line segment between two end points: what a sketch draws with {@code line()}.
 *
 * <p>Closed: its end points belong to it, so segments that meet at an end intersect, and so do
 * collinear segments that overlap ({@link Collide#lineLine}). Like a point, it has no inside:
 * it collides with a circle, rectangle or polygon only by reaching into that shape's inside
 * ({@link Collide#lineCircle}, {@link Collide#lineRect}, {@link Collide#polygonLine}), so
 * running along an edge does not count, and it never collides with a circle of radius 0 or a
 * rectangle of width or height 0. A segment of length 0 is a point. A point is in it
 * ({@link #contains(float, float)}) when it lies on it, end points included.
 *
 * @param x1 the first end's x
 * @param y1 the first end's y
 * @param x2 the second end's x
 * @param y2 the second end's y
 */
public record Segment(float x1, float y1, float x2, float y2) implements Shape {

    /**
     * Makes a segment, checking its values. Both ends may be the same point.
     *
     * @param x1 the first end's x
     * @param y1 the first end's y
     * @param x2 the second end's x
     * @param y2 the second end's y
     *
     * @throws IllegalArgumentException if a value is NaN or infinite
     */
    public Segment {
        Check.finite("x1", x1);
        Check.finite("y1", y1);
        Check.finite("x2", x2);
        Check.finite("y2", y2);
    }

    /** {@inheritDoc} */
    @Override
    public Segment translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Segment(Check.finite("x1 + dx", x1 + dx), Check.finite("y1 + dy", y1 + dy),
                Check.finite("x2 + dx", x2 + dx), Check.finite("y2 + dy", y2 + dy));
    }

    /**
     * {@inheritDoc} A segment stays a segment: its two ends transformed (a singular transform
     * may bring them together, a segment of length 0).
     *
     * @throws IllegalArgumentException if {@code t} is null, or an end goes beyond the float
     *                                  range
     */
    @Override
    public Segment transformed(Transform t) {
        return Transforms.segment(this, Check.notNull("t", t).affine());
    }

    /**
     * {@inheritDoc}
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or an end goes beyond
     *                                  the float range
     */
    @Override
    public Segment rotated(float angle, float pivotX, float pivotY) {
        return (Segment) Transform.turn(this, angle, pivotX, pivotY);
    }

    /**
     * Which side of this segment's line is the point on, walking from the first end to the
     * second? Same as {@link Collide#lineSide}.
     *
     * <p>A NaN in any argument answers 0
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param px the point's x
     * @param py the point's y
     * @return 1 (the walker's right on screen), -1 (left) or 0 (on the line)
     */
    public int side(float px, float py) {
        return Collide.lineSide(x1, y1, x2, y2, px, py);
    }

    /** @return the segment's length */
    public float length() {
        return (float) Math.hypot(x2 - x1, y2 - y1);
    }
}
