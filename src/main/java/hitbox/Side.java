package hitbox;

import hitbox.internal.*;

import java.util.EnumSet;
import java.util.Set;

/**
 * A side of a box: which side of an obstacle a moving shape ran into, or which edge of the
 * window a shape crossed. The one answer to every "which side" question in Hitbox.
 *
 * <p>With y growing down (Processing's axes): a player that falls onto a platform hits its
 * {@link #TOP} (it has landed, and may jump again); one that jumps into it from below hits
 * its {@link #BOTTOM} (it bumped its head); {@link #LEFT} and {@link #RIGHT} are walls. For
 * the window ({@link Edges}), {@link #LEFT} is the edge {@code x = 0}, {@link #TOP} the edge
 * {@code y = 0}.
 *
 * <h2 id="bits">Several sides at once: one bit scheme</h2>
 * Answers that can name several sides at once (the edges a shape crossed, the axes a move is
 * blocked on, the sides a {@link Sweep#move} hit) are {@code int}s with one bit per side, so
 * that a sketch can keep them in a plain variable and test them without allocating:
 * {@link #LEFT} is 1, {@link #RIGHT} 2, {@link #TOP} 4 and {@link #BOTTOM} 8 ({@link #bit()}),
 * and {@link #NONE} is 0. Read them with {@link #has(int, Side)}, print them with
 * {@link #describe(int)}, or turn them into an {@link EnumSet} with {@link #setOf(int)}. The
 * bits are fixed numbers, never the enum's ordinals. {@link #LEFT_RIGHT} and
 * {@link #TOP_BOTTOM} name the two pairs {@link Motion} answers for a blocked axis; ask
 * about several bits at once with {@link #hasAny(int, int)}. {@link Edges} and
 * {@link Motion} take and give these bits; their own constants and {@code has} and
 * {@code describe} are deprecated aliases of these (kept one release).
 *
 * <h2 id="results">The side of a result</h2>
 * Every result that names one side gives it as {@code side()}: {@link Hit#side()},
 * {@link RayHit#side()}, {@link Contact#side()} and {@link Snap.Push#side()}, each a
 * {@code Side}, {@link #NONE} when the result has none. A result that can name several
 * gives them as an {@code int} in the bit scheme: {@link Sweep.Move#sides()} (with
 * {@link Sweep.Move#sideSet()} for an {@code EnumSet}), like the answers of {@link Edges}
 * and {@link Motion}.
 */
public enum Side {
    /** No side: nothing was hit. Its bit is 0. */
    NONE(0),
    /** The top edge: the mover came from above and has landed on it. Bit 4. */
    TOP(4),
    /** The bottom edge: the mover came from below and hit its head. Bit 8. */
    BOTTOM(8),
    /** The left edge: the mover came from the left and hit a wall. Bit 1. */
    LEFT(1),
    /** The right edge: the mover came from the right and hit a wall. Bit 2. */
    RIGHT(2);

    /** Every side's bit: {@code LEFT | RIGHT | TOP | BOTTOM}, 15. */
    public static final int ALL_BITS = 15;

    /**
     * The two walls' bits, {@code LEFT | RIGHT}, 3: what {@link Motion} answers when the move
     * across is blocked (the next-position check knows the axis, not the face), so
     * {@code Side.hasAny(blocked, Side.LEFT_RIGHT)} reads "reverse vx". Replaces
     * {@code Motion.X}.
     */
    public static final int LEFT_RIGHT = 3;

    /**
     * The top and bottom bits, {@code TOP | BOTTOM}, 12: what {@link Motion} answers when the
     * move down (or up) is blocked. Replaces {@code Motion.Y}.
     */
    public static final int TOP_BOTTOM = 12;

    private final int bit;

    Side(int bit) {
        this.bit = bit;
    }

    /**
     * This side's bit in the <a href="#bits">bit scheme</a>: LEFT 1, RIGHT 2, TOP 4, BOTTOM 8,
     * NONE 0.
     *
     * @return the bit
     */
    public int bit() {
        return bit;
    }

    /**
     * Did the mover land? True for {@link #TOP}: it stands on the obstacle and may jump again.
     *
     * @return true for {@link #TOP}
     */
    public boolean landed() {
        return this == TOP;
    }

    /**
     * Did the mover run into a wall?
     *
     * @return true for {@link #LEFT} or {@link #RIGHT}
     */
    public boolean isWall() {
        return this == LEFT || this == RIGHT;
    }

    /**
     * The side across from this one: TOP and BOTTOM, LEFT and RIGHT; NONE stays NONE.
     *
     * @return the opposite side, never null
     */
    public Side opposite() {
        return switch (this) {
            case TOP -> BOTTOM;
            case BOTTOM -> TOP;
            case LEFT -> RIGHT;
            case RIGHT -> LEFT;
            case NONE -> NONE;
        };
    }

    /**
     * The side of an obstacle that a normal points into. The normal is Hitbox's one
     * convention, <em>from the mover into what it hit</em> (see the package documentation):
     * pointing down ({@code ny > 0}) it goes into the obstacle's {@link #TOP}, up into its
     * {@link #BOTTOM}, right into its {@link #LEFT} and left into its {@link #RIGHT}. The
     * larger part decides; at exactly 45 degrees the vertical one wins, so landing on a corner
     * counts as landing. This is the rule behind {@link Contact#side()} and {@link Hit#side()}.
     *
     * @param nx the normal's x, any length
     * @param ny the normal's y
     * @return the side; {@link #NONE} for (0, 0) or a NaN part
     */
    public static Side ofNormal(double nx, double ny) {
        if (Double.isNaN(nx) || Double.isNaN(ny) || (nx == 0 && ny == 0)) {
            return NONE;
        }
        if (Math.abs(ny) >= Math.abs(nx)) {
            return ny > 0 ? TOP : BOTTOM;
        }
        return nx > 0 ? LEFT : RIGHT;
    }

    /**
     * Is this side among the sides of a bit set? Reads better than
     * {@code (sides & side.bit()) != 0}.
     *
     * @param sides the sides, in the <a href="#bits">bit scheme</a>
     * @param side  the side to ask about, not null
     * @return true if {@code sides} has that side's bit; for {@link #NONE}, true if
     *         {@code sides} names no side at all
     * @throws IllegalArgumentException if {@code side} is null
     */
    public static boolean has(int sides, Side side) {
        Check.notNull("side", side);
        return side == NONE ? (sides & ALL_BITS) == 0 : (sides & side.bit) != 0;
    }

    /**
     * Do two bit sets share a side? True when {@code sides} has any of the bits of
     * {@code bits}: {@code Side.hasAny(crossed, Side.LEFT_RIGHT)} asks "did it cross the left
     * or the right edge?", {@code Side.hasAny(blocked, Side.TOP_BOTTOM)} "is the move down or
     * up blocked?". For one side, {@link #has(int, Side)} reads better.
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param sides the sides, in the <a href="#bits">bit scheme</a> (an answer of
     *              {@link Edges}, {@link Motion} or {@link Sweep.Move#sides()})
     * @param bits  the sides to ask about, in the same scheme
     * @return true if {@code sides & bits} names a side; false when either names none
     */
    public static boolean hasAny(int sides, int bits) {
        return (sides & bits & ALL_BITS) != 0;
    }

    /**
     * The bits of some sides, OR-ed together.
     *
     * @param sides the sides, none of them null; {@link #NONE} adds nothing
     * @return the bit set, 0 for none
     * @throws IllegalArgumentException if {@code sides} or one of them is null
     */
    public static int bits(Side... sides) {
        Check.notNull("sides", sides);
        int bits = 0;
        for (int i = 0; i < sides.length; i++) {
            bits |= Check.notNull("sides[" + i + "]", sides[i]).bit;
        }
        return bits;
    }

    /**
     * The bits of a set of sides, OR-ed together.
     *
     * @param sides the sides, not null, with no null element
     * @return the bit set, 0 for an empty set
     * @throws IllegalArgumentException if {@code sides} or an element is null
     */
    public static int bits(Set<Side> sides) {
        Check.notNull("sides", sides);
        return bits(sides.toArray(new Side[0]));
    }

    /**
     * The sides of a bit set, as a set: LEFT, RIGHT, TOP and BOTTOM for their bits. Bits that
     * name no side are ignored.
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param sides the sides, in the <a href="#bits">bit scheme</a>
     * @return a new modifiable set; empty (never holding {@link #NONE}) when no bit is set, never null
     */
    public static EnumSet<Side> setOf(int sides) {
        EnumSet<Side> set = EnumSet.noneOf(Side.class);
        for (Side s : BY_BIT) {
            if ((sides & s.bit) != 0) {
                set.add(s);
            }
        }
        return set;
    }

    /**
     * The sides of a bit set as words, for printing: {@code "LEFT|TOP"}, or {@code "NONE"}.
     * This is the one way Hitbox prints a bit set, whatever answered it: a move of
     * {@link Motion} blocked across is {@link #LEFT_RIGHT}, printed {@code "LEFT|RIGHT"}
     * (the deprecated {@code Motion.describe} printed it {@code "X"}).
     *
     * <p>Any int is taken: bits outside the scheme are ignored.
     *
     * @param sides the sides, in the <a href="#bits">bit scheme</a>
     * @return the names, in the order LEFT, RIGHT, TOP, BOTTOM, joined by {@code |}, never null
     */
    public static String describe(int sides) {
        StringBuilder s = new StringBuilder();
        for (Side side : BY_BIT) {
            if ((sides & side.bit) != 0) {
                s.append(s.length() == 0 ? "" : "|").append(side.name());
            }
        }
        return s.length() == 0 ? "NONE" : s.toString();
    }

    /** The four real sides in bit order: LEFT, RIGHT, TOP, BOTTOM. */
    private static final Side[] BY_BIT = {LEFT, RIGHT, TOP, BOTTOM};
}
