package hitbox;

import hitbox.internal.*;

/**
 * How far apart two shapes are that do not overlap: the distance between them, and a point on
 * each that are that far apart (dyn4j's {@code Separation}, Box2D's {@code b2DistanceOutput}).
 * For a game's "how far is it", a proximity sensor, the nearest of several shapes.
 *
 * <p>{@link #between(Shape, Shape)} answers for every pair of shapes, in either order: null
 * when they overlap by the <a href="package-summary.html#touching">touching rule</a> (use
 * {@link Contact} for how deep), else the distance, 0 when they touch, and the closest points,
 * {@code (ax, ay)} on the first shape's outline and {@code (bx, by)} on the second's (for a
 * segment, on the segment). Swapping the shapes swaps the points, {@link #flipped()}, and keeps
 * the distance. Where several pairs of points are equally close (two parallel edges, say),
 * the pair given is the one whose midpoint comes first (the least x, then the least y), so
 * the same pair either way round; for a pair with an ellipse of two different radii (found by
 * a search), one of them. Touching shapes give one point, the same for both.
 *
 * <p><b>How exact.</b> Worked in double from the floats and rounded once to float. Between
 * shapes with straight edges, circles and capsules, the distance is exact for whole-number
 * coordinates of modest size (up to about a million) wherever it is a number a float holds:
 * an axis-aligned gap, a corner-to-corner or centre-to-centre distance that is a whole number
 * (a 3-4-5 triangle), so touching shapes give exactly 0; otherwise it is the true distance
 * rounded, to a few units of 2^-53 of the coordinates before the float rounding. A pair with
 * an ellipse of two different radii is found by an iterative search (Eberly's closest point
 * on an ellipse, and a bisection along the other shape's edges or outline) and is right to
 * about 1e-9 of the shapes' size; its closest points lie on the outlines to that accuracy
 * too, but where the least is flat (two outlines nearly parallel) they may slide along them
 * by up to about 1e-6 of the size. The points are rounded to floats, so the distance between
 * them agrees with {@link #distance()} to a float's rounding of the coordinates.
 *
 * <p>One raw-float form stays, {@link #circleCircle}: the distance alone of two circles, 0
 * when they overlap, where the narrow-phase table shows {@link #between} more than 10% slower.
 *
 * <p>Made by hand, a separation checks only its own values: NaN or infinite values, or a
 * negative distance, throw an {@link IllegalArgumentException}; it does not check that the
 * distance is the points' distance.
 *
 * @param distance how far apart the shapes are, 0 or more (0 when they touch)
 * @param ax       the closest point on the first shape, x
 * @param ay       the closest point on the first shape, y
 * @param bx       the closest point on the second shape, x
 * @param by       the closest point on the second shape, y
 */
public record Separation(float distance, float ax, float ay, float bx, float by) {

    /**
     * Makes a separation, checking its values.
     *
     * @param distance how far apart, 0 or more
     * @param ax       the closest point on the first shape, x
     * @param ay       the closest point on the first shape, y
     * @param bx       the closest point on the second shape, x
     * @param by       the closest point on the second shape, y
     * @throws IllegalArgumentException if a value is NaN or infinite, or the distance is
     *                                  negative
     */
    public Separation {
        // -0 becomes 0, as in Contact, so that a computed value equals one written by hand.
        distance += 0.0f;
        Check.size("distance", distance);
        Check.finite("ax", ax);
        Check.finite("ay", ay);
        Check.finite("bx", bx);
        Check.finite("by", by);
    }

    /**
     * The separation of two shapes, or null when they overlap. Same as
     * {@code a.separation(b)}.
     *
     * @param a the first shape, not null
     * @param b the second shape, not null
     * @return the distance and the closest points (on a, then on b), or null when the shapes
     *         overlap (touching shapes give distance 0, not null)
     * @throws IllegalArgumentException if a shape is null
     */
    public static Separation between(Shape a, Shape b) {
        return Distances.between(Check.notNull("a", a), Check.notNull("b", b));
    }

    /**
     * The direction from the closest point on the first shape to the one on the second, x:
     * a unit vector with {@link #ny()}, or (0, 0) when the two points are one (the shapes
     * touch).
     *
     * @return the direction's x, from a to b
     */
    public float nx() {
        double dx = (double) bx - ax, dy = (double) by - ay, len = Math.hypot(dx, dy);
        return len == 0 ? 0 : (float) (dx / len);
    }

    /**
     * The direction from a's closest point to b's, y; see {@link #nx()}.
     *
     * @return the direction's y, from a to b (y grows down)
     */
    public float ny() {
        double dx = (double) bx - ax, dy = (double) by - ay, len = Math.hypot(dx, dy);
        return len == 0 ? 0 : (float) (dy / len);
    }

    /**
     * The same separation seen from b: the points swapped, the distance kept.
     *
     * @return the separation with b's point first, never null
     */
    public Separation flipped() {
        return new Separation(distance, bx, by, ax, ay);
    }

    // ---------------------------------------------------------------- raw floats

    /**
     * How far apart two circles are, 0 when they touch or overlap, on plain floats: the one
     * raw-float form this class keeps, because the narrow-phase table (docs/narrow-phase.md,
     * "separation, circle vs circle") shows {@link #between} about 8 times slower on it (it
     * makes the closest points, this only the distance). {@code dist(x1, y1, x2, y2) - (r1 + r2)},
     * {@code dist(x1, y1, x2, y2) - (r1 + r2)}, held at 0 (the tutorial compares that
     * distance with r1 + r2; this is by how much it misses). Exact for whole numbers when the
     * centres' distance is a whole number.
     *
     * <p>A NaN in any argument, an infinite one or a negative radius answers
     * {@code +Infinity} (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first circle's centre x
     * @param y1 the first circle's centre y
     * @param r1 the first circle's radius
     * @param x2 the second circle's centre x
     * @param y2 the second circle's centre y
     * @param r2 the second circle's radius
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        if (Check.notFinite(x1, y1, r1, x2, y2) || !Float.isFinite(r2) || r1 < 0 || r2 < 0) {
            return Float.POSITIVE_INFINITY;
        }
        return Check.held(Distances.discs(x1, y1, r1, x2, y2, r2));
    }

}
