package hitbox.bench;

import java.util.concurrent.TimeUnit;

import hitbox.Polygon;
import hitbox.Transform;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * A polygon moved and turned every frame by a fractional amount, as a sprite is (issue 20):
 * {@code translated} and {@code rotated} on a convex polygon (a regular one) and a concave one
 * (a comb), of 16 to 1024 vertices. Before issue 20 a fractional move ran {@code Polygon.of}
 * again, O(n<sup>2</sup>); now it checks convexity again (O(n)) or relies on the polygon's
 * margin (O(n) after the first move).
 *
 * <p>Measured on 27 November 2026 on the shared 2-core machine under a load of about 18
 * (so only the orders of magnitude count), a plain timing loop of 2,000,000 / n fractional
 * moves, best of 5, before (f74da73) and after: convex 16 vertices 12-25 us before, 2.7-3.2
 * us after; 1024 vertices 12.8-19.8 ms before, 89-137 us after; concave 14 vertices 10-16 us
 * before, 1.5-2.1 us after; 1022 vertices 49-53 ms before, 7.6-8.4 us after. This JMH
 * benchmark (-f 1 -wi 2 -i 3, same load): translatedFractional 2.0 / 1.0 us (16, convex /
 * concave) and 91 / 46 us (1024); rotated 3.0 / 2.3 us and 347 / 375 us, with errors as
 * large as the scores. A convex polygon of many sides pays for its n exact orientations
 * (near-straight corners fall back to exact arithmetic); the concave comb has none.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class PolygonMoveBench {
    @Param({"16", "1024"})
    int vertices;

    @Param({"convex", "concave"})
    String kind;

    Polygon polygon;
    Transform turn = Transform.rotation(0.013f, 300, 200);

    @Setup
    public void setup() {
        polygon = kind.equals("convex") ? Polygon.regular(300, 200, 150, vertices, 0) : comb((vertices - 2) / 4);
        polygon.translated(0.1f, 0.1f); // the concave margin, found once (as a game's first frame does)
    }

    /** A bar with n teeth hanging down: 2 + 4n vertices, concave. */
    static Polygon comb(int n) {
        float[] xy = new float[2 * (2 + 4 * n)];
        int k = 0;
        xy[k++] = 0;
        xy[k++] = 0;
        xy[k++] = 10 * n;
        xy[k++] = 0;
        for (int i = n - 1; i >= 0; i--) {
            float x = 10 * i;
            float[] tooth = {x + 7.5f, 5, x + 7.5f, 40, x + 2.5f, 40, x + 2.5f, 5};
            System.arraycopy(tooth, 0, xy, k, 8);
            k += 8;
        }
        return Polygon.of(xy);
    }

    @Benchmark
    public Polygon translatedFractional() {
        return polygon.translated(0.1f, -0.37f);
    }

    @Benchmark
    public Polygon rotated() {
        return polygon.transformed(turn);
    }
}
