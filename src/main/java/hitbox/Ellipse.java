package hitbox;

import hitbox.internal.*;

/**
 * An ellipse: its centre, its two radii and how far it is turned (0 by default, an
 * axis-aligned ellipse, Processing's {@code ellipse(x, y, w, h)} in the default
 * {@code CENTER} mode with {@code rx = w / 2} and {@code ry = h / 2}). Draw it with
 * {@code ellipse(x, y, 2 * rx, 2 * ry)} when it is not turned, or with
 * {@code hitbox.processing.Draw.shape} either way.
 *
 * <p>Open, like every shape with area: a point on the outline is not in it. An ellipse with
 * a radius of 0 is flat and has no inside: it behaves as its box, a rectangle of width or
 * height 0 (a segment without its ends, or a point). With equal radii it is a circle, and
 * answers as {@link Circle} does. How exactly each pair is decided, for an axis-aligned
 * ellipse: a point and a rectangle (its point nearest the centre, by the point's equation)
 * exactly for every float; a segment in double, scaled into a circle, exact for whole numbers
 * up to about 4,000; a circle, another ellipse, a polygon or a capsule by the distance to the
 * outline (D. Eberly's robust bisection), unless the discs inside and around the ellipse or a
 * few rounds of closest points settle it first by a margin of 1e-10 of the sizes: touching on
 * the ellipse's axes is exact, and elsewhere the answer can be wrong only when the gap or
 * overlap is below about 1e-12 of the sizes involved (1e-9 against a capsule).
 *
 * <p><b>Turned.</b> An ellipse may be turned about its centre by {@code angle} radians,
 * clockwise on screen for a positive angle, as Processing's {@code rotate()} turns what is
 * drawn after it (and as {@link Polygon#rotatedRect} takes its angle): draw it with
 * {@code pushMatrix(); translate(x, y); rotate(angle); ellipse(0, 0, 2 * rx, 2 * ry); popMatrix();}.
 * Then {@code rx} is the radius along the turned x axis. An angle of 0 (the default) is the
 * axis-aligned ellipse above, decided exactly; a turned ellipse is decided in double in its
 * own frame (the other shape turned by {@code -angle} about its centre), so a pair within
 * about 1e-12 of its size of touching may go either way. A turned ellipse with equal radii is
 * a circle and one with both radii 0 a point, whatever the angle, and both are decided as
 * without the angle; a turned ellipse with one radius 0 is flat: a segment without its ends
 * between {@code (x, y) +- r (cos angle, sin angle)} (r the radius that is not 0, turned with
 * its axis), each end rounded to float.
 *
 * @param x     the centre's x
 * @param y     the centre's y
 * @param rx    the horizontal radius (half the width, along the turned x axis), 0 or more
 * @param ry    the vertical radius (half the height, along the turned y axis), 0 or more
 * @param angle how far the ellipse is turned about its centre, in radians, clockwise on screen;
 *              0 for an axis-aligned ellipse
 */
public record Ellipse(float x, float y, float rx, float ry, float angle) implements Shape {

    /**
     * Makes a turned ellipse, checking its values.
     *
     * @param x     the centre's x
     * @param y     the centre's y
     * @param rx    the radius along the turned x axis, 0 or more
     * @param ry    the radius along the turned y axis, 0 or more
     * @param angle how far it is turned about its centre, radians, clockwise on screen
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or a radius is negative
     */
    public Ellipse {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.size("radius rx", rx);
        Check.size("radius ry", ry);
        Check.finite("angle", angle);
    }

    /**
     * Makes an axis-aligned ellipse (angle 0), checking its values: Processing's
     * {@code ellipse(x, y, 2 * rx, 2 * ry)}.
     *
     * @param x  the centre's x
     * @param y  the centre's y
     * @param rx the horizontal radius, 0 or more
     * @param ry the vertical radius, 0 or more
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or a radius is negative
     */
    public Ellipse(float x, float y, float rx, float ry) {
        this(x, y, rx, ry, 0);
    }

    /** {@inheritDoc} */
    @Override
    public boolean overlaps(Shape other) {
        // this kind's own small part of the table, which a caller's loop can inline (see Overlaps)
        return Overlaps.ellipseWith(this, Check.notNull("other", other));
    }

    /**
     * {@inheritDoc} For an axis-aligned ellipse the equation
     * {@code (dx / rx)^2 + (dy / ry)^2 < 1} multiplied out so nothing is divided, decided exactly
     * for every float; a turned one takes the point into its own frame first.
     */
    @Override
    public boolean contains(float px, float py) {
        return TurnedEllipses.aligned(this) ? RawTests.ellipsePoint(x, y, rx, ry, px, py) : TurnedEllipses.turnedPoint(this, px, py);
    }

    /** {@inheritDoc} */
    @Override
    public boolean contains(Shape other) {
        return Containment.ellipseContains(this, Check.notNull("other", other));
    }

    /**
     * {@inheritDoc} Rounded outwards, so the box holds the ellipse even when x - rx is not a
     * float; a turned ellipse's box is its exact extent, {@code hypot(rx cos, ry sin)} either
     * side of the centre, widened by a few double roundings before it is rounded outwards.
     */
    @Override
    public Rect bounds() {
        return Bounds.enclosing(minX(), minY(), maxX(), maxY());
    }

    /**
     * The shape's smallest x (the extent {@link #bounds()} rounds outwards): exact when aligned,
     * a turned ellipse's a hair beyond, widened past the rounding of its cos and sin.
     */
    @Override
    public double minX() {
        return (double) x - TurnedEllipses.halfWidth(this);
    }

    /** The shape's smallest y, as {@link #minX()}. */
    @Override
    public double minY() {
        return (double) y - TurnedEllipses.halfHeight(this);
    }

    /** The shape's largest x, as {@link #minX()}. */
    @Override
    public double maxX() {
        return (double) x + TurnedEllipses.halfWidth(this);
    }

    /** The shape's largest y, as {@link #minX()}. */
    @Override
    public double maxY() {
        return (double) y + TurnedEllipses.halfHeight(this);
    }

    /** {@inheritDoc} The angle is kept. */
    @Override
    public Ellipse translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Ellipse(Check.finite("x + dx", x + dx), Check.finite("y + dy", y + dy), rx, ry, angle);
    }

    /**
     * {@inheritDoc}
     *
     * <p>An ellipse stays an ellipse (the image of an ellipse under an affine map is one): its
     * centre transformed, its radii and angle those of the transformed outline, from the 2x2
     * singular value decomposition. Exact where it can be: an aligned ellipse under an axis
     * scale or a quarter turn stays aligned (angle 0, radii times the factors); under a turn
     * or mirror the radii are kept and the angle turned. A singular transform gives a flat
     * ellipse (a radius of 0).
     *
     * @throws IllegalArgumentException if {@code t} is null, or the centre or a radius goes
     *                                  beyond the float range
     */
    @Override
    public Ellipse transformed(Transform t) {
        return Transforms.ellipse(this, Check.notNull("t", t).affine());
    }

    /**
     * {@inheritDoc} The radii are kept and the angle grows by {@code angle}.
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or the centre goes
     *                                  beyond the float range
     */
    @Override
    public Ellipse rotated(float angle, float pivotX, float pivotY) {
        return (Ellipse) Transform.turn(this, angle, pivotX, pivotY);
    }
}
