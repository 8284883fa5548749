package hitbox;

import hitbox.internal.*;

/**
 * A capsule: the points closer than {@code r} to a segment, a stadium with round ends. The
 * usual shape for a top-down player or a thick laser.
 *
 * <p>Open, like every shape with area: a point at distance exactly r from the segment is not
 * in it. A capsule whose segment is a point is a circle; a capsule of radius 0 has no inside
 * and behaves as its segment does against shapes with area (it collides by reaching into
 * their inside), but, like a circle of radius 0, never collides with a segment, a point or
 * another shape without area. Every pair is "is the distance less than the sum of the
 * radii?", compared squared as exact signs of double products, so touching between whole
 * numbers of modest size (up to about 2^20) is exact; against an ellipse, see {@link Ellipse}.
 *
 * @param x1 the segment's first end x
 * @param y1 the segment's first end y
 * @param x2 the segment's second end x
 * @param y2 the segment's second end y
 * @param r  the radius, 0 or more
 */
public record Capsule(float x1, float y1, float x2, float y2, float r) implements Shape {

    /**
     * Makes a capsule, checking its values. Both ends may be the same point.
     *
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @param r  the radius, 0 or more
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or the radius is negative
     */
    public Capsule {
        Check.finite("x1", x1);
        Check.finite("y1", y1);
        Check.finite("x2", x2);
        Check.finite("y2", y2);
        Check.size("radius r", r);
    }

    /** {@inheritDoc} */
    @Override
    public Capsule translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Capsule(Check.finite("x1 + dx", x1 + dx), Check.finite("y1 + dy", y1 + dy),
                Check.finite("x2 + dx", x2 + dx), Check.finite("y2 + dy", y2 + dy), r);
    }

    /**
     * {@inheritDoc}
     *
     * <p>A capsule stays a capsule under a similarity (a turn, a mirror, a scale the same both
     * ways, a move): its segment's ends transformed, its radius times the scale. Under a scale
     * that differs by direction, or a shear, its round ends would become elliptical: there is
     * no exact result, and it is refused (scale it the same both ways, or transform
     * {@link #segment()} and choose the radius). A capsule of radius 0 is its segment, and
     * takes any transform.
     *
     * @throws IllegalArgumentException if {@code t} is null, an end or the radius goes beyond
     *                                  the float range, or the transform stretches a capsule
     *                                  with a radius more one way than another (after rounding
     *                                  to float)
     */
    @Override
    public Capsule transformed(Transform t) {
        return Transforms.capsule(this, Check.notNull("t", t).affine());
    }

    /**
     * {@inheritDoc}
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or an end goes beyond
     *                                  the float range
     */
    @Override
    public Capsule rotated(float angle, float pivotX, float pivotY) {
        return (Capsule) Transform.turn(this, angle, pivotX, pivotY);
    }

    /** @return the segment between the capsule's two round ends, never null */
    public Segment segment() {
        return new Segment(x1, y1, x2, y2);
    }
}
