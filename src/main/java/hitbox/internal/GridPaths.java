package hitbox.internal;

import hitbox.*;

import java.lang.ref.SoftReference;
import java.util.Arrays;

/**
 * Shortest and cheapest routes on a {@link Grid}, behind {@link Grid#path}: breadth-first
 * search for the fewest straight steps, A* for the cheapest route under {@link PathCosts}.
 *
 * <p>Both work on {@code int} and {@code double} arrays indexed by cell, kept from one search
 * to the next (per thread, and let go of when memory runs short), and a mark per search
 * instead of clearing them, so a search costs only the cells it reaches.
 *
 * <p>Reference: Peter Hart, Nils Nilsson and Bertram Raphael, "A Formal Basis for the
 * Heuristic Determination of Minimum Cost Paths", IEEE Transactions on Systems Science and
 * Cybernetics, 1968 (A*).
 */
public final class GridPaths {
    /** How much longer a diagonal step is than a straight one. */
    public static final double DIAGONAL = Math.sqrt(2);


    private static final int[] NONE = new int[0];
    /** The four straight steps, then the four diagonal ones. */
    private static final int[] STEP_COL = {1, -1, 0, 0, 1, 1, -1, -1};
    private static final int[] STEP_ROW = {0, 0, 1, -1, 1, -1, 1, -1};

    private GridPaths() {
    }

    /** See {@link Grid#path(int, int, int, int)}: breadth-first, from the goal back to the start. */
    public static int[] path(Grid grid, int fromCol, int fromRow, int toCol, int toRow) {
        checkCells(grid, fromCol, fromRow, toCol, toRow);
        if (grid.isSolid(fromCol, fromRow) || grid.isSolid(toCol, toRow)) {
            return NONE;
        }
        int cols = grid.cols();
        int rows = grid.rows();
        int start = fromRow * cols + fromCol;
        int goal = toRow * cols + toCol;
        if (start == goal) {
            return new int[] {start};
        }
        Buffers b = Buffers.get(cols * rows, false);
        int mark = b.nextMark();
        int[] seen = b.seen;
        int[] link = b.link;
        int[] queue = b.queue;
        // Searching from the goal leaves every link pointing one step nearer to it, so the
        // route is read off forwards from the start. A cell is marked seen the first time it
        // is looked at, solid or not, so the grid is asked about each cell at most once.
        seen[goal] = mark;
        queue[0] = goal;
        int head = 0;
        int tail = 1;
        while (head < tail) {
            int cell = queue[head++];
            int row = cell / cols;
            int col = cell - row * cols;
            for (int k = 0; k < 4; k++) {
                int c = col + STEP_COL[k];
                int r = row + STEP_ROW[k];
                if (c < 0 || c >= cols || r < 0 || r >= rows) {
                    continue;
                }
                int next = r * cols + c;
                if (seen[next] == mark) {
                    continue;
                }
                seen[next] = mark;
                if (grid.isSolid(c, r)) {
                    continue;
                }
                link[next] = cell;
                if (next == start) {
                    return follow(link, start, goal, false);
                }
                queue[tail++] = next;
            }
        }
        return NONE;
    }

    /**
     * The cells along the links from {@code first} to {@code last}, both included, in that
     * order, or the other way round ({@code reversed}: the links lead from the goal back to
     * the start).
     */
    private static int[] follow(int[] link, int first, int last, boolean reversed) {
        int length = 1;
        for (int cell = first; cell != last; cell = link[cell]) {
            length++;
        }
        int[] route = new int[length];
        int cell = first;
        for (int i = 0; i < length; i++) {
            route[reversed ? length - 1 - i : i] = cell;
            cell = link[cell];
        }
        return route;
    }

    /** See {@link Grid#path(int, int, int, int, PathCosts)}: A* from the start to the goal. */
    public static int[] path(Grid grid, int fromCol, int fromRow, int toCol, int toRow, PathCosts costs) {
        checkCells(grid, fromCol, fromRow, toCol, toRow);
        Check.notNull("costs", costs);
        int cols = grid.cols();
        int rows = grid.rows();
        Buffers b = Buffers.get(cols * rows, true);
        int mark = b.nextMark();
        Search s = new Search(grid, costs, b, mark);
        int start = fromRow * cols + fromCol;
        int goal = toRow * cols + toCol;
        if (Double.isInfinite(s.cost(fromCol, fromRow)) || Double.isInfinite(s.cost(toCol, toRow))) {
            return NONE;
        }
        if (start == goal) {
            return new int[] {start};
        }
        boolean diagonals = costs.diagonals();
        int steps = diagonals ? 8 : 4;
        double cheapest = costs.cheapest();
        int[] seen = b.seen;
        int[] link = b.link;
        double[] dist = b.dist;
        Heap open = b.heap;
        open.clear();
        seen[start] = mark;
        dist[start] = 0;
        open.push(estimate(cheapest, diagonals, fromCol, fromRow, toCol, toRow), 0, start);
        while (!open.isEmpty()) {
            double here = open.topDist();
            int cell = open.pop();
            if (here > dist[cell]) {
                continue;  // an old entry: the cell was reached more cheaply since
            }
            if (cell == goal) {
                return follow(link, goal, start, true);
            }
            int col = cell % cols;
            int row = cell / cols;
            for (int k = 0; k < steps; k++) {
                int c = col + STEP_COL[k];
                int r = row + STEP_ROW[k];
                double cost = s.cost(c, r);
                if (Double.isInfinite(cost)) {
                    continue;
                }
                if (k >= 4) {
                    // A diagonal needs both straight steps beside it open: no cut corners.
                    if (Double.isInfinite(s.cost(c, row)) || Double.isInfinite(s.cost(col, r))) {
                        continue;
                    }
                    cost *= DIAGONAL;
                }
                int next = r * cols + c;
                double d = here + cost;
                if (seen[next] != mark || d < dist[next]) {
                    seen[next] = mark;
                    dist[next] = d;
                    link[next] = cell;
                    open.push(d + estimate(cheapest, diagonals, c, r, toCol, toRow), d, next);
                }
            }
        }
        return NONE;
    }

    /**
     * A lower bound on the cost from (col, row) to the goal: the cheapest step times the fewest
     * steps, so A* stays exact (admissible and consistent).
     */
    private static double estimate(double cheapest, boolean diagonals, int col, int row, int toCol, int toRow) {
        if (cheapest == 0) {
            return 0;
        }
        int dc = Math.abs(toCol - col);
        int dr = Math.abs(toRow - row);
        if (!diagonals) {
            return cheapest * (dc + dr);
        }
        int straight = Math.abs(dc - dr);
        int diagonal = Math.min(dc, dr);
        return cheapest * (straight + DIAGONAL * diagonal);
    }

    /** One weighted search: the cost of stepping into each cell, worked out once per cell. */
    private static final class Search {
        private final Grid grid;
        private final PathCosts costs;
        private final int cols;
        private final int rows;
        private final int mark;
        private final int[] known;
        private final double[] cost;

        public Search(Grid grid, PathCosts costs, Buffers b, int mark) {
            this.grid = grid;
            this.costs = costs;
            this.cols = grid.cols();
            this.rows = grid.rows();
            this.mark = mark;
            this.known = b.costKnown;
            this.cost = b.cost;
        }

        /** The cost of stepping into (col, row): infinite if it is outside, solid or impassable. */
        public double cost(int col, int row) {
            if (col < 0 || col >= cols || row < 0 || row >= rows) {
                return Double.POSITIVE_INFINITY;
            }
            int i = row * cols + col;
            if (known[i] == mark) {
                return cost[i];
            }
            double c;
            if (grid.isSolid(col, row)) {
                c = Double.POSITIVE_INFINITY;
            } else {
                int terrain = grid.get(col, row);
                try {
                    c = costs.cost(terrain);
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("cell (col " + col + ", row " + row + "): " + e.getMessage(), e);
                }
            }
            known[i] = mark;
            cost[i] = c;
            return c;
        }
    }

    private static void checkCells(Grid grid, int fromCol, int fromRow, int toCol, int toRow) {
        checkCell(grid, "fromCol", fromCol, grid.cols());
        checkCell(grid, "fromRow", fromRow, grid.rows());
        checkCell(grid, "toCol", toCol, grid.cols());
        checkCell(grid, "toRow", toRow, grid.rows());
    }

    private static void checkCell(Grid grid, String name, int value, int count) {
        if (value < 0 || value >= count) {
            throw new IndexOutOfBoundsException(name + " must be from 0 to " + (count - 1) + " (a cell of the "
                    + grid.cols() + " x " + grid.rows() + " grid), was " + value);
        }
    }

    /** The arrays a search works in, grown as needed and kept for the next search on this thread. */
    private static final class Buffers {
        private static final ThreadLocal<SoftReference<Buffers>> KEPT = new ThreadLocal<>();

        public int[] seen = new int[0];
        public int[] link = new int[0];
        public int[] queue = new int[0];
        public double[] dist = new double[0];
        public int[] costKnown = new int[0];
        public double[] cost = new double[0];
        public final Heap heap = new Heap();
        private int mark;

        /** The buffers for a search of this many cells; {@code weighted} adds the arrays only A* needs. */
        public static Buffers get(int cells, boolean weighted) {
            SoftReference<Buffers> ref = KEPT.get();
            Buffers b = ref == null ? null : ref.get();
            if (b == null) {
                b = new Buffers();
                KEPT.set(new SoftReference<>(b));
            }
            if (b.seen.length < cells) {
                b.seen = new int[cells];
                b.link = new int[cells];
                b.queue = new int[cells];
                b.dist = new double[0];
                b.costKnown = new int[0];
                b.cost = new double[0];
                b.mark = 0;
            }
            if (weighted && b.dist.length < cells) {
                b.dist = new double[cells];
                b.costKnown = new int[cells];
                b.cost = new double[cells];  // zeros: marks start at 1, so no cell's cost is known yet
            }
            return b;
        }

        /** A mark no cell holds yet: the cells marked with it are this search's. */
        public int nextMark() {
            if (mark == Integer.MAX_VALUE) {
                Arrays.fill(seen, 0);
                Arrays.fill(costKnown, 0);
                mark = 0;
            }
            return ++mark;
        }
    }

    /**
     * A binary min-heap of cells by estimated total cost, ties going to the cell reached at the
     * greater cost (nearer the goal, which keeps A* from fanning out over equal routes); an
     * improved cell is pushed again and the old entry skipped.
     */
    private static final class Heap {
        private double[] keys = new double[256];
        private double[] dists = new double[256];
        private int[] cells = new int[256];
        private int size;

        public void clear() {
            size = 0;
        }

        public boolean isEmpty() {
            return size == 0;
        }

        public double topDist() {
            return dists[0];
        }

        /** Does an entry with this key and cost come out before one with the other key and cost? */
        private static boolean before(double key, double dist, double otherKey, double otherDist) {
            return key < otherKey || (key == otherKey && dist > otherDist);
        }

        /** Puts an entry at place i. */
        private void put(int i, double key, double dist, int cell) {
            keys[i] = key;
            dists[i] = dist;
            cells[i] = cell;
        }

        public void push(double key, double dist, int cell) {
            if (size == keys.length) {
                keys = Arrays.copyOf(keys, size * 2);
                dists = Arrays.copyOf(dists, size * 2);
                cells = Arrays.copyOf(cells, size * 2);
            }
            int i = size++;
            // Up from the bottom: parents that come later move down a place.
            while (i > 0) {
                int parent = (i - 1) >>> 1;
                if (!before(key, dist, keys[parent], dists[parent])) {
                    break;
                }
                put(i, keys[parent], dists[parent], cells[parent]);
                i = parent;
            }
            put(i, key, dist, cell);
        }

        public int pop() {
            int top = cells[0];
            size--;
            // The last entry goes down from the top: children that come first move up a place.
            double key = keys[size];
            double dist = dists[size];
            int cell = cells[size];
            int i = 0;
            for (int child = 1; child < size; i = child, child = 2 * i + 1) {
                if (child + 1 < size && before(keys[child + 1], dists[child + 1], keys[child], dists[child])) {
                    child++;
                }
                if (!before(keys[child], dists[child], key, dist)) {
                    break;
                }
                put(i, keys[child], dists[child], cells[child]);
            }
            put(i, key, dist, cell);
            return top;
        }
    }
}
