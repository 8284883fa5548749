package hitbox;

import hitbox.internal.*;

/**
 * A circle: its centre and its radius (the tutorial's, not Processing's diameter; draw it
 * with {@code circle(x, y, 2 * r)}).
 *
 * <p>Open: a point on the outline is not in it. A circle of radius 0 behaves as a point.
 *
 * <p><b>Transformed</b> ({@link #transformed}): a circle stays a circle (its centre
 * transformed, its radius times the scale) under a similarity: a turn, a mirror, a scale the
 * same both ways, a move. Under a scale that differs by direction or a shear it becomes a
 * turned {@link Ellipse}, an aligned one when the transform keeps the axes, flat (a radius of
 * 0) when the transform is singular; whenever the image's two radii round to the same float
 * it is a circle again. Refused only when the centre or a radius goes beyond the float range.
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
    public Circle translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Circle(Check.finite("x + dx", x + dx), Check.finite("y + dy", y + dy), r);
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
