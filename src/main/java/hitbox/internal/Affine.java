package hitbox.internal;

/**
 * A {@link hitbox.Transform}'s six entries in double, as the kernels read them:
 * {@code x' = m00 x + m01 y + m02}, {@code y' = m10 x + m11 y + m12}.
 *
 * <p>Not a record, so that {@link Poses} can keep one per thread and set it for each pose it
 * places: a turned body's shape is placed every frame, and a new matrix for each was a third
 * of the bytes the world's stress scene made a frame. Only this package sets entries, and
 * only on its own scratch; every other {@code Affine} (a {@code Transform}'s) is never
 * changed after it is made.
 */
public final class Affine {
    private double m00, m01, m02, m10, m11, m12;

    /**
     * @param m00 how much x' takes from x
     * @param m01 how much x' takes from y
     * @param m02 how far x' is moved
     * @param m10 how much y' takes from x
     * @param m11 how much y' takes from y
     * @param m12 how far y' is moved
     */
    public Affine(double m00, double m01, double m02, double m10, double m11, double m12) {
        set(m00, m01, m02, m10, m11, m12);
    }

    /** Sets every entry: for this package's own scratch matrix only (see the class comment). */
    Affine set(double m00, double m01, double m02, double m10, double m11, double m12) {
        this.m00 = m00;
        this.m01 = m01;
        this.m02 = m02;
        this.m10 = m10;
        this.m11 = m11;
        this.m12 = m12;
        return this;
    }

    /** @return how much x' takes from x */
    public double m00() {
        return m00;
    }

    /** @return how much x' takes from y */
    public double m01() {
        return m01;
    }

    /** @return how far x' is moved */
    public double m02() {
        return m02;
    }

    /** @return how much y' takes from x */
    public double m10() {
        return m10;
    }

    /** @return how much y' takes from y */
    public double m11() {
        return m11;
    }

    /** @return how far y' is moved */
    public double m12() {
        return m12;
    }

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

    /** @return the entries, as a record would print them (error messages quote them) */
    @Override
    public String toString() {
        return "Affine[m00=" + m00 + ", m01=" + m01 + ", m02=" + m02 + ", m10=" + m10 + ", m11=" + m11 + ", m12=" + m12 + "]";
    }
}
