package hitbox;

import hitbox.internal.*;

/**
 * The window's edges: which ones a shape has crossed, and the three things a sketch does about
 * it: bounce back, wrap around to the other side, or stay inside.
 *
 * <p>The window runs from 0 to {@code width} across and from 0 to {@code height} down
 * (Processing's {@code width} and {@code height}). Every method is static, takes plain
 * {@code float}s, allocates nothing and checks nothing, so it is safe to call every frame:
 * <pre>{@code
 * x += vx;
 * y += vy;
 * int crossed = Edges.circleCrossed(x, y, r, width, height);
 * vx = Edges.bounceX(crossed, vx);
 * vy = Edges.bounceY(crossed, vy);
 * }</pre>
 *
 * <p>Crossing follows the <a href="package-summary.html#touching">touching rule</a>: a shape
 * that only touches an edge (a ball of radius 10 at {@code x = 10}) has not crossed it; one
 * that reaches past it, even by a little, has. The answer is a set of sides in
 * {@link Side}'s <a href="Side.html#bits">bit scheme</a> ({@code Side.LEFT.bit()} and so on),
 * or {@link #NONE}: test one with {@code Side.has(crossed, Side.LEFT)}, print them with
 * {@link Side#describe(int)}, and get an {@code EnumSet} with {@link Side#setOf}. (This
 * class's own {@code LEFT}..{@code BOTTOM}, {@code has} and {@code describe} are deprecated
 * aliases of {@code Side}'s, kept one release.)
 * A shape bigger than the window crosses both opposite edges at once.
 *
 * <p>Circles are centre and radius, rectangles top-left corner and size, as everywhere in
 * Hitbox; for a point use {@link #pointCrossed}, or a circle of radius 0 with the others.
 * Nothing is checked and nothing throws (the <a href="package-summary.html#bad-input">NaN
 * rule</a>): with a NaN argument the crossing tests answer {@link #NONE}, the bounce methods
 * hand the speed back unchanged, and the wrap and clamp methods answer NaN (a NaN position)
 * or hand the position back unchanged (a NaN size or window). A negative size or window
 * counts as NaN does: no crossing, the position unchanged.
 *
 * <p>This class is longer than most (about 470 lines) for one release only: beside the
 * crossing, bounce, wrap and clamp methods it carries the deprecated aliases of
 * {@link Side}'s bits, each with the javadoc that says what to call instead.
 */
public final class Edges {
    private Edges() {
    }

    /** No edge crossed: the shape is inside the window (touching an edge is inside). */
    public static final int NONE = 0;
    /**
     * The left edge, {@code x = 0}: {@code Side.LEFT.bit()}, 1.
     *
     * @deprecated an alias of {@link Side#LEFT}'s bit, kept one release: test a crossing with
     *             {@code Side.has(crossed, Side.LEFT)}, build one with {@code Side.LEFT.bit()}.
     */
    @Deprecated
    public static final int LEFT = 1;
    /**
     * The right edge, {@code x = width}: {@code Side.RIGHT.bit()}, 2.
     *
     * @deprecated an alias of {@link Side#RIGHT}'s bit, kept one release: use
     *             {@code Side.has(crossed, Side.RIGHT)} or {@code Side.RIGHT.bit()}.
     */
    @Deprecated
    public static final int RIGHT = 2;
    /**
     * The top edge, {@code y = 0}: {@code Side.TOP.bit()}, 4.
     *
     * @deprecated an alias of {@link Side#TOP}'s bit, kept one release: use
     *             {@code Side.has(crossed, Side.TOP)} or {@code Side.TOP.bit()}.
     */
    @Deprecated
    public static final int TOP = 4;
    /**
     * The bottom edge, {@code y = height}: {@code Side.BOTTOM.bit()}, 8.
     *
     * @deprecated an alias of {@link Side#BOTTOM}'s bit, kept one release: use
     *             {@code Side.has(crossed, Side.BOTTOM)} or {@code Side.BOTTOM.bit()}.
     */
    @Deprecated
    public static final int BOTTOM = 8;

    /**
     * Has the point gone past a window edge? A point exactly on an edge has not.
     *
     * <p>A NaN in any argument answers {@link #NONE}, and so does a negative size or window
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param px     the point's x
     * @param py     the point's y
     * @param width  the window's width
     * @param height the window's height
     * @return the crossed edges, a combination of {@link #LEFT}, {@link #RIGHT}, {@link #TOP}
     *         and {@link #BOTTOM}, or {@link #NONE}
     */
    public static int pointCrossed(float px, float py, float width, float height) {
        return crossed(px, px, py, py, width, height);
    }

    /**
     * Which window edges has the circle crossed? The tutorial's bouncing ball
     * tests its centre, {@code x < 0 || x > width}; Hitbox tests the circle's edge,
     * {@code x < r || x > width - r}, for each edge, so the ball turns before it is half out; a circle touching an edge has not crossed
     * it.
     *
     * <p>A NaN in any argument answers {@link #NONE}, and so does a negative size or window
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx     the circle's centre x
     * @param cy     the circle's centre y
     * @param r      the circle's radius (not its diameter)
     * @param width  the window's width
     * @param height the window's height
     * @return the crossed edges, a combination of {@link #LEFT}, {@link #RIGHT}, {@link #TOP}
     *         and {@link #BOTTOM}, or {@link #NONE}
     */
    public static int circleCrossed(float cx, float cy, float r, float width, float height) {
        return crossed((double) cx - r, (double) cx + r, (double) cy - r, (double) cy + r, width, height);
    }

    /**
     * Which window edges has the rectangle crossed? A rectangle touching an edge has not
     * crossed it.
     *
     * <p>A NaN in any argument answers {@link #NONE}, and so does a negative size or window
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x      the rectangle's left edge
     * @param y      the rectangle's top edge
     * @param w      the rectangle's width
     * @param h      the rectangle's height
     * @param width  the window's width
     * @param height the window's height
     * @return the crossed edges, a combination of {@link #LEFT}, {@link #RIGHT}, {@link #TOP}
     *         and {@link #BOTTOM}, or {@link #NONE}
     */
    public static int rectCrossed(float x, float y, float w, float h, float width, float height) {
        return crossed(x, (double) x + w, y, (double) y + h, width, height);
    }

    /**
     * Which window edges has the shape crossed? Every shape is tested by how far it reaches,
     * in double, as {@link #circleCrossed} tests a circle: exactly as far as the shape (a
     * polygon by its {@link Shape#bounds() bounds}, a turned ellipse a hair farther).
     *
     * <p>A NaN or negative window size answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>); a shape never holds NaN.
     *
     * @param shape  the shape, not null
     * @param width  the window's width
     * @param height the window's height
     * @return the crossed edges, a combination of {@link #LEFT}, {@link #RIGHT}, {@link #TOP}
     *         and {@link #BOTTOM}, or {@link #NONE}
     * @throws IllegalArgumentException if {@code shape} is null
     */
    public static int crossed(Shape shape, float width, float height) {
        Check.notNull("shape", shape);
        return crossed(shape.minX(), shape.maxX(), shape.minY(), shape.maxY(), width, height);
    }

    /**
     * The one crossing rule: strictly beyond an edge, in double so touching is exact. A NaN
     * anywhere crosses nothing.
     */
    private static int crossed(double left, double right, double top, double bottom, float width, float height) {
        if (Double.isNaN(left) || Double.isNaN(right) || Double.isNaN(top) || Double.isNaN(bottom)
                || Float.isNaN(width) || Float.isNaN(height)) {
            return NONE;
        }
        // A negative size or window is no shape and no window: no answer, as for NaN (the
        // package's bad-input rule). The sums are exact in double, so left > right only for
        // a negative size.
        if (left > right || top > bottom || width < 0 || height < 0) {
            return NONE;
        }
        int edges = NONE;
        if (left < 0) {
            edges |= LEFT;
        }
        if (right > width) {
            edges |= RIGHT;
        }
        if (top < 0) {
            edges |= TOP;
        }
        if (bottom > height) {
            edges |= BOTTOM;
        }
        return edges;
    }

    /**
     * Is this edge among the crossed ones? Reads better than {@code (crossed & edge) != 0}.
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param crossed the edges from one of the crossing tests
     * @param edge    the edge to ask about: {@link #LEFT}, {@link #RIGHT}, {@link #TOP} or
     *                {@link #BOTTOM}
     * @return true if {@code crossed} includes {@code edge}
     * @deprecated kept one release; the same answer as {@link Side#hasAny(int, int)} for
     *             the edges' bits (for one side, {@link Side#has(int, Side)} reads better:
     *             {@code Side.has(crossed, Side.LEFT)}).
     */
    @Deprecated
    public static boolean has(int crossed, int edge) {
        return (crossed & edge) != 0;
    }

    /**
     * The crossed edges as words, for printing: {@code "LEFT|TOP"}, or {@code "NONE"}.
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param crossed the edges from one of the crossing tests
     * @return the names of the edges in {@code crossed}, joined by {@code |}, never null
     * @deprecated kept one release; returns exactly what {@link Side#describe(int)} returns.
     */
    @Deprecated
    public static String describe(int crossed) {
        return Side.describe(crossed);
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
     * @param crossed the edges from one of the crossing tests
     * @param vx      the horizontal speed
     * @return {@code |vx|} if only {@link #LEFT} was crossed, {@code -|vx|} if only
     *         {@link #RIGHT} was, {@code vx} otherwise
     */
    public static float bounceX(int crossed, float vx) {
        return bounce(crossed & (LEFT | RIGHT), LEFT, RIGHT, vx);
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
     * @param crossed the edges from one of the crossing tests
     * @param vy      the vertical speed (down is positive)
     * @return {@code |vy|} if only {@link #TOP} was crossed, {@code -|vy|} if only
     *         {@link #BOTTOM} was, {@code vy} otherwise
     */
    public static float bounceY(int crossed, float vy) {
        return bounce(crossed & (TOP | BOTTOM), TOP, BOTTOM, vy);
    }

    /** Points v away from the one crossed edge of a pair (low edge: positive; high: negative). */
    private static float bounce(int pair, int low, int high, float v) {
        if (pair == low) {
            return Math.abs(v);
        }
        if (pair == high) {
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
     * (the crossing tests say {@link #NONE} for it).
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
