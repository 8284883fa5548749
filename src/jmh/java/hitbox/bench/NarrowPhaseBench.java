package hitbox.bench;

import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * The narrow-phase table's one benchmark: the contender named by {@link #contender}
 * (question.key, see {@link NarrowQuestions}) answers all {@value NarrowCase#N} cases of its
 * question; the score is per case. JMH runs each contender in a JVM of its own, so the answer
 * call inside the loop only ever sees that contender and is inlined as a direct call would be.
 * Run it through {@code gradle narrowPhaseTable}, which passes every contender as the
 * parameter; by hand: {@code -p contender=poly8.collide,poly8.dyn4jGjk}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class NarrowPhaseBench {
    /** Which contender to time: question.key. */
    @Param({"poly8.collide"})
    public String contender;

    private NarrowContender chosen;
    private final float[] scratch = new float[3];

    @Setup
    public void setup() {
        chosen = NarrowQuestions.contender(contender);
        chosen.prepare(NarrowQuestions.question(chosen.question).cases().get());
    }

    @Benchmark
    @OperationsPerInvocation(NarrowCase.N)
    public double answerEveryCase() {
        return chosen.run(scratch);
    }
}
