package hitbox;

import hitbox.internal.*;

/**
 * How two overlapping shapes overlap: the direction and the distance that pull them apart.
 *
 * <p>The normal (nx, ny) has length 1 and points <em>from a to b</em>, the first shape to the
 * second (dyn4j's {@code Penetration} convention). The depth is the minimum translation:
 * moving b by {@code normal * depth}, or a by {@code -normal * depth}, or each part of the
 * way (see {@link Response}), leaves the two shapes just touching. No shorter move in any
 * direction separates them.
 *
 * <h2>When there is a contact</h2>
 * {@link Shape#contact a.contact(b)} returns null exactly when the shapes do not overlap by the
 * <a href="package-summary.html#touching">touching rule</a>, which is exactly when the depth
 * would be 0 or less: shapes that touch have depth 0 and give null, so a returned contact
 * always has {@code depth > 0}. (A hair's-width overlap that rounds to a depth of 0 gives
 * the smallest positive float, {@link Float#MIN_VALUE}; a depth past the float range, for
 * shapes spanning more than {@code Float.MAX_VALUE}, is held at {@code Float.MAX_VALUE}.) Swapping the shapes gives the same
 * depth and the opposite normal, {@link #flipped()}, except where the two directions are
 * exactly equally short (see below).
 *
 * <h2>Ties and degenerate cases</h2>
 * When several directions are equally short (to within {@link #TIE}, so that rounding does
 * not decide), the tie goes to the most vertical one, and
 * between opposite directions to the one that pushes a up (normal (0, 1), a lands on b's
 * top): a platformer character standing exactly inside a block is lifted onto it, not sunk
 * into it. In full: the larger {@code |ny|} wins, then the larger {@code nx * ny}, then the
 * larger {@code ny}, then the larger {@code nx}; each of these keys is read from computed
 * normals, so keys within {@link #TIE} of each other are equal too (within 1e-6 for the pairs
 * found by a search, with an ellipse, a capsule or a concave polygon, whose normals are that
 * precise), and mirror images such as (0.866, 0.5) and (0.866, -0.5) go by the rule, never by
 * an ulp of rounding. For the axis-aligned pairs this is the order
 * (0, 1), (0, -1), (1, 0), (-1, 0). So circles with the same centre get the normal (0, 1)
 * and depth {@code r1 + r2}; a circle whose centre is exactly in the middle of a square is
 * pushed out through the square's top. When the two shapes are placed symmetrically (the
 * same centre, for example) swapping them gives the same normal, not the opposite one: no
 * rule can tell the two apart.
 *
 * <h2>Which pairs</h2>
 * Every pair of shapes with area: circles, rectangles (zero-size ones included), polygons,
 * convex or concave, ellipses, aligned or turned, and capsules, in either order. Convex pairs
 * of straight-edged shapes use the separating axis theorem ({@link SeparatingAxis}); a circle
 * against a convex polygon, its closest edge or corner. A pair with an ellipse or a capsule
 * minimises the two shapes' support functions over the normal's angle (the depth to about
 * 1e-12 of their size, the normal to about 1e-6 radians where the least is flat), and
 * against a concave polygon finds the shortest push that clears every convex piece.
 * Concave polygons are cut into convex pieces and the shortest move that clears all of them
 * together is found, so the answer is the true minimum translation for them too (up to a
 * rounding tolerance of about 1e-9 of the shapes' size), not just a push out of the nearest
 * edge, which can land a shape in another part of the polygon. That costs more: tens of
 * microseconds for a concave polygon of a dozen vertices against a circle or a rectangle,
 * and around a millisecond for two such concave polygons (the work grows with the product
 * of their numbers of pieces). Test {@link Shape#overlaps} or the bounds first when many
 * pairs are apart. A {@link Segment} has no area, so it has no contact: use
 * {@link Shape#overlaps} to test it, or a sweep or ray cast to find where a moving shape
 * first touches it.
 *
 * @param nx    the normal's x: the normal has length 1 and points from a to b
 * @param ny    the normal's y (y grows down, so ny &gt; 0 means b is below a)
 * @param depth how far apart to move the shapes along the normal so that they just touch,
 *              greater than 0
 */
public record Contact(float nx, float ny, float depth) {

    /**
     * How far from 1 the normal's length may be when a contact is made by hand. A unit
     * vector rounded to floats is within about 1e-7 of length 1, far inside this.
     */
    public static final float UNIT_TOLERANCE = 1e-3f;

    /**
     * How close two candidate depths must be, relative to their size, to count as equally
     * short for the tie rule: far below a float's precision (about 1e-7), far above the
     * rounding of the double arithmetic behind them (about 1e-15).
     */
    public static final double TIE = 1e-10;

    /**
     * Makes a contact, checking its values.
     *
     * @param nx    the normal's x
     * @param ny    the normal's y
     * @param depth how far apart to move the shapes, greater than 0
     * @throws IllegalArgumentException if a value is NaN or infinite, the depth is not greater
     *                                  than 0, or the normal's length is not 1 (within
     *                                  {@link #UNIT_TOLERANCE})
     */
    public Contact {
        // -0 becomes 0, so that a flipped or computed normal equals one written by hand.
        nx += 0.0f;
        ny += 0.0f;
        Check.finite("nx", nx);
        Check.finite("ny", ny);
        Check.positive("depth", depth);
        double length = Math.hypot(nx, ny);
        if (Math.abs(length - 1) > UNIT_TOLERANCE) {
            throw new IllegalArgumentException("the normal (nx, ny) must have length 1, but ("
                    + nx + ", " + ny + ") has length " + (float) length);
        }
    }

    /**
     * The contact between two shapes with its one or two contact points, or null when they do
     * not overlap (touching is not overlapping): see {@link Manifold} for where the points
     * are. Its contact is exactly {@link Shape#contact a.contact(b)}, and swapping the shapes
     * gives the same points with that contact flipped.
     *
     * @param a the first shape, not null
     * @param b the second shape, not null
     * @return the manifold, its normal pointing from a to b, or null when apart
     * @throws IllegalArgumentException if a shape is null or is a {@link Segment}, which has
     *                                  no area to push out of (as {@link Shape#contact})
     */
    public static Manifold manifold(Shape a, Shape b) {
        return Manifolds.between(Check.notNull("a", a), Check.notNull("b", b));
    }

    // ---------------------------------------------------------------- ellipses and capsules, raw floats

    /**
     * The same contact seen from b: the normal reversed, the depth kept.
     *
     * @return the contact with the normal pointing from b to a, never null
     */
    public Contact flipped() {
        return new Contact(-nx, -ny, depth);
    }

    /**
     * Which side of b the contact is on, for platformers: a normal pointing down (ny &gt; 0)
     * means b is below a, so a is on b's {@link Side#TOP} (it has landed); pointing up, b's
     * {@link Side#BOTTOM}; pointing right, a is at b's {@link Side#LEFT}; pointing left, at
     * b's {@link Side#RIGHT}.
     *
     * <p>The larger component decides; at exactly 45 degrees the vertical one wins, so
     * landing on a corner counts as landing. Never {@link Side#NONE}: a contact means a hit.
     *
     * @return the side of b that a is against, never null
     */
    public Side side() {
        return Side.ofNormal(nx, ny);
    }

}
