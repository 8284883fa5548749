package hitbox;

import hitbox.internal.*;

/**
 * Where two overlapping shapes meet: their {@link Contact} (the normal from a to b and the
 * depth) with one or two contact points, Box2D's {@code b2Manifold} and dyn4j's
 * {@code Manifold}. A response that turns a body needs the points: a box lying flat on the
 * floor touches it along a face (two points, its ends), a box standing on a corner at one
 * point. Made by {@link Contact#manifold(Shape, Shape)}.
 *
 * <h2>The points</h2>
 * Each point lies in both shapes, or on their outlines (in the closure of both, to within
 * {@link #TOLERANCE} of their size; the points of an ellipse pair, found by a search, to
 * within {@link #CURVED_TOLERANCE}):
 * <ul>
 *   <li>Two straight-edged shapes (rectangles, polygons, capsules' flat sides): the reference
 *       face is the face of either shape most nearly along the normal, the incident edge the
 *       other shape's edge most nearly against it, and the points are the incident edge's
 *       ends clipped to the reference shape and its face's side lines (Sutherland-Hodgman,
 *       as Box2D and dyn4j clip), those that lie behind the reference face. So the points
 *       are on the outline of the overlap; two when an edge lies along a face (a box on a
 *       box, a capsule lying flat), one for a corner. When both faces are equally along the
 *       normal the reference is the upper one (the one the tie rule's normal (0, 1) points
 *       away from; for an axis other than vertical, the same rule by
 *       {@link Contact}'s order of directions), so that swapping the shapes gives the same
 *       points.</li>
 *   <li>A circle or an ellipse: one point, the round shape's deepest point into the other
 *       (the end of its radius along the normal), or, where that lies beyond the other shape
 *       (a small shape deep inside a big round one), the other shape's deepest point into
 *       it. Two round shapes: the middle of the overlap along the normal, halfway between
 *       the two deepest points. Where neither deepest point lies in both shapes (a round
 *       shape in a concave polygon's notch), the overlap's deepest corners, as below.</li>
 *   <li>Concave polygons: through their convex pieces, with the one normal of the contact;
 *       the points may then lie on a cut between pieces, inside the polygon. Of more than two
 *       candidates the two farthest apart along the surface are kept.</li>
 *   <li>Two shapes crossing deeply (a plus sign), or one wholly inside the other, where no
 *       incident edge lies inside the reference shape: the deepest corners of the overlap
 *       (worked out with a round shape or a capsule's ends as an inscribed 64-gon), one, or
 *       the two farthest apart along the surface.</li>
 * </ul>
 * Depths and places that differ only by the rounding of the shapes' float coordinates (a
 * regular polygon's corners, say) count as equal, so that a pair placed symmetrically about
 * a line gets symmetric points.
 * Swapping the shapes gives the same points, in the same order (by x, then y), and the
 * contact {@link Contact#flipped() flipped}, wherever {@link Shape#contact} gives the
 * flipped contact.
 *
 * <h2>The depths</h2>
 * A point's depth is how far b must move along the normal for that point, as a point of b,
 * to leave a, plus how far a must move against it for the point, as a point of a, to leave
 * b: for a point on b's outline inside a (the usual case) the first alone, Box2D's
 * separation from the reference face. It is greater than 0 and at most the contact's depth
 * (held there where rounding would pass it); the corner of a shape standing on it has the
 * contact's depth, and so does the one point of a round pair. The contact's normal and
 * depth are exactly {@link Shape#contact}'s.
 *
 * @param contact    the contact: normal from a to b, and depth
 * @param pointCount how many contact points, 1 or 2
 * @param x1         the first point's x
 * @param y1         the first point's y
 * @param depth1     the first point's depth, greater than 0, at most the contact's depth
 * @param x2         the second point's x (the first's again when there is one point)
 * @param y2         the second point's y (the first's again when there is one point)
 * @param depth2     the second point's depth (the first's again when there is one point)
 */
public record Manifold(Contact contact, int pointCount, float x1, float y1, float depth1,
                       float x2, float y2, float depth2) {

    /**
     * How far (relative to the shapes' size, the largest of their extents and coordinates) a
     * point may lie outside a shape of a straight-edged or circle pair: rounding only.
     */
    public static final double TOLERANCE = 1e-5;

    /**
     * How far, relative as {@link #TOLERANCE}, a point may lie outside a shape in a pair
     * with an ellipse, whose contact normal is found by a search to about 1e-6 radians.
     */
    public static final double CURVED_TOLERANCE = 1e-4;

    /**
     * Makes a manifold, checking its values.
     *
     * @param contact    the contact, not null
     * @param pointCount 1 or 2
     * @param x1         the first point's x
     * @param y1         the first point's y
     * @param depth1     the first point's depth, greater than 0, at most the contact's depth
     * @param x2         the second point's x, the first's when {@code pointCount} is 1
     * @param y2         the second point's y, the first's when {@code pointCount} is 1
     * @param depth2     the second point's depth, as depth1; the first's when
     *                   {@code pointCount} is 1
     * @throws IllegalArgumentException if the contact is null, the count is not 1 or 2, a
     *                                  value is NaN or infinite, a depth is not greater than
     *                                  0 or is more than the contact's depth, or a
     *                                  one-point manifold's second point is not its first
     */
    public Manifold {
        Check.notNull("contact", contact);
        if (pointCount != 1 && pointCount != 2) {
            throw new IllegalArgumentException("pointCount must be 1 or 2, was " + pointCount);
        }
        Check.finite("x1", x1);
        Check.finite("y1", y1);
        Check.finite("x2", x2);
        Check.finite("y2", y2);
        depth("depth1", depth1, contact);
        depth("depth2", depth2, contact);
        if (pointCount == 1 && (Float.compare(x1, x2) != 0 || Float.compare(y1, y2) != 0 || Float.compare(depth1, depth2) != 0)) {
            throw new IllegalArgumentException("a manifold with pointCount 1 repeats its point: x2, y2, depth2 must be x1, y1, depth1, were ("
                    + x2 + ", " + y2 + ", " + depth2 + ") and (" + x1 + ", " + y1 + ", " + depth1 + ")");
        }
    }

    private static void depth(String name, float d, Contact contact) {
        Check.positive(name, d);
        if (d > contact.depth()) {
            throw new IllegalArgumentException(name + " must be at most the contact's depth " + contact.depth() + ", was " + d);
        }
    }

    /**
     * Point i's x.
     *
     * @param i the point, 0 or 1 (0 only, for one point)
     * @return its x
     * @throws IndexOutOfBoundsException if i is not below {@link #pointCount()}
     */
    public float x(int i) {
        return index(i) == 0 ? x1 : x2;
    }

    /**
     * Point i's y.
     *
     * @param i the point, 0 or 1 (0 only, for one point)
     * @return its y
     * @throws IndexOutOfBoundsException if i is not below {@link #pointCount()}
     */
    public float y(int i) {
        return index(i) == 0 ? y1 : y2;
    }

    /**
     * Point i's depth: how far b must move along the normal for that point to leave the
     * other shape.
     *
     * @param i the point, 0 or 1 (0 only, for one point)
     * @return its depth, greater than 0 and at most the contact's {@link Contact#depth() depth}
     * @throws IndexOutOfBoundsException if i is not below {@link #pointCount()}
     */
    public float depth(int i) {
        return index(i) == 0 ? depth1 : depth2;
    }

    private int index(int i) {
        if (i < 0 || i >= pointCount) {
            throw new IndexOutOfBoundsException("point index i must be 0" + (pointCount == 2 ? " or 1" : "")
                    + " for a manifold of " + pointCount + (pointCount == 1 ? " point" : " points") + ", was " + i);
        }
        return i;
    }

    /**
     * The same manifold seen from b: the contact flipped, the points kept.
     *
     * @return the manifold with the normal pointing from b to a, never null
     */
    public Manifold flipped() {
        return new Manifold(contact.flipped(), pointCount, x1, y1, depth1, x2, y2, depth2);
    }
}
