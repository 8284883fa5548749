package hitbox;

/**
 * The tutorial's collision tests, one static method per pair of shapes, on plain floats.
 *
 * <p>Each method is the {@code if} statement the tutorial writes, made exact: the arithmetic is
 * done in {@code double}, so for whole-number coordinates up to about a million a touching case
 * is decided by the <a href="package-summary.html#touching">touching rule</a> and never by
 * rounding. The methods allocate nothing and check nothing: NaN in any argument makes every
 * comparison false, so the answer is "no collision". Circles are centre and radius; rectangles
 * are top-left corner, width and height (Processing's {@code CORNER} mode).
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
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius (not its diameter)
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside the circle
     */
    public static boolean circlePoint(float cx, float cy, float r, float px, float py) {
        double dx = (double) px - cx;
        double dy = (double) py - cy;
        return dx * dx + dy * dy < (double) r * r;
    }

    /**
     * Do two circles overlap? Circles that touch do not.
     *
     * <p>The tutorial's {@code dist(x1, y1, x2, y2) < r1 + r2}, compared squared. With radius 0
     * a circle behaves as a point, so {@code circleCircle(x, y, 0, ...)} is
     * {@link #circlePoint}; two circles of radius 0 never collide.
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
        double dx = (double) x2 - x1;
        double dy = (double) y2 - y1;
        double reach = (double) r1 + r2;
        return dx * dx + dy * dy < reach * reach;
    }

    /**
     * Is the point inside the rectangle? A point on an edge is not inside.
     *
     * <p>The tutorial's {@code px > rx && px < rx + rw && py > ry && py < ry + rh}. A rectangle
     * of width or height 0 contains no point.
     *
     * @param rx the rectangle's left edge
     * @param ry the rectangle's top edge
     * @param rw the rectangle's width
     * @param rh the rectangle's height
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside the rectangle
     */
    public static boolean rectPoint(float rx, float ry, float rw, float rh, float px, float py) {
        return px > rx && px < (double) rx + rw && py > ry && py < (double) ry + rh;
    }

    /**
     * Do two rectangles overlap? Rectangles side by side, sharing an edge, do not.
     *
     * <p>The tutorial's four comparisons: {@code x1 + w1 > x2 && x1 < x2 + w2 &&
     * y1 + h1 > y2 && y1 < y2 + h2}. A rectangle of width or height 0 behaves as a segment (or
     * a point) and collides only when it reaches into the other's inside, so two of them never
     * collide, even when they cross like a plus sign.
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
        return (double) x1 + w1 > x2 && x1 < (double) x2 + w2
                && (double) y1 + h1 > y2 && y1 < (double) y2 + h2
                // The four comparisons alone would let a zero-width and a zero-height
                // rectangle that cross collide, though neither has an inside to reach into.
                && (w1 > 0 && h1 > 0 || w2 > 0 && h2 > 0);
    }

    /**
     * Does the circle overlap the rectangle? Touching an edge or a corner is not overlapping.
     *
     * <p>The tutorial's method: find the rectangle's point closest to the centre (clamp the
     * centre into the rectangle), then test its distance against the radius. A circle of
     * radius 0 behaves as a point, so it collides only when strictly inside the rectangle.
     *
     * @param cx the circle's centre x
     * @param cy the circle's centre y
     * @param r  the circle's radius
     * @param rx the rectangle's left edge
     * @param ry the rectangle's top edge
     * @param rw the rectangle's width
     * @param rh the rectangle's height
     * @return true if the circle's inside and the rectangle's inside overlap
     */
    public static boolean circleRect(float cx, float cy, float r, float rx, float ry, float rw, float rh) {
        double dx = cx - clamp(cx, rx, (double) rx + rw);
        double dy = cy - clamp(cy, ry, (double) ry + rh);
        double d2 = dx * dx + dy * dy;
        if (d2 == 0) {
            // The centre is in the closed rectangle (NaN cannot get here: clamp passes it on,
            // and NaN is not 0). A real circle's inside covers the centre, so the two meet,
            // even for a zero-size rectangle; a circle of radius 0 is a point, which must be
            // strictly inside. A NaN radius fails both tests.
            return r > 0 || (r == 0 && rectPoint(rx, ry, rw, rh, cx, cy));
        }
        return d2 < (double) r * r;
    }

    /**
     * Is the point inside the polygon? A point on an edge is not inside.
     *
     * @param xy the polygon's vertices, {@code x0, y0, x1, y1, ...}
     * @param px the point's x
     * @param py the point's y
     * @return true if the point is strictly inside
     */
    public static boolean polygonPoint(float[] xy, float px, float py) {
        return Polygons.contains(xy, px, py);
    }

    /**
     * Clamps {@code v} into [lo, hi]; used for the closest point of a rectangle. NaN in any
     * argument gives NaN (Math.min and Math.max pass it on), so a NaN rectangle edge cannot
     * be clamped away into a false "collision".
     */
    static double clamp(double v, double lo, double hi) {
        return Math.max(lo, Math.min(v, hi));
    }
}
