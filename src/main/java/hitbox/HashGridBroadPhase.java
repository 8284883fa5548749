package hitbox;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * {@link BroadPhase#grid()}: a hierarchy of hash grids over the {@link Lattice}, rebuilt from
 * scratch by the first question after a change.
 *
 * <p>Each box goes to the finest level at which its edges are at most one cell apart (level L
 * has cells {@code 2^L} times the base cell), in the cell of its top-left corner. The cells
 * are hashed into buckets, and the boxes laid out bucket by bucket by a counting sort
 * (entries: copies of the boxes with their cell, so a scan reads memory in order).
 *
 * <p>Pairs within a level: each box against the boxes after it in its own cell and against
 * the four cells after its own (right-above, right, right-below, below), so each pair of
 * neighbouring cells is looked at from one side only. Pairs across levels L &lt; M: either each
 * level-L box looks up the two or three cells per axis of level M it can reach, or each level-M
 * box looks up the cells of level L it covers, whichever looks up fewer cells; a level is
 * scanned whole when that is cheaper still.
 */
final class HashGridBroadPhase extends AbstractBroadPhase {
    private static final int LEVELS = 63;

    /** The cell size asked for, or 0 to choose it from the boxes. */
    private final float fixedCell;
    private double cell;
    private double perCell;
    private boolean stale;

    // Per entry (bucket order), filled by the rebuild.
    private float[] ex = new float[0];
    private double[] er = new double[0];
    private float[] ey = new float[0];
    private double[] eb = new double[0];
    private int[] eid = new int[0];
    private int[] eslot = new int[0];
    private long[] ea = new long[0];
    private long[] ebCell = new long[0];
    private int[] elevel = new int[0];
    private int[] ebucket = new int[0];

    // Per slot, scratch of the rebuild.
    private long[] slotA = new long[0];
    private long[] slotB = new long[0];
    private int[] slotLevel = new int[0];
    private int[] slotBucket = new int[0];

    /** Bucket k's entries are start[k] to start[k + 1] - 1. */
    private int[] start = new int[1];
    private int bits;
    private final int[] levelCount = new int[LEVELS];
    private final int[] levelStart = new int[LEVELS + 1];
    /** Entries grouped by level: levelStart[L] to levelStart[L + 1] - 1. */
    private int[] byLevel = new int[0];
    private final int[] occupied = new int[LEVELS];
    private int levels;
    private double minX;
    private double minY;
    private double maxRight;
    private double maxBottom;
    /** For rays: the stamp of the cast that last considered each slot. */
    private int[] seen = new int[0];
    private int stamp;
    private final int[] sizeCounts = new int[256];

    HashGridBroadPhase(float cellSize) {
        fixedCell = cellSize;
        setCell(cellSize > 0 ? cellSize : 1);
    }

    private void setCell(double size) {
        cell = size;
        perCell = 1 / size;
    }

    @Override
    void added(int slot) {
        stale = true;
    }

    @Override
    void moved(int slot, float oldX, float oldY) {
        stale = true;
    }

    @Override
    void removing(int slot) {
        stale = true;
    }

    @Override
    void relocated(int from, int to) {
    }

    @Override
    void cleared() {
        stale = true;
    }

    @Override
    void grown(int capacity) {
        slotA = Arrays.copyOf(slotA, capacity);
        slotB = Arrays.copyOf(slotB, capacity);
        slotLevel = Arrays.copyOf(slotLevel, capacity);
        slotBucket = Arrays.copyOf(slotBucket, capacity);
        seen = Arrays.copyOf(seen, capacity);
        ex = Arrays.copyOf(ex, capacity);
        er = Arrays.copyOf(er, capacity);
        ey = Arrays.copyOf(ey, capacity);
        eb = Arrays.copyOf(eb, capacity);
        eid = Arrays.copyOf(eid, capacity);
        eslot = Arrays.copyOf(eslot, capacity);
        ea = Arrays.copyOf(ea, capacity);
        ebCell = Arrays.copyOf(ebCell, capacity);
        elevel = Arrays.copyOf(elevel, capacity);
        ebucket = Arrays.copyOf(ebucket, capacity);
        byLevel = Arrays.copyOf(byLevel, capacity);
    }

    // ---------------------------------------------------------------- the rebuild

    @Override
    void prepare() {
        if (stale) {
            rebuild();
            stale = false;
        }
    }

    private void rebuild() {
        int n = count;
        if (fixedCell == 0) {
            chooseCell();
        }
        bits = Math.max(4, 33 - Integer.numberOfLeadingZeros(Math.max(n, 1)));  // 2n to 4n buckets
        int buckets = 1 << bits;
        if (start.length < buckets + 1) {
            start = new int[buckets + 1];
        } else {
            Arrays.fill(start, 0, buckets + 1, 0);
        }
        Arrays.fill(levelCount, 0);
        double left = Double.POSITIVE_INFINITY, top = Double.POSITIVE_INFINITY;
        double right = Double.NEGATIVE_INFINITY, bottom = Double.NEGATIVE_INFINITY;
        for (int s = 0; s < n; s++) {
            long x0 = Lattice.cell(xs[s], perCell), x1 = Lattice.cell(rights[s], perCell);
            long y0 = Lattice.cell(ys[s], perCell), y1 = Lattice.cell(bottoms[s], perCell);
            int level = Math.max(Lattice.level(x0, x1), Lattice.level(y0, y1));
            long a = x0 >> level, b = y0 >> level;
            int bucket = bucket(level, a, b);
            slotA[s] = a;
            slotB[s] = b;
            slotLevel[s] = level;
            slotBucket[s] = bucket;
            start[bucket]++;
            levelCount[level]++;
            left = Math.min(left, xs[s]);
            top = Math.min(top, ys[s]);
            right = Math.max(right, rights[s]);
            bottom = Math.max(bottom, bottoms[s]);
        }
        minX = left;
        minY = top;
        maxRight = right;
        maxBottom = bottom;
        // Counting sort: start[k] becomes the end of bucket k, then each entry is placed
        // before it, leaving start[k] at the bucket's beginning.
        int sum = 0;
        for (int k = 0; k < buckets; k++) {
            sum += start[k];
            start[k] = sum;
        }
        start[buckets] = n;
        for (int s = n - 1; s >= 0; s--) {
            int e = --start[slotBucket[s]];
            ex[e] = xs[s];
            er[e] = rights[s];
            ey[e] = ys[s];
            eb[e] = bottoms[s];
            eid[e] = ids[s];
            eslot[e] = s;
            ea[e] = slotA[s];
            ebCell[e] = slotB[s];
            elevel[e] = slotLevel[s];
            ebucket[e] = slotBucket[s];
        }
        // The entries of each level, for the passes across levels.
        levels = 0;
        int at = 0;
        for (int level = 0; level < LEVELS; level++) {
            levelStart[level] = at;
            at += levelCount[level];
            if (levelCount[level] > 0) {
                occupied[levels++] = level;
            }
        }
        levelStart[LEVELS] = at;
        if (levels > 1) {
            int[] fill = sizeCounts;  // reused as a cursor per level
            System.arraycopy(levelStart, 0, fill, 0, LEVELS);
            for (int e = 0; e < n; e++) {
                byLevel[fill[elevel[e]]++] = e;
            }
        }
    }

    /**
     * The base cell: a power of two, twice the median box size rounded up to a power of two
     * (the median from a histogram of the sizes' exponents). When most boxes are points, the
     * size that would put about one box in each cell of their bounds.
     */
    private void chooseCell() {
        int n = count;
        if (n == 0) {
            return;
        }
        Arrays.fill(sizeCounts, 0);
        double left = Double.POSITIVE_INFINITY, top = Double.POSITIVE_INFINITY;
        double right = Double.NEGATIVE_INFINITY, bottom = Double.NEGATIVE_INFINITY;
        for (int s = 0; s < n; s++) {
            sizeCounts[Math.getExponent(Math.max(ws[s], hs[s])) + 127]++;  // 0 and subnormals in bucket 0
        }
        int median = 0;
        for (int k = 0, seenSoFar = 0; k < 256; k++) {
            seenSoFar += sizeCounts[k];
            if (2 * seenSoFar >= n) {
                median = k;
                break;
            }
        }
        if (median > 0) {
            setCell(Math.scalb(1.0, median - 127 + 2));  // sizes in [2^e, 2^(e+1)): cells of 2^(e+2)
            return;
        }
        for (int s = 0; s < n; s++) {
            left = Math.min(left, xs[s]);
            top = Math.min(top, ys[s]);
            right = Math.max(right, rights[s]);
            bottom = Math.max(bottom, bottoms[s]);
        }
        double spread = Math.max(right - left, bottom - top) / Math.sqrt(n);
        setCell(spread > 0 ? Math.scalb(1.0, Math.max(-126, Math.getExponent(spread) + 1)) : 1);
    }

    private int bucket(int level, long a, long b) {
        long h = a * 0x9E3779B97F4A7C15L + b * 0xC2B2AE3D27D4EB4FL + level * 0x165667B19E3779F9L;
        h ^= h >>> 31;
        h *= 0xD6E8FEB86659FD93L;
        return (int) (h >>> (64 - bits));
    }

    // ---------------------------------------------------------------- pairs

    @Override
    void findPairs(PairConsumer out) {
        int n = count;
        long tests = 0;
        for (int e = 0; e < n; e++) {
            int level = elevel[e];
            long a = ea[e], b = ebCell[e];
            float x = ex[e], y = ey[e];
            double r = er[e], bt = eb[e];
            int id = eid[e];
            for (int k = e + 1, end = start[ebucket[e] + 1]; k < end; k++) {
                if (ea[k] == a && ebCell[k] == b && elevel[k] == level) {
                    tests++;
                    if (overlap(x, r, y, bt, ex[k], er[k], ey[k], eb[k])) {
                        emit(out, id, eid[k]);
                    }
                }
            }
            tests += pairsInCell(out, e, level, a + 1, b - 1)
                    + pairsInCell(out, e, level, a + 1, b)
                    + pairsInCell(out, e, level, a + 1, b + 1)
                    + pairsInCell(out, e, level, a, b + 1);
        }
        tally += tests;
        for (int i = 0; i < levels; i++) {
            for (int j = i + 1; j < levels; j++) {
                pairsAcross(out, occupied[i], occupied[j]);
            }
        }
    }

    /** Entry e against the entries of one cell; returns the number of box tests. */
    private int pairsInCell(PairConsumer out, int e, int level, long a, long b) {
        int bucket = bucket(level, a, b);
        int tests = 0;
        for (int k = start[bucket], end = start[bucket + 1]; k < end; k++) {
            if (ea[k] == a && ebCell[k] == b && elevel[k] == level) {
                tests++;
                if (overlap(ex[e], er[e], ey[e], eb[e], ex[k], er[k], ey[k], eb[k])) {
                    emit(out, eid[e], eid[k]);
                }
            }
        }
        return tests;
    }

    /** Every pair with one box at level fine and one at level coarse (fine &lt; coarse). */
    private void pairsAcross(PairConsumer out, int fine, int coarse) {
        double span = Math.scalb(1.0, coarse - fine) + 2;
        boolean fineLooksUp = levelCount[fine] * 9.0 <= levelCount[coarse] * span * span;
        int from = fineLooksUp ? fine : coarse, to = fineLooksUp ? coarse : fine;
        for (int i = levelStart[from], end = levelStart[from + 1]; i < end; i++) {
            int e = byLevel[i];
            lookUp(ex[e], ey[e], er[e], eb[e], to, e, out, null, null);
        }
    }

    // ---------------------------------------------------------------- lookups

    /**
     * Visits every entry at {@code level} whose box can overlap the box (x, y, right, bottom):
     * those in the cells from one before the box's top-left cell to its bottom-right cell, or
     * the whole level when that has fewer entries than the cells. Each entry found is tested
     * against the box and reported as a pair with entry {@code e} (pairs), reported as an id
     * (query), or handed to a ray, whichever is given.
     */
    private void lookUp(double x, double y, double right, double bottom, int level,
                        int e, PairConsumer pairs, IntConsumer ids, RayCast ray) {
        long a0 = (Lattice.cell(x, perCell) >> level) - 1, a1 = Lattice.cell(right, perCell) >> level;
        long b0 = (Lattice.cell(y, perCell) >> level) - 1, b1 = Lattice.cell(bottom, perCell) >> level;
        int tests = 0;
        if ((double) (a1 - a0 + 1) * (b1 - b0 + 1) > levelCount[level]) {
            for (int i = levelStart[level], end = levelStart[level + 1]; i < end; i++) {
                tests += visit(byLevelEntry(i, level), x, y, right, bottom, e, pairs, ids, ray);
            }
        } else {
            for (long a = a0; a <= a1; a++) {
                for (long b = b0; b <= b1; b++) {
                    int bucket = bucket(level, a, b);
                    for (int k = start[bucket], end = start[bucket + 1]; k < end; k++) {
                        if (ea[k] == a && ebCell[k] == b && elevel[k] == level) {
                            tests += visit(k, x, y, right, bottom, e, pairs, ids, ray);
                        }
                    }
                }
            }
        }
        tally += tests;
    }

    /** With one level only, byLevel is not filled: the entries are 0 to n - 1 in order. */
    private int byLevelEntry(int i, int level) {
        return levels > 1 ? byLevel[i] : i;
    }

    private int visit(int k, double x, double y, double right, double bottom,
                      int e, PairConsumer pairs, IntConsumer ids, RayCast ray) {
        if (ray != null) {
            int slot = eslot[k];
            if (seen[slot] != stamp) {
                seen[slot] = stamp;
                ray.consider(slot);
            }
            return 0;
        }
        if (overlap(x, right, y, bottom, ex[k], er[k], ey[k], eb[k])) {
            if (pairs != null) {
                emit(pairs, eid[e], eid[k]);
            } else {
                ids.accept(eid[k]);
            }
        }
        return 1;
    }

    @Override
    void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        for (int i = 0; i < levels; i++) {
            lookUp(x, y, right, bottom, occupied[i], -1, null, out, null);
        }
    }

    /**
     * The ray, cut to the boxes' bounds, in pieces about four base cells long; each piece's
     * bounding box is looked up as a query would be, and each slot handed to the ray once.
     */
    @Override
    void findRayCandidates(RayCast ray) {
        if (count == 0) {
            return;
        }
        double t0 = ray.enter(minX, minY, maxRight, maxBottom), t1 = ray.exit(minX, minY, maxRight, maxBottom);
        if (!(t0 <= t1)) {
            return;
        }
        if (++stamp == 0) {
            Arrays.fill(seen, 0);
            stamp = 1;
        }
        double length = Math.hypot(ray.dx, ray.dy);
        double step = Math.max((t1 - t0) / 4096, 4 * cell / length);
        for (double t = t0; t <= t1; t += step) {
            double u = Math.min(t + step, t1);
            double xa = ray.ox + t * ray.dx, xb = ray.ox + u * ray.dx;
            double ya = ray.oy + t * ray.dy, yb = ray.oy + u * ray.dy;
            double left = Math.min(xa, xb), right = Math.max(xa, xb), top = Math.min(ya, yb), bottom = Math.max(ya, yb);
            double padX = 1e-9 * (Math.abs(left) + Math.abs(right)) + 1e-30;
            double padY = 1e-9 * (Math.abs(top) + Math.abs(bottom)) + 1e-30;
            for (int i = 0; i < levels; i++) {
                lookUp(left - padX, top - padY, right + padX, bottom + padY, occupied[i], -1, null, null, ray);
            }
            if (u >= t1) {
                break;
            }
        }
    }

    /** Each occupied cell once (the first entry of its cell in its bucket draws it). */
    @Override
    void findCells(BoxConsumer out) {
        for (int e = 0; e < count; e++) {
            boolean first = true;
            for (int k = start[ebucket[e]]; k < e && first; k++) {
                first = !(ea[k] == ea[e] && ebCell[k] == ebCell[e] && elevel[k] == elevel[e]);
            }
            if (first) {
                int level = elevel[e];
                double x0 = Lattice.edge(ea[e], level, cell), x1 = Lattice.edge(ea[e] + 1, level, cell);
                double y0 = Lattice.edge(ebCell[e], level, cell), y1 = Lattice.edge(ebCell[e] + 1, level, cell);
                out.box(level, (float) x0, (float) y0, (float) (x1 - x0), (float) (y1 - y0));
            }
        }
    }

    @Override
    public String toString() {
        return fixedCell > 0 ? "grid(" + fixedCell + ")" : "grid";
    }
}
