package hitbox.internal;

import hitbox.*;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * {@link BroadPhase#grid()}: a grid per level over the {@link Lattice}, rebuilt from scratch by
 * the first question after a change, except a box's move that keeps it in its level and cell,
 * which changes only its entry's copy of the box (as most moves from one frame to the next do).
 *
 * <p>Each box goes to the finest level at which its edges are at most one cell apart (level L
 * has cells {@code 2^L} times the base cell), in the cell of its top-left corner. Each occupied
 * level has its own region of buckets:
 * <ul>
 *   <li><b>dense</b> when its boxes span few enough cells (at most about eight times as many
 *       cells as boxes): one bucket per cell of the span, row by row, with an empty row above
 *       and below and an empty column on the right, so a bucket is a cell, no cell needs
 *       checking, and a cell and the one on its right are side by side in memory, as are the
 *       three below them;</li>
 *   <li><b>hashed</b> otherwise (sparse or enormous worlds): the cell's column and row wrapped
 *       into a power-of-two rectangle of about two buckets per box, and each entry keeps its
 *       cell, to tell apart the cells that share a bucket.</li>
 * </ul>
 * A counting sort lays the boxes out bucket by bucket, level by level (entries: copies of the
 * boxes, four doubles each), so each cell's boxes are side by side in memory and the cells
 * next door were just read.
 *
 * <p>Pairs within a level: each cell's boxes with each other, and with the boxes of four of its
 * neighbours (right, below-left, below, below-right), so each pair of neighbouring cells is
 * looked at from one side only. Pairs across levels L &lt; M: either each level-L box looks up
 * the two or three cells per axis of level M it can reach, or each level-M box looks up the
 * cells of level L it covers, whichever looks up fewer; a level is scanned whole when that is
 * cheaper still.
 *
 * <p>This class is longer than most (about 640 lines) because it is one data structure: the
 * rebuild, the choice of cell size, the dense and hashed levels and the lookups all share the
 * same bucket and entry arrays; the cell arithmetic they rest on is already apart, in
 * {@link Lattice}.
 */
public final class HashGridBroadPhase extends AbstractBroadPhase {
    private static final int LEVELS = 63;

    /** The cell size asked for, or 0 to choose it from the boxes. */
    private final float fixedCell;
    private double cell;
    private double perCell;
    private boolean stale;

    // Per entry (bucket order), filled by the rebuild.
    /** Entry e's box at 4 * e: x, right, y, bottom. */
    private double[] ebox = new double[0];
    private int[] eid = new int[0];
    private int[] eslot = new int[0];
    /** An entry's bucket, so that the pairs can go entry by entry without looking at empty buckets. */
    private int[] ebucket = new int[0];
    /** An entry's cell, kept for hashed levels only. */
    private long[] ea = new long[0];
    private long[] eb = new long[0];

    // Per slot, scratch of the rebuild.
    private long[] slotA = new long[0];
    private long[] slotB = new long[0];
    private int[] slotLevel = new int[0];
    private int[] slotBucket = new int[0];
    /** Each slot's entry, from the last rebuild: where a box that stays in its cell is updated. */
    private int[] slotEntry = new int[0];

    /** Bucket k's entries are start[k] to start[k + 1] - 1. */
    private int[] start = new int[1];

    // Per level.
    private final int[] levelCount = new int[LEVELS];
    private final boolean[] dense = new boolean[LEVELS];
    /** The level's first bucket. */
    private final int[] base = new int[LEVELS];
    /** The cell the level's columns and rows count from. */
    private final long[] originA = new long[LEVELS];
    private final long[] originB = new long[LEVELS];
    /** Dense: the columns and rows of the span. Hashed: the bits of each. */
    private final long[] columns = new long[LEVELS];
    private final long[] rows = new long[LEVELS];
    private final long[] lastA = new long[LEVELS];
    private final long[] lastB = new long[LEVELS];
    private final int[] occupied = new int[LEVELS];
    /**
     * A dense level's bucket of cell (a, b) is {@code denseOffset + a + b * (columns + 1)}: its
     * base, less its origin, one row down (in long arithmetic, which wraps exactly).
     */
    private final long[] denseOffset = new long[LEVELS];
    private int levels;

    private double minX;
    private double minY;
    private double maxRight;
    private double maxBottom;
    /** For rays: the stamp of the cast that last considered each slot. */
    private int[] seen = new int[0];
    private int stamp;
    private final int[] sizeCounts = new int[1024];

    public HashGridBroadPhase(float cellSize) {
        fixedCell = cellSize;
        setCell(cellSize > 0 ? cellSize : 1);
    }

    private void setCell(double size) {
        cell = size;
        perCell = 1 / size;
    }

    @Override
    public void added(int slot) {
        stale = true;
    }

    @Override
    public void moved(int slot, float oldX, float oldY) {
        int k = 4 * slot;
        if (fitsInPlace(slot, box[k], box[k + 1], box[k + 2], box[k + 3])) {
            placedInPlace(slot);
        } else {
            stale = true;
        }
    }

    /**
     * A box that goes to the same level and the same cell as the slot's entry from the last
     * rebuild needs none: only the entry's copy of the box changes (and the bounds, widened).
     * A box moved a little inside its cell, as most are from one frame to the next, keeps the
     * grid as it is.
     */
    @Override
    public boolean fitsInPlace(int slot, double x, double right, double y, double bottom) {
        if (stale) {
            return false;
        }
        long x0 = Lattice.cell(x, perCell), x1 = Lattice.cell(right, perCell);
        long y0 = Lattice.cell(y, perCell), y1 = Lattice.cell(bottom, perCell);
        int level = Math.max(Lattice.level(x0, x1), Lattice.level(y0, y1));
        return level == slotLevel[slot] && x0 >> level == slotA[slot] && y0 >> level == slotB[slot];
    }

    @Override
    public void placedInPlace(int slot) {
        int k = 4 * slot, j = 4 * slotEntry[slot];
        ebox[j] = box[k];
        ebox[j + 1] = box[k + 1];
        ebox[j + 2] = box[k + 2];
        ebox[j + 3] = box[k + 3];
        minX = Math.min(minX, box[k]);
        maxRight = Math.max(maxRight, box[k + 1]);
        minY = Math.min(minY, box[k + 2]);
        maxBottom = Math.max(maxBottom, box[k + 3]);
    }

    @Override
    public void removing(int slot) {
        stale = true;
    }

    @Override
    public void relocated(int from, int to) {
    }

    @Override
    public void cleared() {
        stale = true;
    }

    @Override
    public void grown(int capacity) {
        slotA = Arrays.copyOf(slotA, capacity);
        slotB = Arrays.copyOf(slotB, capacity);
        slotLevel = Arrays.copyOf(slotLevel, capacity);
        slotBucket = Arrays.copyOf(slotBucket, capacity);
        slotEntry = Arrays.copyOf(slotEntry, capacity);
        seen = Arrays.copyOf(seen, capacity);
        ebox = Arrays.copyOf(ebox, 4 * capacity);
        eid = Arrays.copyOf(eid, capacity);
        eslot = Arrays.copyOf(eslot, capacity);
        ebucket = Arrays.copyOf(ebucket, capacity);
        ea = Arrays.copyOf(ea, capacity);
        eb = Arrays.copyOf(eb, capacity);
    }

    // ---------------------------------------------------------------- the rebuild

    @Override
    public void prepare() {
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
        Arrays.fill(levelCount, 0);
        Arrays.fill(originA, Long.MAX_VALUE);
        Arrays.fill(originB, Long.MAX_VALUE);
        Arrays.fill(lastA, Long.MIN_VALUE);
        Arrays.fill(lastB, Long.MIN_VALUE);
        double[] bx = box;
        double left = Double.POSITIVE_INFINITY, top = Double.POSITIVE_INFINITY;
        double right = Double.NEGATIVE_INFINITY, bottom = Double.NEGATIVE_INFINITY;
        for (int s = 0, k = 0; s < n; s++, k += 4) {
            long x0 = Lattice.cell(bx[k], perCell), x1 = Lattice.cell(bx[k + 1], perCell);
            long y0 = Lattice.cell(bx[k + 2], perCell), y1 = Lattice.cell(bx[k + 3], perCell);
            int level = Math.max(Lattice.level(x0, x1), Lattice.level(y0, y1));
            long a = x0 >> level, b = y0 >> level;
            slotA[s] = a;
            slotB[s] = b;
            slotLevel[s] = level;
            levelCount[level]++;
            originA[level] = Math.min(originA[level], a);
            lastA[level] = Math.max(lastA[level], a);
            originB[level] = Math.min(originB[level], b);
            lastB[level] = Math.max(lastB[level], b);
            left = Math.min(left, bx[k]);
            right = Math.max(right, bx[k + 1]);
            top = Math.min(top, bx[k + 2]);
            bottom = Math.max(bottom, bx[k + 3]);
        }
        minX = left;
        minY = top;
        maxRight = right;
        maxBottom = bottom;
        int buckets = layOutLevels();
        if (start.length < buckets + 1) {
            start = new int[buckets + buckets / 4 + 64];  // room to grow: spans change a little every frame
        } else {
            Arrays.fill(start, 0, buckets + 1, 0);
        }
        for (int s = 0; s < n; s++) {
            int level = slotLevel[s];
            // A dense level's bucket without bucket()'s range checks: every box is inside its level's span.
            int bucket = dense[level] ? (int) (denseOffset[level] + slotA[s] + slotB[s] * (columns[level] + 1))
                    : bucket(level, slotA[s], slotB[s]);
            slotBucket[s] = bucket;
            start[bucket]++;
        }
        // Counting sort: start[k] becomes the end of bucket k, then each entry is placed
        // before it, leaving start[k] at the bucket's beginning.
        int sum = 0;
        for (int k = 0; k < buckets; k++) {
            sum += start[k];
            start[k] = sum;
        }
        start[buckets] = n;
        for (int s = n - 1; s >= 0; s--) {
            int e = --start[slotBucket[s]], k = 4 * s, j = 4 * e;
            ebox[j] = bx[k];
            ebox[j + 1] = bx[k + 1];
            ebox[j + 2] = bx[k + 2];
            ebox[j + 3] = bx[k + 3];
            eid[e] = ids[s];
            eslot[e] = s;
            slotEntry[s] = e;
            ebucket[e] = slotBucket[s];
            if (!dense[slotLevel[s]]) {
                ea[e] = slotA[s];
                eb[e] = slotB[s];
            }
        }
    }

    /**
     * Gives each occupied level its region of buckets, dense or hashed (see the class
     * description), one after the other; returns the number of buckets.
     */
    private int layOutLevels() {
        levels = 0;
        int next = 0;
        for (int level = 0; level < LEVELS; level++) {
            int n = levelCount[level];
            if (n == 0) {
                continue;
            }
            occupied[levels++] = level;
            base[level] = next;
            long spanA = lastA[level] - originA[level] + 1, spanB = lastB[level] - originB[level] + 1;
            int bits = 33 - Integer.numberOfLeadingZeros(Math.max(n, 8));  // 2n to 4n buckets
            dense[level] = (double) (spanA + 1) * (spanB + 2) <= 8.0 * n + 4096;
            if (dense[level]) {
                // A row of empty cells above and below, and a column of them on the right, so that
                // every cell has the four neighbours the pairs look at.
                columns[level] = spanA;
                rows[level] = spanB;
                denseOffset[level] = next - originA[level] + (1 - originB[level]) * (spanA + 1);
                next += (int) ((spanA + 1) * (spanB + 2));
            } else {
                int wide = 64 - Long.numberOfLeadingZeros(spanA - 1), tall = 64 - Long.numberOfLeadingZeros(spanB - 1);
                // Columns get the bits they need if the rows still fit; else each axis wraps, the
                // rows keeping what they need when that leaves the columns half the bits or more.
                int columnBits = wide + tall <= bits ? wide : Math.min(wide, Math.max(bits - tall, bits / 2));
                columns[level] = columnBits;
                rows[level] = bits - columnBits;
                next += 1 << bits;
            }
        }
        return next;
    }

    /** The bucket of cell (a, b) of a level, or -1 for a cell outside a dense level's span. */
    private int bucket(int level, long a, long b) {
        long column = a - originA[level], row = b - originB[level];
        if (dense[level]) {
            if (column < 0 || column >= columns[level] || row < 0 || row >= rows[level]) {
                return -1;
            }
            return base[level] + (int) (column + (row + 1) * (columns[level] + 1));
        }
        int columnBits = (int) columns[level];
        long columnMask = (1L << columnBits) - 1, rowMask = (1L << rows[level]) - 1;
        return base[level] + ((int) (column & columnMask) | (int) (row & rowMask) << columnBits);
    }

    /**
     * The base cell, from a histogram of the boxes' sizes ({@code max(w, h)}), four bins to
     * each power of two: the top of the bin that holds nine boxes in ten, so that most boxes
     * share the finest level and the few larger ones go up. When most boxes are points, the
     * size that would put about one box in each cell of their bounds.
     */
    private void chooseCell() {
        int n = count;
        if (n == 0) {
            return;
        }
        Arrays.fill(sizeCounts, 0);
        for (int s = 0; s < n; s++) {
            sizeCounts[bin(Math.max(ws[s], hs[s]))]++;
        }
        int at = 0;
        for (int k = 0, seenSoFar = 0; k < sizeCounts.length; k++) {
            seenSoFar += sizeCounts[k];
            if (10L * seenSoFar >= 9L * n) {
                at = k;
                break;
            }
        }
        if (at > 0) {
            setCell(Math.min(binTop(at), Float.MAX_VALUE));
            return;
        }
        double left = Double.POSITIVE_INFINITY, top = Double.POSITIVE_INFINITY;
        double right = Double.NEGATIVE_INFINITY, bottom = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < 4 * n; k += 4) {
            left = Math.min(left, box[k]);
            right = Math.max(right, box[k + 1]);
            top = Math.min(top, box[k + 2]);
            bottom = Math.max(bottom, box[k + 3]);
        }
        double spread = Math.max(right - left, bottom - top) / Math.sqrt(n);
        setCell(spread > 0 && spread < Float.MAX_VALUE ? spread : 1);
    }

    /** The histogram bin of a size: 4 per power of two (the exponent and the next two bits); 0 for 0 and subnormals. */
    private static int bin(float size) {
        int bits = Float.floatToRawIntBits(size);
        return bits >>> 21 & 0x3FF;  // the 8 exponent bits and the top 2 of the mantissa
    }

    /** The largest size in a bin (rounded up a hair). */
    private static double binTop(int bin) {
        return Float.intBitsToFloat((bin + 1) << 21);
    }

    // ---------------------------------------------------------------- pairs

    @Override
    public void findPairs(PairConsumer out) {
        for (int i = 0; i < levels; i++) {
            int level = occupied[i];
            if (dense[level]) {
                densePairs(out, level);
            } else {
                hashedPairs(out, level);
            }
        }
        for (int i = 0; i < levels; i++) {
            for (int j = i + 1; j < levels; j++) {
                pairsAcross(out, occupied[i], occupied[j]);
            }
        }
    }

    /**
     * A dense level, entry by entry: each box against the boxes after it in its cell and in the
     * cell on its right (side by side in memory), and against the three cells below, from
     * below-left to below-right (side by side too: the empty column on the right of a row is the
     * cell left of the next row's first). Those are half the eight neighbours, so each pair of
     * neighbouring cells is looked at from one side only; and going by entries, not by cells,
     * no empty cell is looked at.
     */
    private void densePairs(PairConsumer out, int level) {
        int stride = (int) columns[level] + 1;
        int[] at = start, bucketOf = ebucket;
        double[] b = ebox;  // a local: the callback could change a field, so it would be read again after each
        long tests = 0;
        for (int i = levelFirst(level), last = i + levelCount[level]; i < last; i++) {
            int bucket = bucketOf[i];
            int rightEnd = at[bucket + 2], below = at[bucket + stride - 1], belowEnd = at[bucket + stride + 2];
            int k = 4 * i;
            double x = b[k], right = b[k + 1], y = b[k + 2], bottom = b[k + 3];
            for (int j = i + 1; j < rightEnd; j++) {
                if (overlap(x, right, y, bottom, b[4 * j], b[4 * j + 1], b[4 * j + 2], b[4 * j + 3])) {
                    emitEntries(out, i, j);
                }
            }
            for (int j = below; j < belowEnd; j++) {
                if (overlap(x, right, y, bottom, b[4 * j], b[4 * j + 1], b[4 * j + 2], b[4 * j + 3])) {
                    emitEntries(out, i, j);
                }
            }
            tests += (rightEnd - i - 1) + (belowEnd - below);
        }
        tally += tests;
    }

    private void emitEntries(PairConsumer out, int e, int k) {
        emit(out, eid[e], eid[k]);
    }

    /** A hashed level, entry by entry: its own cell after it, then the four cells after its own. */
    private void hashedPairs(PairConsumer out, int level) {
        long tests = 0;
        for (int e = levelFirst(level), last = e + levelCount[level]; e < last; e++) {
            long a = ea[e], b = eb[e];
            for (int k = e + 1, end = start[bucket(level, a, b) + 1]; k < end; k++) {
                if (ea[k] == a && eb[k] == b) {
                    tests++;
                    if (overlap(ebox, 4 * e, ebox, 4 * k)) {
                        emitEntries(out, e, k);
                    }
                }
            }
            tests += cellPairs(out, e, level, a + 1, b - 1) + cellPairs(out, e, level, a + 1, b)
                    + cellPairs(out, e, level, a + 1, b + 1) + cellPairs(out, e, level, a, b + 1);
        }
        tally += tests;
    }

    /** Entry e against the entries of one cell of a hashed level; returns the number of tests. */
    private int cellPairs(PairConsumer out, int e, int level, long a, long b) {
        int bucket = bucket(level, a, b), tests = 0;
        for (int k = start[bucket], end = start[bucket + 1]; k < end; k++) {
            if (ea[k] == a && eb[k] == b) {
                tests++;
                if (overlap(ebox, 4 * e, ebox, 4 * k)) {
                    emitEntries(out, e, k);
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
        for (int e = levelFirst(from), end = levelFirst(from) + levelCount[from]; e < end; e++) {
            int k = 4 * e;
            lookUp(ebox[k], ebox[k + 2], ebox[k + 1], ebox[k + 3], to, e, out, null, null);
        }
    }

    /** The first entry of a level: its region's first bucket's. */
    private int levelFirst(int level) {
        return start[base[level]];
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
        long tests = 0;
        if (dense[level]) {
            // Only the part of the range inside the level's span has buckets.
            a0 = Math.max(a0, originA[level]);
            a1 = Math.min(a1, lastA[level]);
            b0 = Math.max(b0, originB[level]);
            b1 = Math.min(b1, lastB[level]);
        }
        if (a0 > a1 || b0 > b1) {
            return;
        }
        if ((double) (a1 - a0 + 1) * (b1 - b0 + 1) > levelCount[level]) {
            for (int k = levelFirst(level), end = k + levelCount[level]; k < end; k++) {
                tests += visit(k, x, y, right, bottom, e, pairs, ids, ray);
            }
        } else {
            for (long b = b0; b <= b1; b++) {
                for (long a = a0; a <= a1; a++) {
                    int bucket = bucket(level, a, b);
                    for (int k = start[bucket], end = start[bucket + 1]; k < end; k++) {
                        if (dense[level] || ea[k] == a && eb[k] == b) {
                            tests += visit(k, x, y, right, bottom, e, pairs, ids, ray);
                        }
                    }
                }
            }
        }
        tally += tests;
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
        int j = 4 * k;
        if (overlap(x, right, y, bottom, ebox[j], ebox[j + 1], ebox[j + 2], ebox[j + 3])) {
            if (pairs != null) {
                emitEntries(pairs, e, k);
            } else {
                ids.accept(eid[k]);
            }
        }
        return 1;
    }

    @Override
    public void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        for (int i = 0; i < levels; i++) {
            lookUp(x, y, right, bottom, occupied[i], -1, null, out, null);
        }
    }

    /**
     * The ray, cut to the boxes' bounds, in pieces about four base cells long; each piece's
     * bounding box is looked up as a query would be, and each slot handed to the ray once.
     */
    @Override
    public void findRayCandidates(RayCast ray) {
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
            double padX = Tolerance.pad(left, right);
            double padY = Tolerance.pad(top, bottom);
            for (int i = 0; i < levels; i++) {
                lookUp(left - padX, top - padY, right + padX, bottom + padY, occupied[i], -1, null, null, ray);
            }
            if (u >= t1) {
                break;
            }
        }
    }

    /** Each occupied cell once: a dense level's non-empty buckets, a hashed level's first entry of each cell in its bucket. */
    @Override
    public void findCells(BoxConsumer out) {
        for (int i = 0; i < levels; i++) {
            int level = occupied[i];
            for (int e = levelFirst(level), end = e + levelCount[level]; e < end; e++) {
                long a, b;
                int bucket;
                if (dense[level]) {
                    bucket = bucketOfEntry(level, e);
                    if (start[bucket] != e) {
                        continue;
                    }
                    int within = bucket - base[level];
                    a = originA[level] + within % (columns[level] + 1);
                    b = originB[level] + within / (columns[level] + 1) - 1;
                } else {
                    a = ea[e];
                    b = eb[e];
                    bucket = bucket(level, a, b);
                    boolean first = true;
                    for (int k = start[bucket]; k < e && first; k++) {
                        first = !(ea[k] == a && eb[k] == b);
                    }
                    if (!first) {
                        continue;
                    }
                }
                double x0 = Lattice.edge(a, level, cell), x1 = Lattice.edge(a + 1, level, cell);
                double y0 = Lattice.edge(b, level, cell), y1 = Lattice.edge(b + 1, level, cell);
                out.box(level, (float) x0, (float) y0, (float) (x1 - x0), (float) (y1 - y0));
            }
        }
    }

    /** The bucket an entry of a dense level is in: the last bucket that starts at or before it. */
    private int bucketOfEntry(int level, int e) {
        int lo = base[level], hi = base[level] + (int) ((columns[level] + 1) * (rows[level] + 2)) - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (start[mid] <= e) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    @Override
    public String toString() {
        return fixedCell > 0 ? "grid(" + fixedCell + ")" : "grid";
    }
}
