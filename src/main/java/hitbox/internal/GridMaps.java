package hitbox.internal;

import hitbox.*;

import java.util.Arrays;
import java.util.Random;

/**
 * A {@link Grid}'s maps: reading one from text ({@link Grid#parse(String, float)}),
 * writing one as text ({@link Grid#toMap()}) and filling one at random
 * ({@link Grid#fillRandom(float, long, int, int)}). Grid keeps the public methods; the work
 * is here, apart from the cells and the pixel tests.
 */
public final class GridMaps {
    private GridMaps() {
    }

    /** Reads a map; see {@link Grid#parse(String, float)} for the format and the messages. */
    public static Grid parse(String map, float cellWidth, float cellHeight) {
        Check.notNull("map", map);
        String[] lines = map.split("\r\n|\r|\n", -1);
        int first = 0;
        int last = lines.length - 1;
        while (first <= last && lines[first].isEmpty()) {
            first++;
        }
        while (last >= first && lines[last].isEmpty()) {
            last--;
        }
        if (first > last) {
            throw new IllegalArgumentException("map has no rows: write one line of cells per row, "
                    + "'#' for solid and '.' for empty");
        }
        int width = lines[first].length();
        Grid grid = new Grid(width, last - first + 1, cellWidth, cellHeight);
        for (int i = first; i <= last; i++) {
            String line = lines[i];
            if (line.length() != width) {
                throw new IllegalArgumentException("map line " + (i + 1) + " has " + line.length()
                        + " cells, but line " + (first + 1) + " has " + width
                        + ": every row needs the same width (use '.' for empty cells; editors and"
                        + " text blocks may strip spaces at the end of a line)");
            }
            for (int col = 0; col < width; col++) {
                HiddenParts.cells(grid)[(i - first) * width + col] = terrainOf(line.charAt(col), i + 1, col + 1);
            }
        }
        return grid;
    }

    private static int terrainOf(char c, int line, int column) {
        if (c == '#') {
            return Grid.SOLID;
        }
        if (c == '.' || c == ' ') {
            return Grid.EMPTY;
        }
        if (c >= '0' && c <= '9') {
            return c - '0';
        }
        String shown = Character.isISOControl(c) || Character.isWhitespace(c) || Character.isSpaceChar(c)
                ? "(code " + (int) c + ", a tab or other invisible character)" : "'" + c + "'";
        throw new IllegalArgumentException("map line " + line + ", column " + column + ": unknown character "
                + shown + "; use '#' for solid, '.' or ' ' for empty, or a digit 0-9 for a terrain type");
    }

    /** The map as text; see {@link Grid#toMap()}. */
    public static String toMap(Grid grid) {
        StringBuilder s = new StringBuilder((grid.cols() + 1) * grid.rows());
        for (int row = 0; row < grid.rows(); row++) {
            if (row > 0) {
                s.append('\n');
            }
            for (int col = 0; col < grid.cols(); col++) {
                int t = HiddenParts.cells(grid)[row * grid.cols() + col];
                s.append(t == Grid.EMPTY ? '.' : t == Grid.SOLID ? '#' : t >= 2 && t <= 9 ? (char) ('0' + t) : '?');
            }
        }
        return s.toString();
    }

    /**
     * Fills the cells at random, keeping cell {@code free} (an index) empty. Partial
     * Fisher-Yates shuffle of the other cells: the first {@code solid} indices are solid.
     */
    public static void fillRandom(int[] cells, float fraction, long seed, int free) {
        if (!(fraction >= 0 && fraction <= 1)) {
            throw new IllegalArgumentException("fraction must be between 0 and 1, was " + fraction
                    + " (for 20% solid cells write 0.2)");
        }
        int n = cells.length;
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        // Move the free cell to the end and shuffle only the others.
        order[free] = n - 1;
        order[n - 1] = free;
        int candidates = n - 1;
        int solid = (int) Math.min(Math.round((double) fraction * n), candidates);
        Random random = new Random(seed);
        Arrays.fill(cells, Grid.EMPTY);
        for (int i = 0; i < solid; i++) {
            int j = i + random.nextInt(candidates - i);
            int t = order[i];
            order[i] = order[j];
            order[j] = t;
            cells[order[i]] = Grid.SOLID;
        }
    }

}
