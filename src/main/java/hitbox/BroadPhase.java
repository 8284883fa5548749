package hitbox;

import hitbox.internal.*;

import java.util.function.IntConsumer;

/**
 * A broad phase: many boxes, each under an id you choose, and the one question an all-pairs
 * loop answers slowly, "which of them overlap?". The tutorial's section 10 names the tool for
 * it: location-based structures such as R-trees and quadtrees, which organise the objects so
 * that a player on the left of the screen is not checked against the objects on the right.
 * <pre>{@code
 * BroadPhase world = BroadPhase.grid();
 * for (int i = 0; i < n; i++) {
 *   world.put(i, x[i], y[i], w[i], h[i]);       // add, or move if already there
 * }
 * world.pairs((a, b) -> { hit[a] = true; hit[b] = true; });
 * world.query(mouseX - 20, mouseY - 20, 40, 40, id -> picked[id] = true);
 * }</pre>
 *
 * <h2>One answer, five structures</h2>
 * Two boxes overlap exactly when {@link Collide#rectRect} says so on the stored numbers: the
 * <a href="package-summary.html#touching">touching rule</a> (boxes side by side are not a
 * pair), boxes of width or height 0 included, any finite coordinates, near the origin or far
 * from it. Every structure gives the same pairs whatever happened before (which boxes moved,
 * were removed or came back), and reports each pair once, smaller id first. They differ only
 * in speed:
 * <table>
 *   <caption>Which structure to pick</caption>
 *   <tr><th>factory</th><th>how it works</th><th>pick it when</th></tr>
 *   <tr><td>{@link #grid()}</td><td>a hash grid, rebuilt by counting sort on the first question
 *       after a change; boxes larger than a cell go to coarser grids</td>
 *       <td>most boxes move every frame: the fastest here for thousands of moving boxes, and
 *       the default choice</td></tr>
 *   <tr><td>{@link #sweepAndPrune()}</td><td>boxes sorted by left edge, kept sorted by
 *       insertion sort as they move</td><td>up to some thousands of boxes moving a little each
 *       frame, spread more across than down</td></tr>
 *   <tr><td>{@link #dynamicTree()}</td><td>a balanced tree of slightly enlarged boxes, Box2D's
 *       {@code b2DynamicTree}</td><td>many boxes stand still and a few move, or the boxes have
 *       very different sizes; many queries and rays between changes</td></tr>
 *   <tr><td>{@link #quadtree()}</td><td>a loose quadtree that splits crowded squares into four</td>
 *       <td>to see how space is divided ({@link #cells}), and for boxes that mostly stay
 *       put</td></tr>
 *   <tr><td>{@link #bruteForce()}</td><td>every pair, n(n-1)/2 tests</td><td>a few dozen
 *       boxes, and as the reference the others are tested against</td></tr>
 * </table>
 * {@code docs/benchmarks.md} (linked from the README) gives the numbers.
 *
 * <h2>Rules</h2>
 * <ul>
 *   <li>Ids are 0 or more, in any order and as sparse as you like (an id need not be an
 *       index). A box is its top-left corner and size, as {@link Rect}.</li>
 *   <li>Bad input is refused before anything changes: a NaN or infinite coordinate, a negative
 *       size or id, or a null argument throws an {@link IllegalArgumentException} that names
 *       the parameter, such as {@code "w must be >= 0, was -1.0"}, and the structure is as it
 *       was.</li>
 *   <li>While {@link #pairs}, {@link #query}, {@link #raycast} or {@link #forEachBox} is
 *       running, its callback may read ({@link #contains}, {@link #query}, ...) but not change the
 *       structure: {@link #put}, {@link #remove} and {@link #clear} then throw an
 *       {@link IllegalStateException}. Collect the ids, change afterwards.</li>
 *   <li>Once it has grown to its size, moving boxes with {@code put} and asking for pairs or
 *       box queries allocates nothing; {@link #raycast} sorts its hits and may allocate for
 *       very many of them. Not thread-safe: one thread at a time.</li>
 *   <li>Each structure's {@code toString()} is the name of its factory, for labels.</li>
 * </ul>
 */
public interface BroadPhase {

    /**
     * The reference: every pair tested, n(n-1)/2 tests for n boxes. Fast enough for a few
     * dozen boxes, and simple enough to trust.
     *
     * @return an empty brute-force broad phase, never null
     */
    static BroadPhase bruteForce() {
        return new BruteForceBroadPhase();
    }

    /**
     * A uniform grid whose cell size is chosen from the boxes each time it is rebuilt: about
     * the size ({@code max(w, h)}) that 9 boxes in 10 do not exceed, or, when most boxes are
     * points, the spacing that puts about one box in each cell of their bounds.
     *
     * <p>Each box is stored once, in the cell of its top-left corner, in the finest grid whose
     * cells are at least as large as the box; larger boxes go to grids of cells 2, 4, 8... times
     * as large, so a few very large boxes do not slow down the rest. Each grid is an array of
     * cells where the boxes are dense enough, and hashed where they are sparse (a world with a
     * few boxes far apart costs no more than a small one). The grid is rebuilt (by counting
     * sort, in time proportional to the number of boxes) by the first {@link #pairs},
     * {@link #query} or {@link #raycast} after a change, which suits boxes that all move every
     * frame. Any float coordinates work; beyond about 2^61 cells from the origin the cells are
     * shared, which is still exact but slower.
     *
     * @return an empty grid, never null
     */
    static BroadPhase grid() {
        return new HashGridBroadPhase(0);
    }

    /**
     * A loose quadtree. Each square of the tree holds the boxes whose top-left corner is in it
     * and that are no larger than it (so a box overlaps at most the square and its neighbours
     * right and below: the square "loosened" to twice its size). A square holding more than 8
     * boxes splits into four, and the boxes small enough go down; a square whose part of the
     * tree holds 4 or fewer merges back. The squares are powers of two in size and the root
     * grows to take in any box, so there are no world bounds to set. A box that moves within
     * its square costs nothing to update. The smallest squares are 2^-16 pixels; beyond about
     * 3 * 10^13 pixels from the origin boxes share squares, which is still exact but slower.
     *
     * @return an empty quadtree, never null
     */
    static BroadPhase quadtree() {
        return new QuadtreeBroadPhase();
    }

    /**
     * Sweep and prune: the boxes sorted by their left edge, kept sorted by an insertion sort,
     * which costs little when the boxes move a little each frame (a full sort is used when they
     * do not). Pairs are found by sweeping from each box to the right for as long as the next
     * box starts before it ends.
     *
     * @return an empty sweep and prune, never null
     */
    static BroadPhase sweepAndPrune() {
        return new SweepAndPruneBroadPhase();
    }

    /**
     * A dynamic AABB tree, as Box2D's {@code b2DynamicTree}: a balanced binary tree of boxes,
     * each leaf's box enlarged by 2 pixels and, when it moves, by 4 times its last move ahead
     * of it, so a box that moves a little stays inside its enlarged box and the tree does not
     * change. As Box2D's broad phase, it keeps the list of pairs whose enlarged boxes overlap,
     * and only the boxes that left theirs are looked up again; the exact test then runs over
     * that list.
     *
     * @return an empty dynamic tree, never null
     */
    static BroadPhase dynamicTree() {
        return new DynamicTreeBroadPhase();
    }

    // ---------------------------------------------------------------- changing

    /**
     * Adds a box under an id, or moves and resizes the box already under it.
     *
     * @param id the box's id, 0 or more
     * @param x  the left edge, finite
     * @param y  the top edge, finite
     * @param w  the width, finite and 0 or more
     * @param h  the height, finite and 0 or more
     * @throws IllegalArgumentException if a value is NaN or infinite, a size or the id is
     *                                  negative; nothing is changed
     * @throws IllegalStateException    if called from a callback of this broad phase
     */
    void put(int id, float x, float y, float w, float h);

    /**
     * Adds or moves a box under an id: the shape's bounding box, {@link Shape#bounds()}.
     *
     * @param id    the box's id, 0 or more
     * @param shape the shape whose bounds to store, not null
     * @throws IllegalArgumentException if the id is negative or the shape null
     * @throws IllegalStateException    if called from a callback of this broad phase
     */
    void put(int id, Shape shape);

    /**
     * Removes the box under an id.
     *
     * @param id the id, 0 or more
     * @return true if there was a box under it
     * @throws IllegalArgumentException if the id is negative
     * @throws IllegalStateException    if called from a callback of this broad phase
     */
    boolean remove(int id);

    /**
     * Removes every box. The memory grown so far is kept for the next ones.
     *
     * @throws IllegalStateException if called from a callback of this broad phase
     */
    void clear();

    // ---------------------------------------------------------------- reading the boxes

    /** @return how many boxes are stored */
    int size();

    /**
     * Is there a box under this id?
     *
     * @param id the id, 0 or more
     * @return true if a box is stored under it
     * @throws IllegalArgumentException if the id is negative
     */
    boolean contains(int id);

    /**
     * Visits every stored box once, with its id, in no particular order: for drawing them all.
     *
     * @param out receives each id and box, not null
     * @throws IllegalArgumentException if {@code out} is null
     */
    void forEachBox(BoxConsumer out);

    // ---------------------------------------------------------------- the questions

    /**
     * Reports every overlapping pair of stored boxes ({@link Collide#rectRect} on their
     * numbers), each pair once, smaller id first, in no particular order of pairs.
     *
     * @param out receives each pair, not null
     * @throws IllegalArgumentException if {@code out} is null
     */
    void pairs(PairConsumer out);

    /**
     * Reports every stored box that overlaps the given box ({@link Collide#rectRect}), once
     * each, in no particular order.
     *
     * @param x   the left edge, finite
     * @param y   the top edge, finite
     * @param w   the width, finite and 0 or more
     * @param h   the height, finite and 0 or more
     * @param out receives the id of each box found, not null
     * @throws IllegalArgumentException if a value is NaN or infinite, a size is negative, or
     *                                  {@code out} is null
     */
    void query(float x, float y, float w, float h, IntConsumer out);

    /**
     * Visits the boxes a ray goes into, nearest first (equal distances: smaller id first),
     * until the visitor returns false. Distances are those of {@link Ray#distanceToRect}: in
     * pixels, 0 for a box the ray starts inside, and a box is visited only if the ray goes
     * into its inside within its {@code maxDistance} (a ray along an edge, or a box of width or
     * height 0, is not hit).
     *
     * @param ray the ray, not null
     * @param out receives each box hit and its distance, not null
     * @throws IllegalArgumentException if {@code ray} or {@code out} is null
     */
    void raycast(Ray ray, RayVisitor out);

    // ---------------------------------------------------------------- looking inside

    /**
     * How many box-against-box tests the last {@link #pairs}, {@link #query} or
     * {@link #raycast} made (with those its callbacks made): for showing what a structure
     * saves against the n(n-1)/2 tests of an all-pairs loop. Tests of the structure's own
     * cells or nodes are not counted.
     *
     * @return the number of tests, 0 before the first question
     */
    long checks();

    /**
     * Visits the structure's own regions, for drawing: the quadtree's squares (key: depth, 0
     * for the root), the grid's occupied cells (key: level, 0 for the finest cells), the
     * dynamic tree's enlarged boxes, leaves and inner nodes (key: depth, 0 for the root).
     * Sweep and prune and brute force have none. The grid is rebuilt first if it needs to be.
     *
     * @param out receives each region, not null
     * @throws IllegalArgumentException if {@code out} is null
     */
    void cells(BoxConsumer out);
}
