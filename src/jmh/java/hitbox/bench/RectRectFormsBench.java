package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Collide;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Rectangle against rectangle, 1024 pairs per call, written the tutorial's two ways (sketch
 * S05b_RectRectTwoWays): the && form that is true when they collide (the baseline), and the
 * flipped || form that is true when they do not, with the collision in its else, which the
 * rectangle-collision video calls "a bit more efficient"; and Collide.rectRect, the && form
 * in double.
 *
 * <p>Comparison i of the || form is the opposite of comparison i of the && form (but for
 * touching edges, which the positions here never have), so both stop after the same number
 * of comparisons; what could differ is only what the JIT makes of them. The layouts decide
 * how many comparisons run: far apart (most pairs stop at the first comparison), mixed
 * (about half the pairs overlap) and overlapping (most run all four).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class RectRectFormsBench {
    static final int N = 1024;

    @Param({"apart", "mixed", "overlapping"})
    String layout;

    float[] x = new float[N + 1];
    float[] y = new float[N + 1];
    float[] w = new float[N + 1];
    float[] h = new float[N + 1];

    @Setup
    public void setup() {
        // Whole sizes, and positions with a quarter that alternates with i, so the edges of
        // neighbours i and i + 1 are never equal: no pair touches.
        float range = switch (layout) {
            case "apart" -> 4000;
            case "mixed" -> 90;
            case "overlapping" -> 30;
            default -> throw new IllegalArgumentException("layout " + layout);
        };
        Random random = new Random(5);
        for (int i = 0; i <= N; i++) {
            float quarter = i % 2 == 0 ? 0.25f : 0.75f;
            x[i] = random.nextInt((int) range) + quarter;
            y[i] = random.nextInt((int) range) + quarter;
            w[i] = 20 + random.nextInt(40);
            h[i] = 20 + random.nextInt(40);
        }
        int and = andForm();
        if (and != orForm() || and != collide()) {
            throw new IllegalStateException("the forms disagree");
        }
    }

    /** Baseline: the tutorial's && form, true when the rectangles collide. */
    @Benchmark
    public int andForm() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float r1Left = x[i], r1Right = x[i] + w[i], r1Top = y[i], r1Bottom = y[i] + h[i];
            float r2Left = x[i + 1], r2Right = x[i + 1] + w[i + 1], r2Top = y[i + 1], r2Bottom = y[i + 1] + h[i + 1];
            if (r1Right > r2Left && r1Left < r2Right && r1Bottom > r2Top && r1Top < r2Bottom) {
                n++;
            }
        }
        return n;
    }

    /** The flipped || form, true when they do NOT collide; the collision is its else. */
    @Benchmark
    public int orForm() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float r1Left = x[i], r1Right = x[i] + w[i], r1Top = y[i], r1Bottom = y[i] + h[i];
            float r2Left = x[i + 1], r2Right = x[i + 1] + w[i + 1], r2Top = y[i + 1], r2Bottom = y[i + 1] + h[i + 1];
            if (r1Right < r2Left || r1Left > r2Right || r1Bottom < r2Top || r1Top > r2Bottom) {
                continue;   // not colliding
            } else {
                n++;
            }
        }
        return n;
    }

    /** The library's call: the && form, the sums in double. */
    @Benchmark
    public int collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Collide.rectRect(x[i], y[i], w[i], h[i], x[i + 1], y[i + 1], w[i + 1], h[i + 1])) {
                n++;
            }
        }
        return n;
    }
}
