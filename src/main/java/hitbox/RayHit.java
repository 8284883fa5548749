package hitbox;

import hitbox.internal.*;

/**
 * Where a {@link Ray} first meets a shape: the answer of {@link Ray#cast}.
 *
 * <p>The normal points <em>from the ray into the shape</em>, the package's one convention for
 * every result (the shape's inward surface normal at the hit point, a unit vector), so it
 * goes straight to {@link Response#bounce(float, float, float, float, float)}. A ray that
 * starts inside a shape with area hits it at once: distance 0, the point is the ray's origin
 * and the normal points along the ray. {@link #side()} names the side of the shape that was
 * hit, by the same rule as {@link Hit#side()} (worked out from the normal, where a
 * {@code Hit} carries it, since a hit that started overlapping has a zero normal and still
 * says so); every result that names one side gives it this way, as {@code side()} (see
 * <a href="Side.html#results">the side of a result</a>). For a shape that spans more than the float
 * range, the distance and the point are held at {@code Float.MAX_VALUE}.
 *
 * @param distance how far along the ray the hit is, in pixels (0 or more)
 * @param x        the hit point's x
 * @param y        the hit point's y
 * @param nx       the normal from the ray into the shape, x part (unit length)
 * @param ny       the normal from the ray into the shape, y part (unit length)
 */
public record RayHit(float distance, float x, float y, float nx, float ny) {

    /**
     * Makes a ray hit, checking its values.
     *
     * @param distance how far along the ray the hit is, in pixels (0 or more)
     * @param x the hit point's x
     * @param y the hit point's y
     * @param nx the normal from the ray into the shape, x part (unit length)
     * @param ny the normal from the ray into the shape, y part (unit length)
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

    /**
     * Which side of the shape the ray hit, from the normal: {@link Side#TOP} for a ray coming
     * down onto it, and so on ({@link Side#ofNormal}).
     *
     * @return the side hit; {@link Side#NONE} only for a hand-made hit with a zero normal
     */
    public Side side() {
        return Side.ofNormal(nx, ny);
    }
}
