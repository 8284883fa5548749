package hitbox;

import hitbox.internal.*;

import java.util.List;
import java.util.Set;

/**
 * Moving objects: the tutorial's next-position check, one axis at a time, so a sketch knows
 * which speeds to reverse before it moves.
 *
 * <p>Before moving a shape by its speed {@code (vx, vy)}, ask whether it would run into an
 * obstacle: across (the set holds {@link Side#LEFT} and {@link Side#RIGHT}) if the shape moved
 * to {@code (x + vx, y)} would overlap it, down ({@link Side#TOP} and {@link Side#BOTTOM}) if
 * the shape moved to {@code (x, y + vy)} would. The next-position check knows the axis, not
 * which face, so a blocked axis names both its sides. The sketch reverses exactly those speeds:
 * <pre>{@code
 * Set<Side> blocked = Motion.blocked(box, vx, vy, walls);
 * vx = Motion.reverseX(blocked, vx);
 * vy = Motion.reverseY(blocked, vy);
 * box = box.translated(vx, vy);
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
 * that already overlaps the obstacle usually gets both axes every frame and jitters in
 * place; push it out first with {@link Snap#pushOut}. With several obstacles the
 * answer is the union over them, and a reversed speed can carry the mover into another
 * obstacle that lies closer than one frame's move ({@link #bounce} handles that).
 *
 * <p>Obstacles are rectangles in a list (for thousands, ask a {@link BroadPhase} or a
 * {@link World} for the ones near the move); movers are rectangles or
 * circles. The next positions are computed as a sketch does, {@code x + vx} in
 * {@code float}, and tested with {@link Collide#rectRect} and {@link Collide#circleRect}. The
 * answer is an unmodifiable set of sides (see <a href="Side.html#sets">several sides at
 * once</a>), empty when the move is free; asking allocates nothing. A NaN speed blocks
 * nothing (the <a href="package-summary.html#bad-input">NaN rule</a>); a null mover, list or
 * element is refused.
 */
public final class Motion {
    private Motion() {
    }

    /**
     * Which axes of the rectangle's next move would run into any of the obstacles? Both sides
     * of an axis ({@link Side#LEFT} and {@link Side#RIGHT} across, {@link Side#TOP} and
     * {@link Side#BOTTOM} down) when the mover moved along it alone would overlap an
     * obstacle, all four for a diagonal hit on a corner (see the class description).
     *
     * <p>A NaN speed blocks nothing (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover     the moving rectangle, not null
     * @param vx        its horizontal speed, pixels per frame
     * @param vy        its vertical speed, pixels per frame (down is positive)
     * @param obstacles the obstacles, not null, no null element
     * @return the blocked axes' sides, an unmodifiable set, empty if the move is free, never
     *         null
     * @throws IllegalArgumentException if {@code mover}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static Set<Side> blocked(Rect mover, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("mover", mover);
        return SideSets.of(rectBits(mover.x(), mover.y(), mover.w(), mover.h(), vx, vy, obstacles));
    }

    /**
     * Which axes of the circle's next move would run into any of the obstacles? As
     * {@link #blocked(Rect, float, float, List)}, for a ball.
     *
     * <p>A NaN speed blocks nothing (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param mover     the moving circle, not null
     * @param vx        its horizontal speed, pixels per frame
     * @param vy        its vertical speed, pixels per frame (down is positive)
     * @param obstacles the obstacles, not null, no null element
     * @return the blocked axes' sides, an unmodifiable set, empty if the move is free, never
     *         null
     * @throws IllegalArgumentException if {@code mover}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static Set<Side> blocked(Circle mover, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("mover", mover);
        Check.notNull("obstacles", obstacles);
        int blocked = 0;
        for (int i = 0, n = obstacles.size(); i < n && blocked != SideSets.ALL; i++) {
            Rect o = Hits.element(obstacles, i, "obstacles");
            blocked |= NextPosition.circle(mover.x(), mover.y(), mover.r(), vx, vy, o.x(), o.y(), o.w(), o.h());
        }
        return SideSets.of(blocked);
    }

    /** The OR of the next-position check over a list, in SideSets' bits. */
    private static int rectBits(float x, float y, float w, float h, float vx, float vy, List<Rect> obstacles) {
        Check.notNull("obstacles", obstacles);
        int blocked = 0;
        for (int i = 0, n = obstacles.size(); i < n && blocked != SideSets.ALL; i++) {
            Rect o = Hits.element(obstacles, i, "obstacles");
            blocked |= NextPosition.rect(x, y, w, h, vx, vy, o.x(), o.y(), o.w(), o.h());
        }
        return blocked;
    }

    // ---- reading the answer -----------------------------------------------------------

    /**
     * The horizontal speed to use this frame: reversed if the move across is blocked,
     * unchanged otherwise.
     *
     * <p>A NaN speed comes back NaN, unchanged
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param blocked the answer of {@link #blocked}, not null
     * @param vx      the horizontal speed
     * @return {@code -vx} if {@code blocked} holds {@link Side#LEFT} or {@link Side#RIGHT}, else {@code vx}
     * @throws IllegalArgumentException if {@code blocked} is null
     */
    public static float reverseX(Set<Side> blocked, float vx) {
        Check.notNull("blocked", blocked);
        return blocked.contains(Side.LEFT) || blocked.contains(Side.RIGHT) ? -vx : vx;
    }

    /**
     * The vertical speed to use this frame: reversed if the move down is blocked,
     * unchanged otherwise.
     *
     * <p>A NaN speed comes back NaN, unchanged
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param blocked the answer of {@link #blocked}, not null
     * @param vy      the vertical speed
     * @return {@code -vy} if {@code blocked} holds {@link Side#TOP} or {@link Side#BOTTOM}, else {@code vy}
     * @throws IllegalArgumentException if {@code blocked} is null
     */
    public static float reverseY(Set<Side> blocked, float vy) {
        Check.notNull("blocked", blocked);
        return blocked.contains(Side.TOP) || blocked.contains(Side.BOTTOM) ? -vy : vy;
    }

    /**
     * One frame of a box bouncing among many obstacles and the window's edges (the tutorial's
     * section 8 bounces a box off obstacles only), made safe: reverse the speeds
     * {@link #blocked} reports, bounce off the window's edges, then move only along the axes
     * that are still free.
     *
     * <p>Why the last step: with several obstacles, a reversed speed can point straight at a
     * second obstacle less than one move away (a box squeezed between two). Asking again with
     * the new speeds, and waiting a frame on an axis that is still blocked, means the box never
     * ends a frame inside an obstacle it started outside of, nor outside the window it started
     * inside of.
     *
     * <p>A NaN speed blocks nothing and stays NaN; a NaN window size crosses no edge (the
     * <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param box       the box, not null
     * @param vx        its horizontal speed
     * @param vy        its vertical speed
     * @param obstacles the obstacles, not null, no null element
     * @param width     the window's width
     * @param height    the window's height
     * @return where the box is after this frame, its new speeds, and what blocked it, never null
     * @throws IllegalArgumentException if {@code box}, {@code obstacles} or one of its
     *                                  elements is null
     */
    public static Step bounce(Rect box, float vx, float vy, List<Rect> obstacles, float width, float height) {
        Check.notNull("box", box);
        Check.notNull("obstacles", obstacles);
        float x = box.x(), y = box.y(), w = box.w(), h = box.h();
        return bounce(x, y, w, h, vx, vy, width, height, (nvx, nvy) -> rectBits(x, y, w, h, nvx, nvy, obstacles));
    }

    /** Which axes a move with these speeds would block, against whatever obstacles, in SideSets' bits. */
    private interface Blocked {
        int at(float vx, float vy);
    }

    private static Step bounce(float x, float y, float w, float h, float vx, float vy,
                               float width, float height, Blocked obstacles) {
        Set<Side> blocked = SideSets.of(obstacles.at(vx, vy));
        vx = reverseX(blocked, vx);
        vy = reverseY(blocked, vy);
        // The box at its next place against the window, by Edges' one crossing rule; on the
        // floats, so that a NaN speed crosses nothing rather than making a box that is refused.
        float nx0 = x + vx, ny0 = y + vy;
        Set<Side> crossed = SideSets.of(Edges.crossed(nx0, (double) nx0 + w, ny0, (double) ny0 + h, width, height));
        vx = Edges.bounceX(crossed, vx);
        vy = Edges.bounceY(crossed, vy);
        int still = obstacles.at(vx, vy);
        float nx = (still & SideSets.LEFT_RIGHT) != 0 ? x : x + vx;
        float ny = (still & SideSets.TOP_BOTTOM) != 0 ? y : y + vy;
        return new Step(nx, ny, vx, vy, blocked, crossed);
    }

    /**
     * What one {@link #bounce} frame did.
     *
     * @param x       the box's left edge after the frame
     * @param y       the box's top edge after the frame
     * @param vx      its horizontal speed for the next frame
     * @param vy      its vertical speed for the next frame
     * @param blocked the axes the obstacles blocked this frame (as {@link #blocked} says),
     *                unmodifiable, empty if none
     * @param crossed the window edges the box would have crossed, unmodifiable, empty if none
     */
    public record Step(float x, float y, float vx, float vy, Set<Side> blocked, Set<Side> crossed) {

        /**
         * Makes a step, keeping unmodifiable copies of the sets. A plain carrier of
         * {@link #bounce}'s answer: it takes any float, NaN included (the
         * <a href="package-summary.html#bad-input">NaN rule</a>: a NaN speed stays NaN).
         *
         * @param x       the box's left edge after the frame
         * @param y       the box's top edge after the frame
         * @param vx      its horizontal speed for the next frame
         * @param vy      its vertical speed for the next frame
         * @param blocked the axes blocked, not null
         * @param crossed the edges crossed, not null
         * @throws IllegalArgumentException if a set is null or holds null
         */
        public Step {
            blocked = SideSets.of(SideSets.bits(Check.notNull("blocked", blocked)));
            crossed = SideSets.of(SideSets.bits(Check.notNull("crossed", crossed)));
        }

        /** @return true if an obstacle blocked the box this frame */
        public boolean hitObstacle() {
            return !blocked.isEmpty();
        }
    }
}
