package hitbox;

import hitbox.internal.*;

import java.util.Set;

/**
 * The window's edges: which ones a shape has crossed, and the three things a sketch does about
 * it: bounce back, wrap around to the other side, or stay inside.
 *
 * <p>The window runs from 0 to {@code width} across and from 0 to {@code height} down
 * (Processing's {@code width} and {@code height}). Every method is static and allocates
 * nothing, so it is safe to call every frame:
 * <pre>{@code
 * ball = ball.translated(vx, vy);
 * Set<Side> crossed = Edges.crossed(ball, width, height);
 * vx = Edges.bounceX(crossed, vx);
 * vy = Edges.bounceY(crossed, vy);
 * }</pre>
 *
 * <p>Crossing follows the <a href="package-summary.html#touching">touching rule</a>: a shape
 * that only touches an edge (a ball of radius 10 at {@code x = 10}) has not crossed it; one
 * that reaches past it, even by a little, has. The answer is an unmodifiable set of
 * {@link Side}s (see <a href="Side.html#sets">several sides at once</a>), empty when none is
 * crossed: {@code crossed.contains(Side.LEFT)}. A shape bigger than the window crosses both
 * opposite edges at once.
 *
 * <p>Circles are centre and radius, rectangles top-left corner and size, as everywhere in
 * Hitbox; for a point use a circle of radius 0. The wrap and clamp methods take plain floats
 * and check nothing (the <a href="package-summary.html#bad-input">NaN rule</a>): they answer
 * NaN for a NaN position, and hand the position back unchanged for a NaN or negative size
 * or window; a NaN speed comes back from the bounce methods unchanged.
 */
public final class Edges {
    private Edges() {
    }

    /**
     * Which edges of the window has the shape crossed? Its exact extents (its
     * {@link Shape#bounds()} before rounding to floats) against the window: {@link Side#LEFT} if it reaches left of
     * {@code x = 0}, {@link Side#RIGHT} right of {@code x = width}, {@link Side#TOP} above
     * {@code y = 0}, {@link Side#BOTTOM} below {@code y = height}. A point is a circle of
     * radius 0.
     *
     * <p>A NaN or negative {@code width} or {@code height} is no window: nothing is crossed.
     *
     * @param shape  the shape, not null
     * @param width  the window's width
     * @param height the window's height
     * @return the crossed edges, an unmodifiable set, empty (not null) if none, never null;
     *         allocates nothing
     * @throws IllegalArgumentException if {@code shape} is null
     */
    public static Set<Side> crossed(Shape shape, float width, float height) {
        Check.notNull("shape", shape);
        return SideSets.of(crossed(Extents.minX(shape), Extents.maxX(shape), Extents.minY(shape), Extents.maxY(shape), width, height));
    }

    /**
     * The one crossing rule, in {@code SideSets}' bits: strictly beyond an edge, in double so
     * touching is exact. A NaN anywhere crosses nothing. Also {@link Motion#bounce}'s, on the
     * floats of a box's next place.
     */
    static int crossed(double left, double right, double top, double bottom, float width, float height) {
        if (Double.isNaN(left) || Double.isNaN(right) || Double.isNaN(top) || Double.isNaN(bottom)
                || Float.isNaN(width) || Float.isNaN(height)) {
            return 0;
        }
        // A negative size or window is no shape and no window: no answer, as for NaN (the
        // package's bad-input rule). The sums are exact in double, so left > right only for
        // a negative size.
        if (left > right || top > bottom || width < 0 || height < 0) {
            return 0;
        }
        int edges = 0;
        if (left < 0) {
            edges |= SideSets.LEFT;
        }
        if (right > width) {
            edges |= SideSets.RIGHT;
        }
        if (top < 0) {
            edges |= SideSets.TOP;
        }
        if (bottom > height) {
            edges |= SideSets.BOTTOM;
        }
        return edges;
    }

    /**
     * The horizontal speed after bouncing off the left or right edge: pointing right (back
     * inside) after crossing the left edge, pointing left after crossing the right edge, and
     * unchanged otherwise.
     *
     * <p>Why not the tutorial's {@code vx *= -1}: a ball that is still beyond the edge on the
     * next frame (it went far past, the window shrank, or it was placed there) gets its speed
     * flipped again, back outwards, then again inwards, and jitters at the edge forever. Setting
     * the direction instead of flipping it can only ever send the ball back inside. A shape
     * wider than the window crosses both sides at once and has no inside direction; its speed
     * is left as it is.
     *
     * <p>A NaN speed comes back NaN, unchanged
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param crossed the edges from {@link #crossed}, not null
     * @param vx      the horizontal speed
     * @return {@code |vx|} if only {@link Side#LEFT} was crossed, {@code -|vx|} if only
     *         {@link Side#RIGHT} was, {@code vx} otherwise
     * @throws IllegalArgumentException if {@code crossed} is null
     */
    public static float bounceX(Set<Side> crossed, float vx) {
        Check.notNull("crossed", crossed);
        return bounce(crossed.contains(Side.LEFT), crossed.contains(Side.RIGHT), vx);
    }

    /**
     * The vertical speed after bouncing off the top or bottom edge: pointing down (back
     * inside) after crossing the top edge, pointing up after crossing the bottom edge, and
     * unchanged otherwise. See {@link #bounceX} for why this sets the direction instead of
     * flipping it.
     *
     * <p>A NaN speed comes back NaN, unchanged
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param crossed the edges from {@link #crossed}, not null
     * @param vy      the vertical speed (down is positive)
     * @return {@code |vy|} if only {@link Side#TOP} was crossed, {@code -|vy|} if only
     *         {@link Side#BOTTOM} was, {@code vy} otherwise
     * @throws IllegalArgumentException if {@code crossed} is null
     */
    public static float bounceY(Set<Side> crossed, float vy) {
        Check.notNull("crossed", crossed);
        return bounce(crossed.contains(Side.TOP), crossed.contains(Side.BOTTOM), vy);
    }

    /** Points v away from the one crossed edge of a pair (low edge: positive; high: negative). */
    private static float bounce(boolean low, boolean high, float v) {
        if (low && !high) {
            return Math.abs(v);
        }
        if (high && !low) {
            return -Math.abs(v);
        }
        return v;
    }

    /**
     * The circle's centre x after wrapping around the left and right edges, like Pac-Man: once
     * the circle has completely left through one side, it comes back in through the other.
     *
     * <p>The two sides are joined with a gap the size of the circle, so the circle is never
     * drawn half on each side, and its motion stays smooth: the moment it has fully left on
     * the left (touching the edge from outside) is the moment it starts to come in on the
     * right (touching from outside), and whatever it moved beyond that it keeps. The result
     * always lies in {@code [-r, width + r]}, however far out the circle was. A centre already
     * in that range is returned unchanged.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx    the circle's centre x
     * @param r     the circle's radius
     * @param width the window's width
     * @return the wrapped centre x
     */
    public static float circleWrapX(float cx, float r, float width) {
        return wrap(cx, r, r, width);
    }

    /**
     * The circle's centre y after wrapping around the top and bottom edges; see
     * {@link #circleWrapX}. The result always lies in {@code [-r, height + r]}.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cy     the circle's centre y
     * @param r      the circle's radius
     * @param height the window's height
     * @return the wrapped centre y
     */
    public static float circleWrapY(float cy, float r, float height) {
        return wrap(cy, r, r, height);
    }

    /**
     * The rectangle's left edge after wrapping around the left and right edges; see
     * {@link #circleWrapX}. The result always lies in {@code [-w, width]}: once the rectangle
     * has completely left on one side it comes back in on the other.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x     the rectangle's left edge
     * @param w     the rectangle's width
     * @param width the window's width
     * @return the wrapped left edge
     */
    public static float rectWrapX(float x, float w, float width) {
        return wrap(x, 0, w, width);
    }

    /**
     * The rectangle's top edge after wrapping around the top and bottom edges; see
     * {@link #circleWrapX}. The result always lies in {@code [-h, height]}.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param y      the rectangle's top edge
     * @param h      the rectangle's height
     * @param height the window's height
     * @return the wrapped top edge
     */
    public static float rectWrapY(float y, float h, float height) {
        return wrap(y, 0, h, height);
    }

    /**
     * Wraps a position whose shape reaches {@code before} behind it and {@code after} ahead of
     * it. The shape's far end, {@code pos + after}, lives on a loop of length
     * {@code window + before + after} starting at 0 (the shape has just left on the low side);
     * 0 and the loop's length are the same place, so both are kept as they are.
     */
    private static float wrap(float pos, float before, float after, float window) {
        if (before < 0 || after < 0 || window < 0) {
            return pos;  // a negative size or window: the position back unchanged, as for NaN
        }
        double end = (double) pos + after;
        double loop = (double) window + before + after;
        // Already in [-after, window + before]: decided exactly, not on the rounded end and
        // loop, which for a size far above the window (1e17 against 1) round to the same
        // double and kept a position outside the promised range.
        if (pos >= -after && atMost(pos, window, before)) {
            return pos;
        }
        if (!(loop > 0)) {
            // A NaN window or size: unchanged. A point in a window of width 0: the range is 0.
            return loop == 0 ? 0 : pos;
        }
        double wrapped = end - Math.floor(end / loop) * loop;
        // Rounding, in the remainder for far-away positions and in the final float, can land
        // a hair outside [0, loop]; pull it back so the promised range always holds.
        wrapped = Math.min(Math.max(wrapped, 0), loop);
        float result = (float) (wrapped - after);
        // The promised range is [-after, window + before]; rounding the far end's position in
        // double cannot see a step that small next to a big shape, so clamp to it directly.
        double top = (double) window + before;
        float hi = (float) top;
        if (hi > top) {
            hi = Math.nextDown(hi);
        }
        result = Math.min(Math.max(result, -after), hi);
        return result;
    }

    /**
     * Is {@code p <= a + b}, exactly? The sum in double, trusted when p is more than its
     * rounding away from it; within that, compared in {@link java.math.BigDecimal}.
     */
    private static boolean atMost(float p, float a, float b) {
        double s = (double) a + b;
        if (!Double.isFinite(s) || Math.abs(p - s) > 2 * Math.ulp(s)) {
            return p < s || p == s;  // an infinite or NaN sum decides as it is (NaN: false)
        }
        return new java.math.BigDecimal(p).compareTo(new java.math.BigDecimal(a).add(new java.math.BigDecimal(b))) <= 0;
    }

    /**
     * The circle's centre x moved the least so the circle lies inside the window, between the
     * left and right edges (it may touch them). A circle wider than the window cannot fit; it is
     * centred instead, sticking out equally on both sides.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx    the circle's centre x
     * @param r     the circle's radius
     * @param width the window's width
     * @return the centre x, kept in {@code [r, width - r]}
     */
    public static float circleClampX(float cx, float r, float width) {
        return clamp(cx, r, r, width);
    }

    /**
     * The circle's centre y moved the least so the circle lies inside the window, between the
     * top and bottom edges; see {@link #circleClampX}.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cy     the circle's centre y
     * @param r      the circle's radius
     * @param height the window's height
     * @return the centre y, kept in {@code [r, height - r]}
     */
    public static float circleClampY(float cy, float r, float height) {
        return clamp(cy, r, r, height);
    }

    /**
     * The rectangle's left edge moved the least so the rectangle lies inside the window,
     * between the left and right edges (it may touch them). A rectangle wider than the window
     * is centred instead.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x     the rectangle's left edge
     * @param w     the rectangle's width
     * @param width the window's width
     * @return the left edge, kept in {@code [0, width - w]}
     */
    public static float rectClampX(float x, float w, float width) {
        return clamp(x, 0, w, width);
    }

    /**
     * The rectangle's top edge moved the least so the rectangle lies inside the window, between
     * the top and bottom edges; see {@link #rectClampX}.
     *
     * <p>A NaN position answers NaN; a NaN or negative size or window hands the position back
     * unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param y      the rectangle's top edge
     * @param h      the rectangle's height
     * @param height the window's height
     * @return the top edge, kept in {@code [0, height - h]}
     */
    public static float rectClampY(float y, float h, float height) {
        return clamp(y, 0, h, height);
    }

    /**
     * Clamps a position whose shape reaches {@code before} behind and {@code after} ahead of it.
     * The bounds are rounded towards the inside, so the float answer never crosses an edge
     * ({@link #crossed} finds no edge crossed).
     */
    private static float clamp(float pos, float before, float after, float window) {
        if (before < 0 || after < 0 || window < 0) {
            return pos;  // a negative size or window: the position back unchanged, as for NaN
        }
        double lo = before;
        double hi = (double) window - after;
        if (lo > hi) {
            return (float) ((lo + hi) / 2);
        }
        if (pos < lo) {
            return inward((float) lo, lo, true);
        }
        if (pos > hi) {
            return inward((float) hi, hi, false);
        }
        return pos;
    }

    /** {@code f}, the float nearest to {@code exact}, nudged one step inside if it rounded out. */
    private static float inward(float f, double exact, boolean low) {
        if (low && f < exact) {
            return Math.nextUp(f);
        }
        if (!low && f > exact) {
            return Math.nextDown(f);
        }
        return f;
    }
}
