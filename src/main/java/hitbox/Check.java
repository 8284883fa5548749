package hitbox;

/** Argument checks shared by the validating constructors, with messages a learner can act on. */
final class Check {
    private Check() {
    }

    /** Returns {@code value}, or throws if it is NaN or infinite. */
    static float finite(String name, float value) {
        if (Float.isNaN(value) || Float.isInfinite(value)) {
            throw new IllegalArgumentException(name + " must be a finite number, was " + value);
        }
        return value;
    }

    /** Returns {@code value}, or throws if it is NaN, infinite or negative. */
    static float size(String name, float value) {
        finite(name, value);
        if (value < 0) {
            throw new IllegalArgumentException(name + " must be >= 0, was " + value);
        }
        return value;
    }

    /** Returns {@code value}, or throws if it is NaN, infinite, zero or negative. */
    static float positive(String name, float value) {
        finite(name, value);
        if (value <= 0) {
            throw new IllegalArgumentException(name + " must be > 0, was " + value);
        }
        return value;
    }

    /** Returns {@code value}, or throws if it is null. */
    static <T> T notNull(String name, T value) {
        if (value == null) {
            throw new IllegalArgumentException(name + " must not be null");
        }
        return value;
    }
}
