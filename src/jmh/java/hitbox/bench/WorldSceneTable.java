package hitbox.bench;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The world scene's table on a shared machine ({@code gradle worldTable}): every contender of
 * {@link WorldSceneBench} in one JVM, each on its own copy of the scene, checked as the benchmark
 * checks them, then timed in turns (a round of frames for each, round after round), by the
 * thread's CPU time and the bytes it allocates. Wall-clock time on a machine whose load is ten
 * times its cores measures the other jobs; CPU time measures the frame's work (caches shared
 * with the other jobs still slow it), and the turns give every contender the same load. JMH
 * ({@code gradle jmh -Pjmh.include=WorldSceneBench}) is the measurement for a quiet machine.
 *
 * <p>After the Java contenders of each size, detect-collisions runs the same scene in Node, in its
 * own process ({@link WorldSceneNode}): checked the same way, timed the same way but alone (a
 * process cannot take turns with this thread), by its main thread's CPU time. Without Node or
 * its package, its cells say so and the Java rows stand.
 *
 * <p>Arguments: the sizes (default 1000 10000 100000). System properties: {@code rounds}
 * (default 7), {@code budgetMs} (CPU time per contender per round, default 300 ms),
 * {@code nodeScript} (default {@code src/jmh/node/world-scene.mjs}), {@code node} (the Node
 * executable, default {@code node} on the PATH).
 */
public final class WorldSceneTable {
    private static final String[] CONTENDERS = {"hitboxWorld", "hitboxParts", "dyn4jWorld", "jbox2dWorld"};

    private WorldSceneTable() {
    }

    public static void main(String[] args) {
        int[] sizes = args.length == 0 ? new int[] {1000, 10000, 100000} : Arrays.stream(args).mapToInt(Integer::parseInt).toArray();
        int rounds = Integer.getInteger("rounds", 7);
        long budget = Long.getLong("budgetMs", 300) * 1_000_000;
        java.nio.file.Path script = java.nio.file.Paths.get(System.getProperty("nodeScript", "src/jmh/node/world-scene.mjs"));
        List<String> notes = new ArrayList<>();
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        List<String> rows = new ArrayList<>();
        for (int n : sizes) {
            WorldScene[] scenes = new WorldScene[CONTENDERS.length];
            WorldSceneContenders.Contender[] its = new WorldSceneContenders.Contender[CONTENDERS.length];
            for (int c = 0; c < CONTENDERS.length; c++) {
                scenes[c] = new WorldScene(n, 42);
                its[c] = WorldSceneContenders.of(CONTENDERS[c]);
                its[c].load(scenes[c]);
                WorldSceneBench.check(scenes[c], its[c], CONTENDERS[c]);
            }
            double[][] ms = new double[CONTENDERS.length][rounds];
            double[][] bytes = new double[CONTENDERS.length][rounds];
            for (int r = -2; r < rounds; r++) {  // two rounds of warming up
                for (int c = 0; c < CONTENDERS.length; c++) {
                    long t0 = mx.getCurrentThreadCpuTime(), b0 = mx.getCurrentThreadAllocatedBytes();
                    int frames = 0;
                    long t;
                    do {
                        scenes[c].step();
                        its[c].frame();
                        frames++;
                        t = mx.getCurrentThreadCpuTime() - t0;
                    } while (t < budget);
                    long b = mx.getCurrentThreadAllocatedBytes() - b0;
                    if (r >= 0) {
                        ms[c][r] = t / 1e6 / frames;
                        bytes[c][r] = (double) b / frames;
                    }
                }
            }
            for (int c = 0; c < CONTENDERS.length; c++) {
                WorldSceneBench.check(scenes[c], its[c], CONTENDERS[c]);
            }
            StringBuilder row = new StringBuilder(String.format(Locale.ROOT, "| %,d |", n));
            for (int c = 0; c < CONTENDERS.length; c++) {
                row.append(String.format(Locale.ROOT, " %s (%s) |", millis(median(ms[c])), kilobytes(median(bytes[c]))));
            }
            double fasterPeer = Math.min(median(ms[2]), median(ms[3]));
            row.append(String.format(Locale.ROOT, " %.1fx |", fasterPeer / median(ms[0])));
            WorldSceneNode.Result node = WorldSceneNode.run(script, n, checkFrames(n), rounds, budget / 1_000_000);
            if (node.failure != null) {
                row.append(" ").append(node.failure).append(" | |");
            } else {
                // Without Linux's per-thread clock, the whole process's CPU time, and the note says so.
                double nodeMs = node.threadMs >= 0 ? node.threadMs : node.processMs;
                row.append(String.format(Locale.ROOT, " %s (%s) | %.1fx |", millis(nodeMs),
                        node.bytes < 0 ? "bytes not measured" : kilobytes(node.bytes), nodeMs / median(ms[0])));
                notes.add(String.format(Locale.ROOT, "%,d bodies: detect-collisions %s (check2d %s), %s ms of the process's CPU a frame"
                        + " (V8's collector and compiler threads too) beside %s of its main thread", n,
                        node.versions.split(" ")[0], node.versions.split(" ")[1], millis(node.processMs),
                        node.threadMs >= 0 ? millis(node.threadMs) : "(not measured here: the row is the process's)"));
            }
            rows.add(row.toString());
            System.out.println(row);
        }
        System.out.println();
        System.out.println("| bodies | `World` | parts (grid + new shapes) | dyn4j World | JBox2D World | faster peer / `World` "
                + "| detect-collisions System (Node) | detect-collisions / `World` |");
        System.out.println("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
        rows.forEach(System.out::println);
        System.out.println("\nms of CPU a frame (median of " + rounds + " rounds), and (bytes allocated a frame)");
        notes.forEach(System.out::println);
    }

    /** The frames between the two checked ones, as {@link WorldSceneBench}'s trials have them: 100, 10 at 100,000 bodies. */
    static int checkFrames(int n) {
        return Math.max(3, Math.min(100, 1_000_000 / n));
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }

    /** Three significant digits, or whole milliseconds with a thousands separator from 100 on. */
    private static String millis(double ms) {
        return ms >= 100 ? String.format(Locale.ROOT, "%,.0f", ms) : String.format(Locale.ROOT, "%.3g", ms);
    }

    private static String kilobytes(double b) {
        return b < 1024 ? String.format(Locale.ROOT, "%.0f B", b) : b < 1024 * 1024
                ? String.format(Locale.ROOT, "%.0f KB", b / 1024) : b < 1024 * 1024 * 1024
                ? String.format(Locale.ROOT, "%.1f MB", b / 1024 / 1024) : String.format(Locale.ROOT, "%.2f GB", b / 1024 / 1024 / 1024);
    }
}
