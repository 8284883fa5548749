package hitbox;

/**
 * Which side of an obstacle a moving shape ran into, seen from the obstacle.
 *
 * <p>With y growing down (Processing's axes): a player that falls onto a platform hits its
 * {@link #TOP} (it has landed, and may jump again); one that jumps into it from below hits
 * its {@link #BOTTOM} (it bumped its head); {@link #LEFT} and {@link #RIGHT} are walls.
 */
public enum Side {
    /** No side: nothing was hit. */
    NONE,
    /** The obstacle's top edge: the mover came from above and has landed on it. */
    TOP,
    /** The obstacle's bottom edge: the mover came from below and hit its head. */
    BOTTOM,
    /** The obstacle's left edge: the mover came from the left and hit a wall. */
    LEFT,
    /** The obstacle's right edge: the mover came from the right and hit a wall. */
    RIGHT;

    /**
     * Did the mover land? True for {@link #TOP}: it stands on the obstacle and may jump again.
     *
     * @return true for {@link #TOP}
     */
    public boolean landed() {
        return this == TOP;
    }

    /**
     * Did the mover run into a wall?
     *
     * @return true for {@link #LEFT} or {@link #RIGHT}
     */
    public boolean isWall() {
        return this == LEFT || this == RIGHT;
    }
}
