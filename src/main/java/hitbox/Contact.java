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
 * {@link #between(Shape, Shape)} returns null exactly when the shapes do not overlap by the
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
 * <p>This class is longer than most (about 450 lines): besides the record, it is the home of
 * the contact's raw-float forms for the tutorial's pairs, of the tie rule's statement, and of
 * {@link #manifold}, each with the documentation a learner reads.
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
     * The contact between two shapes, or null when they do not overlap (touching is not
     * overlapping). Same as {@code a.contact(b)}.
     *
     * @param a the first shape, not null
     * @param b the second shape, not null
     * @return the contact, with its normal pointing from a to b, or null when apart
     * @throws IllegalArgumentException if a shape is null or is a {@link Segment}, which has
     *                                  no area to push out of
     */
    public static Contact between(Shape a, Shape b) {
        return Contacts.between(Check.notNull("a", a), Check.notNull("b", b));
    }

    /**
     * The contact between two shapes with its one or two contact points, or null when they do
     * not overlap (touching is not overlapping): see {@link Manifold} for where the points
     * are. Its contact is exactly {@link #between between(a, b)}, and swapping the shapes
     * gives the same points with that contact flipped.
     *
     * @param a the first shape, not null
     * @param b the second shape, not null
     * @return the manifold, its normal pointing from a to b, or null when apart
     * @throws IllegalArgumentException if a shape is null or is a {@link Segment}, which has
     *                                  no area to push out of (as {@link #between})
     */
    public static Manifold manifold(Shape a, Shape b) {
        return Manifolds.between(Check.notNull("a", a), Check.notNull("b", b));
    }

    /**
     * The contact between two circles, or null when they do not overlap.
     *
     * <p>The normal points from the first centre to the second; the depth is
     * {@code r1 + r2 - dist}. Overlap is decided exactly as by {@link Collide#circleCircle}.
     * Circles with the same centre get the normal (0, 1) (the first is pushed up) and the
     * depth {@code r1 + r2}.
     *
     * @param x1 the first circle's centre x
     * @param y1 the first circle's centre y
     * @param r1 the first circle's radius
     * @param x2 the second circle's centre x
     * @param y2 the second circle's centre y
     * @param r2 the second circle's radius
     * @return the contact, or null when the circles touch or are apart, and for NaN or
     *         infinite input or a negative radius (never throws)
     */
    public static Contact circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return Contacts.circleCircle(x1, y1, r1, x2, y2, r2);
    }

    /**
     * The contact between a circle (first) and a rectangle (second), or null when they do not
     * overlap.
     *
     * <p>With the centre outside the rectangle, the normal points from the centre to the
     * rectangle's closest point and the depth is {@code r - dist}. With the centre inside (or
     * on the outline) the circle is pushed out through the nearest edge: the depth is the
     * centre's distance to that edge plus r. Overlap is decided exactly as by
     * {@link Collide#circleRect}.
     *
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return the contact, normal from the circle to the rectangle, or null when apart, and
     *         for NaN or infinite input or a negative size (never throws)
     */
    public static Contact circleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        if (Check.notFinite(cx, cy, r, rectX, rectY) || Check.notFinite(rectW, rectH, 0, 0, 0) || r < 0 || rectW < 0 || rectH < 0
                || !Collide.circleRect(cx, cy, r, rectX, rectY, rectW, rectH)) {
            return null;
        }
        return Contacts.circleRect(cx, cy, r, rectX, rectY, rectW, rectH, false);
    }

    /**
     * The contact between a rectangle (first) and a circle (second): {@link #circleRect} seen
     * from the rectangle, with the normal pointing from the rectangle to the circle.
     *
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @return the contact, or null when apart, and for NaN or infinite input or a negative
     *         size (never throws)
     */
    public static Contact rectCircle(float rectX, float rectY, float rectW, float rectH, float cx, float cy, float r) {
        if (Check.notFinite(cx, cy, r, rectX, rectY) || Check.notFinite(rectW, rectH, 0, 0, 0) || r < 0 || rectW < 0 || rectH < 0) {
            return null;
        }
        return Contacts.circleRect(cx, cy, r, rectX, rectY, rectW, rectH, true);
    }

    /**
     * The contact between two rectangles, or null when they do not overlap.
     *
     * <p>The normal is one of (0, 1), (0, -1), (1, 0), (-1, 0): whichever way the second
     * rectangle has the least distance to go, so that an edge of one meets the opposite edge
     * of the other. This is right for containment too (a small rectangle inside a big one
     * leaves through the big one's nearest edge). Overlap is decided exactly as by
     * {@link Collide#rectRect}.
     *
     * @param x1 the first rectangle's left edge
     * @param y1 the first rectangle's top edge
     * @param w1 the first rectangle's width
     * @param h1 the first rectangle's height
     * @param x2 the second rectangle's left edge
     * @param y2 the second rectangle's top edge
     * @param w2 the second rectangle's width
     * @param h2 the second rectangle's height
     * @return the contact, or null when apart, and for NaN or infinite input or a negative
     *         size (never throws)
     */
    public static Contact rectRect(float x1, float y1, float w1, float h1,
                                   float x2, float y2, float w2, float h2) {
        return Contacts.rectRect(x1, y1, w1, h1, x2, y2, w2, h2);
    }

    // ---------------------------------------------------------------- ellipses and capsules, raw floats

    /**
     * The contact between an axis-aligned ellipse (first) and a circle (second), or null when
     * they do not overlap: {@link #between} on the two shapes, for a sketch that keeps plain
     * floats. Overlap is decided as by {@link Collide#ellipseCircle}; the depth is found to
     * about 1e-12 of the shapes' size and the normal to about 1e-6 radians (see
     * {@link Shape#contact}).
     *
     * @param x       the ellipse's centre x
     * @param y       the ellipse's centre y
     * @param radiusX the ellipse's horizontal radius
     * @param radiusY the ellipse's vertical radius
     * @param cx      the circle's centre x
     * @param cy      the circle's centre y
     * @param r       the circle's radius
     * @return the contact, normal from the ellipse to the circle, or null when apart or
     *         touching, and for NaN or infinite input or a negative size (never throws)
     */
    public static Contact ellipseCircle(float x, float y, float radiusX, float radiusY, float cx, float cy, float r) {
        if (Check.notFinite(x, y, radiusX, radiusY, cx) || Check.notFinite(cy, r, 0, 0, 0)
                || radiusX < 0 || radiusY < 0 || r < 0) {
            return null;
        }
        return between(new Ellipse(x, y, radiusX, radiusY), new Circle(cx, cy, r));
    }

    /**
     * The contact between an axis-aligned ellipse (first) and a rectangle (second), or null
     * when they do not overlap, as {@link #ellipseCircle} (overlap as by
     * {@link Collide#ellipseRect}).
     *
     * @param x       the ellipse's centre x
     * @param y       the ellipse's centre y
     * @param radiusX the ellipse's horizontal radius
     * @param radiusY the ellipse's vertical radius
     * @param rectX      the rectangle's left edge
     * @param rectY      the rectangle's top edge
     * @param rectW      the rectangle's width
     * @param rectH      the rectangle's height
     * @return the contact, normal from the ellipse to the rectangle, or null when apart or
     *         touching, and for NaN or infinite input or a negative size (never throws)
     */
    public static Contact ellipseRect(float x, float y, float radiusX, float radiusY, float rectX, float rectY, float rectW, float rectH) {
        if (Check.notFinite(x, y, radiusX, radiusY, rectX) || Check.notFinite(rectY, rectW, rectH, 0, 0)
                || radiusX < 0 || radiusY < 0 || rectW < 0 || rectH < 0) {
            return null;
        }
        return between(new Ellipse(x, y, radiusX, radiusY), new Rect(rectX, rectY, rectW, rectH));
    }

    /**
     * The contact between two axis-aligned ellipses, or null when they do not overlap, as
     * {@link #ellipseCircle} (overlap as by {@link Collide#ellipseEllipse}).
     *
     * @param x1       the first ellipse's centre x
     * @param y1       the first ellipse's centre y
     * @param radiusX1 the first ellipse's horizontal radius
     * @param radiusY1 the first ellipse's vertical radius
     * @param x2       the second ellipse's centre x
     * @param y2       the second ellipse's centre y
     * @param radiusX2 the second ellipse's horizontal radius
     * @param radiusY2 the second ellipse's vertical radius
     * @return the contact, normal from the first ellipse to the second, or null when apart or
     *         touching, and for NaN or infinite input or a negative size (never throws)
     */
    public static Contact ellipseEllipse(float x1, float y1, float radiusX1, float radiusY1,
                                         float x2, float y2, float radiusX2, float radiusY2) {
        if (Check.notFinite(x1, y1, radiusX1, radiusY1, x2) || Check.notFinite(y2, radiusX2, radiusY2, 0, 0)
                || radiusX1 < 0 || radiusY1 < 0 || radiusX2 < 0 || radiusY2 < 0) {
            return null;
        }
        return between(new Ellipse(x1, y1, radiusX1, radiusY1), new Ellipse(x2, y2, radiusX2, radiusY2));
    }

    /**
     * The contact between a capsule (first) and a circle (second), or null when they do not
     * overlap, as {@link #ellipseCircle} (overlap as by {@link Collide#capsuleCircle}).
     *
     * @param x1 the capsule's segment, first end x
     * @param y1 the capsule's segment, first end y
     * @param x2 the capsule's segment, second end x
     * @param y2 the capsule's segment, second end y
     * @param r  the capsule's radius
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param cr the circle's radius
     * @return the contact, normal from the capsule to the circle, or null when apart or
     *         touching, and for NaN or infinite input or a negative radius (never throws)
     */
    public static Contact capsuleCircle(float x1, float y1, float x2, float y2, float r, float cx, float cy, float cr) {
        if (Check.notFinite(x1, y1, x2, y2, r) || Check.notFinite(cx, cy, cr, 0, 0) || r < 0 || cr < 0) {
            return null;
        }
        return between(new Capsule(x1, y1, x2, y2, r), new Circle(cx, cy, cr));
    }

    /**
     * The contact between a capsule (first) and a rectangle (second), or null when they do not
     * overlap, as {@link #ellipseCircle} (overlap as by {@link Collide#capsuleRect}).
     *
     * @param x1 the capsule's segment, first end x
     * @param y1 the capsule's segment, first end y
     * @param x2 the capsule's segment, second end x
     * @param y2 the capsule's segment, second end y
     * @param r  the capsule's radius
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return the contact, normal from the capsule to the rectangle, or null when apart or
     *         touching, and for NaN or infinite input or a negative size (never throws)
     */
    public static Contact capsuleRect(float x1, float y1, float x2, float y2, float r, float rectX, float rectY, float rectW, float rectH) {
        if (Check.notFinite(x1, y1, x2, y2, r) || Check.notFinite(rectX, rectY, rectW, rectH, 0) || r < 0 || rectW < 0 || rectH < 0) {
            return null;
        }
        return between(new Capsule(x1, y1, x2, y2, r), new Rect(rectX, rectY, rectW, rectH));
    }

    /**
     * The contact between two capsules, or null when they do not overlap, as
     * {@link #ellipseCircle} (overlap as by {@link Collide#capsuleCapsule}).
     *
     * @param ax1 the first capsule's segment, first end x
     * @param ay1 the first capsule's segment, first end y
     * @param ax2 the first capsule's segment, second end x
     * @param ay2 the first capsule's segment, second end y
     * @param r1  the first capsule's radius
     * @param bx1 the second capsule's segment, first end x
     * @param by1 the second capsule's segment, first end y
     * @param bx2 the second capsule's segment, second end x
     * @param by2 the second capsule's segment, second end y
     * @param r2  the second capsule's radius
     * @return the contact, normal from the first capsule to the second, or null when apart or
     *         touching, and for NaN or infinite input or a negative radius (never throws)
     */
    public static Contact capsuleCapsule(float ax1, float ay1, float ax2, float ay2, float r1,
                                         float bx1, float by1, float bx2, float by2, float r2) {
        if (Check.notFinite(ax1, ay1, ax2, ay2, r1) || Check.notFinite(bx1, by1, bx2, by2, r2) || r1 < 0 || r2 < 0) {
            return null;
        }
        return between(new Capsule(ax1, ay1, ax2, ay2, r1), new Capsule(bx1, by1, bx2, by2, r2));
    }

    /**
     * The contact between an axis-aligned ellipse (first) and a capsule (second), or null when
     * they do not overlap, as {@link #ellipseCircle} (overlap as by
     * {@link Collide#ellipseCapsule}).
     *
     * @param x       the ellipse's centre x
     * @param y       the ellipse's centre y
     * @param radiusX the ellipse's horizontal radius
     * @param radiusY the ellipse's vertical radius
     * @param x1      the capsule's segment, first end x
     * @param y1      the capsule's segment, first end y
     * @param x2      the capsule's segment, second end x
     * @param y2      the capsule's segment, second end y
     * @param r       the capsule's radius
     * @return the contact, normal from the ellipse to the capsule, or null when apart or
     *         touching, and for NaN or infinite input or a negative size (never throws)
     */
    public static Contact ellipseCapsule(float x, float y, float radiusX, float radiusY,
                                         float x1, float y1, float x2, float y2, float r) {
        if (Check.notFinite(x, y, radiusX, radiusY, x1) || Check.notFinite(y1, x2, y2, r, 0)
                || radiusX < 0 || radiusY < 0 || r < 0) {
            return null;
        }
        return between(new Ellipse(x, y, radiusX, radiusY), new Capsule(x1, y1, x2, y2, r));
    }

    /**
     * The same contact seen from b: the normal reversed, the depth kept.
     *
     * @return the contact with the normal pointing from b to a, never null
     */
    public Contact flipped() {
        return new Contact(-nx, -ny, depth);
    }

    /**
     * The normal as a vector.
     *
     * @return (nx, ny), the unit normal from a to b, never null
     */
    public Vec normal() {
        return new Vec(nx, ny);
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
