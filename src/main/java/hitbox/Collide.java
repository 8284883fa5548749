package hitbox;

import hitbox.internal.*;

/**
 * The tutorial's collision tests, one static method per pair of shapes, on plain floats: the
 * four it writes (circle/point, circle/circle, rectangle/point, rectangle/rectangle), the
 * circle/rectangle and line tests it links to, and the polygon and triangle tests of its
 * section 10, with the steps the sketches draw ({@link #rayCrossesEdge}, {@link #lineSide}) and
 * the filled arc of a vision cone ({@link #arcPoint}). Every other pair (ellipses, capsules,
 * one shape inside another) is asked of the shapes: {@code a.overlaps(b)}, {@code a.contains(b)}.
 *
 * <p>The tutorial's four are the {@code if} statements it writes, made exact: the arithmetic is
 * done in {@code double}, so for whole-number coordinates up to about a million a touching case
 * is decided by the <a href="package-summary.html#touching">touching rule</a> and never by
 * rounding. The methods allocate nothing and never throw for any float: NaN in any argument
 * (a coordinate of a polygon's array included) answers "no collision", false (the package's
 * <a href="package-summary.html#bad-input">NaN rule</a>); so does a negative size or radius.
 * Infinite values are compared as the formulas compare them. The polygon methods throw only
 * for a null array ({@link IllegalArgumentException} naming it). Circles are centre and
 * radius; rectangles are top-left corner, width and height (Processing's {@code CORNER}
 * mode), named {@code rectX, rectY, rectW, rectH} where another shape comes first.
 *
 * <p>The {@code line...} methods ({@link #lineLine}, {@link #lineCircle}, {@link #lineRect},
 * {@link #lineSide}, and {@link #polygonLine}) take <em>segments</em>: two end points, closed,
 * as a {@link Segment} is. "Line" is the tutorial's word and the method names keep it;
 * everywhere else, {@link Sweep} and {@link Ray} included, Hitbox says segment.
 * {@link #lineSide} alone reads the whole line through the two points.
 *
 * <p>This class is longer than most (about 490 lines): it is the tutorial's table of tests,
 * one public method per pair with its full javadoc. Each answers by calling its kernel in
 * {@code hitbox.internal} ({@code RawTests}, which the shapes' and the world's code call
 * directly, so that nothing calls back up into this class).
 */
public final class Collide {
    private Collide() {
    }

    /**
     * Is the point inside the circle? Touching the outline is not inside.
     *
     * <p>The tutorial's {@code dist(px, py, cx, cy) < r}, compared squared so no square root
     * is taken. A circle of radius 0 contains no point.
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius (not its diameter)
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside the circle
     */
    public static boolean circlePoint(float cx, float cy, float r, float px, float py) {
        return RawTests.circlePoint(cx, cy, r, px, py);
    }

    /**
     * Do two circles overlap? Circles that touch do not.
     *
     * <p>The tutorial's {@code dist(x1, y1, x2, y2) < r1 + r2}, compared squared. With radius 0
     * a circle behaves as a point, so {@code circleCircle(x, y, 0, ...)} is
     * {@link #circlePoint}; two circles of radius 0 never collide.
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first circle's centre x
     * @param y1 the first circle's centre y
     * @param r1 the first circle's radius
     * @param x2 the second circle's centre x
     * @param y2 the second circle's centre y
     * @param r2 the second circle's radius
     * @return true if the distance between the centres is less than the sum of the radii
     */
    public static boolean circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return RawTests.circleCircle(x1, y1, r1, x2, y2, r2);
    }


    /**
     * Is the point inside the rectangle? A point on an edge is not inside.
     *
     * <p>The tutorial's {@code px > rx && px < rx + rw && py > ry && py < ry + rh} (its {@code rx} is
     * this method's {@code rectX}, and so on). A rectangle
     * of width or height 0 contains no point.
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside the rectangle
     */
    public static boolean rectPoint(float rectX, float rectY, float rectW, float rectH, float px, float py) {
        return RawTests.rectPoint(rectX, rectY, rectW, rectH, px, py);
    }

    /**
     * Do two rectangles overlap? Rectangles side by side, sharing an edge, do not.
     *
     * <p>The tutorial's four comparisons: {@code x1 + w1 > x2 && x1 < x2 + w2 &&
     * y1 + h1 > y2 && y1 < y2 + h2}. A rectangle of size 0 behaves as a point (or a segment
     * without its ends) and collides with a real rectangle only when it reaches into its
     * inside; two flat rectangles collide only when they cross like a plus sign.
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first rectangle's left edge
     * @param y1 the first rectangle's top edge
     * @param w1 the first rectangle's width
     * @param h1 the first rectangle's height
     * @param x2 the second rectangle's left edge
     * @param y2 the second rectangle's top edge
     * @param w2 the second rectangle's width
     * @param h2 the second rectangle's height
     * @return true if the rectangles' insides overlap
     */
    public static boolean rectRect(float x1, float y1, float w1, float h1,
                                   float x2, float y2, float w2, float h2) {
        return RawTests.rectRect(x1, y1, w1, h1, x2, y2, w2, h2);
    }

    /**
     * Does the circle overlap the rectangle? Touching an edge or a corner is not overlapping.
     *
     * <p>The usual method (the tutorial has no circle/rectangle code): find the rectangle's
     * point closest to the centre (clamp the
     * centre into the rectangle), then test its distance against the radius. A circle of
     * radius 0 behaves as a point, so it collides only when strictly inside the rectangle.
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return true if the circle's inside and the rectangle's inside overlap
     */
    public static boolean circleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        return RawTests.circleRect(cx, cy, r, rectX, rectY, rectW, rectH);
    }

    /**
     * Is the point inside the polygon? A point on an edge or at a vertex is not inside.
     *
     * <p>The crossing test the video names (count the edges a line from the point crosses; odd
     * is inside; the tutorial has no polygon code), with the line going to the right, made
     * exact: each edge counts by the half-open rule (one end below the point,
     * the other at or above it), so a ray through a vertex is counted by rule, and which side
     * of an edge the point lies on is an orientation sign, so vertical edges and points on an
     * edge are exact cases too. On a rectangle's four corners it answers exactly as
     * {@link #rectPoint}.
     *
     * <p>Reference: E. Haines, "Point in Polygon Strategies", Graphics Gems IV (1994).
     *
     * <p>A NaN in any argument, a coordinate of {@code xy} included, answers false
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param xy the polygon's vertices, {@code x0, y0, x1, y1, ...}: any simple polygon,
     *           convex or concave, in either winding (a polygon that crosses itself is read
     *           even-odd). Fewer than 3 vertices never contain a point; an odd last
     *           coordinate is ignored; a vertex repeated (such as the first one again at
     *           the end) changes nothing. Not checked ({@link Polygon#of} checks), not null.
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static boolean polygonPoint(float[] xy, float px, float py) {
        return RawTests.polygonPoint(xy, px, py);
    }

    /**
     * Does the ray cast from the point to the right cross this polygon edge, by the rule
     * {@link #polygonPoint} counts with? An odd count over all edges means inside.
     *
     * <p>The rule is half-open, so that a ray through a corner is counted right: the edge
     * counts only when one end is below the point's level and the other at or above it (y
     * grows down), and the crossing is to the right of the point. A corner the ray passes
     * through is counted once; a corner it only touches, twice or not at all. A point on the
     * edge gives false ({@code polygonPoint} then says "outside").
     *
     * <p>A NaN in any argument answers false; infinite values are compared as the formula
     * compares them (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param ax the edge's first end, x
     * @param ay the edge's first end, y
     * @param bx the edge's second end, x
     * @param by the edge's second end, y
     * @param px the point's x
     * @param py the point's y
     * @return true if this edge counts as a crossing
     */
    public static boolean rayCrossesEdge(float ax, float ay, float bx, float by, float px, float py) {
        return RawTests.rayCrossesEdge(ax, ay, bx, by, px, py);
    }

    /**
     * Which side of the line through (x1, y1) and (x2, y2) is the point on, walking from the
     * first point to the second? The orientation test behind every segment answer here.
     *
     * <p>On screen (y down), 1 is the walker's right-hand side and -1 the left; 0 means the
     * point is on the line. Exact for whole numbers up to about 16 million. NaN gives 0.
     *
     * @param x1 the line's first point, x
     * @param y1 the line's first point, y
     * @param x2 the line's second point, x
     * @param y2 the line's second point, y
     * @param px the point's x
     * @param py the point's y
     * @return 1 (right), -1 (left) or 0 (on the line)
     */
    public static int lineSide(float x1, float y1, float x2, float y2, float px, float py) {
        return RawTests.lineSide(x1, y1, x2, y2, px, py);
    }

    /**
     * Do two line segments meet? Segments are closed: touching at an end counts, and so do
     * two collinear segments that overlap.
     *
     * <p>Instead of the usual division for the crossing point (which fails for parallel and
     * vertical lines; the tutorial has no line code), four orientation signs: the segments
     * cross when each one's ends lie
     * on opposite sides of the other's line. A zero sign means an end lies on the other's
     * line, and then it is a meeting point exactly when it is also within the other's extent.
     * A segment of length 0 is a point, so it meets a segment through it, and another
     * zero-length segment at the same place.
     *
     * <p>Reference: T. Cormen, C. Leiserson, R. Rivest, C. Stein, Introduction to Algorithms,
     * section 33.1 (SEGMENTS-INTERSECT).
     *
     * <p>A NaN in any argument answers false; infinite values are compared as the formula
     * compares them (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first segment's first end x
     * @param y1 the first segment's first end y
     * @param x2 the first segment's second end x
     * @param y2 the first segment's second end y
     * @param x3 the second segment's first end x
     * @param y3 the second segment's first end y
     * @param x4 the second segment's second end x
     * @param y4 the second segment's second end y
     * @return true if the segments have a point in common
     */
    public static boolean lineLine(float x1, float y1, float x2, float y2,
                                   float x3, float y3, float x4, float y4) {
        return RawTests.lineLine(x1, y1, x2, y2, x3, y3, x4, y4);
    }

    /**
     * Does the segment reach into the circle? It must come closer to the centre than the
     * radius: a segment that only touches the outline (a tangent) does not collide.
     *
     * <p>The usual method (Jeff Thompson's; the tutorial has no line code): an end inside the
     * circle, or else the point of the segment closest to the centre inside it. The closest point is not computed (that would divide):
     * whether it lies between the ends is the sign of a dot product, and its distance is
     * compared as {@code cross^2 < r^2 * length^2} with an exact product difference. A circle
     * of radius 0 has no inside, so no segment reaches it (a segment and a zero-size shape
     * never collide); a negative radius also gives false. A segment of length 0 is a point.
     *
     * <p>Reference: J. Thompson, Collision Detection, "Line/Circle".
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @return true if some point of the segment is strictly inside the circle
     */
    public static boolean lineCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        return RawTests.lineCircle(x1, y1, x2, y2, cx, cy, r);
    }

    /**
     * Does the segment reach into the rectangle? Running along an edge or touching a corner
     * does not; a segment wholly inside does (the common recipe of four line/line tests misses
     * that case, since it crosses no edge).
     *
     * <p>A separating-axis test: the segment misses the rectangle's open inside exactly when
     * it lies, end points included, on or beyond one side of the rectangle (left, right, top
     * or bottom), or when all four corners lie on or beyond one side of the segment's line.
     * A rectangle of width or height 0 has no inside, so no segment reaches it. A segment of
     * length 0 is a point and collides when strictly inside.
     *
     * <p>Reference: C. Ericson, Real-Time Collision Detection (2005), section 5.2.1
     * (separating-axis test).
     *
     * <p>A NaN in any argument answers false, and so does a negative size; infinite values
     * are compared as the formula compares them (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return true if some point of the segment is strictly inside the rectangle
     */
    public static boolean lineRect(float x1, float y1, float x2, float y2,
                                   float rectX, float rectY, float rectW, float rectH) {
        return RawTests.lineRect(x1, y1, x2, y2, rectX, rectY, rectW, rectH);
    }

    /**
     * Does the circle overlap the polygon? Touching the outline is not overlapping; a circle
     * wholly inside the polygon, or a polygon wholly inside the circle, overlaps.
     *
     * <p>Either an edge reaches into the circle ({@link #lineCircle}), or no edge does and the
     * circle is then wholly inside or wholly outside, which its centre settles
     * ({@link #polygonPoint}). A circle of radius 0 behaves as a point: it collides when
     * strictly inside. A negative or NaN radius gives false.
     *
     * @param xy the polygon's vertices, {@code x0, y0, x1, y1, ...}, as in {@link #polygonPoint}
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @return true if the insides of the circle and the polygon overlap
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static boolean polygonCircle(float[] xy, float cx, float cy, float r) {
        return RawTests.polygonCircle(xy, cx, cy, r);
    }

    /**
     * Does the rectangle overlap the polygon? Sharing an edge or touching at a corner is not
     * overlapping; one wholly inside the other overlaps, and so do a polygon and a rectangle
     * with the same outline.
     *
     * <p>Either an edge reaches into the rectangle ({@link #lineRect}), or no edge does and the
     * rectangle is wholly inside or wholly outside: a step from its top-left corner into it
     * settles which, exactly, even when that corner sits on the outline. A rectangle of width
     * or height 0 behaves as a segment (or a point), as in {@link #polygonLine}. A negative or
     * NaN size gives false.
     *
     * @param xy the polygon's vertices, {@code x0, y0, x1, y1, ...}, as in {@link #polygonPoint}
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return true if the insides of the rectangle and the polygon overlap
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static boolean polygonRect(float[] xy, float rectX, float rectY, float rectW, float rectH) {
        return RawTests.polygonRect(xy, rectX, rectY, rectW, rectH);
    }

    /**
     * Does the segment reach into the polygon? Running along an edge, touching a vertex, or
     * crossing a concave notch through its corners does not; a segment wholly inside does.
     *
     * <p>Walk the segment from its first end to its second: it reaches the inside when its
     * first end is inside, or when it steps in somewhere along the way, which can only happen
     * where it meets the outline: crossing an edge properly, starting on an edge and heading
     * for the inside side, or passing a vertex heading into the corner's wedge. All exact
     * orientation signs, no crossing points; the answer is the same walked either way. A
     * segment of length 0 is a point.
     *
     * <p>A NaN in any argument, a coordinate of {@code xy} included, answers false
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param xy the polygon's vertices, {@code x0, y0, x1, y1, ...}, as in {@link #polygonPoint}
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @return true if some point of the segment is strictly inside the polygon
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static boolean polygonLine(float[] xy, float x1, float y1, float x2, float y2) {
        return RawTests.polygonLine(xy, x1, y1, x2, y2);
    }

    /**
     * Do two polygons overlap? Sharing an edge or touching at a vertex is not overlapping; a
     * polygon wholly inside the other overlaps, and so do two polygons with the same outline.
     *
     * <p>Either some edge of {@code a} reaches into {@code b} (as in {@link #polygonLine}), or
     * none does and {@code b} is then wholly inside {@code a} or wholly outside it: a step from
     * {@code b}'s leftmost corner into {@code b} settles which, exactly. This works for concave
     * polygons too, where the separating-axis test does not. Time grows with the product of
     * the two vertex counts; far-apart polygons are rejected by their bounds first. When both
     * outlines are convex (checked on the way, one orientation per vertex; {@code b}'s only
     * when no edge of a convex {@code a} already separates them), the separating
     * axes are asked instead, with exact orientation signs: the same answers, in about the
     * time of a sum of the vertex counts when they overlap.
     *
     * <p>A NaN anywhere in either array answers false
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param a the first polygon's vertices, {@code x0, y0, x1, y1, ...}, as in {@link #polygonPoint}
     * @param b the second polygon's vertices, the same way
     * @return true if the insides of the polygons overlap
     * @throws IllegalArgumentException if {@code a} or {@code b} is null
     */
    public static boolean polygonPolygon(float[] a, float[] b) {
        return RawTests.polygonPolygon(a, b);
    }

    /**
     * Is the point inside the triangle? A point on an edge or at a corner is not. Same answer
     * as {@link #polygonPoint} for the three corners, without an array.
     *
     * <p>The point is inside when it lies on the same side of all three edges: three
     * orientation signs, all positive or all negative (either winding). Exact, unlike the
     * common sum-of-areas recipe, which rounds. A flat triangle contains no point.
     *
     * <p>A NaN in any argument answers false; infinite values are compared as the formula
     * compares them (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first corner's x
     * @param y1 the first corner's y
     * @param x2 the second corner's x
     * @param y2 the second corner's y
     * @param x3 the third corner's x
     * @param y3 the third corner's y
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside the triangle
     */
    public static boolean trianglePoint(float x1, float y1, float x2, float y2, float x3, float y3,
                                        float px, float py) {
        return RawTests.trianglePoint(x1, y1, x2, y2, x3, y3, px, py);
    }

    // ---------------------------------------------------------------- arcs

    /**
     * Is the point inside the arc Processing fills for
     * {@code arc(x, y, 2 * radiusX, 2 * radiusY, start, stop, mode)} (the default
     * {@code CENTER} ellipse mode)? The outline does not count.
     *
     * <p>Angles are radians, clockwise on screen from the right (y grows down), exactly as
     * {@code arc()} takes them: nothing is filled unless {@code stop > start}; both angles are
     * brought up to 0 or more by adding {@code TWO_PI}, and a span over {@code TWO_PI} is the
     * whole ellipse; on a squashed ellipse the angles are its parametric angles, as Java2D
     * draws them (the point at angle a is {@code (x + radiusX cos a, y + radiusY sin a)}).
     * The modes are Processing's: {@code PIE} (3; also 0, {@code arc()} without a mode, and
     * any other value) fills the slice from the centre, which is a vision cone or a sword
     * swing; {@code OPEN} (1) and {@code CHORD} (2) fill the part cut off by the chord
     * between the arc's ends. A start so far below 0 that adding {@code TWO_PI} in float
     * cannot bring it up (Processing's own loop would not end) fills nothing.
     *
     * <p>Decided in double with {@code atan2}: the answer can differ from the pixels only
     * within rounding of the outline.
     *
     * <p>A NaN in any argument answers false, and so does a negative radius; a mode other
     * than 1 or 2 is read as {@code PIE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x       the ellipse's centre x
     * @param y       the ellipse's centre y
     * @param radiusX its horizontal radius (half of {@code arc()}'s width)
     * @param radiusY its vertical radius
     * @param start   the start angle, radians
     * @param stop    the stop angle, radians
     * @param mode    Processing's {@code OPEN} (1), {@code CHORD} (2) or {@code PIE} (3)
     * @param px      the point's x
     * @param py      the point's y
     * @return true if the point is strictly inside the filled arc
     */
    public static boolean arcPoint(float x, float y, float radiusX, float radiusY, float start, float stop, int mode,
                                   float px, float py) {
        return RawTests.arcPoint(x, y, radiusX, radiusY, start, stop, mode, px, py);
    }
}
