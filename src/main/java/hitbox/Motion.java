package hitbox;

import hitbox.internal.*;

import java.util.List;

/**
 * Moving objects: the tutorial's next-position check, one axis at a time, so a sketch knows
 * which speeds to reverse before it moves.
 *
 * <p>Before moving a shape by its speed {@code (vx, vy)}, ask whether it would run into an
 * obstacle: across ({@link Side#LEFT_RIGHT}) if the shape moved to {@code (x + vx, y)} would
 * overlap it, down ({@link Side#TOP_BOTTOM}) if the shape moved to {@code (x, y + vy)} would.
 * The answer is a set of {@link Side} bits, so the sketch reverses exactly those speeds:
 * <pre>{@code
 * int blocked = Motion.rectBlocked(x, y, w, h, vx, vy, walls);
 * vx = Motion.reverseX(blocked, vx);
 * vy = Motion.reverseY(blocked, vy);
 * x += vx;
 * y += vy;
 * }</pre>
 *
 * <p><b>The corner case.</b> Heading straight at an obstacle's corner, the mover can miss it
 * on each axis alone and still hit it moving diagonally. The tutorial's two tests would both
 * say "free" and let it sink into the corner. Here, when neither axis alone is blocked but
 * the whole move is, <em>both</em> axes are reported: reversing both sends the mover back
 * the way it came, like a ball bouncing straight back off a corner.
 *
 * <p><b>What this guarantees.</b> For one obstacle, a mover that starts outside it and
 * reverses the reported speeds every frame never ends a frame overlapping it (touching is
 * allowed, by the <a href="package-summary.html#touching">touching rule</a>). It is a check of
 * the next position, not of the path: a mover faster than an obstacle is thick can jump over
 * it in one frame (use a swept test for bullets). It assumes the mover starts outside: one
 * that already overlaps the obstacle usually gets both axes ({@link Side#ALL_BITS}) every frame and jitters in
 * place; push it out first with {@link Snap#pushOut(Rect, Rect)}. With several obstacles the
 * answer is the OR over them, and a reversed speed can carry the mover into another obstacle
 * that lies closer than one frame's move.
 *
 * <p>Obstacles are rectangles; movers are rectangles or circles. The next positions are
 * computed as a sketch does, {@code x + vx} in {@code float}, and tested with
 * {@link Collide#rectRect} and {@link Collide#circleRect}. The raw-float methods allocate
 * nothing, check nothing and never throw: a NaN in any argument gives {@link #NONE} (the
 * <a href="package-summary.html#bad-input">NaN rule</a>); the array and list overloads check
 * that the obstacles are there.
 *
 * <p>The answer is an {@code int} in {@link Side}'s <a href="Side.html#bits">bit scheme</a>:
 * a blocked axis sets the bits of both its sides ({@link Side#LEFT_RIGHT} across,
 * {@link Side#TOP_BOTTOM} down), since the next-position check knows the axis, not which face;
 * {@code Side.hasAny(blocked, Side.LEFT_RIGHT)} (or {@code Side.has(blocked, Side.LEFT)}) reads
 * it, {@link #reverseX} and {@link #reverseY} act on it, and {@link Side#describe(int)} prints
 * it. This class's own {@code X}, {@code Y}, {@code BOTH}, {@code has} and {@code describe} are
 * deprecated aliases of {@code Side}'s, kept one release; {@link #NONE} stays.
 *
 * <p>Which form to call: the mover as raw floats (the tutorial's {@code x, y, w, h} and
 * {@code vx, vy}) or as a shape, against one obstacle's raw floats, a list or an array of
 * {@code Rect}s, or a {@link BroadPhase}. The forms taking one {@code Rect} obstacle are
 * deprecated (kept one release).
 *
 * <p>This class is longer than most (about 590 lines) because it is the public face of
 * "which axes are blocked" for a box and a ball, against one obstacle, an array, a list and a
 * broad phase, on raw floats and on shapes, each overload with its full javadoc; the code
 * behind them is two small tests and one bounce step (the broad-phase work is in
 * {@code BroadPhaseHits}).
 */
public final class Motion {
    private Motion() {
    }

    /** Neither axis is blocked: move freely. 0. */
    public static final int NONE = 0;
    /**
     * The horizontal move is blocked: reverse (or stop) {@code vx}. In {@link Side}'s
     * <a href="Side.html#bits">bit scheme</a> it is the two walls, {@code LEFT | RIGHT}: 3.
     *
     * @deprecated an alias of {@link Side#LEFT_RIGHT}, kept one release: test it with
     *             {@code Side.hasAny(blocked, Side.LEFT_RIGHT)}, or let {@link #reverseX} read it.
     */
    @Deprecated
    public static final int X = Side.LEFT_RIGHT;
    /**
     * The vertical move is blocked: reverse (or stop) {@code vy}. In {@link Side}'s bit
     * scheme, {@code TOP | BOTTOM}: 12.
     *
     * @deprecated an alias of {@link Side#TOP_BOTTOM}, kept one release: test it with
     *             {@code Side.hasAny(blocked, Side.TOP_BOTTOM)}, or let {@link #reverseY} read it.
     */
    @Deprecated
    public static final int Y = Side.TOP_BOTTOM;
    /**
     * Both axes are blocked, {@code X | Y}: reverse both speeds. 15.
     *
     * @deprecated an alias of {@link Side#ALL_BITS}, kept one release.
     */
    @Deprecated
    public static final int BOTH = Side.ALL_BITS;

    // ---- rectangle mover --------------------------------------------------------------

    /**
     * Which axes of a moving rectangle's next move would run into the obstacle?
     * {@link Side#LEFT_RIGHT} if the rectangle at {@code (x + vx, y)} would overlap it,
     * {@link Side#TOP_BOTTOM} if the rectangle at {@code (x, y + vy)} would, and both
     * ({@link Side#ALL_BITS}) for a diagonal hit on a corner (see the
     * class description).
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x  the mover's left edge
     * @param y  the mover's top edge
     * @param w  the mover's width
     * @param h  the mover's height
     * @param vx the mover's horizontal speed, pixels per frame
     * @param vy the mover's vertical speed, pixels per frame (down is positive)
     * @param ox the obstacle's left edge
     * @param oy the obstacle's top edge
     * @param ow the obstacle's width
     * @param oh the obstacle's height
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     */
    public static int rectBlocked(float x, float y, float w, float h, float vx, float vy,
                                  float ox, float oy, float ow, float oh) {
        if (Check.nan(x, y, w, h, vx) || Check.nan(vy, ox, oy, ow, oh)) {
            return NONE;
        }
        float nx = x + vx;
        float ny = y + vy;
        int blocked = (Collide.rectRect(nx, y, w, h, ox, oy, ow, oh) ? X : NONE)
                | (Collide.rectRect(x, ny, w, h, ox, oy, ow, oh) ? Y : NONE);
        if (blocked == NONE && Collide.rectRect(nx, ny, w, h, ox, oy, ow, oh)) {
            return BOTH;
        }
        return blocked;
    }

    /**
     * Which axes of a moving rectangle's next move would run into the obstacle? See
     * {@link #rectBlocked(float, float, float, float, float, float, float, float, float, float)}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x        the mover's left edge
     * @param y        the mover's top edge
     * @param w        the mover's width
     * @param h        the mover's height
     * @param vx       the mover's horizontal speed
     * @param vy       the mover's vertical speed
     * @param obstacle the obstacle, not null
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacle} is null
     * @deprecated kept one release: one {@code Rect} obstacle is a fourth form of the same
     *             question; call {@link #rectBlocked(float, float, float, float, float, float, float, float, float, float)} with
     *             the obstacle's {@code x(), y(), w(), h()}, or the {@code List} form.
     */
    @Deprecated
    public static int rectBlocked(float x, float y, float w, float h, float vx, float vy, Rect obstacle) {
        Check.notNull("obstacle", obstacle);
        return rectBlocked(x, y, w, h, vx, vy, obstacle.x(), obstacle.y(), obstacle.w(), obstacle.h());
    }

    /**
     * Which axes of a moving rectangle's next move would run into any of the obstacles: the
     * OR of the answers for each one.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the mover's left edge
     * @param y         the mover's top edge
     * @param w         the mover's width
     * @param h         the mover's height
     * @param vx        the mover's horizontal speed
     * @param vy        the mover's vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacles} or one of its elements is null
     */
    public static int rectBlocked(float x, float y, float w, float h, float vx, float vy, Rect[] obstacles) {
        return rectBlocked(x, y, w, h, vx, vy, Hits.view("obstacles", obstacles));
    }

    /**
     * Which axes of a moving rectangle's next move would run into any of the obstacles: the
     * OR of the answers for each one.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the mover's left edge
     * @param y         the mover's top edge
     * @param w         the mover's width
     * @param h         the mover's height
     * @param vx        the mover's horizontal speed
     * @param vy        the mover's vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacles} or one of its elements is null
     */
    public static int rectBlocked(float x, float y, float w, float h, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("obstacles", obstacles);
        int blocked = NONE;
        for (int i = 0, n = obstacles.size(); i < n && blocked != BOTH; i++) {
            Rect o = Hits.element(obstacles, i, "obstacles");
            blocked |= rectBlocked(x, y, w, h, vx, vy, o.x(), o.y(), o.w(), o.h());
        }
        return blocked;
    }

    // ---- circle mover -----------------------------------------------------------------

    /**
     * Which axes of a moving circle's next move would run into the rectangular obstacle?
     * {@link Side#LEFT_RIGHT} if the circle centred at {@code (cx + vx, cy)} would overlap it,
     * {@link Side#TOP_BOTTOM} if the circle centred at {@code (cx, cy + vy)} would, and both
     * ({@link Side#ALL_BITS}) for a diagonal hit
     * (see the class description).
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx the mover's centre x
     * @param cy the mover's centre y
     * @param r  the mover's radius
     * @param vx the mover's horizontal speed, pixels per frame
     * @param vy the mover's vertical speed, pixels per frame (down is positive)
     * @param ox the obstacle's left edge
     * @param oy the obstacle's top edge
     * @param ow the obstacle's width
     * @param oh the obstacle's height
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     */
    public static int circleBlocked(float cx, float cy, float r, float vx, float vy,
                                    float ox, float oy, float ow, float oh) {
        if (Check.nan(cx, cy, r, vx, vy) || Check.nan(ox, oy, ow, oh, 0)) {
            return NONE;
        }
        float nx = cx + vx;
        float ny = cy + vy;
        int blocked = (Collide.circleRect(nx, cy, r, ox, oy, ow, oh) ? X : NONE)
                | (Collide.circleRect(cx, ny, r, ox, oy, ow, oh) ? Y : NONE);
        if (blocked == NONE && Collide.circleRect(nx, ny, r, ox, oy, ow, oh)) {
            return BOTH;
        }
        return blocked;
    }

    /**
     * Which axes of a moving circle's next move would run into the obstacle? See
     * {@link #circleBlocked(float, float, float, float, float, float, float, float, float)}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx       the mover's centre x
     * @param cy       the mover's centre y
     * @param r        the mover's radius
     * @param vx       the mover's horizontal speed
     * @param vy       the mover's vertical speed
     * @param obstacle the obstacle, not null
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacle} is null
     * @deprecated kept one release: one {@code Rect} obstacle is a fourth form of the same
     *             question; call {@link #circleBlocked(float, float, float, float, float, float, float, float, float)} with
     *             the obstacle's {@code x(), y(), w(), h()}, or the {@code List} form.
     */
    @Deprecated
    public static int circleBlocked(float cx, float cy, float r, float vx, float vy, Rect obstacle) {
        Check.notNull("obstacle", obstacle);
        return circleBlocked(cx, cy, r, vx, vy, obstacle.x(), obstacle.y(), obstacle.w(), obstacle.h());
    }

    /**
     * Which axes of a moving circle's next move would run into any of the obstacles: the OR
     * of the answers for each one.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx        the mover's centre x
     * @param cy        the mover's centre y
     * @param r         the mover's radius
     * @param vx        the mover's horizontal speed
     * @param vy        the mover's vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacles} or one of its elements is null
     */
    public static int circleBlocked(float cx, float cy, float r, float vx, float vy, Rect[] obstacles) {
        return circleBlocked(cx, cy, r, vx, vy, Hits.view("obstacles", obstacles));
    }

    /**
     * Which axes of a moving circle's next move would run into any of the obstacles: the OR
     * of the answers for each one.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cx        the mover's centre x
     * @param cy        the mover's centre y
     * @param r         the mover's radius
     * @param vx        the mover's horizontal speed
     * @param vy        the mover's vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacles} or one of its elements is null
     */
    public static int circleBlocked(float cx, float cy, float r, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("obstacles", obstacles);
        int blocked = NONE;
        for (int i = 0, n = obstacles.size(); i < n && blocked != BOTH; i++) {
            Rect o = Hits.element(obstacles, i, "obstacles");
            blocked |= circleBlocked(cx, cy, r, vx, vy, o.x(), o.y(), o.w(), o.h());
        }
        return blocked;
    }

    // ---- shape movers -----------------------------------------------------------------

    /**
     * Which axes of the rectangle's next move would run into the obstacle? Same as
     * {@link #rectBlocked(float, float, float, float, float, float, Rect)}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover    the moving rectangle, not null
     * @param vx       its horizontal speed
     * @param vy       its vertical speed
     * @param obstacle the obstacle, not null
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code mover} or {@code obstacle} is null
     * @deprecated kept one release: one {@code Rect} obstacle is a fourth form of the same
     *             question; call {@link #blocked(Rect, float, float, List)} with {@code List.of(obstacle)}, or
     *             {@link #rectBlocked(float, float, float, float, float, float, float, float, float, float)}.
     */
    @Deprecated
    public static int blocked(Rect mover, float vx, float vy, Rect obstacle) {
        Check.notNull("mover", mover);
        return rectBlocked(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy, obstacle);
    }

    /**
     * Which axes of the rectangle's next move would run into any of the obstacles? Same as
     * {@link #rectBlocked(float, float, float, float, float, float, Rect[])}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover     the moving rectangle, not null
     * @param vx        its horizontal speed
     * @param vy        its vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code mover}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static int blocked(Rect mover, float vx, float vy, Rect[] obstacles) {
        Check.notNull("mover", mover);
        return rectBlocked(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy, obstacles);
    }

    /**
     * Which axes of the rectangle's next move would run into any of the obstacles? Same as
     * {@link #rectBlocked(float, float, float, float, float, float, List)}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover     the moving rectangle, not null
     * @param vx        its horizontal speed
     * @param vy        its vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code mover}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static int blocked(Rect mover, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("mover", mover);
        return rectBlocked(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy, obstacles);
    }

    /**
     * Which axes of the circle's next move would run into the obstacle? Same as
     * {@link #circleBlocked(float, float, float, float, float, Rect)}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover    the moving circle, not null
     * @param vx       its horizontal speed
     * @param vy       its vertical speed
     * @param obstacle the obstacle, not null
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code mover} or {@code obstacle} is null
     * @deprecated kept one release: one {@code Rect} obstacle is a fourth form of the same
     *             question; call {@link #blocked(Circle, float, float, List)} with {@code List.of(obstacle)}, or
     *             {@link #circleBlocked(float, float, float, float, float, float, float, float, float)}.
     */
    @Deprecated
    public static int blocked(Circle mover, float vx, float vy, Rect obstacle) {
        Check.notNull("mover", mover);
        return circleBlocked(mover.x(), mover.y(), mover.r(), vx, vy, obstacle);
    }

    /**
     * Which axes of the circle's next move would run into any of the obstacles? Same as
     * {@link #circleBlocked(float, float, float, float, float, Rect[])}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover     the moving circle, not null
     * @param vx        its horizontal speed
     * @param vy        its vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code mover}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static int blocked(Circle mover, float vx, float vy, Rect[] obstacles) {
        Check.notNull("mover", mover);
        return circleBlocked(mover.x(), mover.y(), mover.r(), vx, vy, obstacles);
    }

    /**
     * Which axes of the circle's next move would run into any of the obstacles? Same as
     * {@link #circleBlocked(float, float, float, float, float, List)}.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover     the moving circle, not null
     * @param vx        its horizontal speed
     * @param vy        its vertical speed
     * @param obstacles the obstacles, not null and with no null element
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code mover}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static int blocked(Circle mover, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("mover", mover);
        return circleBlocked(mover.x(), mover.y(), mover.r(), vx, vy, obstacles);
    }

    // ---- reading the answer -----------------------------------------------------------

    /**
     * Is this axis among the blocked ones? Reads better than {@code (blocked & axis) != 0}.
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param blocked the axes from one of the checks
     * @param axis    {@link #X} or {@link #Y}
     * @return true if {@code blocked} includes {@code axis}
     * @deprecated kept one release; the same answer as {@link Side#hasAny(int, int)}:
     *             {@code Side.hasAny(blocked, Side.LEFT_RIGHT)} for the move across.
     */
    @Deprecated
    public static boolean has(int blocked, int axis) {
        return (blocked & axis) != 0;
    }

    /**
     * The horizontal speed to use this frame: reversed if the move across is blocked,
     * unchanged otherwise.
     *
     * <p>A NaN speed comes back NaN, unchanged
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param blocked the axes from one of the checks
     * @param vx      the horizontal speed
     * @return {@code -vx} if {@code blocked} has a bit of {@link Side#LEFT_RIGHT}, else {@code vx}
     */
    public static float reverseX(int blocked, float vx) {
        return has(blocked, X) ? -vx : vx;
    }

    /**
     * The vertical speed to use this frame: reversed if the move down is blocked,
     * unchanged otherwise.
     *
     * <p>A NaN speed comes back NaN, unchanged
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param blocked the axes from one of the checks
     * @param vy      the vertical speed
     * @return {@code -vy} if {@code blocked} has a bit of {@link Side#TOP_BOTTOM}, else {@code vy}
     */
    public static float reverseY(int blocked, float vy) {
        return has(blocked, Y) ? -vy : vy;
    }

    /**
     * The blocked axes as words, for printing: {@code "NONE"}, {@code "X"}, {@code "Y"} or
     * {@code "BOTH"}. An axis counts as blocked when either of its bits is set, so 3 and 1
     * both print {@code "X"}.
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param blocked the axes from one of the checks
     * @return the name of the answer, never null
     * @deprecated kept one release, still answering {@code "NONE"}, {@code "X"}, {@code "Y"}
     *             or {@code "BOTH"} as before. Hitbox prints every bit set one way,
     *             {@link Side#describe(int)}, which names the sides: {@code "LEFT|RIGHT"} for
     *             a move blocked across, {@code "TOP|BOTTOM"} down, {@code "LEFT|RIGHT|TOP|BOTTOM"}
     *             both.
     */
    @Deprecated
    public static String describe(int blocked) {
        boolean x = has(blocked, X);
        boolean y = has(blocked, Y);
        return x && y ? "BOTH" : x ? "X" : y ? "Y" : "NONE";
    }

    /**
     * One frame of a box bouncing among many obstacles and the window's edges (the tutorial's
     * section 8 bounces a box off obstacles only), made safe: reverse the
     * speeds {@link #rectBlocked} reports, bounce off the window's edges, then move only along
     * the axes that are still free.
     *
     * <p>Why the last step: with several obstacles, a reversed speed can point straight at a
     * second obstacle less than one move away (a box squeezed between two). Asking again with
     * the new speeds, and waiting a frame on an axis that is still blocked, means the box never
     * ends a frame inside an obstacle it started outside of, nor outside the window it started
     * inside of.
     *
     * <p>A NaN in the box or its speed blocks nothing, so {@code blocked} is {@link #NONE}, and a
     * NaN position or speed stays NaN; a NaN window size crosses no edge, so {@code crossed} is
     * {@link #NONE} (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the box's left edge
     * @param y         the box's top edge
     * @param w         the box's width
     * @param h         the box's height
     * @param vx        its speed across, pixels per frame
     * @param vy        its speed down, pixels per frame
     * @param obstacles the obstacles, none of them null
     * @param width     the window's width
     * @param height    the window's height
     * @return where the box is after this frame, its new speeds, and what blocked it, never null
     * @throws IllegalArgumentException if {@code obstacles} or one of its elements is null
     */
    public static Step bounce(float x, float y, float w, float h, float vx, float vy,
                              List<Rect> obstacles, float width, float height) {
        Check.notNull("obstacles", obstacles);
        return bounce(x, y, w, h, vx, vy, width, height, (nvx, nvy) -> rectBlocked(x, y, w, h, nvx, nvy, obstacles));
    }

    /**
     * Which axes of a moving rectangle's next move would run into any box of the broad phase:
     * the same answer as {@link #rectBlocked(float, float, float, float, float, float, List)}
     * over the same boxes, asking only the ones near the move.
     *
     * <p>A NaN in any argument answers {@link #NONE}
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the mover's left edge
     * @param y         the mover's top edge
     * @param w         the mover's width
     * @param h         the mover's height
     * @param vx        the mover's horizontal speed
     * @param vy        the mover's vertical speed
     * @param obstacles the obstacles, each stored under its id, not null
     * @return the blocked axes: {@link #NONE}, {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM} or {@link Side#ALL_BITS}
     * @throws IllegalArgumentException if {@code obstacles} is null
     */
    public static int rectBlocked(float x, float y, float w, float h, float vx, float vy, BroadPhase obstacles) {
        return BroadPhaseHits.rectBlocked(x, y, w, h, vx, vy, obstacles);
    }

    /**
     * {@link #bounce(float, float, float, float, float, float, List, float, float)} among the
     * boxes of a broad phase: the same step, so a sketch with thousands of obstacles changes
     * one argument.
     *
     * <p>A NaN in the box or its speed blocks nothing, so {@code blocked} is {@link #NONE}, and a
     * NaN position or speed stays NaN; a NaN window size crosses no edge, so {@code crossed} is
     * {@link #NONE} (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the box's left edge
     * @param y         the box's top edge
     * @param w         the box's width
     * @param h         the box's height
     * @param vx        its speed across, pixels per frame
     * @param vy        its speed down, pixels per frame
     * @param obstacles the obstacles, each stored under its id, not null
     * @param width     the window's width
     * @param height    the window's height
     * @return where the box is after this frame, its new speeds, and what blocked it, never null
     * @throws IllegalArgumentException if {@code obstacles} is null
     */
    public static Step bounce(float x, float y, float w, float h, float vx, float vy,
                              BroadPhase obstacles, float width, float height) {
        Check.notNull("obstacles", obstacles);
        return bounce(x, y, w, h, vx, vy, width, height, (nvx, nvy) -> rectBlocked(x, y, w, h, nvx, nvy, obstacles));
    }

    /** Which axes a move with these speeds would block, against whatever obstacles. */
    private interface Blocked {
        int at(float vx, float vy);
    }

    private static Step bounce(float x, float y, float w, float h, float vx, float vy,
                               float width, float height, Blocked obstacles) {
        int blocked = obstacles.at(vx, vy);
        vx = reverseX(blocked, vx);
        vy = reverseY(blocked, vy);
        int crossed = Edges.rectCrossed(x + vx, y + vy, w, h, width, height);
        vx = Edges.bounceX(crossed, vx);
        vy = Edges.bounceY(crossed, vy);
        int still = obstacles.at(vx, vy);
        float nx = has(still, X) ? x : x + vx;
        float ny = has(still, Y) ? y : y + vy;
        return new Step(nx, ny, vx, vy, blocked, crossed);
    }

    /**
     * What one {@link #bounce} frame did. A plain carrier of the answer: it takes any value,
     * NaN included, since {@code bounce} works on plain floats and never throws.
     *
     * @param x       the box's new left edge
     * @param y       the box's new top edge
     * @param vx      its new speed across
     * @param vy      its new speed down
     * @param blocked the axes an obstacle blocked before the move (in {@link Side}'s bit scheme:
     *                {@link Side#LEFT_RIGHT}, {@link Side#TOP_BOTTOM}, both, or {@link #NONE}): non-zero means it hit an obstacle
     * @param crossed the window edges the move would have crossed ({@link Edges} flags, in
     *                {@link Side}'s bit scheme)
     */
    public record Step(float x, float y, float vx, float vy, int blocked, int crossed) {

        /** @return true if an obstacle blocked the box this frame */
        public boolean hitObstacle() {
            return blocked != NONE;
        }
    }
}
