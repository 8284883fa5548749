package hitbox.internal;

/**
 * Integer cells for the grid and the quadtree: {@code cell(v) = floor(v / size)}, shifted to
 * be 0 or more and clamped to [0, 2^62], so that every level above (cells 2, 4, 8... times as
 * large) is a right shift, {@code cell >> level}, and adding or taking 1 never overflows.
 *
 * <p>Why the pairs are never missed: the map from a coordinate to its cell only has to be
 * monotone (never smaller for a larger coordinate), which rounding and clamping keep. Put each
 * box in the cell of its left edge, at a level where its left and right edges are at most one
 * cell apart. If two boxes overlap, each one's left edge is left of the other's right edge, so
 * their cells are at most one apart at that level: a box's partners are in its own cell and
 * the eight around it. The same holds down the page.
 */
public final class Lattice {
    /** Cells are clamped to [0, 2 * OFFSET]; the cell of 0 is OFFSET. */
    public static final long OFFSET = 1L << 61;
    private static final long MAX = 2 * OFFSET;

    private Lattice() {
    }

    /**
     * The cell of a coordinate.
     *
     * @param v       the coordinate
     * @param perCell 1 / the cell size
     * @return the cell, in [0, 2^62]
     */
    public static long cell(double v, double perCell) {
        double c = Math.floor(v * perCell);
        if (!(c > -OFFSET)) {
            return 0;
        }
        return c >= OFFSET ? MAX : (long) c + OFFSET;
    }

    /**
     * The smallest level at which the cells lo and hi (lo &lt;= hi) are at most one apart.
     *
     * @param lo the cell of the left (or top) edge
     * @param hi the cell of the right (or bottom) edge
     * @return the level, 0 to 62
     */
    public static int level(long lo, long hi) {
        long d = hi - lo;
        if (d <= 1) {
            return 0;
        }
        int k = 63 - Long.numberOfLeadingZeros(d);  // 2^k <= d < 2^(k+1): the level is k or k + 1
        return (hi >> k) - (lo >> k) <= 1 ? k : k + 1;
    }

    /**
     * Where a cell begins, as a coordinate: the inverse of {@link #cell}, for drawing and for
     * the bounds of tree nodes. The first cell (0) begins at minus infinity, and the last
     * (2^62 at level 0) runs on to infinity, so a cell past it begins at infinity.
     *
     * @param cell  the cell at {@code level}, which may be one or two past the last
     * @param level the level
     * @param size  the size of a level-0 cell
     * @return the left (or top) edge of the cell
     */
    public static double edge(long cell, int level, double size) {
        if (cell <= 0) {
            return Double.NEGATIVE_INFINITY;
        }
        if (level >= 63 || cell > MAX >> level) {
            return Double.POSITIVE_INFINITY;
        }
        return (double) ((cell << level) - OFFSET) * size;
    }
}
