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
 * drawn after it (and as {@link Shape#rotated} takes its angle): draw it with
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
