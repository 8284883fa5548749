package hitbox.internal;

/**
 * Every tolerance Hitbox uses, each with its reason: the one place to look before asking
 * "is there an epsilon in this answer?".
 *
 * <p>None of them decides a touching case but {@code Containment.CONTAINMENT}, for the curved
 * pairs of {@link Shape#contains(Shape)} whose exact answer is a quartic's root (an ellipse
 * against a circle, a capsule or an ellipse): there a pair within it of touching from
 * inside counts as held; and {@link #SWEEP_PASSES}, for the sweeps found by conservative
 * advancement: a path that enters the obstacle less deep than it counts as clear. They are
 * of four kinds:
 * <ul>
 *   <li><b>Guard bands</b> around a double comparison whose rounding is bounded: outside the
 *       band the double answer is sure; inside it an exact (or slower, exact-enough) test
 *       decides. Widening a band costs time, never an answer.</li>
 *   <li><b>Paddings</b> of a broad phase's query box: a candidate filter may take a box too
 *       many (the exact test drops it), never one too few.</li>
 *   <li><b>Stopping rules</b> of the iterative searches behind the curved and turning cases
 *       (contacts of ellipses and capsules, sweeps of curved or turning shapes), whose answers
 *       are as close as those rules say, no closer.</li>
 *   <li><b>Checks on hand-made results</b>: the public {@link Contact#UNIT_TOLERANCE}, and the
 *       tie rule's {@link Contact#TIE}; {@link Hybrid#CIRCLE_SLACK}, a public guard band.</li>
 * </ul>
 *
 * <p>Named next to their one use, with their reasons there:
 * <ul>
 *   <li>the searches: {@code Clearance.TOLERANCE} (1e-9, how close a search's point must be
 *       to the overlap set), {@code ConvexSweep.TOUCH} (1e-6 pixels, where conservative
 *       advancement stops), {@code TurningSweep.TOUCH} (1e-3 pixels, the same for a turning
 *       mover), {@code Containment.SEARCH_STOP} (1e-9 radians, where the search for how far a
 *       curved shape pokes out stops), {@code Golden.AXIS_NEAR} (1e-3 radians, how near an
 *       axis a searched least is tried on it) and {@code CurvedClearance.CONE_STEP} (1e-4
 *       radians, how far past a cone's end its rise is measured);</li>
 *   <li>the contacts: {@code Ray.SAME_EVENT} (1e-12 of the ray, events on a polygon's outline
 *       that are one), {@code Containment.CONTAINMENT} (1e-9 of the container's size, how far
 *       a curved pair that is searched rather than decided may poke out and still count as
 *       held), the public {@code Manifold.TOLERANCE} (1e-5 of the shapes' size, how far a
 *       manifold's point may lie outside a shape of a straight-edged or circle pair) and
 *       {@code Manifold.CURVED_TOLERANCE} (1e-4, the same beside an ellipse), and the
 *       manifold builder's {@code Manifolds.SAME} (1e-9 of the pair's scale, two points that
 *       are one), {@code Manifolds.ALONG} (1e-3, a cosine below which a side is along a ray)
 *       and {@code Manifolds.AS_DEEP} (1e-6 of the scale, corners equally deep);</li>
 *   <li>the world: the slide's {@code Mover.SKIN} (1/64 pixel, the gap a slanted surface keeps
 *       from a body that slides on it), {@code Mover.PLANE_TIE} (1e-12 of a motion, how far
 *       into a plane its projection may round), {@code Mover.AXIS_TIE} (1e-6, how near an axis
 *       a normal is taken as the axis), {@code CharacterBody.SLOPE_TIE} (1e-6 of a cosine,
 *       so that a 45-degree slope is ground at a 45-degree limit) and
 *       {@code GridCollider.CELL_PAD} (1e-6 of a cell, how far past its edge a ray still looks
 *       at a grid's cell);</li>
 *   <li>guard bands and roundings: {@code RawTests.FILTER_BELOW} and
 *       {@code RawTests.FILTER_ABOVE} (1 -/+ 2^-18, the band outside which the float squares
 *       of {@code Collide.circleCircle} decide) and {@code RawTests.FILTER_TINY} (2^-100, below
 *       which a float square may be subnormal), {@code Lines.UNDERFLOW_GUARD} (2^-900, products
 *       large enough that an exact {@code fma} residual proves them exact),
 *       {@code Polygons.DISTANCE_ROUNDING} (1e-13 of the coordinates, a point-to-edge
 *       distance's rounding), {@code Transforms.STRETCH_ROUNDING} (1e-12, a transform's least
 *       stretch), {@code Poses.ELLIPSE_BOX_WIDEN} (1e-6 of the radius, a turned ellipse's box),
 *       {@code Distances.PROJECTION_ROUNDING} (1e-12, an edge's reach) and
 *       {@code ConvexPolygonSweep.PROJECTION_ROUNDING} (2^-48, a corner's projection);</li>
 *   <li>drawing: {@code Draw.SHORTEST_ARROW} (1e-3 pixels, an arrow too short for a head);</li>
 *   <li>fdlibm's own constants, which are not tolerances but look like them:
 *       {@code Fdlibm.TWON24} (2^-24, a scale of its 24-bit pieces) and {@code Fdlibm.TINY}
 *       (1e-300, added to an inexact answer to raise "inexact", never changing it);</li>
 *   <li>the public ones above; and three proven error bounds of floating-point sums,
 *       {@code Lines.ORIENT_ERROR}, {@code Ellipses.SUM_ERROR} and
 *       {@code Containment.SUM_ROUNDING} (multiples of 2^-53 with their derivation beside
 *       them).</li>
 * </ul>
 * The rest are here. {@code SourceRulesTest} keeps this list whole: it fails on a named
 * tolerance missing from it and on a bare tolerance literal anywhere in the library.
 *
 * <p>The values are the ones the code had when they were written out as literals; naming
 * them changed no answer (they are compile-time constants, so even the bytecode is the same).
 * The package documentation lists them for users.
 */
public final class Tolerance {
    private Tolerance() {
    }

    // ---- guard bands ----------------------------------------------------------------

    /**
     * A relative band around a comparison of two sums of squares or products in double
     * ({@code x*x + y*y} against {@code r*r}; an edge's facing, {@code dx*ey - dy*ex}): each
     * side is off by a few units of 2^-53 (about 1e-16) of itself, so a difference larger than
     * 1e-9 of their size is sure; inside it the exact test decides. Used by
     * {@link Capsules}, {@link Ellipses#discs} and {@link Ray}'s concave polygon cast.
     */
    public static final double NEAR_TIE = 1e-9;

    /**
     * A relative margin over one rounding of a difference of two floats in double (at most a
     * unit of 2^-53, 1.1e-16, of itself): a gap larger than {@code r * (1 + 1e-15)} is larger
     * than {@code r} exactly. {@link Capsules}' box test.
     */
    public static final double DIFFERENCE_ROUNDING = 1e-15;

    /**
     * A relative bound on the rounding of an orientation (two products of differences, each
     * off by a few units of 2^-53 of its size) over the size of its terms: below it, "touching
     * or not" is decided with exact orientation signs. {@link SeparatingAxis}' reach and
     * {@link Ray}'s convex cast.
     */
    public static final double ORIENTATION_ROUNDING = 1e-14;

    /**
     * The relative rounding allowed in a corner's turn (a cross product of two edges) when
     * {@link ConvexPolygonSweep} asks whether a polygon stays convex after a move rounded to
     * floats: generous against the double products, so "stays convex" is only said when sure.
     */
    public static final double TURN_ROUNDING = 1e-12;

    /**
     * A float's relative step, 2^-23: how far a coordinate moved in float ({@code x + t * vx})
     * can be from the exact sum, relative to its size. {@link ConvexPolygonSweep}.
     */
    public static final double FLOAT_STEP = 0x1p-23;

    /**
     * The relative margin {@link Ellipses#capsuleQuick}'s proofs must hold by: far above the
     * double rounding of its sums, so the quick answer never differs from the long way's.
     */
    public static final double QUICK_MARGIN = 1e-10;

    /**
     * How much a turned ellipse's box half-size is widened, relative: a few double roundings
     * (cos, sin, products, hypot) of 2^-53 each, so the float box still holds the ellipse.
     * {@link TurnedEllipses}.
     */
    public static final double TURNED_BOX_WIDEN = 0x1p-48;

    /**
     * The relative slack of {@link ConvexSweep}'s cheap "boxes apart" test: a position moved
     * in float lies within a float step (about 6e-8 of its size) of the exact one, and 1e-6
     * covers that for every coordinate of both boxes.
     */
    public static final double SWEEP_BOX_SLACK = 1e-6;

    // ---- paddings -------------------------------------------------------------------

    /**
     * How much a broad phase widens a query box, relative to its coordinates: far above the
     * rounding of the double sums behind the box ({@code x + w}, a ray's points), so a box
     * that touches the query is always found. See {@link #pad}.
     */
    public static final double PAD = 1e-9;

    /** The least padding, for a box at the origin: any positive amount keeps an edge at 0. */
    public static final double PAD_FLOOR = 1e-30;

    /**
     * The padding for a query interval [lo, hi]: {@code PAD * (|lo| + |hi|) + PAD_FLOOR}, the
     * one formula behind every broad phase's widened query ({@link AbstractBroadPhase},
     * {@link HashGridBroadPhase}, {@link SweepAndPruneBroadPhase}, {@link RayCast}).
     *
     * @param lo the interval's low end
     * @param hi the interval's high end
     * @return the amount to move each end outwards, positive
     */
    public static double pad(double lo, double hi) {
        return PAD * (Math.abs(lo) + Math.abs(hi)) + PAD_FLOOR;
    }

    // ---- stopping rules of the searches ---------------------------------------------

    /**
     * The tie slack of {@link Supports}' contact search, relative to the scene's largest
     * coordinate: pushes within this of the least tie, and the rule of {@link Contact} picks
     * among them. Two float steps: the float inputs are rounded to half a step of their
     * coordinates, so pushes meant to be equal (the edge normals of a regular polygon placed
     * by cos and sin) differ by about 1e-8 of them, and the depth is reported as a float.
     */
    public static final double SUPPORT_TIE = 0x1p-22;

    /**
     * Where {@link Supports}' angle search stops, in radians: at a double's resolution of an
     * angle near pi (its 80 steps usually end first).
     */
    public static final double SUPPORT_ANGLE = 1e-15;

    /**
     * The rounding of a support sum (two shapes' reaches along a direction, in double),
     * relative to the scene's size: a least that the angle search found off an axis is
     * taken on the axis when the axis is as short to within this, so that mirror images
     * agree. {@link Supports} and {@code CurvedClearance}.
     */
    public static final double SUPPORT_SUM_ROUNDING = 1e-12;

    /**
     * A direction's part smaller than this is taken as 0 ({@link Supports}): cos and sin of
     * an axis direction round to about 6e-17, not 0, and the exact axis keeps a box's
     * support exact.
     */
    public static final double AXIS_SNAP = 1e-15;

    /**
     * How close {@link Separation}'s distance is for a pair with an ellipse (two different
     * radii), relative to the shapes' size: the searches behind it ({@link Distances}) stop
     * at a double's resolution of the slope of the distance (Eberly's bisection for a point,
     * a bisection along an edge or around a second ellipse), so the distance, which is flat
     * at its least, is right to far better than this; the closest points, along the outline,
     * to about its square root. Not used to decide anything: the stated accuracy, which the
     * tests hold the answers to.
     */
    public static final double SEPARATION_CURVED = 1e-9;

    /**
     * How close two keys of the tie rule ({@link Contacts#preferred}) must be to count as
     * equal when the candidates come from a search ({@link Supports}, {@link Clearance},
     * {@link CircleClearance}, {@link CurvedClearance}): their normals are only placed to
     * about 1e-6 radians where the least is flat, so mirror images must not be told apart by
     * less. The exact pairs use {@link Contact#TIE}.
     */
    public static final double SEARCH_KEY_TIE = 1e-6;

    /**
     * Where {@link ConvexSweep}'s search for the best separating direction stops, in radians:
     * any direction gives a safe step, so this only buys a longer one.
     */
    public static final double SWEEP_ANGLE = 1e-13;

    /**
     * How far into the obstacle, relative to the shapes' size (their largest coordinate plus
     * the motion), the swept hull of a mover found by conservative advancement may reach and
     * still count as clear of it ({@code ConvexSweep.passes}): the rounding of the reaches,
     * summed in double (a few units in 2^-52 of the size), and of the angle search at a kink
     * ({@link #SWEEP_ANGLE} times the motion). A path that enters no deeper than this
     * is a graze, no hit (about 1/100,000 of a float step of the size). Where touching is
     * meeting (two shapes without area), the hull must keep this far off instead.
     */
    public static final double SWEEP_PASSES = 0x1p-40;

    /**
     * Where {@link CurvedClearance}'s angle search stops, in radians: far below what its
     * answers are checked against ({@code Clearance.TOLERANCE}).
     */
    public static final double CLEARANCE_ANGLE = 1e-10;
}
