package hitbox.internal;

/**
 * A {@link hitbox.Transform}'s six entries in double, as the kernels read them:
 * {@code x' = m00 x + m01 y + m02}, {@code y' = m10 x + m11 y + m12}.
 *
 * @param m00 how much x' takes from x
 * @param m01 how much x' takes from y
 * @param m02 how far x' is moved
 * @param m10 how much y' takes from x
 * @param m11 how much y' takes from y
 * @param m12 how far y' is moved
 */
public record Affine(double m00, double m01, double m02, double m10, double m11, double m12) {

    /** The point's image's x, in double. */
    public double x(double x, double y) {
        return m00 * x + m01 * y + m02;
    }

    /** The point's image's y, in double. */
    public double y(double x, double y) {
        return m10 * x + m11 * y + m12;
    }

    /** The determinant of the linear part. */
    public double det() {
        return m00 * m11 - m01 * m10;
    }

    /** Is the linear part exactly the identity (a move only)? */
    public boolean isTranslation() {
        return m00 == 1 && m01 == 0 && m10 == 0 && m11 == 1;
    }

    /**
     * Is the linear part exactly a similarity (a turn, a mirror, a uniform scale): columns at
     * right angles and equally long, in double? A circle stays a circle under it.
     */
    public boolean isSimilarity() {
        return m00 * m01 + m10 * m11 == 0 && m00 * m00 + m10 * m10 == m01 * m01 + m11 * m11;
    }

    /** Does the linear part keep the axes: diagonal, or a quarter turn's anti-diagonal? */
    public boolean keepsAxes() {
        return (m01 == 0 && m10 == 0) || (m00 == 0 && m11 == 0);
    }
}
