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
 * The broad-phase workload of {@link BroadPhaseBench} for the O(n^2) contenders: Hitbox's
 * bruteForce and a plain loop over every pair (not the tutorial's code: its section 10 only says
 * in words that R-trees and quadtrees cut such checks down), at 1,000 and 10,000 boxes only
 * (100,000 would take seconds a frame).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class BroadPhaseQuadraticBench {

    @Param({"1000", "10000"})
    public int n;

    @Param({"uniform", "clustered", "heavy"})
    public String world;

    @Param({"bruteForce", "plainLoop"})
    public String structure;

    private BroadPhaseWorld boxes;
    private BroadPhaseContenders.Contender contender;

    @Setup(Level.Trial)
    public void setup() {
        boxes = new BroadPhaseWorld(world, n, 42);
        contender = BroadPhaseContenders.of(structure);
        contender.load(boxes);
        BroadPhaseBench.check(boxes, contender);
    }

    @Benchmark
    public long frame() {
        boxes.step();
        return contender.frame();
    }
}
