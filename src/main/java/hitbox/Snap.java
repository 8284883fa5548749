package hitbox;

import hitbox.internal.*;

/**
 * Snapping to an edge: after a move has put a rectangle into the ground or into an obstacle,
 * move it back out so that it just touches, and say which side it hit.
 *
 * <p>The ground line, for a player that falls onto a floor at {@code groundY}:
 * <pre>{@code
 * vy += gravity;
 * y += vy;
 * if (Snap.onGround(y, h, groundY)) {
 *   y = Snap.standY(h, groundY);   // bottom exactly on the ground
 *   vy = 0;
 *   canJump = true;
 * }
 * }</pre>
 *
 * <p>Any rectangular obstacle, for a platformer: {@link #pushOut} moves the mover out along
 * the axis where it is in the least, and reports the {@link Side} of the obstacle it was
 * pushed to: {@link Side#TOP} means it landed (it may jump again), {@link Side#BOTTOM} that it
 * bumped its head, {@link Side#LEFT} or {@link Side#RIGHT} that it walked into a wall.
 * <pre>{@code
 * Snap.Push p = Snap.pushOut(x, y, w, h, ox, oy, ow, oh);
 * x = p.x();
 * y = p.y();
 * vx = p.vxAfter(vx);
 * vy = p.vyAfter(vy);
 * if (p.landed()) canJump = true;
 * }</pre>
 * Least overlap guesses the side from where the mover <em>is</em>; a fast mover that sank
 * more than halfway into a thin platform in one frame is pushed out through the wrong side.
 * {@link #pushBack} uses the mover's speed to find the side it came <em>from</em>.
 *
 * <p>After a push the two rectangles touch and do not overlap: {@link Collide#rectRect} says
 * false for them, and for whole-number coordinates the edges meet exactly. When the exact
 * touching position is not a float, the mover is placed within one float step of it, on the
 * side where {@code Collide.rectRect} says they do not overlap. Every method here takes plain
 * floats, as the tutorial's code keeps its rectangles (a {@link Rect}'s {@code x(), y(), w(),
 * h()} go in as they are, and {@link Push#applyTo} puts the answer back into one); they check
 * nothing and never throw (the <a href="package-summary.html#bad-input">NaN
 * rule</a>): a NaN or infinite value gives no push, {@link Side#NONE} and the position
 * unchanged. The answer for a push is a small immutable {@link Push}; it is never null,
 * because it always carries a position ({@link Side#NONE} and the mover's own when there was
 * nothing to push out of).
 */
public final class Snap {
    private Snap() {
    }

    // ---- the ground line --------------------------------------------------------------

    /**
     * The top edge that stands a rectangle of height {@code h} on the ground line: its bottom
     * exactly on {@code groundY} (y grows down, so the ground is below the rectangle).
     *
     * <p>That is {@code groundY - h}, exact for whole numbers; when the difference is not a
     * float, the float just above it (a smaller y), so the rectangle never sinks into the
     * ground.
     *
     * <p>A NaN in any argument answers NaN, and so does a negative height
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param h       the rectangle's height
     * @param groundY the ground line's y
     * @return {@code groundY - h}, or the float just above it: {@code y + h} never passes
     *         {@code groundY}
     */
    public static float standY(float h, float groundY) {
        if (h < 0) {
            // A negative height is no rectangle: no answer, as for NaN (the bad-input rule);
            // onGround and landY, which ask this, then say false and hand y back.
            return Float.NaN;
        }
        return RectPush.touchBefore(groundY, h);
    }

    /**
     * Has the rectangle reached the ground: is its bottom at or below the ground line?
     * Standing exactly on the ground counts, so a player that has landed stays on the ground
     * (and may jump) on the next frame.
     *
     * <p>A NaN in any argument answers false, and so does a negative height
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param y       the rectangle's top edge
     * @param h       the rectangle's height
     * @param groundY the ground line's y
     * @return true if {@code y + h >= groundY}, that is {@code y >= standY(h, groundY)}
     */
    public static boolean onGround(float y, float h, float groundY) {
        return y >= standY(h, groundY);
    }

    /**
     * The rectangle's top edge after landing on the ground line: moved up to stand on it if it
     * has reached or sunk below it, and unchanged while it is above.
     *
     * <p>A NaN {@code y} answers NaN; a NaN or negative height, or a NaN ground, hands {@code y}
     * back unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param y       the rectangle's top edge
     * @param h       the rectangle's height
     * @param groundY the ground line's y
     * @return {@code standY(h, groundY)} if {@link #onGround}, else {@code y}
     */
    public static float landY(float y, float h, float groundY) {
        return onGround(y, h, groundY) ? standY(h, groundY) : y;
    }

    // ---- pushing out of an obstacle ---------------------------------------------------

    /**
     * Where a push put the mover, and the side of the obstacle it was pushed to.
     *
     * <p>{@link Side#NONE} means the two did not overlap and the position is the mover's own,
     * unchanged. A plain carrier of the answer: it takes any position, NaN included, since
     * the pushes work on plain floats and never throw; only the side must be given.
     *
     * @param x    the mover's new left edge
     * @param y    the mover's new top edge
     * @param side the obstacle's side the mover now touches: {@link Side#TOP} (it landed),
     *             {@link Side#BOTTOM} (it hit its head), {@link Side#LEFT} or
     *             {@link Side#RIGHT} (a wall), or {@link Side#NONE} (no overlap, no push)
     */
    public record Push(float x, float y, Side side) {

        /**
         * Makes a push result.
         *
         * <p>Any position is taken, NaN included: a push is a plain carrier of an answer.
         *
         * @param x    the mover's new left edge
         * @param y    the mover's new top edge
         * @param side the side of the obstacle the mover touches, or {@link Side#NONE}
         * @throws IllegalArgumentException if {@code side} is null
         */
        public Push {
            Check.notNull("side", side);
        }

        /** @return true if the mover overlapped the obstacle and was pushed out */
        public boolean hit() {
            return side != Side.NONE;
        }

        /** @return true if the mover was pushed onto the obstacle's top: it stands and may jump */
        public boolean landed() {
            return side == Side.TOP;
        }

        /**
         * The horizontal speed after the push: 0 if it was heading into the wall it was
         * pushed out of, unchanged otherwise (sliding along a floor keeps its speed).
         *
         * <p>A NaN speed comes back NaN, unchanged
         * (the <a href="package-summary.html#bad-input">NaN rule</a>).
         *
         * @param vx the mover's horizontal speed
         * @return 0 for a speed into the hit wall, else {@code vx}
         */
        public float vxAfter(float vx) {
            return (side == Side.LEFT && vx > 0) || (side == Side.RIGHT && vx < 0) ? 0 : vx;
        }

        /**
         * The vertical speed after the push: 0 if it was heading into the top or bottom it was
         * pushed out of (falling onto a platform, or jumping into a ceiling), unchanged
         * otherwise.
         *
         * <p>A NaN speed comes back NaN, unchanged
         * (the <a href="package-summary.html#bad-input">NaN rule</a>).
         *
         * @param vy the mover's vertical speed (down is positive)
         * @return 0 for a speed into the hit side, else {@code vy}
         */
        public float vyAfter(float vy) {
            return (side == Side.TOP && vy > 0) || (side == Side.BOTTOM && vy < 0) ? 0 : vy;
        }

        /**
         * The mover at its new position.
         *
         * @param mover the rectangle that was pushed, not null
         * @return {@code mover} moved to ({@link #x()}, {@link #y()}), its size kept, never null
         * @throws IllegalArgumentException if {@code mover} is null
         */
        public Rect applyTo(Rect mover) {
            return Check.notNull("mover", mover).at(x, y);
        }
    }

    /**
     * Pushes the mover out of the obstacle along the axis of least overlap, the shortest way
     * out, so that the two touch.
     *
     * <p>Which push-out: this one for two boxes, when the side matters (landed, bumped a
     * wall); {@link Response#separate} for any other pair, or a guaranteed clear result;
     * {@link Response#pushOut(Shape, Contact, float)} to move by a contact you already have (see the
     * <a href="package-summary.html#push-out">package documentation</a>).
     *
     * <p>Of the four ways out (up onto the top, down below the bottom, left, right) the
     * shortest wins. Ties go in the order {@link Side#TOP}, {@link Side#BOTTOM},
     * {@link Side#LEFT}, {@link Side#RIGHT}: vertical before horizontal, so a player that
     * lands exactly on a corner lands instead of being pushed off sideways.
     *
     * <p>A NaN in any argument gives no push: the side is {@link Side#NONE} and the position
     * comes back unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x  the mover's left edge
     * @param y  the mover's top edge
     * @param w  the mover's width
     * @param h  the mover's height
     * @param ox the obstacle's left edge
     * @param oy the obstacle's top edge
     * @param ow the obstacle's width
     * @param oh the obstacle's height
     * @return the mover's new position and the side hit; {@link Side#NONE} and
     *         {@code (x, y)} if they do not overlap (touching is not overlapping), never null
     */
    public static Push pushOut(float x, float y, float w, float h, float ox, float oy, float ow, float oh) {
        if (!Collide.rectRect(x, y, w, h, ox, oy, ow, oh) || Check.notFinite(x, y, w, h, 0) || Check.notFinite(ox, oy, ow, oh, 0)) {
            return new Push(x, y, Side.NONE);
        }
        return place(RectPush.leastOverlap(x, y, w, h, ox, oy, ow, oh), x, y, w, h, ox, oy, ow, oh);
    }

    /**
     * Pushes the mover back out of the obstacle through the side it came in by, judging by
     * the speed it moved with this frame: for fast movers, where the least overlap can pick
     * the wrong side.
     *
     * <p>Going back along {@code (-vx, -vy)}, the mover stops overlapping the obstacle on one
     * axis first: that is the axis it crossed last, and the side it came through. A player
     * falling at 30 px per frame onto a 10 px platform lands on it even when its bottom went
     * 25 px in, where {@link #pushOut} would push it out underneath. Ties (arriving exactly at
     * a corner) go to the vertical side, as in {@code pushOut}. A speed of 0 on an axis means
     * it did not come in that way; with no speed at all this is {@code pushOut}.
     *
     * <p>The speed is trusted: if the mover was already overlapping before this frame's move,
     * the answer is still the side it would have come through moving this way.
     *
     * <p>A NaN in any argument gives no push: the side is {@link Side#NONE} and the position
     * comes back unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x  the mover's left edge, after this frame's move
     * @param y  the mover's top edge, after this frame's move
     * @param w  the mover's width
     * @param h  the mover's height
     * @param vx the horizontal speed of this frame's move
     * @param vy the vertical speed of this frame's move (down is positive)
     * @param ox the obstacle's left edge
     * @param oy the obstacle's top edge
     * @param ow the obstacle's width
     * @param oh the obstacle's height
     * @return the mover's new position and the side hit; {@link Side#NONE} and
     *         {@code (x, y)} if they do not overlap, never null
     */
    public static Push pushBack(float x, float y, float w, float h, float vx, float vy,
                                float ox, float oy, float ow, float oh) {
        if (!Collide.rectRect(x, y, w, h, ox, oy, ow, oh) || Check.notFinite(x, y, w, h, vx)
                || Check.notFinite(vy, ox, oy, ow, oh)) {
            return new Push(x, y, Side.NONE);
        }
        Side vertical = vy > 0 ? Side.TOP : vy < 0 ? Side.BOTTOM : Side.NONE;
        Side horizontal = vx > 0 ? Side.LEFT : vx < 0 ? Side.RIGHT : Side.NONE;
        Side side;
        if (vertical == Side.NONE && horizontal == Side.NONE) {
            side = RectPush.leastOverlap(x, y, w, h, ox, oy, ow, oh);
        } else if (horizontal == Side.NONE) {
            side = vertical;
        } else if (vertical == Side.NONE) {
            side = horizontal;
        } else {
            // Time back to leave on each axis is depth / |speed|; compare the cross products
            // instead of dividing, so a tie is exact: ty <= tx  <=>  dy * |vx| <= dx * |vy|.
            double dx = RectPush.depth(horizontal, x, y, w, h, ox, oy, ow, oh);
            double dy = RectPush.depth(vertical, x, y, w, h, ox, oy, ow, oh);
            side = dy * Math.abs((double) vx) <= dx * Math.abs((double) vy) ? vertical : horizontal;
        }
        return place(side, x, y, w, h, ox, oy, ow, oh);
    }

    /** The mover placed against the obstacle's {@code side}, touching it. */
    private static Push place(Side side, float x, float y, float w, float h, float ox, float oy, float ow, float oh) {
        return new Push(RectPush.placedX(side, x, w, ox, ow), RectPush.placedY(side, y, h, oy, oh), side);
    }
}
