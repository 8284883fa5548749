package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import com.badlogic.gdx.math.Intersector;
import hitbox.Collide;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * What exactness costs on the small tests, with the memory layout taken out: every form of a
 * question reads the same cases from the same flat arrays, so the scores differ only by the
 * arithmetic. For each question there are libGDX's float form (its own method where it takes
 * floats, else its formula written out), Hitbox's call, and the forms in between that a
 * floating-point filter could take:
 * <ul>
 *   <li>{@code *_doubleUnfiltered}: Hitbox's arithmetic in double with no error bound, so
 *       not exact for every float (the floor a filter in double can reach);</li>
 *   <li>{@code *_floatBand}: the float form, trusted outside a relative band wider than its
 *       rounding, Hitbox's call inside it (exact, like Hitbox's);</li>
 *   <li>{@code rectRect_floatTieCheck}: the sums in float, which round monotonically, so a
 *       strict comparison is exact unless the rounded sum equals the other edge; only then
 *       is the sum taken again in double (exact).</li>
 * </ul>
 * docs/benchmarks.md ("Filtered predicates") has a run and what it shows; the narrow-phase
 * table (docs/narrow-phase.md) links there where it explains why a small test trails libGDX. By hand: {@code gradle jmh -Pjmh.include=FilterFormsBench}. The setup
 * checks that every exact form answers as Hitbox's call does.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class FilterFormsBench {
    static final int N = 1024;
    /** Wider than the float forms' rounding (a few units of 2^-24 relative). */
    private static final float LOW = 1 - 0x1p-18f, HIGH = 1 + 0x1p-18f;
    /** Below this a float square may be subnormal, where the relative band does not hold. */
    private static final float TINY = 0x1p-100f;

    /** Case i is the pair (a, b): circles x, y, r; rects x, y, w, h; segments and triangles. */
    final float[] ax = new float[N], ay = new float[N], aw = new float[N], ah = new float[N];
    final float[] bx = new float[N], by = new float[N], bw = new float[N], bh = new float[N];
    final float[] cx = new float[N], cy = new float[N], px = new float[N], py = new float[N];

    @Setup
    public void setup() {
        // Whole and half coordinates in a 100 px square, sizes 5 to 25: about half the pairs
        // meet, and some touch exactly.
        Random random = new Random(23);
        for (int i = 0; i < N; i++) {
            ax[i] = random.nextInt(200) * 0.5f;
            ay[i] = random.nextInt(200) * 0.5f;
            aw[i] = 5 + random.nextInt(40) * 0.5f;
            ah[i] = 5 + random.nextInt(40) * 0.5f;
            bx[i] = random.nextInt(200) * 0.5f;
            by[i] = random.nextInt(200) * 0.5f;
            bw[i] = 5 + random.nextInt(40) * 0.5f;
            bh[i] = 5 + random.nextInt(40) * 0.5f;
            cx[i] = random.nextInt(200) * 0.5f;
            cy[i] = random.nextInt(200) * 0.5f;
            px[i] = random.nextInt(200) * 0.5f;
            py[i] = random.nextInt(200) * 0.5f;
        }
        if (circleCircle_floatBand() != circleCircle_collide()
                || rectRect_floatTieCheck() != rectRect_collide()) {
            throw new IllegalStateException("an exact form disagrees with Hitbox's call");
        }
        for (int i = 0; i < N; i++) {
            if (circleBand(ax[i], ay[i], aw[i], bx[i], by[i], bw[i])
                    != Collide.circleCircle(ax[i], ay[i], aw[i], bx[i], by[i], bw[i])
                    || rectTie(ax[i], ay[i], aw[i], ah[i], bx[i], by[i], bw[i], bh[i])
                    != Collide.rectRect(ax[i], ay[i], aw[i], ah[i], bx[i], by[i], bw[i], bh[i])) {
                throw new IllegalStateException("an exact form disagrees with Hitbox's call at case " + i);
            }
        }
    }

    // ---------------------------------------------------------------- circle vs circle

    /** libGDX's {@code Circle.overlaps}: the squares in float (touching counts as apart). */
    @Benchmark
    @OperationsPerInvocation(N)
    public int circleCircle_floatFormula() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float dx = ax[i] - bx[i], dy = ay[i] - by[i], reach = aw[i] + bw[i];
            if (dx * dx + dy * dy < reach * reach) {
                n++;
            }
        }
        return n;
    }

    /**
     * Hitbox's call: since issue 23 the float squares trusted outside a band and the exact
     * comparison inside it, the test {@link #circleCircle_floatBand} writes out (the two
     * differ only by the call).
     */
    @Benchmark
    @OperationsPerInvocation(N)
    public int circleCircle_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Collide.circleCircle(ax[i], ay[i], aw[i], bx[i], by[i], bw[i])) {
                n++;
            }
        }
        return n;
    }

    /** The float formula trusted outside a band, Hitbox's call inside it. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int circleCircle_floatBand() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (circleBand(ax[i], ay[i], aw[i], bx[i], by[i], bw[i])) {
                n++;
            }
        }
        return n;
    }

    private static boolean circleBand(float x1, float y1, float r1, float x2, float y2, float r2) {
        float dx = x2 - x1, dy = y2 - y1, d2 = dx * dx + dy * dy, reach = r1 + r2, rr = reach * reach;
        if ((d2 < rr * LOW | d2 > rr * HIGH) & rr > TINY & r1 >= 0 & r2 >= 0) {
            return d2 < rr;
        }
        return Collide.circleCircle(x1, y1, r1, x2, y2, r2);
    }

    // ---------------------------------------------------------------- rect vs rect

    /** libGDX's {@code Rectangle.overlaps}: the sums in float. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int rectRect_floatFormula() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (ax[i] < bx[i] + bw[i] && ax[i] + aw[i] > bx[i] && ay[i] < by[i] + bh[i] && ay[i] + ah[i] > by[i]) {
                n++;
            }
        }
        return n;
    }

    /** Hitbox's call: the sums in double, then the sizes' signs. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int rectRect_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Collide.rectRect(ax[i], ay[i], aw[i], ah[i], bx[i], by[i], bw[i], bh[i])) {
                n++;
            }
        }
        return n;
    }

    /** The sums in float, exact but for a tie, which goes to Hitbox's call. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int rectRect_floatTieCheck() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (rectTie(ax[i], ay[i], aw[i], ah[i], bx[i], by[i], bw[i], bh[i])) {
                n++;
            }
        }
        return n;
    }

    private static boolean rectTie(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        float r1 = x1 + w1, r2 = x2 + w2, b1 = y1 + h1, b2 = y2 + h2;
        if (r1 != x2 & r2 != x1 & b1 != y2 & b2 != y1 & w1 >= 0 & h1 >= 0 & w2 >= 0 & h2 >= 0) {
            return r1 > x2 && x1 < r2 && b1 > y2 && y1 < b2;
        }
        return Collide.rectRect(x1, y1, w1, h1, x2, y2, w2, h2);
    }

    // ---------------------------------------------------------------- point in triangle

    /** libGDX's {@code Intersector.isPointInTriangle}: cross products in float. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int trianglePoint_gdx() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Intersector.isPointInTriangle(px[i], py[i], ax[i], ay[i], bx[i], by[i], cx[i], cy[i])) {
                n++;
            }
        }
        return n;
    }

    /** Hitbox's call: up to three orientations, each with Shewchuk's error bound. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int trianglePoint_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Collide.trianglePoint(ax[i], ay[i], bx[i], by[i], cx[i], cy[i], px[i], py[i])) {
                n++;
            }
        }
        return n;
    }

    /** Hitbox's test with the orientations in double and no bound: the floor of a filter. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int trianglePoint_doubleUnfiltered() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            double o1 = cross(ax[i], ay[i], bx[i], by[i], px[i], py[i]);
            double o2 = cross(bx[i], by[i], cx[i], cy[i], px[i], py[i]);
            if (o1 > 0 ? !(o2 > 0) : !(o1 < 0 && o2 < 0)) {
                continue;
            }
            double o3 = cross(cx[i], cy[i], ax[i], ay[i], px[i], py[i]);
            if (o1 > 0 ? o3 > 0 : o3 < 0) {
                n++;
            }
        }
        return n;
    }

    // ---------------------------------------------------------------- segment vs segment

    /** libGDX's {@code Intersector.intersectSegments}: one determinant and two divisions. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int lineLine_gdx() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Intersector.intersectSegments(ax[i], ay[i], aw[i] * 4, ah[i] * 4, bx[i], by[i], bw[i] * 4, bh[i] * 4, null)) {
                n++;
            }
        }
        return n;
    }

    /** Hitbox's call: four orientations, each with its error bound, and the NaN rule. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int lineLine_collide() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            if (Collide.lineLine(ax[i], ay[i], aw[i] * 4, ah[i] * 4, bx[i], by[i], bw[i] * 4, bh[i] * 4)) {
                n++;
            }
        }
        return n;
    }

    /** The four orientations in double with no bound: the floor of a filter. */
    @Benchmark
    @OperationsPerInvocation(N)
    public int lineLine_doubleUnfiltered() {
        int n = 0;
        for (int i = 0; i < N; i++) {
            float x1 = ax[i], y1 = ay[i], x2 = aw[i] * 4, y2 = ah[i] * 4;
            float x3 = bx[i], y3 = by[i], x4 = bw[i] * 4, y4 = bh[i] * 4;
            double o1 = cross(x1, y1, x2, y2, x3, y3), o2 = cross(x1, y1, x2, y2, x4, y4);
            if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0)) {
                continue;
            }
            double o3 = cross(x3, y3, x4, y4, x1, y1), o4 = cross(x3, y3, x4, y4, x2, y2);
            if ((o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0)) {
                continue;
            }
            n++;  // collinear pairs not told apart: a floor to compare with, not a correct test
        }
        return n;
    }

    private static double cross(double ax, double ay, double bx, double by, double cx, double cy) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    }
}
