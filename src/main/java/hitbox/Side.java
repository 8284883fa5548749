package hitbox;

/**
 * A side of a box: which side of an obstacle a moving shape ran into, or which edge of the
 * window a shape crossed. The one answer to every "which side" question in Hitbox.
 *
 * <p>With y growing down (Processing's axes): a player that falls onto a platform hits its
 * {@link #TOP} (it has landed, and may jump again); one that jumps into it from below hits
 * its {@link #BOTTOM} (it bumped its head); {@link #LEFT} and {@link #RIGHT} are walls. For
 * the window ({@link Edges}), {@link #LEFT} is the edge {@code x = 0}, {@link #TOP} the edge
 * {@code y = 0}.
 *
 * <h2 id="sets">Several sides at once: a set</h2>
 * Answers that can name several sides at once (the edges a shape crossed, {@link Edges#crossed};
 * the axes a move is blocked on, {@link Motion}; the sides a {@link Sweep#move} hit) are an
 * unmodifiable {@code Set<Side>}, empty when there are none, never containing {@link #NONE}:
 * {@code crossed.contains(Side.LEFT)}, {@code crossed.isEmpty()}. The library keeps one set
 * per combination, so asking allocates nothing.
 *
 * <h2 id="results">The side of a result</h2>
 * Every result that names one side gives it as {@code side()}: {@link Hit#side()},
 * {@link RayHit#side()}, {@link Contact#side()} and {@link Snap.Push#side()}, each a
 * {@code Side}, {@link #NONE} when the result has none. A result that can name several
 * gives them as a set: {@link Sweep.Move#sides()}, like the answers of {@link Edges}
 * and {@link Motion}.
 */
public enum Side {
    /** No side: nothing was hit. */
    NONE,
    /** The top edge: the mover came from above and has landed on it. */
    TOP,
    /** The bottom edge: the mover came from below and hit its head. */
    BOTTOM,
    /** The left edge: the mover came from the left and hit a wall. */
    LEFT,
    /** The right edge: the mover came from the right and hit a wall. */
    RIGHT;

    /**
     * The side of an obstacle that a normal points into. The normal is Hitbox's one
     * convention, <em>from the mover into what it hit</em> (see the package documentation):
     * pointing down ({@code ny > 0}) it goes into the obstacle's {@link #TOP}, up into its
     * {@link #BOTTOM}, right into its {@link #LEFT} and left into its {@link #RIGHT}. The
     * larger part decides; at exactly 45 degrees the vertical one wins, so landing on a corner
     * counts as landing. This is the rule behind {@link Contact#side()} and {@link Hit#side()}.
     *
     * @param nx the normal's x, any length
     * @param ny the normal's y
     * @return the side; {@link #NONE} for (0, 0) or a NaN part
     */
    public static Side ofNormal(double nx, double ny) {
        if (Double.isNaN(nx) || Double.isNaN(ny) || (nx == 0 && ny == 0)) {
            return NONE;
        }
        if (Math.abs(ny) >= Math.abs(nx)) {
            return ny > 0 ? TOP : BOTTOM;
        }
        return nx > 0 ? LEFT : RIGHT;
    }
}
