package hitbox;

/**
 * An axis-aligned ellipse: its centre and its two radii, Processing's
 * {@code ellipse(x, y, w, h)} (in the default {@code CENTER} mode) with {@code rx = w / 2} and
 * {@code ry = h / 2}. Draw it with {@code ellipse(x, y, 2 * rx, 2 * ry)}.
 *
 * <p>Open, like every shape with area: a point on the outline is not in it. An ellipse with
 * a radius of 0 is flat and has no inside: it behaves as its box, a rectangle of width or
 * height 0 (a segment without its ends, or a point). With equal radii it is a circle, and
 * answers as {@link Circle} does. How exactly each pair is decided is stated on the
 * {@code Collide.ellipse...} methods ({@link Collide#ellipseCircle}, say).
 *
 * @param x  the centre's x
 * @param y  the centre's y
 * @param rx the horizontal radius (half the width), 0 or more
 * @param ry the vertical radius (half the height), 0 or more
 */
public record Ellipse(float x, float y, float rx, float ry) implements Shape {

    /**
     * Makes an ellipse, checking its values.
     *
     * @param x  the centre's x
     * @param y  the centre's y
     * @param rx the horizontal radius, 0 or more
     * @param ry the vertical radius, 0 or more
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or a radius is negative
     */
    public Ellipse {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.size("radius rx", rx);
        Check.size("radius ry", ry);
    }

    /** {@inheritDoc} Same as {@link Collide#ellipsePoint}. */
    @Override
    public boolean contains(float px, float py) {
        return Collide.ellipsePoint(x, y, rx, ry, px, py);
    }

    /** {@inheritDoc} Rounded outwards, so the box holds the ellipse even when x - rx is not a float. */
    @Override
    public Rect bounds() {
        return Bounds.enclosing(Bounds.left(this), Bounds.top(this), Bounds.right(this), Bounds.bottom(this));
    }

    /** {@inheritDoc} */
    @Override
    public Ellipse translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Ellipse(Check.finite("x + dx", x + dx), Check.finite("y + dy", y + dy), rx, ry);
    }
}
