package hitbox.internal;

import hitbox.*;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * {@link BroadPhase#sweepAndPrune()}: the boxes in a flat array sorted by left edge (entries),
 * each entry a copy of its box (four doubles, as {@link #box}) so the sweep reads memory in
 * order.
 *
 * <p>Changes only mark the order stale: a new box is appended, a moved box is rewritten in
 * place, a removed box's entry is marked dead. The next question compacts the dead entries
 * and restores the order by insertion sort, which does little work when the boxes moved a
 * little (coherent motion); if it has done more than a few moves per entry, it gives up and
 * sorts all of them at once, by a radix sort on the left edges' bits (three passes, no
 * allocation once grown).
 */
public final class SweepAndPruneBroadPhase extends AbstractBroadPhase {
    private static final int DEAD = -1;

    /** Entries in use, dead ones included until the next sort. */
    private int length;
    /** Entry e's box at 4 * e: x, right, y, bottom. */
    private double[] ebox = new double[0];
    private int[] eid = new int[0];
    private int[] eslot = new int[0];
    /** The entry of each slot. */
    private int[] entryOf = new int[0];
    private int dead;
    private boolean stale;
    /** After a sort: the widest box (right - left), and the bounds of all boxes, for queries and rays. */
    private double widest;
    private double minY;
    private double maxRight;
    private double maxBottom;
    // The full sort's scratch: keys and entries, and a second pair of each for the radix passes.
    private int[] sortKey = new int[0];
    private int[] sortEntry = new int[0];
    private int[] sortKey2 = new int[0];
    private int[] sortEntry2 = new int[0];
    private final int[] digitCount = new int[2049];

    @Override
    public void added(int slot) {
        if (length == eid.length) {
            int capacity = Math.max(16, 2 * length);
            ebox = Arrays.copyOf(ebox, 4 * capacity);
            eid = Arrays.copyOf(eid, capacity);
            eslot = Arrays.copyOf(eslot, capacity);
        }
        int e = length++;
        eid[e] = ids[slot];
        eslot[e] = slot;
        entryOf[slot] = e;
        write(e, slot);
    }

    @Override
    public void moved(int slot, float oldX, float oldY) {
        write(entryOf[slot], slot);
    }

    private void write(int e, int slot) {
        System.arraycopy(box, 4 * slot, ebox, 4 * e, 4);
        stale = true;
    }

    @Override
    public void removing(int slot) {
        eslot[entryOf[slot]] = DEAD;
        dead++;
        stale = true;
    }

    @Override
    public void relocated(int from, int to) {
        int e = entryOf[from];
        entryOf[to] = e;
        eslot[e] = to;
    }

    @Override
    public void cleared() {
        length = 0;
        dead = 0;
        stale = false;
    }

    @Override
    public void grown(int capacity) {
        entryOf = Arrays.copyOf(entryOf, capacity);
    }

    // ---------------------------------------------------------------- keeping the order

    @Override
    public void prepare() {
        if (!stale) {
            return;
        }
        if (dead > 0) {
            compact();
        }
        if (!insertionSort(4L * length + 64)) {
            fullSort();
        }
        double wide = 0, top = Double.POSITIVE_INFINITY, right = Double.NEGATIVE_INFINITY, bottom = Double.NEGATIVE_INFINITY;
        double[] b = ebox;
        for (int k = 0; k < 4 * length; k += 4) {
            wide = Math.max(wide, b[k + 1] - b[k]);
            right = Math.max(right, b[k + 1]);
            top = Math.min(top, b[k + 2]);
            bottom = Math.max(bottom, b[k + 3]);
        }
        widest = wide;
        minY = top;
        maxRight = right;
        maxBottom = bottom;
        stale = false;
    }

    private void compact() {
        int to = 0;
        for (int e = 0; e < length; e++) {
            int slot = eslot[e];
            if (slot != DEAD) {
                copy(e, to);
                entryOf[slot] = to++;
            }
        }
        length = to;
        dead = 0;
    }

    private void copy(int from, int to) {
        System.arraycopy(ebox, 4 * from, ebox, 4 * to, 4);
        eid[to] = eid[from];
        eslot[to] = eslot[from];
    }

    /** Insertion sort by left edge; false if it gave up after {@code budget} moves. */
    private boolean insertionSort(long budget) {
        long moves = 0;
        double[] b = ebox;
        for (int i = 1; i < length; i++) {
            double x = b[4 * i];
            if (!(x < b[4 * i - 4])) {
                continue;
            }
            double r = b[4 * i + 1], y = b[4 * i + 2], bottom = b[4 * i + 3];
            int id = eid[i], slot = eslot[i];
            int j = i - 1;
            do {
                copy(j, j + 1);
                entryOf[eslot[j + 1]] = j + 1;
                j--;
                moves++;
            } while (j >= 0 && b[4 * j] > x);
            j++;
            set(j, x, r, y, bottom, id, slot);
            if (moves > budget) {
                return false;
            }
        }
        return true;
    }

    private void set(int e, double x, double r, double y, double bottom, int id, int slot) {
        int k = 4 * e;
        ebox[k] = x;
        ebox[k + 1] = r;
        ebox[k + 2] = y;
        ebox[k + 3] = bottom;
        eid[e] = id;
        eslot[e] = slot;
        entryOf[slot] = e;
    }

    /** Sorts every entry: a radix sort of the left edges' bits, then the entries moved along each cycle of the order. */
    private void fullSort() {
        if (sortKey.length < length) {
            sortKey = new int[eid.length];
            sortEntry = new int[eid.length];
            sortKey2 = new int[eid.length];
            sortEntry2 = new int[eid.length];
        }
        for (int e = 0; e < length; e++) {
            int bits = Float.floatToRawIntBits((float) ebox[4 * e]);  // exact: the left edge is a float
            // Negative floats in reverse, then the sign bit flipped: the bits now sort as unsigned ints.
            sortKey[e] = (bits ^ ((bits >> 31) & 0x7fffffff)) ^ 0x80000000;
            sortEntry[e] = e;
        }
        for (int shift = 0; shift < 32; shift += 11) {
            Arrays.fill(digitCount, 0);
            for (int e = 0; e < length; e++) {
                digitCount[(sortKey[e] >>> shift & 0x7FF) + 1]++;
            }
            for (int d = 1; d < digitCount.length; d++) {
                digitCount[d] += digitCount[d - 1];
            }
            for (int e = 0; e < length; e++) {
                int at = digitCount[sortKey[e] >>> shift & 0x7FF]++;
                sortKey2[at] = sortKey[e];
                sortEntry2[at] = sortEntry[e];
            }
            int[] swap = sortKey;
            sortKey = sortKey2;
            sortKey2 = swap;
            swap = sortEntry;
            sortEntry = sortEntry2;
            sortEntry2 = swap;
        }
        // sortEntry[e] is the entry that belongs at e. Follow each cycle, so no second set of
        // entry arrays is needed; -1 marks a place filled.
        for (int e = 0; e < length; e++) {
            int from = sortEntry[e];
            if (from < 0) {
                continue;
            }
            int hole = e;
            double x = ebox[4 * e], r = ebox[4 * e + 1], y = ebox[4 * e + 2], b = ebox[4 * e + 3];
            int id = eid[e], slot = eslot[e];
            while (from != e) {
                copy(from, hole);
                entryOf[eslot[hole]] = hole;
                sortEntry[hole] = -1;
                hole = from;
                from = sortEntry[hole];
            }
            set(hole, x, r, y, b, id, slot);
            sortEntry[hole] = -1;
        }
    }

    // ---------------------------------------------------------------- the questions

    @Override
    public void findPairs(PairConsumer out) {
        long tests = 0;
        int end = 4 * length;
        double[] b = ebox;  // locals: the callback could change a field, so it would be read again after each
        int[] id = eid;
        for (int i = 0; i < end; i += 4) {
            double right = b[i + 1];
            int j = i + 4;
            for (; j < end && b[j] < right; j += 4) {
                if (overlap(b, i, b, j)) {
                    emit(out, id[i >> 2], id[j >> 2]);
                }
            }
            tests += (j - i - 4) >> 2;
        }
        tally += tests;
    }

    @Override
    public void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        long tests = 0;
        double[] b = ebox;
        for (int j = firstEntryFrom(x); j < length && b[4 * j] < right; j++) {
            tests++;
            int k = 4 * j;
            if (overlap(x, right, y, bottom, b[k], b[k + 1], b[k + 2], b[k + 3])) {
                out.accept(eid[j]);
            }
        }
        tally += tests;
    }

    /** The first entry whose box could reach right of x: none before it can (its left edge is too far left). */
    private int firstEntryFrom(double x) {
        double from = x - widest;
        from -= Tolerance.PAD * Math.abs(from) + Tolerance.PAD * widest;  // a hair more, against rounding in right - left
        int lo = 0, hi = length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (ebox[4 * mid] < from) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    @Override
    public void findRayCandidates(RayCast ray) {
        if (length == 0) {
            return;
        }
        double minX = ebox[0];
        double t0 = ray.enter(minX, minY, maxRight, maxBottom), t1 = ray.exit(minX, minY, maxRight, maxBottom);
        if (!(t0 <= t1)) {
            return;
        }
        // The stretch of the ray inside the boxes' bounds, and its bounding box: the boxes that
        // meet that bounding box (edges included) are the candidates.
        double xa = ray.ox + t0 * ray.dx, xb = ray.ox + t1 * ray.dx;
        double ya = ray.oy + t0 * ray.dy, yb = ray.oy + t1 * ray.dy;
        double left = Math.min(xa, xb), right = Math.max(xa, xb), top = Math.min(ya, yb), bottom = Math.max(ya, yb);
        double padX = Tolerance.pad(left, right);
        double padY = Tolerance.pad(top, bottom);
        left -= padX;
        right += padX;
        top -= padY;
        bottom += padY;
        double[] b = ebox;
        for (int j = firstEntryFrom(left); j < length && b[4 * j] <= right; j++) {
            if (b[4 * j + 1] >= left && b[4 * j + 2] <= bottom && b[4 * j + 3] >= top) {
                ray.consider(eslot[j]);
            }
        }
    }

    @Override
    public String toString() {
        return "sweepAndPrune";
    }
}
