package hitbox;

import hitbox.internal.*;

/**
 * Where a moving shape first runs into an obstacle: the answer of every
 * {@code Sweep.timeOfImpact} method.
 *
 * <p>{@code t} is the fraction of this frame's motion done at the moment of impact: move the
 * mover the way a sketch does, {@code x + t * vx} and {@code y + t * vy} in {@code float},
 * and it stands against the obstacle without overlapping it, as close as floats allow (see
 * {@link Sweep}). The normal is a unit vector <em>from the mover into the obstacle</em>, the
 * package's one convention (the obstacle's inward surface normal where it was hit; y grows
 * down, so landing on a floor gives {@code (0, 1)}), so it goes straight to
 * {@link Response#bounce(float, float, float, float, float)}.
 * {@link #side()} names the side of the <em>obstacle</em> that was hit, by the one rule of
 * {@link Side#ofNormal}: for a round or slanted surface it is the side the normal mostly
 * points into (a normal exactly at 45 degrees counts as {@link Side#TOP} or
 * {@link Side#BOTTOM}). Every result that names one side gives it this way, as
 * {@code side()} (see <a href="Side.html#results">the side of a result</a>).
 *
 * <p>When the two shapes already overlap at the start of the motion there is no moment of
 * impact to report: {@code t} is 0, the normal is {@code (0, 0)} and the side is
 * {@link Side#NONE} (see {@link #alreadyOverlapping()}); push them apart with a contact
 * test instead. A mover that only touches the obstacle at the start and moves into it gets
 * {@code t = 0} exactly, with a real normal and side (the one exception to the largest float
 * t of {@link Sweep}: there the float position has not moved for a hair above 0, but the
 * exact entry is 0). "Touches" is exact for the pairs {@link Sweep} solves exactly (circles,
 * rectangles, segments, two convex polygons, a rectangle moving into a convex polygon, a
 * circle moving into any polygon). Where a curved shape meets anything but a
 * circle, a rectangle or a segment of those (an ellipse, a capsule, a polygon against a
 * curved shape), touching at a slanted place cannot be built exactly in floats nor decided
 * exactly, and the search stands in for it: a start within 1e-6 pixels, closing in, whose
 * last clear float moves the mover by no more than a float step of its largest coordinate,
 * gets {@code t = 0}; a start a clear gap away (0.01 pixels, say) gets its time. For the
 * turning sweeps ({@link Sweep#turningTimeOfImpact}) it is a gap below their stopping
 * distance, 1e-3 pixels, while closing in.
 *
 * @param t    the fraction of the motion done at impact, from 0 to 1
 * @param nx   the normal from the mover into the obstacle, x part (unit length, or 0)
 * @param ny   the normal from the mover into the obstacle, y part (unit length, or 0)
 * @param side the side of the obstacle that was hit, {@link Side#NONE} if the shapes
 *             already overlapped
 */
public record Hit(float t, float nx, float ny, Side side) {

    /**
     * Makes a hit, checking its values.
     *
     * @param t the fraction of the motion done at impact, from 0 to 1
     * @param nx the normal from the mover into the obstacle, x part (unit length, or 0)
     * @param ny the normal from the mover into the obstacle, y part (unit length, or 0)
     * @param side the side of the obstacle that was hit, {@link Side#NONE} if the shapes already overlapped
     *
     * @throws IllegalArgumentException if {@code t} is not between 0 and 1, the normal is
     *                                  NaN or infinite, or the side is null
     */
    public Hit {
        if (!(t >= 0 && t <= 1)) {
            throw new IllegalArgumentException("t must be between 0 and 1, was " + t);
        }
        Check.finite("nx", nx);
        Check.finite("ny", ny);
        Check.notNull("side", side);
    }

    /**
     * Did the shapes already overlap when the motion started?
     *
     * @return true if there was no moment of impact because the shapes overlapped at
     *         {@code t = 0} (then the side is {@link Side#NONE} and the normal is zero)
     */
    public boolean alreadyOverlapping() {
        return side == Side.NONE;
    }

    /**
     * Did the mover land on top of the obstacle? Same as {@code side() == Side.TOP}.
     *
     * @return true if the obstacle's top side was hit
     */
    public boolean landed() {
        return side == Side.TOP;
    }
}
