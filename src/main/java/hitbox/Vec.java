package hitbox;

import hitbox.internal.*;

/**
 * A 2D vector: a velocity, a direction or a point, as an immutable value.
 *
 * <p>Processing sketches keep their own {@code PVector}s; this is what the library hands back
 * when an answer has two parts, such as the velocity after a bounce. A plain carrier of
 * numbers: it takes any float, NaN included, since it carries the answers of methods on
 * plain floats, which never throw.
 *
 * @param x the x component
 * @param y the y component (down is positive, as in Processing)
 */
public record Vec(float x, float y) {

    /** The zero vector. */
    public static final Vec ZERO = new Vec(0, 0);

    /**
     * @param other the other vector
     * @throws IllegalArgumentException if {@code other} is null
     * @return the dot product
     */
    public float dot(Vec other) {
        Check.notNull("other", other);
        return x * other.x + y * other.y;
    }

    /** @return the length */
    public float length() {
        return (float) Math.hypot(x, y);
    }
}
