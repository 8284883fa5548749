package hitbox.internal;

/**
 * The float lines between a {@link hitbox.Grid}'s cells, the one rule every pixel test of the
 * grid and its line of sight go by: the line before cell {@code i} is the float nearest
 * {@code i * size}, and a pixel belongs to the cell whose lines hold it, left line included.
 */
public final class GridLines {
    private GridLines() {
    }

    /**
     * The line before cell {@code i}: the float nearest {@code i * size}.
     *
     * @param i    the cell's column or row, any long
     * @param size the cells' width or height
     * @return the line's x or y
     */
    public static float edge(long i, float size) {
        return (float) (i * (double) size);
    }

    /**
     * The cell whose lines hold {@code p}: {@code edge(i) <= p < edge(i + 1)}, saturated to the
     * int range.
     *
     * @param p    the pixel's x or y
     * @param size the cells' width or height
     * @return the cell's column or row; -1 for NaN
     */
    public static int cellIndex(float p, float size) {
        if (Float.isNaN(p)) {
            return -1;
        }
        double guess = Math.floor(p / (double) size);
        if (guess >= Integer.MAX_VALUE) {
            return Integer.MAX_VALUE;
        }
        if (guess <= Integer.MIN_VALUE) {
            return Integer.MIN_VALUE;
        }
        long i = (long) guess;
        // The division's rounding can be a cell off next to a line: settle it with the same
        // float lines that edge draws.
        while (i > Integer.MIN_VALUE && edge(i, size) > p) {
            i--;
        }
        while (i < Integer.MAX_VALUE && edge(i + 1, size) <= p) {
            i++;
        }
        return (int) i;
    }
}
