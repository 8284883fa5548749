package hitbox.bench;

import java.util.Locale;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * One frame of the world scene ({@link WorldScene}, after detect-collisions' stress test): move
 * and turn every body, then find every overlapping pair, at 1,000, 10,000 and 100,000 bodies,
 * Hitbox beside dyn4j's and JBox2D's worlds ({@link WorldSceneContenders}).
 *
 * <p>Before timing, each trial checks its contender against Hitbox's answer, on the first frame
 * and again after 100 more (10 at 100,000 bodies, where a peer's frame takes seconds) ({@link #check}): a pair found by one and not the other must be one
 * that nearly touches, within the contender's documented tolerance. The table in
 * docs/world-benchmark.md is made with {@code -prof gc}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class WorldSceneBench {

    @Param({"1000", "10000", "100000"})
    public int n;

    @Param({"hitboxWorld", "hitboxWorldStep", "hitboxParts", "dyn4jWorld", "jbox2dWorld"})
    public String contender;

    private WorldScene scene;
    private WorldSceneContenders.Contender it;

    @Setup(Level.Trial)
    public void setup() {
        scene = new WorldScene(n, 42);
        it = WorldSceneContenders.of(contender);
        it.load(scene);
        check(scene, it, contender);
        for (int f = 0, frames = Math.max(3, Math.min(100, 1_000_000 / n)); f < frames; f++) {
            scene.step();
            it.frame();
        }
        check(scene, it, contender);
    }

    /**
     * The contender's pairs this frame against Hitbox's (a fresh {@code hitboxParts} on the same
     * poses): every pair only one of them finds must be within {@link #tolerance} of touching,
     * measured by dyn4j's GJK on the exact shapes (the gap for a pair found only by the
     * contender, the depth for one found only by Hitbox). Throws otherwise; prints the tally.
     */
    static void check(WorldScene scene, WorldSceneContenders.Contender it, String name) {
        compare(scene, it.framePairs(), name);
    }

    /**
     * {@link #check} for pairs found elsewhere (detect-collisions in Node, {@link WorldSceneNode}):
     * {@code got}, sorted keys {@code min << 32 | max}, against Hitbox's on the scene's poses now.
     */
    static void compare(WorldScene scene, long[] got, String name) {
        WorldSceneContenders.HitboxParts reference = new WorldSceneContenders.HitboxParts();
        reference.load(scene);
        long[] want = reference.framePairs();
        WorldSceneContenders.Referee referee = new WorldSceneContenders.Referee(scene);
        int extra = 0, missing = 0;
        double worstGap = 0, worstDepth = 0;
        int i = 0, j = 0;
        while (i < got.length || j < want.length) {
            if (j == want.length || i < got.length && got[i] < want[j]) {
                int a = (int) (got[i] >>> 32), b = (int) got[i];
                double gap = referee.gap(a, b);
                worstGap = Math.max(worstGap, gap);
                if (gap > tolerance(scene, name, a, b)) {
                    throw new IllegalStateException(name + " finds bodies " + a + " and " + b + " (kinds " + scene.kind[a]
                            + ", " + scene.kind[b] + ") " + gap + " px apart; Hitbox does not");
                }
                extra++;
                i++;
            } else if (i == got.length || want[j] < got[i]) {
                int a = (int) (want[j] >>> 32), b = (int) want[j];
                double depth = referee.depth(a, b);
                worstDepth = Math.max(worstDepth, depth);
                if (depth > tolerance(scene, name, a, b)) {
                    throw new IllegalStateException(name + " misses bodies " + a + " and " + b + " (kinds " + scene.kind[a]
                            + ", " + scene.kind[b] + "), " + depth + " px deep");
                }
                missing++;
                j++;
            } else {
                i++;
                j++;
            }
        }
        System.out.printf(Locale.ROOT, "%n%s, %d bodies: %d pairs, Hitbox %d; %d more (at most %.3g px apart), %d fewer (at most %.3g px deep)%n",
                name, scene.n, got.length, want.length, extra, worstGap, missing, worstDepth);
    }

    /**
     * How far from touching a pair may be and still be answered either way, in pixels: for
     * Hitbox's parts a millionth of the size unit (rounding), for its world and dyn4j that and
     * a float step at 1,024 px for each shape (their corners take another route than the
     * parts' float turns); for JBox2D its skin of
     * 2 x 0.01 m (the size unit being a metre), plus the octagon around an ellipse, up to
     * 8.3% of its larger radius beyond it, plus half of a line's thickness there (0.001 m),
     * plus rounding in float; for detect-collisions, which computes in double where Hitbox's
     * shapes are float, a float step at 1,024 px for each shape, and for each ellipse, a polygon of
     * N points on it ({@link WorldSceneNode#ellipseCorners}), up to {@code 1 - cos(pi / N)} of its
     * larger radius inside it.
     */
    static double tolerance(WorldScene s, String name, int a, int b) {
        double t = 1e-6 * s.size;
        if (name.startsWith("hitboxWorld") || name.startsWith("dyn4j")) {
            // The reference turns its shapes in float (Polygon.of(rect).rotated), the world
            // places each from its pose in double and rounds once, dyn4j keeps double: a
            // corner may differ by a float step at 1,024 px (1.2e-4 px) in each shape, more
            // than a millionth of the size unit at 100,000 bodies (4e-7 px).
            t += 2 * Math.ulp(WorldScene.WIDTH);
        }
        if (name.startsWith("jbox2d")) {
            t += 0.02 * s.size + 1e-4 * s.size;
            t += 0.0005 * s.size * ((s.kind[a] == WorldScene.LINE ? 1 : 0) + (s.kind[b] == WorldScene.LINE ? 1 : 0));
            for (int i : new int[] {a, b}) {
                if (s.kind[i] == WorldScene.ELLIPSE) {
                    t += (1 / Math.cos(Math.PI / 8) - 1) * s.reach[i];
                }
            }
        }
        if (name.startsWith("detectCollisions")) {
            // It computes in double, the reference (Hitbox's parts) in float: each of the reference's
            // corners within a float step at 1,024 px (1.2e-4 px) of the double one, in each shape.
            t += 2 * Math.ulp(WorldScene.WIDTH);
            for (int i : new int[] {a, b}) {
                if (s.kind[i] == WorldScene.ELLIPSE) {
                    t += (1 - Math.cos(Math.PI / WorldSceneNode.ellipseCorners(s.p[i], s.q[i]))) * s.reach[i];
                }
            }
        }
        return t;
    }

    @Benchmark
    public long frame() {
        scene.step();
        return it.frame();
    }
}
