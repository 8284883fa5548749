package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Collide;
import hitbox.Sweep;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * A 2x2 box moving up to 100 pixels a frame at a wall 1 pixel thick, 1024 motions per call:
 * the exact swept test against sub-stepping (the baseline), which needs a test every pixel of
 * the motion not to tunnel and still only knows the time to within a step.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class SweepBench {
    static final int N = 1024;
    float[] x = new float[N];
    float[] y = new float[N];
    float[] vx = new float[N];
    float[] vy = new float[N];

    @Setup
    public void setup() {
        Random random = new Random(7);
        for (int i = 0; i < N; i++) {
            x[i] = random.nextInt(40) - 20;
            y[i] = random.nextInt(40) - 20;
            vx[i] = random.nextInt(100) + 1;
            vy[i] = random.nextInt(41) - 20;
        }
        if (swept() != subStepped()) {
            throw new IllegalStateException("the two ways disagree");
        }
    }

    /** Exact time of impact for each motion; counts the hits. */
    @Benchmark
    public int swept() {
        int hits = 0;
        for (int i = 0; i < N; i++) {
            if (Sweep.rectRect(x[i], y[i], 2, 2, vx[i], vy[i], 50, -100, 1, 200) <= 1) {
                hits++;
            }
        }
        return hits;
    }

    /** Baseline: step the box half a pixel at a time and test each position. */
    @Benchmark
    public int subStepped() {
        int hits = 0;
        for (int i = 0; i < N; i++) {
            int steps = (int) Math.ceil(Math.max(Math.abs(vx[i]), Math.abs(vy[i])) * 2);
            for (int k = 0; k <= steps; k++) {
                float t = (float) k / steps;
                if (Collide.rectRect(x[i] + t * vx[i], y[i] + t * vy[i], 2, 2, 50, -100, 1, 200)) {
                    hits++;
                    break;
                }
            }
        }
        return hits;
    }
}
