package hitbox;

import hitbox.internal.*;

/**
 * A 2D affine transform: what Processing's {@code translate}, {@code rotate} and
 * {@code scale} build up in the drawing matrix, as an immutable value that turns, moves and
 * scales shapes ({@link Shape#transformed}).
 *
 * <p>A point (x, y) goes to
 * <pre>
 *   x' = m00 * x + m01 * y + m02
 *   y' = m10 * x + m11 * y + m12
 * </pre>
 * the order of Processing's {@code PMatrix2D} ({@code Transform.of(m.m00, m.m01, m.m02,
 * m.m10, m.m11, m.m12)}). Angles are in radians, and a positive angle turns clockwise on
 * screen (y grows down), as Processing's {@code rotate()} does.
 *
 * <p><b>Combining.</b> {@code a.then(b)} applies {@code a} first, then {@code b}. Processing
 * reads a drawing's calls the other way round: {@code translate(x, y); rotate(r);} draws a
 * shape turned by r and then moved to (x, y), which is
 * {@code Transform.rotation(r).then(Transform.translation(x, y))}.
 *
 * <p><b>Precision.</b> The six entries are kept in double; {@link #m00()} and the other
 * getters give them rounded to float. A point is transformed in double and rounded once to
 * float. {@link #rotation(float)} turns an angle within two float steps of a whole number of
 * quarter turns ({@code HALF_PI}, {@code PI}, {@code -HALF_PI}, {@code TWO_PI}...) into that
 * quarter turn exactly (cos and sin of 0, 1 or -1), since no float is exactly pi / 2: a
 * rectangle turned by {@code HALF_PI} stays a rectangle.
 *
 * <p><b>Bad input.</b> Every factory refuses a NaN or infinite value with an
 * {@link IllegalArgumentException} naming the parameter (the
 * <a href="package-summary.html#bad-input">NaN rule</a> for methods that take objects),
 * and so does {@link #then} when the combined entries overflow.
 */
public final class Transform {
    // First of the static initialisers: the kernels read the entries in double through this.
    static {
        HiddenParts.grantTransforms(t -> t.affine);
    }

    /** The transform that changes nothing. */
    public static final Transform IDENTITY = new Transform(1, 0, 0, 0, 1, 0);

    private final double m00, m01, m02, m10, m11, m12;
    /** The same entries for the kernels in {@code hitbox.internal}. */
    private final Affine affine;

    private Transform(double m00, double m01, double m02, double m10, double m11, double m12) {
        // -0.0 is kept as 0 (adding 0.0 does that), so that equal transforms hash alike
        this.m00 = m00 + 0.0;
        this.m01 = m01 + 0.0;
        this.m02 = m02 + 0.0;
        this.m10 = m10 + 0.0;
        this.m11 = m11 + 0.0;
        this.m12 = m12 + 0.0;
        this.affine = new Affine(this.m00, this.m01, this.m02, this.m10, this.m11, this.m12);
    }

    /** A transform from double entries, refusing a NaN or infinite one by its name. */
    private static Transform checked(String what, double m00, double m01, double m02, double m10, double m11, double m12) {
        double[] m = {m00, m01, m02, m10, m11, m12};
        String[] names = {"m00", "m01", "m02", "m10", "m11", "m12"};
        for (int i = 0; i < 6; i++) {
            if (!Double.isFinite(m[i]) || Math.abs(m[i]) > Float.MAX_VALUE) {
                throw new IllegalArgumentException(what + " gives entry " + names[i] + " = " + m[i]
                        + ", beyond the float range");
            }
        }
        return new Transform(m00, m01, m02, m10, m11, m12);
    }

    /**
     * A transform from its six entries, in the order of Processing's {@code PMatrix2D}:
     * {@code x' = m00 x + m01 y + m02}, {@code y' = m10 x + m11 y + m12}. A sketch's current
     * matrix is {@code PMatrix2D m = (PMatrix2D) getMatrix();} then
     * {@code Transform.of(m.m00, m.m01, m.m02, m.m10, m.m11, m.m12)} (or
     * {@code hitbox.processing.Drawn.transform(g)}).
     *
     * @param m00 how much x' takes from x
     * @param m01 how much x' takes from y
     * @param m02 how far x' is moved
     * @param m10 how much y' takes from x
     * @param m11 how much y' takes from y
     * @param m12 how far y' is moved
     * @return the transform, never null
     * @throws IllegalArgumentException if a value is NaN or infinite
     */
    public static Transform of(float m00, float m01, float m02, float m10, float m11, float m12) {
        Check.finite("m00", m00);
        Check.finite("m01", m01);
        Check.finite("m02", m02);
        Check.finite("m10", m10);
        Check.finite("m11", m11);
        Check.finite("m12", m12);
        return new Transform(m00 + 0.0, m01 + 0.0, m02 + 0.0, m10 + 0.0, m11 + 0.0, m12 + 0.0);
    }

    /**
     * A move by (dx, dy), as Processing's {@code translate(dx, dy)}.
     *
     * @param dx how far right
     * @param dy how far down
     * @return the transform, never null
     * @throws IllegalArgumentException if a value is NaN or infinite
     */
    public static Transform translation(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Transform(1, 0, dx + 0.0, 0, 1, dy + 0.0);
    }

    /**
     * A turn about the origin, as Processing's {@code rotate(angle)}: radians, clockwise on
     * screen for a positive angle. An angle within two float steps ({@code Math.ulp}) of a
     * whole number of quarter turns is that quarter turn exactly.
     *
     * @param angle the turn, in radians
     * @return the transform, never null
     * @throws IllegalArgumentException if {@code angle} is NaN or infinite
     */
    public static Transform rotation(float angle) {
        Check.finite("angle", angle);
        double[] cs = cosSin(angle);
        return new Transform(cs[0], -cs[1], 0, cs[1], cs[0], 0);
    }

    /**
     * A turn about the point (pivotX, pivotY): the pivot stays where it is, and everything
     * else turns about it as {@link #rotation(float)} turns about the origin. Same as
     * {@code translate(pivotX, pivotY); rotate(angle); translate(-pivotX, -pivotY);}.
     *
     * @param angle  the turn, in radians, clockwise on screen
     * @param pivotX the pivot's x
     * @param pivotY the pivot's y
     * @return the transform, never null
     * @throws IllegalArgumentException if a value is NaN or infinite
     */
    public static Transform rotation(float angle, float pivotX, float pivotY) {
        Check.finite("angle", angle);
        Check.finite("pivotX", pivotX);
        Check.finite("pivotY", pivotY);
        double[] cs = cosSin(angle);
        double c = cs[0], s = cs[1];
        // p' = pivot + R (p - pivot): the move is pivot - R pivot
        return checked("a turn by angle = " + angle + " about pivotX = " + pivotX + ", pivotY = " + pivotY,
                c, -s, pivotX - (c * pivotX - s * pivotY), s, c, pivotY - (s * pivotX + c * pivotY));
    }

    /**
     * The shape turned about the pivot, for {@link Shape#rotated}: a refusal names the turn's
     * arguments.
     */
    static Shape turn(Shape shape, float angle, float pivotX, float pivotY) {
        Transform r = rotation(angle, pivotX, pivotY);
        try {
            return shape.transformed(r);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("turning by angle = " + angle + " about pivotX = " + pivotX
                    + ", pivotY = " + pivotY + ": " + e.getMessage(), e);
        }
    }

    /**
     * A scale about the origin, as Processing's {@code scale(sx, sy)}, and its
     * {@code scale(s)} as {@code scaling(s, s)}. A negative factor mirrors; 0 squashes
     * everything onto a line or a point (a <em>singular</em> transform, see
     * {@link Shape#transformed}).
     *
     * @param sx the factor for x
     * @param sy the factor for y
     * @return the transform, never null
     * @throws IllegalArgumentException if a value is NaN or infinite
     */
    public static Transform scaling(float sx, float sy) {
        Check.finite("sx", sx);
        Check.finite("sy", sy);
        return new Transform(sx + 0.0, 0, 0, 0, sy + 0.0, 0);
    }

    /**
     * The cos and sin of the angle, exact for an angle within two float steps of a whole
     * number of quarter turns.
     */
    private static double[] cosSin(float angle) {
        double quarter = Math.PI / 2;
        double k = Math.rint(angle / quarter);
        if (Math.abs(angle - k * quarter) <= 2 * Math.ulp(angle)) {
            int q = (int) (((long) k % 4 + 4) % 4);
            return switch (q) {
                case 0 -> new double[] {1, 0};
                case 1 -> new double[] {0, 1};
                case 2 -> new double[] {-1, 0};
                default -> new double[] {0, -1};
            };
        }
        return new double[] {StrictMath.cos(angle), StrictMath.sin(angle)};
    }

    /**
     * This transform, then {@code next}: {@code a.then(b).applyX(x, y)} is b applied to a's
     * result. The product is taken in double.
     *
     * @param next the transform applied second, not null
     * @return the combined transform, never null
     * @throws IllegalArgumentException if {@code next} is null, or an entry of the product is
     *                                  beyond the float range
     */
    public Transform then(Transform next) {
        Check.notNull("next", next);
        Transform b = next;
        return checked("combining " + this + " then " + next,
                b.m00 * m00 + b.m01 * m10, b.m00 * m01 + b.m01 * m11, b.m00 * m02 + b.m01 * m12 + b.m02,
                b.m10 * m00 + b.m11 * m10, b.m10 * m01 + b.m11 * m11, b.m10 * m02 + b.m11 * m12 + b.m12);
    }

    /**
     * The transform that undoes this one: {@code t.then(t.inverse())} takes every point back
     * where it was (to within rounding).
     *
     * @return the inverse, never null
     * @throws IllegalArgumentException if the transform is singular (its determinant
     *                                  {@code m00 m11 - m01 m10} is 0: it squashes the plane onto
     *                                  a line or a point, which no transform can undo), or an
     *                                  entry of the inverse is beyond the float range
     */
    public Transform inverse() {
        double det = m00 * m11 - m01 * m10;
        if (det == 0 || !Double.isFinite(1 / det)) {
            throw new IllegalArgumentException("the transform " + this + " is singular (determinant " + det
                    + "): it squashes the plane onto a line or a point, so it has no inverse");
        }
        double i00 = m11 / det, i01 = -m01 / det, i10 = -m10 / det, i11 = m00 / det;
        return checked("inverting " + this, i00, i01, -(i00 * m02 + i01 * m12), i10, i11, -(i10 * m02 + i11 * m12));
    }

    /**
     * Where the point goes: its x.
     *
     * <p>A NaN in any argument answers NaN
     * (the <a href="package-summary.html#bad-input">NaN rule</a>: a position handed back).
     *
     * @param x the point's x
     * @param y the point's y
     * @return {@code m00 x + m01 y + m02}, computed in double and rounded once to float
     *         (infinite if it is beyond the float range)
     */
    public float applyX(float x, float y) {
        return (float) (m00 * x + m01 * y + m02);
    }

    /**
     * Where the point goes: its y.
     *
     * <p>A NaN in any argument answers NaN
     * (the <a href="package-summary.html#bad-input">NaN rule</a>: a position handed back).
     *
     * @param x the point's x
     * @param y the point's y
     * @return {@code m10 x + m11 y + m12}, computed in double and rounded once to float
     *         (infinite if it is beyond the float range)
     */
    public float applyY(float x, float y) {
        return (float) (m10 * x + m11 * y + m12);
    }

    /** @return the entry m00 (how much x' takes from x), rounded to float */
    public float m00() {
        return (float) m00;
    }

    /** @return the entry m01 (how much x' takes from y), rounded to float */
    public float m01() {
        return (float) m01;
    }

    /** @return the entry m02 (how far x' is moved), rounded to float */
    public float m02() {
        return (float) m02;
    }

    /** @return the entry m10 (how much y' takes from x), rounded to float */
    public float m10() {
        return (float) m10;
    }

    /** @return the entry m11 (how much y' takes from y), rounded to float */
    public float m11() {
        return (float) m11;
    }

    /** @return the entry m12 (how far y' is moved), rounded to float */
    public float m12() {
        return (float) m12;
    }

    /**
     * Two transforms are equal when their six entries are (as kept, in double).
     *
     * @param o the other object, may be null
     * @return true for a transform with the same entries
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof Transform t && m00 == t.m00 && m01 == t.m01 && m02 == t.m02
                && m10 == t.m10 && m11 == t.m11 && m12 == t.m12;
    }

    /** @return a hash of the entries, consistent with {@link #equals} */
    @Override
    public int hashCode() {
        int h = Double.hashCode(m00);
        h = 31 * h + Double.hashCode(m01);
        h = 31 * h + Double.hashCode(m02);
        h = 31 * h + Double.hashCode(m10);
        h = 31 * h + Double.hashCode(m11);
        return 31 * h + Double.hashCode(m12);
    }

    /** @return the entries as floats, for printing: {@code Transform[m00, m01, m02; m10, m11, m12]} */
    @Override
    public String toString() {
        return "Transform[" + m00() + ", " + m01() + ", " + m02() + "; " + m10() + ", " + m11() + ", " + m12() + "]";
    }

    /** The entries in double, for the kernels: never handed out by the API. */
    Affine affine() {
        return affine;
    }
}
