package hitbox;

import hitbox.internal.*;

import java.util.List;

/**
 * Many objects: the tutorial's loop over a list of obstacles, written once. Ask whether a shape
 * hits {@link #any any} of them, or the index of the {@link #first first} one it hits:
 * <pre>{@code
 * int i = Hits.first(player, walls);      // -1 if none
 * if (i >= 0) {
 *   Rect wall = walls.get(i);
 *   ...
 * }
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
 * <p>Costs: {@code any} and {@code first} allocate nothing. The list and each element must not
 * be null (an {@link IllegalArgumentException} names the index). An array of shapes is asked
 * as {@code List.of(array)} or {@code Arrays.asList(array)}.
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

    /** Element i of a list, or a learner's message naming the index if it is null. */
    static <T> T element(List<? extends T> list, int i, String name) {
        T t = list.get(i);
        if (t == null) {
            throw new IllegalArgumentException(name + "[" + i + "] is null; remove it or give it a value");
        }
        return t;
    }
}
