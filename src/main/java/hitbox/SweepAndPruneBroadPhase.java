package hitbox;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * {@link BroadPhase#sweepAndPrune()}: the boxes in flat arrays sorted by left edge (entries),
 * each entry a copy of its box so the sweep reads memory in order.
 *
 * <p>Changes only mark the order stale: a new box is appended, a moved box is rewritten in
 * place, a removed box's entry is marked dead. The next question compacts the dead entries
 * and restores the order by insertion sort, which does little work when the boxes moved a
 * little (coherent motion); if it has done more than a few moves per entry, it gives up and
 * sorts all of them at once.
 */
final class SweepAndPruneBroadPhase extends AbstractBroadPhase {
    private static final int DEAD = -1;

    /** Entries in use, dead ones included until the next sort. */
    private int length;
    private float[] ex = new float[0];
    private double[] er = new double[0];
    private float[] ey = new float[0];
    private double[] eb = new double[0];
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
    private long[] sortKeys = new long[0];

    @Override
    void added(int slot) {
        if (length == ex.length) {
            int capacity = Math.max(16, 2 * length);
            ex = Arrays.copyOf(ex, capacity);
            er = Arrays.copyOf(er, capacity);
            ey = Arrays.copyOf(ey, capacity);
            eb = Arrays.copyOf(eb, capacity);
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
    void moved(int slot, float oldX, float oldY) {
        write(entryOf[slot], slot);
    }

    private void write(int e, int slot) {
        ex[e] = xs[slot];
        er[e] = rights[slot];
        ey[e] = ys[slot];
        eb[e] = bottoms[slot];
        stale = true;
    }

    @Override
    void removing(int slot) {
        eslot[entryOf[slot]] = DEAD;
        dead++;
        stale = true;
    }

    @Override
    void relocated(int from, int to) {
        int e = entryOf[from];
        entryOf[to] = e;
        eslot[e] = to;
    }

    @Override
    void cleared() {
        length = 0;
        dead = 0;
        stale = false;
    }

    @Override
    void grown(int capacity) {
        entryOf = Arrays.copyOf(entryOf, capacity);
    }

    // ---------------------------------------------------------------- keeping the order

    @Override
    void prepare() {
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
        for (int e = 0; e < length; e++) {
            wide = Math.max(wide, er[e] - ex[e]);
            top = Math.min(top, ey[e]);
            right = Math.max(right, er[e]);
            bottom = Math.max(bottom, eb[e]);
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
        ex[to] = ex[from];
        er[to] = er[from];
        ey[to] = ey[from];
        eb[to] = eb[from];
        eid[to] = eid[from];
        eslot[to] = eslot[from];
    }

    /** Insertion sort by left edge; false if it gave up after {@code budget} moves. */
    private boolean insertionSort(long budget) {
        long moves = 0;
        for (int i = 1; i < length; i++) {
            float x = ex[i];
            if (!(x < ex[i - 1])) {
                continue;
            }
            double r = er[i], b = eb[i];
            float y = ey[i];
            int id = eid[i], slot = eslot[i];
            int j = i - 1;
            do {
                copy(j, j + 1);
                entryOf[eslot[j + 1]] = j + 1;
                j--;
                moves++;
            } while (j >= 0 && ex[j] > x);
            j++;
            ex[j] = x;
            er[j] = r;
            ey[j] = y;
            eb[j] = b;
            eid[j] = id;
            eslot[j] = slot;
            entryOf[slot] = j;
            if (moves > budget) {
                return false;
            }
        }
        return true;
    }

    /** Sorts every entry: keys of (left edge's bits made sortable, entry), then permuted in place. */
    private void fullSort() {
        if (sortKeys.length < length) {
            sortKeys = new long[ex.length];
        }
        for (int e = 0; e < length; e++) {
            int bits = Float.floatToRawIntBits(ex[e]);
            bits ^= (bits >> 31) & 0x7fffffff;  // negative floats: reverse their order
            sortKeys[e] = (long) bits << 32 | e;
        }
        Arrays.sort(sortKeys, 0, length);
        // Follow each cycle of the permutation, so no second set of arrays is needed.
        for (int e = 0; e < length; e++) {
            int from = (int) sortKeys[e];
            if (from < 0) {
                continue;  // already placed
            }
            int hole = e;
            float x = ex[e], y = ey[e];
            double r = er[e], b = eb[e];
            int id = eid[e], slot = eslot[e];
            while (from != e) {
                copy(from, hole);
                entryOf[eslot[hole]] = hole;
                sortKeys[hole] |= 0xFFFF_FFFFL;  // mark placed (-1 in the low int)
                hole = from;
                from = (int) sortKeys[hole];
            }
            ex[hole] = x;
            er[hole] = r;
            ey[hole] = y;
            eb[hole] = b;
            eid[hole] = id;
            eslot[hole] = slot;
            entryOf[slot] = hole;
            sortKeys[hole] |= 0xFFFF_FFFFL;
        }
    }

    // ---------------------------------------------------------------- the questions

    @Override
    void findPairs(PairConsumer out) {
        long tests = 0;
        int n = length;
        for (int i = 0; i < n; i++) {
            float x = ex[i], y = ey[i];
            double r = er[i], b = eb[i];
            int id = eid[i];
            for (int j = i + 1; j < n && ex[j] < r; j++) {
                tests++;
                if (overlap(x, r, y, b, ex[j], er[j], ey[j], eb[j])) {
                    emit(out, id, eid[j]);
                }
            }
        }
        tally += tests;
    }

    @Override
    void findBoxes(double x, double y, double right, double bottom, IntConsumer out) {
        long tests = 0;
        for (int j = firstEntryFrom(x); j < length && ex[j] < right; j++) {
            tests++;
            if (overlap(x, right, y, bottom, ex[j], er[j], ey[j], eb[j])) {
                out.accept(eid[j]);
            }
        }
        tally += tests;
    }

    /** The first entry whose box could reach right of x: none before it can (its left edge is too far left). */
    private int firstEntryFrom(double x) {
        double from = x - widest;
        from -= 1e-9 * Math.abs(from) + 1e-9 * widest;  // a hair more, against rounding in right - left
        int lo = 0, hi = length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (ex[mid] < from) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    @Override
    void findRayCandidates(RayCast ray) {
        if (length == 0) {
            return;
        }
        double minX = ex[0];
        double t0 = ray.enter(minX, minY, maxRight, maxBottom), t1 = ray.exit(minX, minY, maxRight, maxBottom);
        if (!(t0 <= t1)) {
            return;
        }
        // The stretch of the ray inside the boxes' bounds, and its bounding box: the boxes that
        // meet that bounding box (edges included) are the candidates.
        double xa = ray.ox + t0 * ray.dx, xb = ray.ox + t1 * ray.dx;
        double ya = ray.oy + t0 * ray.dy, yb = ray.oy + t1 * ray.dy;
        double left = Math.min(xa, xb), right = Math.max(xa, xb), top = Math.min(ya, yb), bottom = Math.max(ya, yb);
        double padX = 1e-9 * (Math.abs(left) + Math.abs(right)) + 1e-30;
        double padY = 1e-9 * (Math.abs(top) + Math.abs(bottom)) + 1e-30;
        left -= padX;
        right += padX;
        top -= padY;
        bottom += padY;
        for (int j = firstEntryFrom(left); j < length && ex[j] <= right; j++) {
            if (er[j] >= left && ey[j] <= bottom && eb[j] >= top) {
                ray.consider(eslot[j]);
            }
        }
    }

    @Override
    public String toString() {
        return "sweepAndPrune";
    }
}
