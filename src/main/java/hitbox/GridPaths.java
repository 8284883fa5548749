package hitbox;

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
final class GridPaths {

    private static final int[] NONE = new int[0];
    /** The four straight steps, then the four diagonal ones. */
    private static final int[] STEP_COL = {1, -1, 0, 0, 1, 1, -1, -1};
    private static final int[] STEP_ROW = {0, 0, 1, -1, 1, -1, 1, -1};

    private GridPaths() {
    }

    /** See {@link Grid#path(int, int, int, int)}: breadth-first, from the goal back to the start. */
    static int[] path(Grid grid, int fromCol, int fromRow, int toCol, int toRow) {
        checkCells(grid, fromCol, fromRow, toCol, toRow);
        if (grid.isSolid(fromCol, fromRow) || grid.isSolid(toCol, toRow)) {
            return NONE;
        }
        int cols = grid.cols();
        int start = fromRow * cols + fromCol;
        int goal = toRow * cols + toCol;
        if (start == goal) {
            return new int[] {start};
        }
        Buffers b = Buffers.get(cols * grid.rows());
        int mark = b.nextMark();
        int[] seen = b.seen;
        int[] link = b.link;
        int[] queue = b.queue;
        // Searching from the goal leaves every link pointing one step nearer to it, so the
        // route is read off forwards from the start.
        seen[goal] = mark;
        queue[0] = goal;
        int head = 0;
        int tail = 1;
        while (head < tail) {
            int cell = queue[head++];
            int col = cell % cols;
            int row = cell / cols;
            for (int k = 0; k < 4; k++) {
                int c = col + STEP_COL[k];
                int r = row + STEP_ROW[k];
                if (!grid.isSolid(c, r)) {
                    int next = r * cols + c;
                    if (seen[next] != mark) {
                        seen[next] = mark;
                        link[next] = cell;
                        if (next == start) {
                            return follow(link, start, goal);
                        }
                        queue[tail++] = next;
                    }
                }
            }
        }
        return NONE;
    }

    /** The cells from start to goal along the links, start and goal included. */
    private static int[] follow(int[] link, int start, int goal) {
        int length = 1;
        for (int cell = start; cell != goal; cell = link[cell]) {
            length++;
        }
        int[] route = new int[length];
        int cell = start;
        for (int i = 0; i < length; i++) {
            route[i] = cell;
            cell = link[cell];
        }
        return route;
    }

    /** See {@link Grid#path(int, int, int, int, PathCosts)}: A* from the start to the goal. */
    static int[] path(Grid grid, int fromCol, int fromRow, int toCol, int toRow, PathCosts costs) {
        checkCells(grid, fromCol, fromRow, toCol, toRow);
        Check.notNull("costs", costs);
        if (Double.isInfinite(stepCost(grid, costs, fromCol, fromRow))
                || Double.isInfinite(stepCost(grid, costs, toCol, toRow))) {
            return NONE;
        }
        int cols = grid.cols();
        int start = fromRow * cols + fromCol;
        int goal = toRow * cols + toCol;
        if (start == goal) {
            return new int[] {start};
        }
        int steps = costs.diagonals() ? 8 : 4;
        double cheapest = costs.cheapest();
        Buffers b = Buffers.get(cols * grid.rows());
        int mark = b.nextMark();
        int[] seen = b.seen;
        int[] link = b.link;
        double[] dist = b.dist;
        Heap open = b.heap;
        open.clear();
        seen[start] = mark;
        dist[start] = 0;
        open.push(estimate(cheapest, costs.diagonals(), fromCol, fromRow, toCol, toRow), start);
        while (!open.isEmpty()) {
            double key = open.topKey();
            int cell = open.pop();
            int col = cell % cols;
            int row = cell / cols;
            double here = dist[cell];
            if (key > here + estimate(cheapest, costs.diagonals(), col, row, toCol, toRow)) {
                continue;  // an old entry: the cell was reached more cheaply since
            }
            if (cell == goal) {
                return backwards(link, start, goal);
            }
            for (int k = 0; k < steps; k++) {
                int dc = STEP_COL[k];
                int dr = STEP_ROW[k];
                int c = col + dc;
                int r = row + dr;
                double cost = stepCost(grid, costs, c, r);
                if (Double.isInfinite(cost)) {
                    continue;
                }
                if (k >= 4) {
                    // A diagonal needs both straight steps beside it open: no cut corners.
                    if (Double.isInfinite(stepCost(grid, costs, c, row))
                            || Double.isInfinite(stepCost(grid, costs, col, r))) {
                        continue;
                    }
                    cost *= PathCosts.DIAGONAL;
                }
                int next = r * cols + c;
                double d = here + cost;
                if (seen[next] != mark || d < dist[next]) {
                    seen[next] = mark;
                    dist[next] = d;
                    link[next] = cell;
                    open.push(d + estimate(cheapest, costs.diagonals(), c, r, toCol, toRow), next);
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
        return cheapest * (straight + PathCosts.DIAGONAL * diagonal);
    }

    /** The cost of stepping into (col, row): infinite if it is outside, solid or impassable. */
    private static double stepCost(Grid grid, PathCosts costs, int col, int row) {
        if (grid.isSolid(col, row)) {
            return Double.POSITIVE_INFINITY;
        }
        int terrain = grid.get(col, row);
        try {
            return costs.cost(terrain);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("cell (col " + col + ", row " + row + "): " + e.getMessage(), e);
        }
    }

    /** The cells from start to goal, read backwards along the links from the goal. */
    private static int[] backwards(int[] link, int start, int goal) {
        int length = 1;
        for (int cell = goal; cell != start; cell = link[cell]) {
            length++;
        }
        int[] route = new int[length];
        int cell = goal;
        for (int i = length - 1; i >= 0; i--) {
            route[i] = cell;
            cell = link[cell];
        }
        return route;
    }

    private static void checkCells(Grid grid, int fromCol, int fromRow, int toCol, int toRow) {
        checkCell(grid, "fromCol", fromCol, grid.cols());
        checkCell(grid, "fromRow", fromRow, grid.rows());
        checkCell(grid, "toCol", toCol, grid.cols());
        checkCell(grid, "toRow", toRow, grid.rows());
    }

    private static void checkCell(Grid grid, String name, int value, int count) {
        if (value < 0 || value >= count) {
            throw new IllegalArgumentException(name + " must be from 0 to " + (count - 1) + " (a cell of the "
                    + grid.cols() + " x " + grid.rows() + " grid), was " + value);
        }
    }

    /** The arrays a search works in, grown as needed and kept for the next search on this thread. */
    private static final class Buffers {
        private static final ThreadLocal<SoftReference<Buffers>> KEPT = new ThreadLocal<>();

        int[] seen = new int[0];
        int[] link = new int[0];
        int[] queue = new int[0];
        double[] dist = new double[0];
        final Heap heap = new Heap();
        private int mark;

        static Buffers get(int cells) {
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
                b.dist = new double[cells];
                b.mark = 0;
            }
            return b;
        }

        /** A mark no cell holds yet: the cells marked with it are this search's. */
        int nextMark() {
            if (mark == Integer.MAX_VALUE) {
                Arrays.fill(seen, 0);
                mark = 0;
            }
            return ++mark;
        }
    }

    /** A binary min-heap of cells by key; an improved cell is pushed again and the old entry skipped. */
    private static final class Heap {
        private double[] keys = new double[256];
        private int[] cells = new int[256];
        private int size;

        void clear() {
            size = 0;
        }

        boolean isEmpty() {
            return size == 0;
        }

        double topKey() {
            return keys[0];
        }

        void push(double key, int cell) {
            if (size == keys.length) {
                keys = Arrays.copyOf(keys, size * 2);
                cells = Arrays.copyOf(cells, size * 2);
            }
            int i = size++;
            while (i > 0) {
                int parent = (i - 1) >>> 1;
                if (keys[parent] <= key) {
                    break;
                }
                keys[i] = keys[parent];
                cells[i] = cells[parent];
                i = parent;
            }
            keys[i] = key;
            cells[i] = cell;
        }

        int pop() {
            int top = cells[0];
            size--;
            double key = keys[size];
            int cell = cells[size];
            int i = 0;
            while (true) {
                int child = 2 * i + 1;
                if (child >= size) {
                    break;
                }
                if (child + 1 < size && keys[child + 1] < keys[child]) {
                    child++;
                }
                if (keys[child] >= key) {
                    break;
                }
                keys[i] = keys[child];
                cells[i] = cells[child];
                i = child;
            }
            keys[i] = key;
            cells[i] = cell;
            return top;
        }
    }
}
