package hitbox.processing;

/**
 * The colours every sketch shares, as Processing {@code int} colours (ARGB), so that red means
 * "colliding" and green "not colliding" everywhere in the collection.
 */
public final class Palette {
    private Palette() {
    }

    /** The window background: a dark slate. */
    public static final int BACKGROUND = 0xFF1E2128;
    /** A shape that is colliding. */
    public static final int HIT = 0xFFE8504A;
    /** A shape that is not colliding. */
    public static final int MISS = 0xFF4CC36A;
    /** The shape the learner moves (mouse or keys). */
    public static final int PLAYER = 0xFF5AA9F0;
    /** Obstacles, walls and platforms. */
    public static final int OBSTACLE = 0xFF9AA3B2;
    /** Shapes that are neither: the thing being tested against. */
    public static final int NEUTRAL = 0xFFE6E6E6;
    /** Thin lines, outlines and grid lines. */
    public static final int LINE = 0xFF4A5060;
    /** Accents: crossing points, normals, rays. */
    public static final int ACCENT = 0xFFFFD23F;
}
