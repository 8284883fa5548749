package hitbox;

import java.util.AbstractList;
import java.util.List;
import java.util.RandomAccess;

/**
 * What one move met: the {@link Collision}s in the order met, as an unmodifiable list, and
 * whether the move finished. {@link World#move} and {@link CharacterBody#move} hand one back;
 * read it as any {@code List<Collision>}.
 *
 * <p>A move finishes when it went as far as its reactions let it: the whole way, or stopped
 * by a {@link Reaction#TOUCH}, a crease it cannot slide along, or a wall. It does not finish
 * when it gave up with motion left: after {@value World#MAX_LEGS} legs, or held by rounding
 * against a surface it could not step back from. Such a move says so here, with
 * {@link #finished()} false, instead of repeating its last collision.
 */
public final class Collisions extends AbstractList<Collision> implements RandomAccess {

    /** No collision, and the move finished: the answer of every move that met nothing. */
    public static final Collisions NONE = new Collisions(new Collision[0], true);

    /** No collision, and the move did not finish: what a move that fills the caller's list reports. */
    static final Collisions UNFINISHED = new Collisions(new Collision[0], false);

    /** The array toArray is handed to learn the type: shared, so a copy makes one array only. */
    private static final Collision[] EMPTY = new Collision[0];

    private final Collision[] items;
    private final boolean finished;

    private Collisions(Collision[] items, boolean finished) {
        this.items = items;
        this.finished = finished;
    }

    /** A copy of a move's collisions; {@link #NONE} when there are none and it finished. */
    static Collisions of(List<Collision> met, boolean finished) {
        if (met.isEmpty() && finished) {
            return NONE;
        }
        return new Collisions(met.toArray(EMPTY), finished);
    }

    /**
     * Did the move go as far as its reactions let it?
     *
     * @return false if it gave up with motion left (out of legs, or held by rounding)
     */
    public boolean finished() {
        return finished;
    }

    /**
     * The collision at a place in the list.
     *
     * @param index from 0 to {@code size() - 1}
     * @return the collision, never null
     * @throws IndexOutOfBoundsException if the index is outside the list
     */
    @Override
    public Collision get(int index) {
        return items[index];
    }

    /** @return how many collisions the move met */
    @Override
    public int size() {
        return items.length;
    }

    /** @return the collisions, and "unfinished" if the move gave up */
    @Override
    public String toString() {
        return finished ? super.toString() : super.toString() + " (unfinished)";
    }
}
