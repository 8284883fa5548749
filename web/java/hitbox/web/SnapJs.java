package hitbox.web;

import hitbox.Snap;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;

/**
 * Snapping to a ground line ({@link Snap}, tutorial section 7) for JavaScript, as
 * {@code Snap.onGround(...)}: the same names and parameters; each only calls its namesake.
 */
@JSClass(name = "Snap")
public final class SnapJs {
    private SnapJs() {
    }

    /**
     * {@link Snap#standY}.
     *
     * @param h       the rectangle's height
     * @param groundY the ground line's y
     * @return the top that stands the rectangle on the ground, never in it
     */
    @JSExport
    public static float standY(float h, float groundY) {
        return Snap.standY(h, groundY);
    }

    /**
     * {@link Snap#onGround}.
     *
     * @param y       the rectangle's top
     * @param h       its height
     * @param groundY the ground line's y
     * @return whether its bottom is at or below the ground line
     */
    @JSExport
    public static boolean onGround(float y, float h, float groundY) {
        return Snap.onGround(y, h, groundY);
    }

    /**
     * {@link Snap#landY}.
     *
     * @param y       the rectangle's top
     * @param h       its height
     * @param groundY the ground line's y
     * @return its top after landing: standY when on the ground, else y
     */
    @JSExport
    public static float landY(float y, float h, float groundY) {
        return Snap.landY(y, h, groundY);
    }
}
