package hitbox;

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
 * <p>Each test is {@link Shape#overlaps} (or {@link Collide#rectRect} for the raw-float
 * rectangle overloads), so the <a href="package-summary.html#touching">touching rule</a>
 * holds: an obstacle the shape only touches is not hit. Indices are in list order, first to
 * last.
 *
 * <p>A shape is never counted as hitting <em>itself</em>: an element that is the very same
 * object as {@code shape} ({@code ==}) is skipped, so a ball can be tested against the list of
 * all the balls. An equal but separate shape is not skipped.
 *
 * <p>Costs: {@code any}, {@code first}, {@code count} and {@code each} allocate nothing;
 * {@code all} allocates the array it returns. The list or array and each element must not be
 * null (the message names the index); do not add to or remove from the list during
 * {@code each}: collect the indices with {@code all} first, then remove from the last.
 */
public final class Hits {
    private Hits() {
    }

    // ---- a shape against a list of shapes ---------------------------------------------

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
     * The index of the first of the others that the shape overlaps.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the smallest index of an overlapping shape, or -1 if none overlaps
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int first(Shape shape, List<? extends Shape> others) {
        return next(check(shape), check("others", others), 0);
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
        check(shape);
        check("others", others);
        int count = 0;
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            count++;
        }
        return count;
    }

    /**
     * The indices of all the others that the shape overlaps, in order.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return a new array of the overlapping shapes' indices, ascending; empty if none
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int[] all(Shape shape, List<? extends Shape> others) {
        check(shape);
        check("others", others);
        Found found = new Found();
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            found.add(i);
        }
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
        check(shape);
        check("others", others);
        Check.notNull("action", action);
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            action.accept(i);
        }
    }

    private static int next(Shape shape, List<? extends Shape> others, int from) {
        for (int i = from, n = others.size(); i < n; i++) {
            Shape other = element(others, i, "others");
            if (other != shape && shape.overlaps(other)) {
                return i;
            }
        }
        return -1;
    }

    // ---- a shape against an array of shapes -------------------------------------------

    /**
     * Does the shape overlap any of the others?
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return true if at least one of them overlaps the shape
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static boolean any(Shape shape, Shape[] others) {
        return first(shape, others) >= 0;
    }

    /**
     * The index of the first of the others that the shape overlaps.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the smallest index of an overlapping shape, or -1 if none overlaps
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int first(Shape shape, Shape[] others) {
        return next(check(shape), check("others", others), 0);
    }

    /**
     * How many of the others the shape overlaps.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the number of overlapping shapes, 0 or more
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int count(Shape shape, Shape[] others) {
        check(shape);
        check("others", others);
        int count = 0;
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            count++;
        }
        return count;
    }

    /**
     * The indices of all the others that the shape overlaps, in order.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return a new array of the overlapping shapes' indices, ascending; empty if none
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int[] all(Shape shape, Shape[] others) {
        check(shape);
        check("others", others);
        Found found = new Found();
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            found.add(i);
        }
        return found.toArray();
    }

    /**
     * Calls {@code action} with the index of each of the others that the shape overlaps, in
     * order, allocating nothing.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @param action what to do with each overlapping shape's index, not null
     * @throws IllegalArgumentException if {@code shape}, {@code others}, an element or
     *                                  {@code action} is null
     */
    public static void each(Shape shape, Shape[] others, IntConsumer action) {
        check(shape);
        check("others", others);
        Check.notNull("action", action);
        for (int i = next(shape, others, 0); i >= 0; i = next(shape, others, i + 1)) {
            action.accept(i);
        }
    }

    private static int next(Shape shape, Shape[] others, int from) {
        for (int i = from; i < others.length; i++) {
            Shape other = element(others, i, "others");
            if (other != shape && shape.overlaps(other)) {
                return i;
            }
        }
        return -1;
    }

    // ---- a raw-float rectangle against a list of rectangles ---------------------------

    /**
     * Does the rectangle overlap any of the rects? Each test is {@link Collide#rectRect}.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return true if at least one of them overlaps the rectangle
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static boolean any(float x, float y, float w, float h, List<Rect> rects) {
        return first(x, y, w, h, rects) >= 0;
    }

    /**
     * The index of the first of the rects that the rectangle overlaps.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return the smallest index of an overlapping rectangle, or -1 if none overlaps
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int first(float x, float y, float w, float h, List<Rect> rects) {
        return next(x, y, w, h, check("rects", rects), 0);
    }

    /**
     * How many of the rects the rectangle overlaps.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return the number of overlapping rectangles, 0 or more
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int count(float x, float y, float w, float h, List<Rect> rects) {
        check("rects", rects);
        int count = 0;
        for (int i = next(x, y, w, h, rects, 0); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            count++;
        }
        return count;
    }

    /**
     * The indices of all the rects that the rectangle overlaps, in order.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return a new array of the overlapping rectangles' indices, ascending; empty if none
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int[] all(float x, float y, float w, float h, List<Rect> rects) {
        check("rects", rects);
        Found found = new Found();
        for (int i = next(x, y, w, h, rects, 0); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            found.add(i);
        }
        return found.toArray();
    }

    /**
     * Calls {@code action} with the index of each of the rects that the rectangle overlaps,
     * in order, allocating nothing.
     *
     * @param x      the rectangle's left edge
     * @param y      the rectangle's top edge
     * @param w      the rectangle's width
     * @param h      the rectangle's height
     * @param rects  the rectangles to test against, not null and with no null element; do
     *               not add to or remove from it in {@code action}
     * @param action what to do with each overlapping rectangle's index, not null
     * @throws IllegalArgumentException if {@code rects}, an element or {@code action} is null
     */
    public static void each(float x, float y, float w, float h, List<Rect> rects, IntConsumer action) {
        check("rects", rects);
        Check.notNull("action", action);
        for (int i = next(x, y, w, h, rects, 0); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            action.accept(i);
        }
    }

    private static int next(float x, float y, float w, float h, List<Rect> rects, int from) {
        for (int i = from, n = rects.size(); i < n; i++) {
            Rect r = element(rects, i, "rects");
            if (Collide.rectRect(x, y, w, h, r.x(), r.y(), r.w(), r.h())) {
                return i;
            }
        }
        return -1;
    }

    // ---- a raw-float rectangle against an array of rectangles -------------------------

    /**
     * Does the rectangle overlap any of the rects? Each test is {@link Collide#rectRect}.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return true if at least one of them overlaps the rectangle
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static boolean any(float x, float y, float w, float h, Rect[] rects) {
        return first(x, y, w, h, rects) >= 0;
    }

    /**
     * The index of the first of the rects that the rectangle overlaps.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return the smallest index of an overlapping rectangle, or -1 if none overlaps
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int first(float x, float y, float w, float h, Rect[] rects) {
        return next(x, y, w, h, check("rects", rects), 0);
    }

    /**
     * How many of the rects the rectangle overlaps.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return the number of overlapping rectangles, 0 or more
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int count(float x, float y, float w, float h, Rect[] rects) {
        check("rects", rects);
        int count = 0;
        for (int i = next(x, y, w, h, rects, 0); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            count++;
        }
        return count;
    }

    /**
     * The indices of all the rects that the rectangle overlaps, in order.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return a new array of the overlapping rectangles' indices, ascending; empty if none
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int[] all(float x, float y, float w, float h, Rect[] rects) {
        check("rects", rects);
        Found found = new Found();
        for (int i = next(x, y, w, h, rects, 0); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            found.add(i);
        }
        return found.toArray();
    }

    /**
     * Calls {@code action} with the index of each of the rects that the rectangle overlaps,
     * in order, allocating nothing.
     *
     * @param x      the rectangle's left edge
     * @param y      the rectangle's top edge
     * @param w      the rectangle's width
     * @param h      the rectangle's height
     * @param rects  the rectangles to test against, not null and with no null element
     * @param action what to do with each overlapping rectangle's index, not null
     * @throws IllegalArgumentException if {@code rects}, an element or {@code action} is null
     */
    public static void each(float x, float y, float w, float h, Rect[] rects, IntConsumer action) {
        check("rects", rects);
        Check.notNull("action", action);
        for (int i = next(x, y, w, h, rects, 0); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            action.accept(i);
        }
    }

    private static int next(float x, float y, float w, float h, Rect[] rects, int from) {
        for (int i = from; i < rects.length; i++) {
            Rect r = element(rects, i, "rects");
            if (Collide.rectRect(x, y, w, h, r.x(), r.y(), r.w(), r.h())) {
                return i;
            }
        }
        return -1;
    }

    // ---- shared checks, also used by Motion ------------------------------------------

    private static Shape check(Shape shape) {
        return Check.notNull("shape", shape);
    }

    private static <T> T check(String name, T collection) {
        return Check.notNull(name, collection);
    }

    /** Element i of a list, or a learner's message naming the index if it is null. */
    static <T> T element(List<? extends T> list, int i, String name) {
        T t = list.get(i);
        if (t == null) {
            throw new IllegalArgumentException(name + "[" + i + "] is null; remove it from the list or give it a value");
        }
        return t;
    }

    /** Element i of an array, or a learner's message naming the index if it is null. */
    static <T> T element(T[] array, int i, String name) {
        T t = array[i];
        if (t == null) {
            throw new IllegalArgumentException(name + "[" + i + "] is null; an array of shapes needs every slot filled");
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
