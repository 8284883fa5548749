package hitbox.bench;

import java.util.function.Function;
import java.util.function.IntPredicate;
import java.util.function.IntToDoubleFunction;

/**
 * One contender for one question: what it is called in the table, and how it answers case i
 * of the question's cases. The factory converts the cases to the contender's own data once
 * and returns the per-case answer, which both the timed loop ({@link #run}) and the agreement
 * check ({@link #answer}) call, so what is timed is what is checked.
 *
 * <p>Three forms, by what the question asks: yes or no ({@link IntPredicate}); a distance or
 * a time ({@link IntToDoubleFunction}, {@code +Infinity} for none); a contact, written as
 * (depth, normal x, normal y) into a scratch array, the normal from the first shape to the
 * second; contact points, written as (depth, nx, ny, count, x1, y1, depth1, x2, y2, depth2) into
 * an array of {@value #POINTS} doubles (the first point repeated when there is one).
 */
abstract class NarrowContender {
    /** How many numbers a contact-points answer has. */
    static final int POINTS = 10;

    /** Who answers: Hitbox's own call, Hitbox through {@code Shape}, or a peer. */
    enum Role { HITBOX, SHAPE, PEER }

    final String question;
    final String key;
    final Role role;
    /** How the table names the call. */
    final String call;

    NarrowContender(String question, String key, Role role, String call) {
        this.question = question;
        this.key = key;
        this.role = role;
        this.call = call;
    }

    /** The JMH parameter value that selects this contender: question.key. */
    String id() {
        return question + "." + key;
    }

    /** Builds this contender's data from the cases; called once, before timing. */
    abstract void prepare(NarrowCase cases);

    /** Answers every case once: the timed loop. The sum keeps JMH from dropping the work. */
    abstract double run(float[] scratch);

    /**
     * Case i's answer for the agreement check: null for no hit, else {1} for a yes, {value}
     * for a distance or time (NaN when the contender gives up), {depth, nx, ny} for a
     * contact, {@value #POINTS} numbers for contact points.
     */
    abstract double[] answer(int i, float[] scratch);

    /** A contender whose answer, of type F, a factory builds from the cases. */
    abstract static class Built<F> extends NarrowContender {
        private final Function<NarrowCase, F> factory;
        /** The per-case answer, once {@link #prepare} has built it. */
        F f;

        Built(String question, String key, Role role, String call, Function<NarrowCase, F> factory) {
            super(question, key, role, call);
            this.factory = factory;
        }

        @Override
        void prepare(NarrowCase cases) {
            f = factory.apply(cases);
        }
    }

    /** A yes-or-no contender. */
    static final class Bool extends Built<IntPredicate> {
        Bool(String question, String key, Role role, String call, Function<NarrowCase, IntPredicate> factory) {
            super(question, key, role, call, factory);
        }

        @Override
        double run(float[] scratch) {
            IntPredicate f = this.f;
            int n = 0;
            for (int i = 0; i < NarrowCase.N; i++) {
                if (f.test(i)) {
                    n++;
                }
            }
            return n;
        }

        @Override
        double[] answer(int i, float[] scratch) {
            return f.test(i) ? new double[] {1} : null;
        }
    }

    /** A distance or time contender: +Infinity is no hit. */
    static final class Num extends Built<IntToDoubleFunction> {
        Num(String question, String key, Role role, String call, Function<NarrowCase, IntToDoubleFunction> factory) {
            super(question, key, role, call, factory);
        }

        @Override
        double run(float[] scratch) {
            IntToDoubleFunction f = this.f;
            double sum = 0;
            for (int i = 0; i < NarrowCase.N; i++) {
                double d = f.applyAsDouble(i);
                if (d != Double.POSITIVE_INFINITY) {
                    sum += d;
                }
            }
            return sum;
        }

        @Override
        double[] answer(int i, float[] scratch) {
            double d = f.applyAsDouble(i);
            return d == Double.POSITIVE_INFINITY ? null : new double[] {d};
        }
    }

    /** Case i's contact, written into {@code out} as (depth, nx, ny); false for none. */
    interface ContactFn {
        boolean at(int i, float[] out);
    }

    /** A contact contender. */
    static final class Depth extends Built<ContactFn> {
        Depth(String question, String key, Role role, String call, Function<NarrowCase, ContactFn> factory) {
            super(question, key, role, call, factory);
        }

        @Override
        double run(float[] out) {
            ContactFn f = this.f;
            double sum = 0;
            for (int i = 0; i < NarrowCase.N; i++) {
                if (f.at(i, out)) {
                    sum += out[0] + out[1] + out[2];
                }
            }
            return sum;
        }

        @Override
        double[] answer(int i, float[] out) {
            return f.at(i, out) ? new double[] {out[0], out[1], out[2]} : null;
        }
    }

    /** Case i's contact points, written into {@code out} as {@value #POINTS} numbers; false for none. */
    interface PointsFn {
        boolean at(int i, double[] out);
    }

    /** A contact-points contender. */
    static final class Points extends Built<PointsFn> {
        private final double[] out = new double[POINTS];

        Points(String question, String key, Role role, String call, Function<NarrowCase, PointsFn> factory) {
            super(question, key, role, call, factory);
        }

        @Override
        double run(float[] scratch) {
            PointsFn f = this.f;
            double[] out = this.out;
            double sum = 0;
            for (int i = 0; i < NarrowCase.N; i++) {
                if (f.at(i, out)) {
                    sum += out[0] + out[3] + out[4] + out[5] + out[7] + out[8];
                }
            }
            return sum;
        }

        @Override
        double[] answer(int i, float[] scratch) {
            return f.at(i, out) ? out.clone() : null;
        }
    }
}
