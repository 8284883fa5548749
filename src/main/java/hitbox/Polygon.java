package hitbox;

import hitbox.internal.*;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Arrays;
import java.util.function.Supplier;

/**
 * A simple polygon, convex or concave, in either winding: its vertices in order.
 *
 * <p>Open, like every shape with area: a point on an edge is not in it, and polygons that
 * only share an edge do not overlap. "Simple" means the outline never crosses or touches
 * itself: edges meet only at the corner two neighbouring edges share. {@link #of} checks
 * that, so every {@code Polygon} is a valid shape for {@link Collide}'s polygon tests.
 *
 * <p>Edge i runs from vertex i to vertex i + 1; the last edge closes the outline back to
 * vertex 0, so do not repeat the first vertex at the end. Immutable: moving a polygon makes
 * a new one ({@link #translated}).
 *
 * <p>A rectangle turned about its centre, as Processing draws
 * {@code translate(cx, cy); rotate(angle); rect(-w/2, -h/2, w, h);}, is
 * {@code Polygon.of(Rect.centered(cx, cy, w, h)).rotated(angle, cx, cy)}; a triangle is
 * {@code Polygon.of(x1, y1, x2, y2, x3, y3)}.
 *
 * <p>The class is longer than most: its factories ({@link #of}, {@link #regular}) check
 * every outline a user can hand in, and it grants the kernels in
 * {@code hitbox.internal} read access to the parts it keeps (see {@code HiddenParts}).
 */
public final class Polygon implements Shape {
    // First of the static initialisers: the kernels read a polygon's kept parts through this.
    static {
        HiddenParts.grant(new HiddenParts.PolygonAccess() {
            @Override
            public float[] raw(Polygon p) {
                return p.xy;
            }

            @Override
            public double[] corners(Polygon p) {
                return p.corners();
            }

            @Override
            public int convexWinding(Polygon p) {
                return p.convexWinding;
            }

            @Override
            public int concaveVertex(Polygon p) {
                return p.concaveVertex;
            }

            @Override
            public Rect bounds(Polygon p) {
                return p.box();
            }

            @Override
            public Polygon image(Polygon p, float[] xy, double scaleMin, double delta, Supplier<String> verb) {
                return p.image(xy, scaleMin, delta, verb);
            }

            @Override
            public Polygon taken(float[] xy) {
                Polygons.validate(xy);
                return new Polygon(xy, Polygons.concaveVertex(xy));
            }

            @Override
            public Polygon convexImage(float[] xy) {
                int w = Polygons.convexWinding(xy);
                if (w != 0 && !Polygons.repeatsNeighbour(xy)) {
                    return new Polygon(xy, -1, w, Double.NaN);  // as image's convex case
                }
                return taken(xy);
            }
        });
    }

    /**
     * The most sides {@link #regular} makes: 4096. Checking an outline compares every pair of
     * edges, so more would take seconds, and far more cannot be a float polygon at all.
     */
    public static final int MAX_SIDES = 4096;

    private final float[] xy;
    /** The box, or null until first asked (see {@link #box()}). */
    private volatile Rect bounds;
    /**
     * The first vertex where the outline bends inwards, or -1 when convex: kept, since the
     * polygon cannot change and every contact asks.
     */
    private final int concaveVertex;
    /**
     * The {@link Polygons#winding} if the polygon is convex, else 0: kept, so that the convex
     * fast paths ({@link Polygons#convexOverlap}) need no check per call.
     */
    private final int convexWinding;
    /**
     * The vertices widened to double (exactly), for the contact search and the sweeps; null
     * until the first asks ({@link #corners()}): a body's polygon placed every frame for an
     * overlap test never needs them. Published by the volatile write, the array filled first.
     */
    private volatile double[] corners;
    /**
     * A lower bound on the distance from any vertex to any edge that does not end at it
     * ({@link Polygons#margin}), or NaN until a move first needs it: while rounding moves no
     * vertex by more than half of it, the outline stays simple (see {@link #translated}).
     * Written at most once per value by any thread (like {@code String}'s hash).
     */
    private volatile double margin;

    private Polygon(float[] xy, int concaveVertex) {
        this(xy, concaveVertex, concaveVertex < 0 ? Polygons.winding(xy) : 0, Double.NaN);
    }

    private Polygon(float[] xy, int concaveVertex, int convexWinding, double margin) {
        this.xy = xy;
        this.concaveVertex = concaveVertex;
        this.convexWinding = convexWinding;
        this.margin = margin;
    }

    /**
     * Makes a polygon from its vertices, {@code x0, y0, x1, y1, ...}, in either winding.
     *
     * <p>Checking the outline for crossings compares every pair of edges, so it takes time
     * proportional to the square of the vertex count: make polygons once (in
     * {@code setup()}) and move them with {@link #translated}.
     *
     * @param xy the vertices' coordinates, in pairs
     * @return the polygon, never null
     * @throws IllegalArgumentException if {@code xy} is null, there are fewer than 3 vertices, an
     *                                  odd number of coordinates, a NaN or infinite value, a vertex equal to
     *                                  the next one (or the last equal to the first), no area
     *                                  (all vertices on one line), or two edges that cross or
     *                                  touch; the message names the vertices or edges
     */
    public static Polygon of(float... xy) {
        Check.notNull("xy", xy);
        return HiddenParts.taken(xy.clone());
    }

    /**
     * The rectangle as a polygon: its corners top-left, top-right, bottom-right, bottom-left.
     *
     * @param rect the rectangle, with width and height above 0
     * @return the polygon with the rectangle's four corners, never null
     * @throws IllegalArgumentException if {@code rect} is null or has width or height 0
     */
    public static Polygon of(Rect rect) {
        Check.notNull("rect", rect);
        if (rect.w() == 0 || rect.h() == 0) {
            throw new IllegalArgumentException("a polygon needs area, but the rectangle's width and height are "
                    + rect.w() + " and " + rect.h() + " (both must be > 0)");
        }
        // The corners in double rounded to float are exactly right() and bottom(): a sum of two
        // floats rounded first to double and then to float is their sum rounded to float, as
        // double has more than twice float's precision (S. Figueroa, "When is double rounding
        // innocuous?", 1995).
        double[] corners = Polygons.corners(rect);
        float[] xy = new float[corners.length];
        for (int i = 0; i < xy.length; i++) {
            xy[i] = (float) corners[i];
        }
        return of(xy);
    }

    /**
     * A regular polygon (equal sides, equal angles) with its corners on a circle, like
     * Processing's "Regular Polygon" example, its first corner at {@code angle} from the
     * centre: radians, clockwise on screen as with Processing's {@code rotate} (0 puts it
     * straight to the right of the centre, {@code -HALF_PI} straight above it).
     *
     * @param cx     the centre's x
     * @param cy     the centre's y
     * @param radius the distance from the centre to each corner, above 0
     * @param sides  how many sides, 3 or more
     * @param angle  the direction of the first corner, in radians
     * @return the regular polygon, never null
     * @throws IllegalArgumentException if a value is NaN or infinite, the radius is 0 or less,
     *                                  there are fewer than 3 or more than {@link #MAX_SIDES}
     *                                  sides, or rounding to float makes the corners meet
     *                                  (a radius too small for its centre)
     */
    public static Polygon regular(float cx, float cy, float radius, int sides, float angle) {
        Check.finite("cx", cx);
        Check.finite("cy", cy);
        Check.positive("radius", radius);
        Check.finite("angle", angle);
        if (sides < 3 || sides > MAX_SIDES) {
            throw new IllegalArgumentException("sides must be from 3 to " + MAX_SIDES + ", was " + sides);
        }
        float[] xy = new float[2 * sides];
        for (int i = 0; i < sides; i++) {
            double a = angle + 2 * Math.PI * i / sides;
            xy[2 * i] = (float) (cx + radius * StrictMath.cos(a));
            xy[2 * i + 1] = (float) (cy + radius * StrictMath.sin(a));
        }
        return rounded(xy, "cx = " + cx + ", cy = " + cy + ", radius = " + radius + ", sides = " + sides + ", angle = " + angle);
    }

    /**
     * The polygon of computed corners, or a message naming the arguments that gave corners
     * which rounding to float made invalid (a huge centre, a tiny size, many sides).
     */
    private static Polygon rounded(float[] xy, String arguments) {
        try {
            return of(xy);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("the corners from " + arguments + " round to an outline a polygon"
                    + " cannot have: " + e.getMessage(), e);
        }
    }

    /** @return how many vertices the polygon has */
    public int size() {
        return xy.length / 2;
    }

    /**
     * @param i the vertex index, from 0 to {@code size() - 1}
     * @return vertex i's x
     * @throws IllegalArgumentException if {@code i} is out of range
     */
    public float x(int i) {
        return xy[2 * index("vertex index i", i)];
    }

    /**
     * @param i the vertex index, from 0 to {@code size() - 1}
     * @return vertex i's y
     * @throws IllegalArgumentException if {@code i} is out of range
     */
    public float y(int i) {
        return xy[2 * index("vertex index i", i) + 1];
    }

    /**
     * Edge i, from vertex i to vertex i + 1 (the last edge goes back to vertex 0).
     *
     * @param i the edge index, from 0 to {@code size() - 1} (a closed outline has as many
     *          edges as vertices)
     * @return the edge as a segment, never null
     * @throws IllegalArgumentException if {@code i} is out of range
     */
    public Segment edge(int i) {
        int k = (index("edge index i", i) + 1) % size();
        return new Segment(xy[2 * i], xy[2 * i + 1], xy[2 * k], xy[2 * k + 1]);
    }

    /** @return a copy of the coordinates, {@code x0, y0, x1, y1, ...}, never null */
    public float[] coordinates() {
        return xy.clone();
    }

    /** The coordinates without a copy, for the library's own loops; never handed out. */
    float[] raw() {
        return xy;
    }

    /**
     * The area enclosed, always positive whatever the winding.
     *
     * <p>Computed exactly (in {@link BigDecimal}) and rounded once, so it is right for any
     * coordinates, 1e16 next to 1 included, where float or double sums would cancel.
     *
     * <p>Reference: the shoelace formula (Gauss's area formula).
     *
     * @return the area, in square pixels, above 0 ({@link Float#MIN_VALUE} at least, for a
     *         polygon too thin for a float's area); {@link Float#POSITIVE_INFINITY} if it is
     *         too large for a float
     */
    public float area() {
        // Every polygon Polygon.of makes has area; one too thin for a float still gets the
        // smallest positive float, not 0 (found by fuzzing).
        float area = Polygons.exactDoubleSignedArea(Polygons.toDouble(xy)).abs().floatValue() / 2;
        return Math.max(area, Float.MIN_VALUE);
    }

    /**
     * The centroid: the balance point of the enclosed area (for a concave polygon it may lie
     * outside the polygon).
     *
     * <p>Computed exactly (in {@link BigDecimal}) and rounded once, so it is right for any
     * coordinates a polygon can have, and always finite.
     *
     * <p>Reference: the centroid of a polygon from the signed areas of the triangles fanned
     * out from vertex 0, each weighted at its own centroid.
     *
     * @return the centroid, never null
     */
    public Vec centroid() {
        BigDecimal ox = new BigDecimal(xy[0]);
        BigDecimal oy = new BigDecimal(xy[1]);
        BigDecimal sumX = BigDecimal.ZERO;
        BigDecimal sumY = BigDecimal.ZERO;
        BigDecimal twiceArea = BigDecimal.ZERO;
        for (int i = 1; i + 1 < size(); i++) {
            BigDecimal ax = new BigDecimal(xy[2 * i]).subtract(ox);
            BigDecimal ay = new BigDecimal(xy[2 * i + 1]).subtract(oy);
            BigDecimal bx = new BigDecimal(xy[2 * i + 2]).subtract(ox);
            BigDecimal by = new BigDecimal(xy[2 * i + 3]).subtract(oy);
            BigDecimal t = ax.multiply(by).subtract(ay.multiply(bx)); // twice the signed area of (0, a, b)
            twiceArea = twiceArea.add(t);
            sumX = sumX.add(t.multiply(ax.add(bx))); // the triangle's centroid is (0 + a + b) / 3
            sumY = sumY.add(t.multiply(ay.add(by)));
        }
        // A polygon Polygon.of accepts has area, exactly; the division is rounded once.
        BigDecimal three = twiceArea.multiply(BigDecimal.valueOf(3));
        MathContext mc = new MathContext(60);
        return new Vec(ox.add(sumX.divide(three, mc)).floatValue(), oy.add(sumY.divide(three, mc)).floatValue());
    }

    /**
     * Is the polygon convex: does every corner turn the same way? Corners on a straight line
     * (a vertex in the middle of a side) do not make it concave.
     *
     * @return true if convex, false if it has a corner that points inwards
     */
    public boolean isConvex() {
        return concaveVertex < 0;
    }

    /**
     * The first vertex where the outline bends inwards (turns against its winding), or -1
     * when the polygon is convex.
     */
    int concaveVertex() {
        return concaveVertex;
    }

    /** The winding (+1 or -1) if the polygon is convex, 0 if it is concave. */
    int convexWinding() {
        return convexWinding;
    }

    /**
     * The box, made when first asked: a body's polygon placed every frame for a test against
     * a circle or a segment never needs it (the world has compared the bodies' boxes
     * already). Two threads may each make one: equal rectangles, either kept.
     */
    private Rect box() {
        Rect b = bounds;
        if (b == null) {
            b = Polygons.bounds(xy);
            bounds = b;
        }
        return b;
    }

    /** The vertices in double, without a copy, for the library's own loops; never handed out. */
    double[] corners() {
        double[] c = corners;
        if (c == null) {
            c = Polygons.toDouble(xy);  // two threads may each make one: equal arrays, either kept
            corners = c;
        }
        return c;
    }

    /**
     * {@inheritDoc}
     *
     * <p>Cheap, and checked only as far as rounding could change the outline:
     * <ul>
     *   <li>When every coordinate moves exactly (whole numbers do), the moved outline is as
     *       valid as this one and nothing is checked: O(n).</li>
     *   <li>When rounding shifts vertices (a fractional move), a convex polygon is checked
     *       for convexity again, O(n); a concave one is not checked when its margin (the
     *       shortest distance from a vertex to an edge that does not end at it, found once,
     *       in O(n<sup>2</sup>), the first time it is needed, and handed on to the moved
     *       polygon less what the rounding may have taken) is more than twice the rounding:
     *       no vertex can then have reached an edge, so the outline is still simple, O(n).</li>
     *   <li>Only when neither rule applies (the margin is used up, after very many inexact
     *       moves, or the polygon has features as small as a float step) is the moved outline
     *       checked as {@link #of} checks it, O(n<sup>2</sup>), and a fresh margin found.</li>
     * </ul>
     * A polygon whose features are wider than a few float steps at its coordinates (any
     * polygon a sketch draws) therefore never throws for a finite move.
     *
     * @throws IllegalArgumentException if the move gives a NaN or infinite coordinate, or
     *                                  rounding made the outline touch itself (its features
     *                                  smaller than a float step at the new place)
     */
    @Override
    public Polygon translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        float[] moved = new float[xy.length];
        boolean exact = true;
        float big = 0;
        for (int i = 0; i < moved.length; i += 2) {
            float x = xy[i] + dx;
            float y = xy[i + 1] + dy;
            moved[i] = x;
            moved[i + 1] = y;
            exact &= x == (double) xy[i] + dx && y == (double) xy[i + 1] + dy;
            big = Math.max(big, Math.max(Math.abs(x), Math.abs(y)));
        }
        if (!Float.isFinite(big)) {
            for (int i = 0; i < moved.length; i++) {
                Check.finite((i % 2 == 0 ? "x" : "y") + (i / 2) + (i % 2 == 0 ? " + dx" : " + dy"), moved[i]);
            }
        }
        if (exact) {
            // Every coordinate moved exactly, so every orientation, the concave vertex, the
            // winding and the margin are kept: a sweep moves a polygon many times a call.
            return new Polygon(moved, concaveVertex, convexWinding, margin);
        }
        // Each coordinate is the exact sum rounded once: off by half a float step at most, so
        // each vertex by less than a float step at the largest coordinate.
        return image(moved, 1, Math.ulp(big), () -> "moving by dx = " + dx + ", dy = " + dy);
    }

    /**
     * {@inheritDoc}
     *
     * <p>A polygon stays a polygon. A mirror reverses the winding, which a polygon may have
     * either way; a concave polygon stays concave. The new outline is checked only as far as
     * rounding could have changed it, by the rules of {@link #translated} (its margin scaled
     * by the transform's smallest stretch), so turning a polygon every frame is O(n).
     *
     * @throws IllegalArgumentException if {@code t} is null, the transform is singular (a
     *                                  polygon squashed onto a line has no area), a vertex
     *                                  goes beyond the float range, or rounding made the
     *                                  outline touch itself (features smaller than a float
     *                                  step at the new place)
     */
    @Override
    public Polygon transformed(Transform t) {
        return Transforms.polygon(this, Check.notNull("t", t).affine());
    }

    /**
     * {@inheritDoc}
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, a vertex goes beyond
     *                                  the float range, or rounding made the outline touch
     *                                  itself (see {@link #transformed})
     */
    @Override
    public Polygon rotated(float angle, float pivotX, float pivotY) {
        return (Polygon) Transform.turn(this, angle, pivotX, pivotY);
    }

    /**
     * This polygon's outline moved to {@code moved}, the image of an affine map whose smallest
     * stretch is at least {@code scaleMin}, each vertex rounded at most {@code delta} away
     * from its exact image: checked only as far as that rounding could have changed it.
     */
    private Polygon image(float[] moved, double scaleMin, double delta, Supplier<String> verb) {
        if (convexWinding != 0) {
            // convex before: convex again (n exact orientations) is simple, with area
            int w = Polygons.convexWinding(moved);
            if (w != 0 && !Polygons.repeatsNeighbour(moved)) {
                return new Polygon(moved, -1, w, Double.NaN);
            }
        }
        double m = margin();
        double left = m * scaleMin - 2 * delta;
        if (left > 0) {
            // No vertex came within reach of an edge it does not end: still simple (Polygons.margin)
            int concave = Polygons.concaveVertex(moved);
            return new Polygon(moved, concave, concave < 0 ? Polygons.winding(moved) : 0, left);
        }
        try {
            return of(moved);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(verb.get() + " rounds the outline: " + e.getMessage(), e);
        }
    }

    /** The margin, found the first time it is asked for. */
    private double margin() {
        double m = margin;
        if (m != m) {
            m = Polygons.margin(xy);
            margin = m;
        }
        return m;
    }

    /** Two polygons are equal when they have the same vertices in the same order. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Polygon p && Arrays.equals(xy, p.xy);
    }

    /** @return a hash of the vertices, consistent with {@link #equals} */
    @Override
    public int hashCode() {
        return Arrays.hashCode(xy);
    }

    /** @return the vertices, for printing: {@code Polygon[x0, y0, x1, y1, ...]} */
    @Override
    public String toString() {
        return "Polygon" + Arrays.toString(xy);
    }

    private int index(String name, int i) {
        if (i < 0 || i >= size()) {
            throw new IllegalArgumentException(name + " must be 0 to " + (size() - 1) + ", was " + i);
        }
        return i;
    }
}
