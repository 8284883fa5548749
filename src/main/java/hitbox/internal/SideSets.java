package hitbox.internal;

import hitbox.Side;

import java.util.Collections;
import java.util.EnumSet;
import java.util.Set;

/**
 * The sets of sides the API hands back (the edges a shape crossed, the axes a move is blocked
 * on, the sides a walk hit), made once: one unmodifiable set for each of the 16 combinations
 * of {@code LEFT}, {@code RIGHT}, {@code TOP} and {@code BOTTOM}, so that an answer costs no
 * allocation. The kernels work in bits (LEFT 1, RIGHT 2, TOP 4, BOTTOM 8), private to the
 * library; the API speaks only {@link Side} and sets of it.
 */
public final class SideSets {
    private SideSets() {
    }

    /** Bits of the four sides, private to the library. */
    public static final int LEFT = 1, RIGHT = 2, TOP = 4, BOTTOM = 8, ALL = 15;
    /** Both walls (a blocked horizontal move) and both of top and bottom (a blocked vertical one). */
    public static final int LEFT_RIGHT = LEFT | RIGHT, TOP_BOTTOM = TOP | BOTTOM;

    private static final Set<Side>[] SETS = make();

    @SuppressWarnings({"unchecked", "rawtypes"})  // an array of a generic type is made raw
    private static Set<Side>[] make() {
        Set<Side>[] sets = new Set[16];
        for (int bits = 0; bits < 16; bits++) {
            EnumSet<Side> s = EnumSet.noneOf(Side.class);
            for (Side side : new Side[] {Side.TOP, Side.BOTTOM, Side.LEFT, Side.RIGHT}) {
                if ((bits & bit(side)) != 0) {
                    s.add(side);
                }
            }
            sets[bits] = Collections.unmodifiableSet(s);
        }
        return sets;
    }

    /** The bit of one side; 0 for {@code NONE}. */
    public static int bit(Side side) {
        return switch (side) {
            case LEFT -> LEFT;
            case RIGHT -> RIGHT;
            case TOP -> TOP;
            case BOTTOM -> BOTTOM;
            case NONE -> 0;
        };
    }

    /** The unmodifiable set of the sides whose bits are set (bits past the four are ignored). */
    public static Set<Side> of(int bits) {
        return SETS[bits & ALL];
    }

    /** The bits of a set of sides ({@code NONE} in it adds none). */
    public static int bits(Set<Side> sides) {
        int bits = 0;
        for (Side s : sides) {
            bits |= bit(Check.notNull("a side in the set", s));
        }
        return bits;
    }
}
