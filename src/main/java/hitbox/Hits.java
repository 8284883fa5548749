package hitbox;

import hitbox.internal.*;

import java.util.Arrays;
import java.util.List;
import java.util.function.IntConsumer;

/**
 * Many objects: the tutorial's loop over a list of obstacles, written once. Ask whether a shape
 * hits {@link #any any} of them, the index of the {@link #first first} one it hits, how many
 * it hits ({@link #count count}), {@link #all all} their indices, or visit each hit with
 * {@link #each each}:
 * <pre>{@code
 * int i = Hits.first(player, walls);      // -1 if none
 * if (i >= 0) {
 *   Rect wall = walls.get(i);
 *   ...
 * }
 * Hits.each(bullet, enemies, i -> hit[i] = true);
 * }</pre>
 *
 * <p>Each test is {@link Shape#overlaps}, so the <a href="package-summary.html#touching">touching
 * rule</a> holds: an obstacle the shape only touches is not hit. Indices are in list order,
 * first to last. For thousands of obstacles keep their boxes in a {@link BroadPhase}, ask it for
 * the boxes under the shape's {@link Shape#bounds() bounds}
 * ({@link BroadPhase#query(float, float, float, float, java.util.function.IntConsumer)}), and
 * test only those.
 *
 * <p>A shape is never counted as hitting <em>itself</em>: an element that is the very same
 * object as {@code shape} ({@code ==}) is skipped, so a ball can be tested against the list of
 * all the balls. An equal but separate shape is not skipped.
 *
 * <p>Costs: {@code any}, {@code first}, {@code count} and {@code each} allocate nothing;
 * {@code all} allocates the array it returns. The list and each element must not be null (an
 * {@link IllegalArgumentException} names the index); do not add to or remove from the list
 * during {@code each}: collect the indices with {@code all} first, then remove from the last.
 * An array of shapes is asked as {@code List.of(array)} or {@code Arrays.asList(array)}.
 */
public final class Hits {
    private Hits() {
    }

    // ---- a shape against a list of shapes ------------------------------------------

    /**
     * Does the shape overlap any of the others?
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return true if at least one of them overlaps the shape
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static boolean any(Shape shape, List<? extends Shape> others) {
        return first(shape, others) >= 0;
    }

    /**
     * The index of the first of the others that the shape overlaps. An index into
     * {@code others}, as {@link List#indexOf} gives: not a {@link Hit} (a {@code Hit} is a
     * sweep's moment of impact) and not the shape: the shape itself is
     * {@code others.get(i)}.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the smallest index of an overlapping shape, or -1 if none overlaps
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int first(Shape shape, List<? extends Shape> others) {
        return next(Check.notNull("shape", shape), Check.notNull("others", others), 0);
    }

    /**
     * How many of the others the shape overlaps.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the number of overlapping shapes, 0 or more
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int count(Shape shape, List<? extends Shape> others) {
        int n = 0;
        for (int i = first(shape, others); i >= 0; i = next(shape, others, i + 1)) {
            n++;
        }
        return n;
    }

    /**
     * The indices of all the others that the shape overlaps, in order.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return a new array of the overlapping shapes' indices, ascending; empty if none, never null
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int[] all(Shape shape, List<? extends Shape> others) {
        Found found = new Found();
        each(shape, others, found::add);
        return found.toArray();
    }

    /**
     * Calls {@code action} with the index of each of the others that the shape overlaps, in
     * order, allocating nothing.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element; do not
     *               add to or remove from it in {@code action}
     * @param action what to do with each overlapping shape's index, not null
     * @throws IllegalArgumentException if {@code shape}, {@code others}, an element or
     *                                  {@code action} is null
     */
    public static void each(Shape shape, List<? extends Shape> others, IntConsumer action) {
        Check.notNull("shape", shape);
        Check.notNull("others", others);
        Check.notNull("action", action);
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            action.accept(i);
        }
    }

    /** The first index from {@code from} on whose shape overlaps {@code shape} (never itself), or -1. */
    private static int next(Shape shape, List<? extends Shape> others, int from) {
        for (int i = from, n = others.size(); i < n; i++) {
            Shape other = element(others, i, "others");
            if (other != shape && shape.overlaps(other)) {
                return i;
            }
        }
        return -1;
    }

    // ---- shared checks, also used by Motion -------------------------------------------

    /** A fixed-size list view of the array (no copy), after checking it is there. */
    /** Element i of a list, or a learner's message naming the index if it is null. */
    static <T> T element(List<? extends T> list, int i, String name) {
        T t = list.get(i);
        if (t == null) {
            throw new IllegalArgumentException(name + "[" + i + "] is null; remove it or give it a value");
        }
        return t;
    }

    /** A growing list of ints, so {@code all} makes one pass without boxing. */
    private static final class Found {
        private int[] items = new int[8];
        private int size;

        void add(int i) {
            if (size == items.length) {
                items = Arrays.copyOf(items, size * 2);
            }
            items[size++] = i;
        }

        int[] toArray() {
            return Arrays.copyOf(items, size);
        }
    }
}
