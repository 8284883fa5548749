package hitbox;

/**
 * Receives the overlapping pairs a {@link BroadPhase} finds: {@code broadPhase.pairs((a, b) -> ...)}.
 *
 * <p>Each pair comes once, as two ids, the smaller first ({@code a < b}). Two plain {@code int}s,
 * not objects, so reporting thousands of pairs a frame makes no garbage.
 */
@FunctionalInterface
public interface PairConsumer {

    /**
     * One overlapping pair.
     *
     * @param a the smaller id of the two
     * @param b the larger id of the two
     */
    void pair(int a, int b);
}
