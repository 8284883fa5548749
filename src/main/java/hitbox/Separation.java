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
 * the distance. Where several pairs of points are equally close (two parallel edges, say) one
 * of them is given. Touching shapes give one point, the same for both.
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
 * <p>The raw-float forms ({@link #circleCircle}, {@link #rectRect}, {@link #polygonPoint},
 * ...) give the same distance for the tutorial's pairs without making shapes, and 0 when the
 * shapes overlap (the distance between two sets that meet): {@link Collide} tells overlapping
 * from touching.
 *
 * <p>This class is longer than most (about 480 lines): the record and the raw-float forms of
 * the tutorial's pairs, each a few lines with its full javadoc, as {@link Collide} is.
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

    /** The distance of two cores, 0 where the caller found an overlap. */
    private static float apart(Distances.Core a, Distances.Core b) {
        return Check.held(Distances.apart(a, b, new double[4]));
    }

    private static Distances.Core point(float x, float y, float r) {
        return new Distances.Core(new double[] {x, y}, false, null, r);
    }

    private static Distances.Core segment(float x1, float y1, float x2, float y2) {
        return new Distances.Core(new double[] {x1, y1, x2, y2}, false, null, 0);
    }

    private static Distances.Core rect(float x, float y, float w, float h) {
        return new Distances.Core(Polygons.corners(new Rect(x, y, w, h), new double[8]), true, null, 0);
    }

    /** A raw polygon's outline, or null when it has fewer than 3 vertices or a NaN or infinite coordinate. */
    private static Distances.Core polygon(float[] xy) {
        int n = xy.length / 2;
        if (n < 3) {
            return null;
        }
        double[] d = new double[2 * n];
        for (int i = 0; i < 2 * n; i++) {
            if (!Float.isFinite(xy[i])) {
                return null;
            }
            d[i] = xy[i];
        }
        return new Distances.Core(d, true, null, 0);
    }

    /**
     * How far a point is from a circle's outline, 0 when it is inside or on it:
     * {@code dist(px, py, cx, cy) - r}, held at 0 (the tutorial compares that distance with
     * r; this is by how much it misses).
     *
     * <p>A NaN in any argument, an infinite one or a negative radius answers
     * {@code +Infinity} (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @param px the point's x
     * @param py the point's y
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float circlePoint(float cx, float cy, float r, float px, float py) {
        if (Check.notFinite(cx, cy, r, px, py) || r < 0) {
            return Float.POSITIVE_INFINITY;
        }
        return Check.held(Distances.discs(cx, cy, r, px, py, 0));
    }

    /**
     * How far apart two circles are, 0 when they touch or overlap:
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

    /**
     * How far a point is from a rectangle, 0 when it is inside or on its edge: the length of
     * the gaps to the rectangle's nearest edges, exact for whole numbers when it is one.
     *
     * <p>A NaN in any argument, an infinite one or a negative size answers {@code +Infinity}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @param px    the point's x
     * @param py    the point's y
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float rectPoint(float rectX, float rectY, float rectW, float rectH, float px, float py) {
        if (Check.notFinite(rectX, rectY, rectW, rectH, px) || !Float.isFinite(py) || rectW < 0 || rectH < 0) {
            return Float.POSITIVE_INFINITY;
        }
        if (Collide.rectPoint(rectX, rectY, rectW, rectH, px, py)) {
            return 0;
        }
        return apart(rect(rectX, rectY, rectW, rectH), point(px, py, 0));
    }

    /**
     * How far apart two rectangles are, 0 when they touch or overlap: the length of the gaps
     * between them across and down, exact for whole numbers when it is one (an axis-aligned
     * gap always is).
     *
     * <p>A NaN in any argument, an infinite one or a negative size answers {@code +Infinity}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first rectangle's left edge
     * @param y1 the first rectangle's top edge
     * @param w1 the first rectangle's width
     * @param h1 the first rectangle's height
     * @param x2 the second rectangle's left edge
     * @param y2 the second rectangle's top edge
     * @param w2 the second rectangle's width
     * @param h2 the second rectangle's height
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float rectRect(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        if (Check.notFinite(x1, y1, w1, h1, x2) || Check.notFinite(y2, w2, h2, 0, 0)
                || w1 < 0 || h1 < 0 || w2 < 0 || h2 < 0) {
            return Float.POSITIVE_INFINITY;
        }
        if (Collide.rectRect(x1, y1, w1, h1, x2, y2, w2, h2)) {
            return 0;
        }
        return apart(rect(x1, y1, w1, h1), rect(x2, y2, w2, h2));
    }

    /**
     * How far apart a circle and a rectangle are, 0 when they touch or overlap: the centre's
     * distance from the rectangle less the radius, held at 0.
     *
     * <p>A NaN in any argument, an infinite one or a negative size answers {@code +Infinity}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx    the circle's centre x
     * @param cy    the circle's centre y
     * @param r     the circle's radius
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float circleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        if (Check.notFinite(cx, cy, r, rectX, rectY) || Check.notFinite(rectW, rectH, 0, 0, 0)
                || r < 0 || rectW < 0 || rectH < 0) {
            return Float.POSITIVE_INFINITY;
        }
        if (Collide.circleRect(cx, cy, r, rectX, rectY, rectW, rectH)) {
            return 0;
        }
        return apart(point(cx, cy, r), rect(rectX, rectY, rectW, rectH));
    }

    /**
     * How far a point is from a segment (the tutorial's "line"), 0 when it lies on it.
     *
     * <p>A NaN in any argument or an infinite one answers {@code +Infinity} (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @param px the point's x
     * @param py the point's y
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float linePoint(float x1, float y1, float x2, float y2, float px, float py) {
        if (Check.notFinite(x1, y1, x2, y2, px) || !Float.isFinite(py)) {
            return Float.POSITIVE_INFINITY;
        }
        return apart(segment(x1, y1, x2, y2), point(px, py, 0));
    }

    /**
     * How far apart a segment and a circle are, 0 when they touch or overlap.
     *
     * <p>A NaN in any argument, an infinite one or a negative radius answers
     * {@code +Infinity} (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float lineCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        if (Check.notFinite(x1, y1, x2, y2, cx) || Check.notFinite(cy, r, 0, 0, 0) || r < 0) {
            return Float.POSITIVE_INFINITY;
        }
        return apart(segment(x1, y1, x2, y2), point(cx, cy, r));
    }

    /**
     * How far apart two segments are, 0 when they meet.
     *
     * <p>A NaN in any argument or an infinite one answers {@code +Infinity} (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1 the first segment's first end x
     * @param y1 the first segment's first end y
     * @param x2 the first segment's second end x
     * @param y2 the first segment's second end y
     * @param x3 the second segment's first end x
     * @param y3 the second segment's first end y
     * @param x4 the second segment's second end x
     * @param y4 the second segment's second end y
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float lineLine(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
        if (Check.notFinite(x1, y1, x2, y2, x3) || Check.notFinite(y3, x4, y4, 0, 0)) {
            return Float.POSITIVE_INFINITY;
        }
        return apart(segment(x1, y1, x2, y2), segment(x3, y3, x4, y4));
    }

    /**
     * How far apart a segment and a rectangle are, 0 when they touch or overlap.
     *
     * <p>A NaN in any argument, an infinite one or a negative size answers {@code +Infinity}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x1    the segment's first end x
     * @param y1    the segment's first end y
     * @param x2    the segment's second end x
     * @param y2    the segment's second end y
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     */
    public static float lineRect(float x1, float y1, float x2, float y2, float rectX, float rectY, float rectW, float rectH) {
        if (Check.notFinite(x1, y1, x2, y2, rectX) || Check.notFinite(rectY, rectW, rectH, 0, 0) || rectW < 0 || rectH < 0) {
            return Float.POSITIVE_INFINITY;
        }
        if (Collide.lineRect(x1, y1, x2, y2, rectX, rectY, rectW, rectH)) {
            return 0;
        }
        return apart(segment(x1, y1, x2, y2), rect(rectX, rectY, rectW, rectH));
    }

    /**
     * How far a point is from a polygon, 0 when it is inside or on its outline.
     *
     * <p>A NaN in any argument or an infinite one, a coordinate of {@code xy} included, and a
     * polygon of fewer than 3 vertices answer {@code +Infinity} (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param xy the polygon's vertices, {@code x0, y0, x1, y1, ...}, as
     *           {@link Collide#polygonPoint} takes them (not checked, not null; an odd last
     *           coordinate is ignored)
     * @param px the point's x
     * @param py the point's y
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static float polygonPoint(float[] xy, float px, float py) {
        Distances.Core p = polygon(Check.notNull("xy", xy));
        if (p == null || Check.notFinite(px, py, 0, 0, 0)) {
            return Float.POSITIVE_INFINITY;
        }
        return Collide.polygonPoint(xy, px, py) ? 0 : apart(p, point(px, py, 0));
    }

    /**
     * How far apart a polygon and a circle are, 0 when they touch or overlap.
     *
     * <p>A NaN in any argument or an infinite one, a coordinate of {@code xy} included, a
     * negative radius and a polygon of fewer than 3 vertices answer {@code +Infinity} (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param xy the polygon's vertices, as {@link #polygonPoint} takes them, not null
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static float polygonCircle(float[] xy, float cx, float cy, float r) {
        Distances.Core p = polygon(Check.notNull("xy", xy));
        if (p == null || Check.notFinite(cx, cy, r, 0, 0) || r < 0) {
            return Float.POSITIVE_INFINITY;
        }
        return Collide.polygonCircle(xy, cx, cy, r) ? 0 : apart(p, point(cx, cy, r));
    }

    /**
     * How far apart a polygon and a rectangle are, 0 when they touch or overlap.
     *
     * <p>A NaN in any argument or an infinite one, a coordinate of {@code xy} included, a
     * negative size and a polygon of fewer than 3 vertices answer {@code +Infinity} (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param xy    the polygon's vertices, as {@link #polygonPoint} takes them, not null
     * @param rectX the rectangle's left edge
     * @param rectY the rectangle's top edge
     * @param rectW the rectangle's width
     * @param rectH the rectangle's height
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static float polygonRect(float[] xy, float rectX, float rectY, float rectW, float rectH) {
        Distances.Core p = polygon(Check.notNull("xy", xy));
        if (p == null || Check.notFinite(rectX, rectY, rectW, rectH, 0) || rectW < 0 || rectH < 0) {
            return Float.POSITIVE_INFINITY;
        }
        return Collide.polygonRect(xy, rectX, rectY, rectW, rectH) ? 0 : apart(p, rect(rectX, rectY, rectW, rectH));
    }

    /**
     * How far apart a polygon and a segment are, 0 when they touch or overlap.
     *
     * <p>A NaN in any argument or an infinite one, a coordinate of {@code xy} included, and a
     * polygon of fewer than 3 vertices answer {@code +Infinity} (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param xy the polygon's vertices, as {@link #polygonPoint} takes them, not null
     * @param x1 the segment's first end x
     * @param y1 the segment's first end y
     * @param x2 the segment's second end x
     * @param y2 the segment's second end y
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     * @throws IllegalArgumentException if {@code xy} is null
     */
    public static float polygonLine(float[] xy, float x1, float y1, float x2, float y2) {
        Distances.Core p = polygon(Check.notNull("xy", xy));
        if (p == null || Check.notFinite(x1, y1, x2, y2, 0)) {
            return Float.POSITIVE_INFINITY;
        }
        return Collide.polygonLine(xy, x1, y1, x2, y2) ? 0 : apart(p, segment(x1, y1, x2, y2));
    }

    /**
     * How far apart two polygons are, 0 when they touch or overlap (one inside the other
     * included).
     *
     * <p>A NaN or infinite coordinate in either array, or a polygon of fewer than 3
     * vertices, answers {@code +Infinity} (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param a the first polygon's vertices, as {@link #polygonPoint} takes them, not null
     * @param b the second polygon's vertices, not null
     * @return the distance, 0 or more, or {@code +Infinity} for bad input
     * @throws IllegalArgumentException if {@code a} or {@code b} is null
     */
    public static float polygonPolygon(float[] a, float[] b) {
        Distances.Core p = polygon(Check.notNull("a", a)), q = polygon(Check.notNull("b", b));
        if (p == null || q == null) {
            return Float.POSITIVE_INFINITY;
        }
        return Collide.polygonPolygon(a, b) ? 0 : apart(p, q);
    }
}
