package hitbox.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import hitbox.internal.Fdlibm;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * A turning body's cosine and sine, the two forms a teleport could take: the JVM's
 * {@code StrictMath.cos} and {@code sin} (two native calls, each reducing the angle), and
 * {@code Fdlibm.sinCos} (the same algorithm and bits in Java, one reduction for both), over the
 * float angles of the world benchmark's turning bodies (-pi to pi). The setup checks the bits
 * agree. By hand: {@code gradle jmh -Pjmh.include=TurnTrigBench}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class TurnTrigBench {
    static final int N = 1024;
    final float[] angle = new float[N];
    final double[] out = new double[2];

    @Setup
    public void setup() {
        Random random = new Random(29);
        for (int i = 0; i < N; i++) {
            angle[i] = (float) (2 * Math.PI * random.nextDouble() - Math.PI);
            Fdlibm.sinCos(angle[i], out);
            if (out[0] != StrictMath.cos(angle[i]) || out[1] != StrictMath.sin(angle[i])) {
                throw new AssertionError("sinCos differs from StrictMath at " + angle[i]);
            }
        }
    }

    /** @return a sum of the answers, so nothing is left uncomputed */
    @Benchmark
    @OperationsPerInvocation(N)
    public double strictMathCosAndSin() {
        double sum = 0;
        for (int i = 0; i < N; i++) {
            sum += StrictMath.cos(angle[i]) + StrictMath.sin(angle[i]);
        }
        return sum;
    }

    /** @return a sum of the answers */
    @Benchmark
    @OperationsPerInvocation(N)
    public double fdlibmSinCos() {
        double sum = 0;
        for (int i = 0; i < N; i++) {
            Fdlibm.sinCos(angle[i], out);
            sum += out[0] + out[1];
        }
        return sum;
    }
}
