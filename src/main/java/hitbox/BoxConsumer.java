package hitbox;

/**
 * Receives boxes as plain numbers, with no {@link Rect} made for each:
 * {@link BroadPhase#forEachBox} gives every stored box with its id, {@link BroadPhase#cells}
 * every region of the structure with its depth.
 */
@FunctionalInterface
public interface BoxConsumer {

    /**
     * One box.
     *
     * @param key which box: its id for {@link BroadPhase#forEachBox}, its depth or level for
     *            {@link BroadPhase#cells}
     * @param x   the left edge
     * @param y   the top edge
     * @param w   the width, 0 or more
     * @param h   the height, 0 or more
     */
    void box(int key, float x, float y, float w, float h);
}
