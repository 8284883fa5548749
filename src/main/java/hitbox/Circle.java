package hitbox;

import hitbox.internal.*;

/**
 * A circle: its centre and its radius (the tutorial's, not Processing's diameter; draw it
 * with {@code circle(x, y, 2 * r)}).
 *
 * <p>Open: a point on the outline is not in it. A circle of radius 0 behaves as a point.
 *
 * @param x the centre's x
 * @param y the centre's y
 * @param r the radius, 0 or more
 */
public record Circle(float x, float y, float r) implements Shape {

    /**
     * Makes a circle, checking its values.
     *
     * @param x the centre's x
     * @param y the centre's y
     * @param r the radius, 0 or more
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or the radius is negative
     */
    public Circle {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.size("radius r", r);
    }

    /** {@inheritDoc} */
    @Override
    public boolean overlaps(Shape other) {
        // this kind's own small part of the table, which a caller's loop can inline (see Overlaps)
        return Overlaps.circleWith(this, Check.notNull("other", other));
    }

    /** {@inheritDoc} Same as {@link Collide#circlePoint}. */
    @Override
    public boolean contains(float px, float py) {
        return Collide.circlePoint(x, y, r, px, py);
    }

    /** {@inheritDoc} Rounded outwards, so the box holds the circle even when x - r is not a float. */
    @Override
    public Rect bounds() {
        return Bounds.enclosing(minX(), minY(), maxX(), maxY());
    }

    /** The shape's smallest x, exactly (the extent {@link #bounds()} rounds outwards). */
    @Override
    public double minX() {
        return (double) x - r;
    }

    /** The shape's smallest y, exactly. */
    @Override
    public double minY() {
        return (double) y - r;
    }

    /** The shape's largest x, exactly. */
    @Override
    public double maxX() {
        return (double) x + r;
    }

    /** The shape's largest y, exactly. */
    @Override
    public double maxY() {
        return (double) y + r;
    }

    /** {@inheritDoc} */
    @Override
    public Circle translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Circle(Check.finite("x + dx", x + dx), Check.finite("y + dy", y + dy), r);
    }

    /**
     * {@inheritDoc}
     *
     * <p>A circle stays a circle (its centre transformed, its radius times the scale) under a
     * similarity: a turn, a mirror, a scale the same both ways, a move. Under a scale that
     * differs by direction or a shear it becomes a turned {@link Ellipse}, an aligned one when
     * the transform keeps the axes, flat (a radius of 0) when the transform is singular;
     * whenever the image's two radii round to the same float it is a circle again.
     *
     * @throws IllegalArgumentException if {@code t} is null, or the centre or a radius goes
     *                                  beyond the float range
     */
    @Override
    public Shape transformed(Transform t) {
        return Transforms.circle(this, Check.notNull("t", t).affine());
    }

    /**
     * {@inheritDoc} A turned circle is a circle with the same radius.
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or the centre goes
     *                                  beyond the float range
     */
    @Override
    public Circle rotated(float angle, float pivotX, float pivotY) {
        return (Circle) Transform.turn(this, angle, pivotX, pivotY);
    }
}
