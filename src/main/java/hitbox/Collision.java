package hitbox;

import hitbox.internal.*;

/**
 * One thing a {@link World#move} met: which body, how it reacted, and the {@link Hit}. The
 * list a move returns holds them in the order met.
 *
 * <p>The hit's {@code t} is the fraction of the frame's move done when they met, from 0 to 1
 * (after a slide or a bounce the rest of the move counts on from where it stopped), its normal
 * points from the mover into the other (landing on a floor gives (0, 1)), and its side is the
 * other's side that was met. A body the mover already overlapped when the move started is
 * reported first, with {@code t = 0}, a zero normal and {@link Side#NONE}
 * ({@link Hit#alreadyOverlapping()}). {@code x} and {@code y} are where the mover's
 * {@linkplain Body#pivotX() pivot} was when they met, for drawing the contact.
 *
 * @param mover    the body that was moved, never null
 * @param other    the body it met, never null (for a {@link Grid} added to the world, the
 *                 grid's body, and {@code cell} says which cell)
 * @param reaction how the mover reacted, never null
 * @param hit      when and how they met, never null
 * @param x        the mover's position x when they met
 * @param y        the mover's position y when they met
 * @param cell     for a grid's body, the cell met as {@code row * cols + col}; -1 for any
 *                 other body
 */
public record Collision(Body mover, Body other, Reaction reaction, Hit hit, float x, float y, int cell) {

    /**
     * Makes a collision, checking its values.
     *
     * @param mover    the body that was moved
     * @param other    the body it met
     * @param reaction how the mover reacted
     * @param hit      when and how they met
     * @param x        the mover's position x when they met
     * @param y        the mover's position y when they met
     * @param cell     the grid cell met, or -1
     * @throws IllegalArgumentException if a body, the reaction or the hit is null, x or y is
     *                                  NaN or infinite, or cell is below -1
     */
    public Collision {
        Check.notNull("mover", mover);
        Check.notNull("other", other);
        Check.notNull("reaction", reaction);
        Check.notNull("hit", hit);
        Check.finite("x", x);
        Check.finite("y", y);
        if (cell < -1) {
            throw new IllegalArgumentException("cell must be -1 or more, was " + cell);
        }
    }

    /**
     * Did the mover come down onto the other's top? Same as {@code hit().landed()}.
     *
     * @return true if the other's top side was met
     */
    public boolean landed() {
        return hit.landed();
    }

    /** @return the normal from the mover into the other, x part (0 if they already overlapped) */
    public float nx() {
        return hit.nx();
    }

    /** @return the normal from the mover into the other, y part (0 if they already overlapped) */
    public float ny() {
        return hit.ny();
    }
}
