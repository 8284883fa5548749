package hitbox.internal;

import hitbox.*;

import java.util.function.IntConsumer;

/**
 * Where {@link Motion} turns a {@link BroadPhase} of obstacles into the answers its list
 * versions give: the broad phase names the candidates near a box, and
 * each candidate is then tested exactly as the list versions test every obstacle, so the
 * answers are the same, only found without visiting the far obstacles.
 *
 * <p>The broad phase refuses NaN, infinite and negative boxes, which a move can make (a NaN
 * speed; it answers as {@link Collide#rectRect} would); for such a box every stored obstacle
 * is a candidate.
 */
public final class BroadPhaseHits {
    private BroadPhaseHits() {
    }

    /**
     * Every id whose box might overlap the box {@code (x, y, w, h)}: the broad phase's answer
     * for the box grown by a few float steps on each side (so that rounding in the caller's
     * sums never hides a candidate), or every id when the box is not an ordinary one.
     */
    public static void candidates(BroadPhase obstacles, float x, float y, float w, float h, IntConsumer out) {
        AbstractBroadPhase stored = stored(obstacles);
        boolean ordinary = Float.isFinite(x) && Float.isFinite(y) && Float.isFinite(w) && Float.isFinite(h)
                && w >= 0 && h >= 0 && Float.isFinite(x + w) && Float.isFinite(y + h);
        if (!ordinary) {
            stored.forEach(out);
            return;
        }
        float padX = 4 * Math.ulp(Math.max(Math.abs(x), Math.abs(x + w))) + Float.MIN_NORMAL;
        float padY = 4 * Math.ulp(Math.max(Math.abs(y), Math.abs(y + h))) + Float.MIN_NORMAL;
        float qw = w + 2 * padX;
        float qh = h + 2 * padY;
        if (!Float.isFinite(x - padX) || !Float.isFinite(y - padY) || !Float.isFinite(qw) || !Float.isFinite(qh)) {
            stored.forEach(out);
            return;
        }
        obstacles.query(x - padX, y - padY, qw, qh, out);
    }

    /** The ids of the stored boxes that the box overlaps by {@link Collide#rectRect}, ascending. */
    /** {@link NextPosition#rect} over every obstacle the move could reach: the OR of the answers, in {@link SideSets}' bits. */
    public static int rectBlocked(float x, float y, float w, float h, float vx, float vy, BroadPhase obstacles) {
        float nx = x + vx;
        float ny = y + vy;
        float left = Math.min(x, nx);
        float top = Math.min(y, ny);
        // The box that holds the mover at all three next positions the per-axis check tries.
        float right = Math.max(x, nx) + w;
        float bottom = Math.max(y, ny) + h;
        AbstractBroadPhase stored = stored(obstacles);
        int[] blocked = {0};
        candidates(stored, left, top, right - left, bottom - top, id -> blocked[0] |=
                NextPosition.rect(x, y, w, h, vx, vy, stored.x(id), stored.y(id), stored.w(id), stored.h(id)));
        return blocked[0];
    }

    /**
     * The broad phase as the structure behind every factory of {@link BroadPhase}, which
     * reads a stored box by its id.
     */
    private static AbstractBroadPhase stored(BroadPhase obstacles) {
        return (AbstractBroadPhase) Check.notNull("obstacles", obstacles);
    }
}
