package hitbox.internal;

/** Argument checks shared by the validating constructors, with messages a learner can act on. */
public final class Check {
    private Check() {
    }

    /** Returns {@code value}, or throws if it is NaN or infinite. */
    public static float finite(String name, float value) {
        if (Float.isNaN(value) || Float.isInfinite(value)) {
            throw new IllegalArgumentException(name + " must be a finite number, was " + value);
        }
        return value;
    }

    /** Returns {@code value}, or throws if it is NaN, infinite or negative. */
    public static float size(String name, float value) {
        finite(name, value);
        if (value < 0) {
            throw new IllegalArgumentException(name + " must be >= 0, was " + value);
        }
        return value;
    }

    /** Returns {@code value}, or throws if it is NaN, infinite, zero or negative. */
    public static float positive(String name, float value) {
        finite(name, value);
        if (value <= 0) {
            throw new IllegalArgumentException(name + " must be > 0, was " + value);
        }
        return value;
    }

    /** Is any of the five values NaN? (No array, so the hot paths allocate nothing.) */
    public static boolean nan(float a, float b, float c, float d, float e) {
        return a != a || b != b || c != c || d != d || e != e;
    }

    /** Is any of the values NaN? */
    public static boolean nan(float[] values) {
        for (float v : values) {
            if (v != v) {
                return true;
            }
        }
        return false;
    }

    /** Is any of the five values NaN or infinite? */
    public static boolean notFinite(float a, float b, float c, float d, float e) {
        return !(Float.isFinite(a) && Float.isFinite(b) && Float.isFinite(c) && Float.isFinite(d) && Float.isFinite(e));
    }

    /**
     * The float nearest to v, held in the float range: an answer about shapes that span more
     * than {@code Float.MAX_VALUE} (a distance, a point, a depth) stays finite. NaN stays NaN.
     */
    public static float held(double v) {
        return (float) Math.max(-Float.MAX_VALUE, Math.min(Float.MAX_VALUE, v));
    }

    /** Returns {@code value}, or throws if it is null. */
    public static <T> T notNull(String name, T value) {
        if (value == null) {
            throw new IllegalArgumentException(name + " must not be null");
        }
        return value;
    }
}
