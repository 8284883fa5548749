package hitbox;

import hitbox.internal.*;

/**
 * Where a ray met a body: the answer of {@link World#raycast}, with the body and the
 * {@link RayHit} (distance, point, and normal from the ray into the body).
 *
 * @param body the body the ray met, never null
 * @param hit  where it met it, never null
 * @param cell for a {@link Grid}'s body, the cell met as {@code row * cols + col}; -1 for any
 *             other body
 */
public record BodyHit(Body body, RayHit hit, int cell) {

    /**
     * Makes a ray's hit on a body, checking its values.
     *
     * @param body the body met
     * @param hit  where it met it
     * @param cell the grid cell met, or -1
     * @throws IllegalArgumentException if the body or the hit is null, or cell is below -1
     */
    public BodyHit {
        Check.notNull("body", body);
        Check.notNull("hit", hit);
        if (cell < -1) {
            throw new IllegalArgumentException("cell must be -1 or more, was " + cell);
        }
    }

    /**
     * How far along the ray the body was met: {@code hit().distance()}.
     *
     * @return the distance in pixels, 0 or more, within the ray's reach (never Infinity)
     */
    public float distance() {
        return hit.distance();
    }
}
