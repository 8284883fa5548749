package hitbox;

/**
 * What a body does when {@link World#move} brings it against another: bump.lua's four
 * responses, chosen per pair by a {@link CollisionFilter}.
 *
 * <p>Each is reported as a {@link Collision} in the list {@code move} returns, in the order
 * met. Whatever the reaction, a body the mover already overlaps when the move starts does not
 * stop it (so a body stuck in another can walk out, as with {@link Sweep#move}).
 */
public enum Reaction {
    /**
     * Stop against the other and slide along it with the rest of the move, the part into it
     * dropped: walls, floors and slopes at any angle (two at once, a crease or a V, stop the
     * body; a slanted one is kept a skin of 1/64 pixel away, see {@link World}). The default
     * of {@link World#move(Body, float, float)}.
     */
    SLIDE,
    /** Stop against the other and go no further this move: a dart sticking in a target. */
    TOUCH,
    /**
     * Pass through the other, reporting it once: a coin, a checkpoint. A {@linkplain
     * Body#sensor(boolean) sensor} is always crossed.
     */
    CROSS,
    /**
     * Stop against the other and go on with the rest of the move mirrored about its surface:
     * a ball off a wall. Turn the sketch's own velocity with
     * {@link Response#bounce(float, float, float, float, float)} and the collision's normal.
     */
    BOUNCE
}
