package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Collide;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Circle against circle, 1024 pairs per call: Collide.circleCircle (squared distance in
 * double) against the tutorial's {@code dist(...) < r1 + r2} written with Math.hypot (the
 * baseline) and with Math.sqrt.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class CollideBench {
    static final int N = 1024;
    float[] x = new float[N + 1];
    float[] y = new float[N + 1];
    float[] r = new float[N + 1];

    @Setup
    public void setup() {
        Random random = new Random(3);
        for (int i = 0; i <= N; i++) {
            x[i] = random.nextInt(400);
            y[i] = random.nextInt(400);
            r[i] = 5 + random.nextInt(40);
        }
    }

    @Benchmark
    public int collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Collide.circleCircle(x[i], y[i], r[i], x[i + 1], y[i + 1], r[i + 1])) {
                n++;
            }
        }
        return n;
    }

    /** Baseline: the tutorial's dist() as Math.hypot. */
    @Benchmark
    public int hypot() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Math.hypot(x[i + 1] - x[i], y[i + 1] - y[i]) < r[i] + r[i + 1]) {
                n++;
            }
        }
        return n;
    }

    /** Processing's own dist() is a square root of the sum of squares, in float. */
    @Benchmark
    public int sqrt() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float dx = x[i + 1] - x[i], dy = y[i + 1] - y[i];
            if ((float) Math.sqrt(dx * dx + dy * dy) < r[i] + r[i + 1]) {
                n++;
            }
        }
        return n;
    }
}
