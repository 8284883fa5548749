package hitbox;

/**
 * Chooses how a moving body reacts to another, pair by pair: bump.lua's filter,
 * {@code (mover, other) -> Reaction}. Return null to ignore the other altogether.
 * <pre>{@code
 * world.move(player, vx, vy, (me, other) -> other == coin ? Reaction.CROSS : Reaction.SLIDE);
 * }</pre>
 * It is asked at most once per other body per {@link World#move}, only for bodies whose
 * {@linkplain Body#layers layers} accept each other, and never for a
 * {@linkplain Body#sensor(boolean) sensor} (always crossed). It may read the world but not
 * change it: adding, removing, moving or turning a body from inside throws an
 * {@link IllegalStateException}, and so does the move. A filter that throws leaves the world
 * as it was before the move.
 */
@FunctionalInterface
public interface CollisionFilter {

    /**
     * How the mover reacts to the other.
     *
     * @param mover the body being moved, never null
     * @param other the body it may meet, never null
     * @return the reaction, or null to ignore the other
     */
    Reaction react(Body mover, Body other);

    /**
     * The filter of {@link World#move(Body, float, float)}: slide against everything.
     *
     * @return a filter that always answers {@link Reaction#SLIDE}, never null
     */
    static CollisionFilter slide() {
        return (mover, other) -> Reaction.SLIDE;
    }
}
