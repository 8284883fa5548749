package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.Circle;
import hitbox.Hybrid;
import hitbox.PixelMask;
import hitbox.Rect;
import hitbox.Shape;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Every pair among many objects scattered over a big level, so most pairs are far apart:
 * the hybrid check against the precise test alone (the baseline), for shapes and for masks.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class HybridBench {
    static final int SHAPES = 200;
    static final int SPRITES = 60;

    Shape[] shapes;
    PixelMask[] sprites;
    int[] spriteX;
    int[] spriteY;

    @Setup
    public void setup() {
        Random random = new Random(42);
        shapes = new Shape[SHAPES];
        for (int i = 0; i < SHAPES; i++) {
            float x = random.nextInt(2000), y = random.nextInt(2000), s = 5 + random.nextInt(30);
            shapes[i] = i % 2 == 0 ? new Circle(x, y, s / 2) : new Rect(x, y, s, 5 + random.nextInt(30));
        }
        sprites = new PixelMask[SPRITES];
        spriteX = new int[SPRITES];
        spriteY = new int[SPRITES];
        for (int i = 0; i < SPRITES; i++) {
            boolean[][] blob = new boolean[64][64];
            for (int y = 0; y < 64; y++) {
                for (int x = 0; x < 64; x++) {
                    blob[y][x] = Math.hypot(x - 31.5, y - 31.5) < 20 + random.nextInt(10);
                }
            }
            sprites[i] = PixelMask.fromGrid(blob);
            spriteX[i] = random.nextInt(1500);
            spriteY[i] = random.nextInt(1500);
        }
        if (hybridShapes() != preciseShapes() || hybridMasks() != preciseMasks()) {
            throw new IllegalStateException("the hybrid check and the precise test disagree");
        }
    }

    @Benchmark
    public int hybridShapes() {
        int n = 0;
        for (int i = 0; i < SHAPES; i++) {
            for (int j = i + 1; j < SHAPES; j++) {
                if (Hybrid.check(shapes[i], shapes[j]).overlaps()) {
                    n++;
                }
            }
        }
        return n;
    }

    /** Baseline: Shape.overlaps on every pair. */
    @Benchmark
    public int preciseShapes() {
        int n = 0;
        for (int i = 0; i < SHAPES; i++) {
            for (int j = i + 1; j < SHAPES; j++) {
                if (shapes[i].overlaps(shapes[j])) {
                    n++;
                }
            }
        }
        return n;
    }

    @Benchmark
    public int hybridMasks() {
        int n = 0;
        for (int i = 0; i < SPRITES; i++) {
            for (int j = i + 1; j < SPRITES; j++) {
                if (Hybrid.check(sprites[i], spriteX[i], spriteY[i], sprites[j], spriteX[j], spriteY[j]).overlaps()) {
                    n++;
                }
            }
        }
        return n;
    }

    /** Baseline: PixelMask.overlaps on every pair (it already skips rows outside the solid bounds). */
    @Benchmark
    public int preciseMasks() {
        int n = 0;
        for (int i = 0; i < SPRITES; i++) {
            for (int j = i + 1; j < SPRITES; j++) {
                if (sprites[i].overlaps(sprites[j], spriteX[j] - spriteX[i], spriteY[j] - spriteY[i])) {
                    n++;
                }
            }
        }
        return n;
    }
}
