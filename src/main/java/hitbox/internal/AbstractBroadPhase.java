package hitbox.internal;

import hitbox.*;

import java.util.Arrays;
import java.util.function.IntConsumer;

/**
 * What every {@link BroadPhase} shares: the boxes themselves, in dense slots (slot 0 to
 * {@code count - 1}, a removed box's slot filled by the last one), the id-to-slot map, the
 * argument checks, the exact overlap test, and the machinery of shape queries and rays. Each
 * structure adds its own index over the slots through the hooks below.
 *
 * <p>The exact test is {@link #overlap}: {@link Collide#rectRect} with each box's right and
 * bottom edges stored as {@code (double) x + w}, the very sums rectRect makes, so the answers
 * are the same to the last bit. A box is kept as four doubles side by side, {@code x, right,
 * y, bottom} (see {@link #box}): one array read in order is what makes the tight loops fast.
 *
 * <p>A ray cast's own geometry (the pruning of regions, the sorting of hits) is in
 * {@link RayCast}.
 */
public abstract class AbstractBroadPhase implements BroadPhase {

    /** How many boxes are stored: slots 0 to count - 1. */
    public int count;
    public int[] ids = new int[0];
    /**
     * Slot s's box at {@code 4 * s}: its left edge x, its right edge {@code (double) x + w} (as
     * rectRect computes it), its top edge y and its bottom edge {@code (double) y + h}.
     */
    public double[] box = new double[0];
    /** The sizes as given, for {@link #w} and {@link #h} (right - x may round differently). */
    public float[] ws = new float[0];
    public float[] hs = new float[0];

    /** Box tests made so far; {@link #checks} is the difference over one call. */
    public long tally;
    private long lastChecks;

    private final IdSlots slotOf = new IdSlots();
    private int reading;
    private RayCast idleRay;

    // ---------------------------------------------------------------- hooks for the structures

    /** A box was stored in a new slot (its numbers are already in the arrays). */
    public abstract void added(int slot);

    /** The box in this slot moved or changed size (the arrays hold the new numbers). */
    public abstract void moved(int slot, float oldX, float oldY);

    /** The box in this slot is about to go; its numbers are still in the arrays. */
    public abstract void removing(int slot);

    /** The box in slot {@code from} now lives in slot {@code to} (after a removal). */
    public abstract void relocated(int from, int to);

    /** Every box is gone. */
    public abstract void cleared();

    /** The slot arrays now hold {@code capacity} slots: grow the structure's own per-slot arrays. */
    public abstract void grown(int capacity);

    /** Brings the structure up to date before a question (a rebuild or a sort, if needed). */
    public void prepare() {
    }

    /** Reports every overlapping pair once, through {@link #emit}. */
    public abstract void findPairs(PairConsumer out);

    /**
     * Reports the id of every box that overlaps the query box by {@link #overlap}, once each.
     * The query's edges are doubles so that a shape's bounds can be given exactly.
     */
    public abstract void findBoxes(double x, double y, double right, double bottom, IntConsumer out);

    /** Hands the ray every slot whose box it might go into ({@link RayCast#consider}), once each. */
    public abstract void findRayCandidates(RayCast ray);

    /** Reports the structure's regions for drawing; none by default. */
    public void findCells(BoxConsumer out) {
    }

    // ---------------------------------------------------------------- the exact test, one home

    /**
     * {@link Collide#rectRect}, on left and top edges and the right and bottom edges as it
     * computes them ({@code (double) x + w}); floats widen to double exactly, so this is the
     * same comparison. The four comparisons are joined with {@code &}, not {@code &&}: no
     * branch for the processor to guess wrong in the loops that call this millions of times.
     */
    public static boolean overlap(double x1, double right1, double y1, double bottom1,
                           double x2, double right2, double y2, double bottom2) {
        return right1 > x2 & x1 < right2 & bottom1 > y2 & y1 < bottom2;
    }

    /** Do the boxes at i and j overlap, each four doubles as in {@link #box}? */
    public static boolean overlap(double[] a, int i, double[] b, int j) {
        return overlap(a[i], a[i + 1], a[i + 2], a[i + 3], b[j], b[j + 1], b[j + 2], b[j + 3]);
    }

    /** Reports a pair, smaller id first (min and max, not an if: which comes first is a coin toss). */
    public static void emit(PairConsumer out, int idA, int idB) {
        out.pair(Math.min(idA, idB), Math.max(idA, idB));
    }

    // ---------------------------------------------------------------- changing

    @Override
    public final void put(int id, float x, float y, float w, float h) {
        checkId(id);
        Check.finite("x", x);
        Check.finite("y", y);
        Check.size("w", w);
        Check.size("h", h);
        checkNotReading();
        int slot = slotOf.get(id);
        if (slot < 0) {
            if (count == ids.length) {
                grow();
            }
            slot = count++;
            ids[slot] = id;
            store(slot, x, y, w, h);
            slotOf.put(id, slot);
            added(slot);
        } else {
            float oldX = (float) box[4 * slot], oldY = (float) box[4 * slot + 2];
            store(slot, x, y, w, h);
            moved(slot, oldX, oldY);
        }
    }

    /**
     * Puts a box already held, as {@link #put(int, float, float, float, float)} does, if the
     * structure can take it with no work before its next question (for the grid: the box
     * stays in its cell and level); else changes nothing. For a caller that batches the other
     * changes (the world's waiting boxes): a box put here need not wait.
     *
     * @return whether the box was put
     */
    public final boolean putInPlace(int id, float x, float y, float w, float h) {
        int slot = reading > 0 ? -1 : slotOf.get(id);
        if (slot < 0 || !Float.isFinite(x) || !Float.isFinite(y) || !(w >= 0) || !(h >= 0)
                || w == Float.POSITIVE_INFINITY || h == Float.POSITIVE_INFINITY
                || !fitsInPlace(slot, x, (double) x + w, y, (double) y + h)) {
            return false;
        }
        store(slot, x, y, w, h);
        placedInPlace(slot);
        return true;
    }

    /**
     * Can slot s take a new box (its edges as in {@link #box}) with no work before the next
     * question? False unless a structure says so.
     */
    public boolean fitsInPlace(int slot, double x, double right, double y, double bottom) {
        return false;
    }

    /** Slot s took a new box that {@link #fitsInPlace} allowed (the arrays hold its numbers). */
    public void placedInPlace(int slot) {
    }

    @Override
    public final void put(int id, Shape shape) {
        checkId(id);
        Rect b = Check.notNull("shape", shape).bounds();
        put(id, b.x(), b.y(), b.w(), b.h());
    }

    private void store(int slot, float x, float y, float w, float h) {
        int k = 4 * slot;
        box[k] = x;
        box[k + 1] = (double) x + w;
        box[k + 2] = y;
        box[k + 3] = (double) y + h;
        ws[slot] = w;
        hs[slot] = h;
    }

    @Override
    public final boolean remove(int id) {
        checkId(id);
        checkNotReading();
        int slot = slotOf.get(id);
        if (slot < 0) {
            return false;
        }
        removing(slot);
        int last = count - 1;
        if (slot != last) {
            ids[slot] = ids[last];
            System.arraycopy(box, 4 * last, box, 4 * slot, 4);
            ws[slot] = ws[last];
            hs[slot] = hs[last];
            slotOf.put(ids[slot], slot);
            relocated(last, slot);
        }
        count = last;
        slotOf.remove(id);
        return true;
    }

    @Override
    public final void clear() {
        checkNotReading();
        count = 0;
        slotOf.clear();
        cleared();
    }

    private void grow() {
        int capacity = Math.max(16, ids.length * 2);
        ids = Arrays.copyOf(ids, capacity);
        box = Arrays.copyOf(box, 4 * capacity);
        ws = Arrays.copyOf(ws, capacity);
        hs = Arrays.copyOf(hs, capacity);
        grown(capacity);
    }

    // ---------------------------------------------------------------- reading the boxes

    @Override
    public final int size() {
        return count;
    }

    @Override
    public final boolean contains(int id) {
        return slotOf.get(checkId(id)) >= 0;
    }

    public final float x(int id) {
        return (float) box[4 * slotOf(id)];
    }

    /** @return the top edge of the box stored under the id */
    public final float y(int id) {
        return (float) box[4 * slotOf(id) + 2];
    }

    /** @return the width of the box stored under the id */
    public final float w(int id) {
        return ws[slotOf(id)];
    }

    /** @return the height of the box stored under the id */
    public final float h(int id) {
        return hs[slotOf(id)];
    }

    private int slotOf(int id) {
        int slot = slotOf.get(checkId(id));
        if (slot < 0) {
            throw new IllegalArgumentException("id " + id + " is not stored; put it first");
        }
        return slot;
    }

    /** Visits every stored id once, in no particular order (for {@link BroadPhaseHits}). */
    public final void forEach(IntConsumer out) {
        Check.notNull("out", out);
        reading++;
        try {
            for (int s = 0; s < count; s++) {
                out.accept(ids[s]);
            }
        } finally {
            reading--;
        }
    }

    @Override
    public final void forEachBox(BoxConsumer out) {
        Check.notNull("out", out);
        reading++;
        try {
            for (int s = 0; s < count; s++) {
                out.box(ids[s], (float) box[4 * s], (float) box[4 * s + 2], ws[s], hs[s]);
            }
        } finally {
            reading--;
        }
    }

    // ---------------------------------------------------------------- the questions

    @Override
    public final void pairs(PairConsumer out) {
        Check.notNull("out", out);
        long start = begin();
        try {
            findPairs(out);
        } finally {
            end(start);
        }
    }

    @Override
    public final void query(float x, float y, float w, float h, IntConsumer out) {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.size("w", w);
        Check.size("h", h);
        Check.notNull("out", out);
        long start = begin();
        try {
            findBoxes(x, y, (double) x + w, (double) y + h, out);
        } finally {
            end(start);
        }
    }

    @Override
    public final void raycast(Ray ray, RayVisitor out) {
        Check.notNull("ray", ray);
        Check.notNull("out", out);
        RayCast cast = idleRay != null ? idleRay : new RayCast(this);
        idleRay = null;  // a ray cast from inside the visitor gets its own
        long start = begin();
        try {
            cast.run(ray, out);
        } finally {
            end(start);
            idleRay = cast;
        }
    }

    @Override
    public final long checks() {
        return lastChecks;
    }

    @Override
    public final void cells(BoxConsumer out) {
        Check.notNull("out", out);
        begin();
        try {
            findCells(out);
        } finally {
            reading--;
        }
    }

    private long begin() {
        if (reading == 0) {
            prepare();
        }
        reading++;
        return tally;
    }

    private void end(long start) {
        reading--;
        lastChecks = tally - start;
    }

    // ---------------------------------------------------------------- checks

    public static int checkId(int id) {
        if (id < 0) {
            throw new IllegalArgumentException("id must be >= 0, was " + id);
        }
        return id;
    }

    private void checkNotReading() {
        if (reading > 0) {
            throw new IllegalStateException("a broad phase cannot change while pairs, query, raycast or forEachBox"
                    + " is running: collect the ids in the callback, then put or remove them afterwards");
        }
    }
}
