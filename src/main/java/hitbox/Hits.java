package hitbox;

import hitbox.internal.*;

import java.util.Arrays;
import java.util.List;
import java.util.function.IntConsumer;

/**
 * Many objects: the tutorial's loop over a list of obstacles, written once. Ask whether a shape
 * hits {@link #any any} of them, the index of the {@link #first first} one it hits (or the
 * shape itself, {@link #firstShape firstShape}), how many
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
 * <p>Costs: {@code any}, {@code first}, {@code count} and {@code each} allocate nothing on a
 * list (on an array, only a fixed-size view of it, {@link Arrays#asList}); {@code all}
 * allocates the array it returns. The list or array and each element must not be null (an
 * {@link IllegalArgumentException} names the index); do not add to or remove from the list
 * during {@code each}: collect the indices with {@code all} first, then remove from the last.
 * Every question has one implementation, on a list; the array overloads hand a view of the
 * array to it.
 *
 * <p>Which form to call: a shape against a list or an array of shapes, a raw-float
 * rectangle ({@code x, y, w, h}, the tutorial's way) against a list of {@code Rect}s, or a
 * raw-float rectangle against a {@link BroadPhase} for thousands. The raw-float rectangle
 * against an array of {@code Rect}s is deprecated (kept one release).
 *
 * <p>This class is longer than most (about 590 lines) because it is the public face of five
 * questions for three kinds of obstacle list (shapes, raw rectangles, a broad phase), in list
 * and array forms, each overload with its full javadoc; each answer is a few lines, every
 * array overload hands a view to the list one, and the broad-phase work is in
 * {@code BroadPhaseHits}.
 */
public final class Hits {
    private Hits() {
    }

    // ---- a shape against a list (or an array) of shapes ----------------------------

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
     * sweep's moment of impact) and not the shape; for the shape itself, call
     * {@link #firstShape(Shape, List)}.
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
     * The first of the others that the shape overlaps, itself rather than its index: the
     * element {@link #first(Shape, List)} points at, so
     * {@code Rect wall = Hits.firstShape(player, walls);} needs no {@code get(i)}.
     *
     * @param <T>    the kind of the others ({@code Rect}, {@code Shape}, ...)
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the first overlapping shape, or null if none overlaps
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static <T extends Shape> T firstShape(Shape shape, List<T> others) {
        int i = first(shape, others);
        return i < 0 ? null : others.get(i);
    }

    /**
     * The first of the others that the shape overlaps, itself rather than its index:
     * {@link #firstShape(Shape, List)} for an array.
     *
     * @param <T>    the kind of the others ({@code Rect}, {@code Shape}, ...)
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the first overlapping shape, or null if none overlaps
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static <T extends Shape> T firstShape(Shape shape, T[] others) {
        return firstShape(shape, view("others", others));
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

    /**
     * Does the shape overlap any of the others? {@link #any(Shape, List)} for an array.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return true if at least one of them overlaps the shape
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static boolean any(Shape shape, Shape[] others) {
        return any(shape, view("others", others));
    }

    /**
     * The index of the first of the others that the shape overlaps. {@link #first(Shape, List)}
     * for an array.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the smallest index of an overlapping shape, or -1 if none overlaps
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int first(Shape shape, Shape[] others) {
        return first(shape, view("others", others));
    }

    /**
     * How many of the others the shape overlaps. {@link #count(Shape, List)} for an array.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return the number of overlapping shapes, 0 or more
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int count(Shape shape, Shape[] others) {
        return count(shape, view("others", others));
    }

    /**
     * The indices of all the others that the shape overlaps, in order.
     * {@link #all(Shape, List)} for an array.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @return a new array of the overlapping shapes' indices, ascending; empty if none, never null
     * @throws IllegalArgumentException if {@code shape}, {@code others} or an element is null
     */
    public static int[] all(Shape shape, Shape[] others) {
        return all(shape, view("others", others));
    }

    /**
     * Calls {@code action} with the index of each of the others that the shape overlaps, in
     * order. {@link #each(Shape, List, IntConsumer)} for an array.
     *
     * @param shape  the shape, not null
     * @param others the shapes to test against, not null and with no null element
     * @param action what to do with each overlapping shape's index, not null
     * @throws IllegalArgumentException if {@code shape}, {@code others}, an element or
     *                                  {@code action} is null
     */
    public static void each(Shape shape, Shape[] others, IntConsumer action) {
        each(shape, view("others", others), action);
    }

    // ---- a raw-float rectangle against a list (or an array) of rectangles -------------

    /**
     * Does the rectangle overlap any of the rects? Each test is {@link Collide#rectRect}.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return true if at least one of them overlaps the rectangle (false for NaN)
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
     * @return the smallest index of an overlapping rectangle, or -1 if none overlaps (or for NaN)
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int first(float x, float y, float w, float h, List<Rect> rects) {
        return next(x, y, w, h, Check.notNull("rects", rects), 0);
    }

    /**
     * How many of the rects the rectangle overlaps.
     *
     * <p>A NaN in any argument answers 0
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
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
        int n = 0;
        for (int i = first(x, y, w, h, rects); i >= 0; i = next(x, y, w, h, rects, i + 1)) {
            n++;
        }
        return n;
    }

    /**
     * The indices of all the rects that the rectangle overlaps, in order.
     *
     * <p>A NaN in any argument answers an empty array
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return a new array of the overlapping rectangles' indices, ascending; empty if none, never null
     * @throws IllegalArgumentException if {@code rects} or an element is null
     */
    public static int[] all(float x, float y, float w, float h, List<Rect> rects) {
        Found found = new Found();
        each(x, y, w, h, rects, found::add);
        return found.toArray();
    }

    /**
     * Calls {@code action} with the index of each of the rects that the rectangle overlaps,
     * in order, allocating nothing.
     *
     * <p>A NaN in any argument finds nothing: {@code action} is not called
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
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
        Check.notNull("rects", rects);
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

    /**
     * Does the rectangle overlap any of the rects? {@link #any(float, float, float, float, List)}
     * for an array.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return true if at least one of them overlaps the rectangle (false for NaN)
     * @throws IllegalArgumentException if {@code rects} or an element is null
     * @deprecated kept one release: a raw-float rectangle against an array of {@code Rect}s is
     *             a form the tutorial never writes; call {@link #any(float, float, float, float, List)} with
     *             {@code Arrays.asList(rects)}, or {@link #any(Shape, Shape[])} with the
     *             rectangle as a {@code Rect}.
     */
    @Deprecated
    public static boolean any(float x, float y, float w, float h, Rect[] rects) {
        return any(x, y, w, h, view("rects", rects));
    }

    /**
     * The index of the first of the rects that the rectangle overlaps; see
     * {@link #first(float, float, float, float, List)}.
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return the smallest index of an overlapping rectangle, or -1 if none overlaps (or for NaN)
     * @throws IllegalArgumentException if {@code rects} or an element is null
     * @deprecated kept one release: a raw-float rectangle against an array of {@code Rect}s is
     *             a form the tutorial never writes; call {@link #first(float, float, float, float, List)} with
     *             {@code Arrays.asList(rects)}, or {@link #first(Shape, Shape[])} with the
     *             rectangle as a {@code Rect}.
     */
    @Deprecated
    public static int first(float x, float y, float w, float h, Rect[] rects) {
        return first(x, y, w, h, view("rects", rects));
    }

    /**
     * How many of the rects the rectangle overlaps; see
     * {@link #count(float, float, float, float, List)}.
     *
     * <p>A NaN in any argument answers 0
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return the number of overlapping rectangles, 0 or more
     * @throws IllegalArgumentException if {@code rects} or an element is null
     * @deprecated kept one release: a raw-float rectangle against an array of {@code Rect}s is
     *             a form the tutorial never writes; call {@link #count(float, float, float, float, List)} with
     *             {@code Arrays.asList(rects)}, or {@link #count(Shape, Shape[])} with the
     *             rectangle as a {@code Rect}.
     */
    @Deprecated
    public static int count(float x, float y, float w, float h, Rect[] rects) {
        return count(x, y, w, h, view("rects", rects));
    }

    /**
     * The indices of all the rects that the rectangle overlaps, in order; see
     * {@link #all(float, float, float, float, List)}.
     *
     * <p>A NaN in any argument answers an empty array
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x     the rectangle's left edge
     * @param y     the rectangle's top edge
     * @param w     the rectangle's width
     * @param h     the rectangle's height
     * @param rects the rectangles to test against, not null and with no null element
     * @return a new array of the overlapping rectangles' indices, ascending; empty if none, never null
     * @throws IllegalArgumentException if {@code rects} or an element is null
     * @deprecated kept one release: a raw-float rectangle against an array of {@code Rect}s is
     *             a form the tutorial never writes; call {@link #all(float, float, float, float, List)} with
     *             {@code Arrays.asList(rects)}, or {@link #all(Shape, Shape[])} with the
     *             rectangle as a {@code Rect}.
     */
    @Deprecated
    public static int[] all(float x, float y, float w, float h, Rect[] rects) {
        return all(x, y, w, h, view("rects", rects));
    }

    /**
     * Calls {@code action} with the index of each of the rects that the rectangle overlaps,
     * in order; see {@link #each(float, float, float, float, List, IntConsumer)}.
     *
     * <p>A NaN in any argument finds nothing: {@code action} is not called
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x      the rectangle's left edge
     * @param y      the rectangle's top edge
     * @param w      the rectangle's width
     * @param h      the rectangle's height
     * @param rects  the rectangles to test against, not null and with no null element
     * @param action what to do with each overlapping rectangle's index, not null
     * @throws IllegalArgumentException if {@code rects}, an element or {@code action} is null
     * @deprecated kept one release: a raw-float rectangle against an array of {@code Rect}s is
     *             a form the tutorial never writes; call {@link #each(float, float, float, float, List, IntConsumer)} with
     *             {@code Arrays.asList(rects)}, or {@link #each(Shape, Shape[], IntConsumer)} with the
     *             rectangle as a {@code Rect}.
     */
    @Deprecated
    public static void each(float x, float y, float w, float h, Rect[] rects, IntConsumer action) {
        each(x, y, w, h, view("rects", rects), action);
    }

    // ---- shared checks, also used by Motion ------------------------------------------

    /** A fixed-size list view of the array (no copy), after checking it is there. */
    static <T> List<T> view(String name, T[] array) {
        return Arrays.asList(Check.notNull(name, array));
    }

    /** Element i of a list, or a learner's message naming the index if it is null. */
    static <T> T element(List<? extends T> list, int i, String name) {
        T t = list.get(i);
        if (t == null) {
            throw new IllegalArgumentException(name + "[" + i + "] is null; remove it or give it a value");
        }
        return t;
    }

    /** A growing list of ints, so {@code all} makes one pass without boxing. */
    // ---- obstacles in a broad phase -----------------------------------------------------

    /**
     * Does the rectangle overlap any box of the broad phase? The same answer as
     * {@link #any(float, float, float, float, List)} over the same boxes, found by asking the
     * broad phase for the nearby ones only, so thousands of obstacles cost little.
     *
     * @param x         the rectangle's left edge
     * @param y         the rectangle's top edge
     * @param w         the rectangle's width
     * @param h         the rectangle's height
     * @param obstacles the obstacles, each stored under its id, not null
     * @return true if at least one stored box overlaps the rectangle (false for NaN)
     * @throws IllegalArgumentException if {@code obstacles} is null
     */
    public static boolean any(float x, float y, float w, float h, BroadPhase obstacles) {
        return BroadPhaseHits.overlapping(obstacles, x, y, w, h).length > 0;
    }

    /**
     * The smallest id of a box of the broad phase that the rectangle overlaps.
     *
     * @param x         the rectangle's left edge
     * @param y         the rectangle's top edge
     * @param w         the rectangle's width
     * @param h         the rectangle's height
     * @param obstacles the obstacles, each stored under its id, not null
     * @return the smallest overlapping id, or -1 if none overlaps (or for NaN)
     * @throws IllegalArgumentException if {@code obstacles} is null
     */
    public static int first(float x, float y, float w, float h, BroadPhase obstacles) {
        int[] ids = BroadPhaseHits.overlapping(obstacles, x, y, w, h);
        return ids.length > 0 ? ids[0] : -1;
    }

    /**
     * How many boxes of the broad phase the rectangle overlaps.
     *
     * <p>A NaN in any argument answers 0
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the rectangle's left edge
     * @param y         the rectangle's top edge
     * @param w         the rectangle's width
     * @param h         the rectangle's height
     * @param obstacles the obstacles, each stored under its id, not null
     * @return the number of overlapping boxes, 0 or more
     * @throws IllegalArgumentException if {@code obstacles} is null
     */
    public static int count(float x, float y, float w, float h, BroadPhase obstacles) {
        return BroadPhaseHits.overlapping(obstacles, x, y, w, h).length;
    }

    /**
     * The ids of all the boxes of the broad phase that the rectangle overlaps.
     *
     * <p>A NaN in any argument answers an empty array
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the rectangle's left edge
     * @param y         the rectangle's top edge
     * @param w         the rectangle's width
     * @param h         the rectangle's height
     * @param obstacles the obstacles, each stored under its id, not null
     * @return a new array of the overlapping ids, ascending; empty if none, never null
     * @throws IllegalArgumentException if {@code obstacles} is null
     */
    public static int[] all(float x, float y, float w, float h, BroadPhase obstacles) {
        return BroadPhaseHits.overlapping(obstacles, x, y, w, h);
    }

    /**
     * Calls {@code action} with the id of each box of the broad phase that the rectangle
     * overlaps, ascending.
     *
     * <p>A NaN in any argument finds nothing: {@code action} is not called
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param x         the rectangle's left edge
     * @param y         the rectangle's top edge
     * @param w         the rectangle's width
     * @param h         the rectangle's height
     * @param obstacles the obstacles, each stored under its id, not null; it may be changed
     *                  in {@code action}, since the ids are found first
     * @param action    what to do with each overlapping id, not null
     * @throws IllegalArgumentException if {@code obstacles} or {@code action} is null
     */
    public static void each(float x, float y, float w, float h, BroadPhase obstacles, IntConsumer action) {
        Check.notNull("action", action);
        for (int id : BroadPhaseHits.overlapping(obstacles, x, y, w, h)) {
            action.accept(id);
        }
    }

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
