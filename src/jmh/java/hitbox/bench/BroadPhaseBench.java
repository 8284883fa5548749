package hitbox.bench;

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
 * One frame of the broad-phase workload ({@link BroadPhaseWorld}): move every box, put it,
 * count every overlapping pair. Hitbox's structures against the peers (JTS STRtree and
 * HPRtree rebuilt per frame, dyn4j's DynamicAABBTree, JBox2D's DynamicTree), at 1,000,
 * 10,000 and 100,000 boxes. The O(n^2) contenders are in {@link BroadPhaseQuadraticBench}.
 *
 * <p>Before measuring, each contender's pair count for the first frame must equal a plain
 * sort and sweep's; the setup throws otherwise.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class BroadPhaseBench {

    @Param({"1000", "10000", "100000"})
    public int n;

    @Param({"uniform", "clustered", "heavy"})
    public String world;

    @Param({"grid", "sweepAndPrune", "dynamicTree", "quadtree",
            "jtsSTRtree", "jtsHPRtree", "dyn4jAABBTree", "jbox2dDynamicTree"})
    public String structure;

    private BroadPhaseWorld boxes;
    private BroadPhaseContenders.Contender contender;

    @Setup(Level.Trial)
    public void setup() {
        boxes = new BroadPhaseWorld(world, n, 42);
        contender = BroadPhaseContenders.of(structure);
        contender.load(boxes);
        check(boxes, contender);
    }

    static void check(BroadPhaseWorld boxes, BroadPhaseContenders.Contender contender) {
        long want = boxes.referencePairs(), got = contender.frame();
        if (got != want) {
            throw new IllegalStateException(contender + " found " + got + " pairs, the reference " + want);
        }
    }

    @Benchmark
    public long frame() {
        boxes.step();
        return contender.frame();
    }
}
