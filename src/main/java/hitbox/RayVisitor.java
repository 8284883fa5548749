package hitbox;

/**
 * Receives the boxes a ray goes into, nearest first, from
 * {@link BroadPhase#raycast(Ray, RayVisitor)}.
 *
 * <p>Return {@code false} to stop: for line of sight or a bullet, stop at the first box and the
 * farther ones are not visited.
 */
@FunctionalInterface
public interface RayVisitor {

    /**
     * One box the ray goes into.
     *
     * @param id       the box's id
     * @param distance how far along the ray the box begins, in pixels (0 if the ray starts inside
     *                 it), as {@link Ray#distanceToRect} measures it
     * @return true to go on to the next box, false to stop here
     */
    boolean hit(int id, float distance);
}
