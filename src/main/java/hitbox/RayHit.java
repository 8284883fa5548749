package hitbox;

/**
 * Where a {@link Ray} first meets a shape: the answer of {@link Ray#cast}.
 *
 * <p>The normal is the shape's outward surface normal at the hit point, a unit vector facing
 * back against the ray. A ray that starts inside a shape with area hits it at once: distance
 * 0, the point is the ray's origin and the normal points straight back along the ray.
 *
 * @param distance how far along the ray the hit is, in pixels (0 or more)
 * @param x        the hit point's x
 * @param y        the hit point's y
 * @param nx       the surface normal at the hit point, x part (unit length)
 * @param ny       the surface normal at the hit point, y part (unit length)
 */
public record RayHit(float distance, float x, float y, float nx, float ny) {

    /**
     * Makes a ray hit, checking its values.
     *
     * @param distance how far along the ray the hit is, in pixels (0 or more)
     * @param x the hit point's x
     * @param y the hit point's y
     * @param nx the surface normal at the hit point, x part (unit length)
     * @param ny the surface normal at the hit point, y part (unit length)
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or the distance is
     *                                  negative
     */
    public RayHit {
        Check.size("distance", distance);
        Check.finite("x", x);
        Check.finite("y", y);
        Check.finite("nx", nx);
        Check.finite("ny", ny);
    }
}
