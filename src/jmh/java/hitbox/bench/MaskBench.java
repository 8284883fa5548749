package hitbox.bench;

import java.util.concurrent.TimeUnit;

import hitbox.PixelMask;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Pixel-perfect overlap of two 256x256 sprites: the word-wise bit mask against a plain
 * per-pixel loop (the baseline; the tutorial names pixel-perfect collision detection but
 * writes no code for it). The sprites are a disc sitting in a ring's hole,
 * so their boxes overlap completely but no pixel is shared: both must look at everything.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class MaskBench {
    static final int SIZE = 256;

    PixelMask disc;
    PixelMask ring;
    boolean[] discPixels;
    boolean[] ringPixels;

    @Setup
    public void setup() {
        boolean[][] d = new boolean[SIZE][SIZE], r = new boolean[SIZE][SIZE];
        discPixels = new boolean[SIZE * SIZE];
        ringPixels = new boolean[SIZE * SIZE];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                double dist = Math.hypot(x - 127.5, y - 127.5);
                d[y][x] = discPixels[y * SIZE + x] = dist < 100;
                r[y][x] = ringPixels[y * SIZE + x] = dist > 110 && dist < 127;
            }
        }
        disc = PixelMask.fromGrid(d);
        ring = PixelMask.fromGrid(r);
        if (disc.overlaps(ring, 0, 0) || naiveOverlaps() || naiveCount(0, 0) != 0 || disc.overlapCount(ring, 9, 5) != naiveCount()) {
            throw new IllegalStateException("the two ways disagree");
        }
    }

    /** The word-wise test: the answer is no, found after scanning every shared row. */
    @Benchmark
    public boolean bitsetOverlaps() {
        return disc.overlaps(ring, 0, 0);
    }

    /** Baseline: the per-pixel loop over both sprites' solid flags. */
    @Benchmark
    public boolean naiveOverlaps() {
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                if (discPixels[y * SIZE + x] && ringPixels[y * SIZE + x]) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The word-wise count of shared pixels, with the ring shifted so some are shared. */
    @Benchmark
    public int bitsetCount() {
        return disc.overlapCount(ring, 9, 5);
    }

    /** Baseline for the count. */
    @Benchmark
    public int naiveCount() {
        return naiveCount(9, 5);
    }

    int naiveCount(int dx, int dy) {
        int n = 0;
        for (int y = Math.max(0, dy); y < Math.min(SIZE, SIZE + dy); y++) {
            for (int x = Math.max(0, dx); x < Math.min(SIZE, SIZE + dx); x++) {
                if (discPixels[y * SIZE + x] && ringPixels[(y - dy) * SIZE + (x - dx)]) {
                    n++;
                }
            }
        }
        return n;
    }
}
