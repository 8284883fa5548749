package hitbox.testing;

import java.io.PrintStream;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Test progress as a run goes, for the console-launcher path of {@code gradle/test.gradle}
 * (Gradle 4.4.1, which cannot report JUnit 5 tests itself): a line as each test class
 * finishes, with its counts, and each failure as it happens. The platform finds it through
 * {@code META-INF/services}; it prints only when {@code -Dhitbox.progress} is set, so a
 * Gradle that reports the tests itself prints nothing twice.
 *
 * <p>Each line starts with {@link #MARK}, by which the build tells these lines from what the
 * tests print (which it keeps, and shows only when a launch fails).
 */
public final class Progress implements TestExecutionListener {
    /** What starts every line this listener prints. */
    public static final String MARK = "[progress] ";

    /** The launch's name ("tests", "fuzz tests"), or null when the build does not ask for progress. */
    private final String launch = System.getProperty("hitbox.progress");
    private final boolean on = launch != null;
    private final PrintStream out = System.out;
    private TestPlan plan;
    private int classes;
    private int classesDone;
    private final Map<String, int[]> counts = new HashMap<>();
    private final Map<String, Long> started = new HashMap<>();

    @Override
    public void testPlanExecutionStarted(TestPlan testPlan) {
        plan = testPlan;
        classes = 0;
        for (TestIdentifier root : testPlan.getRoots()) {
            classes += testPlan.getDescendants(root).stream().filter(this::isTopClass).count();
        }
        if (classes > 0) {
            print(launch + ": " + classes + " test classes");
        }
    }

    @Override
    public void executionStarted(TestIdentifier id) {
        if (isClass(id)) {
            started.put(id.getUniqueId(), System.nanoTime());
        }
    }

    @Override
    public void executionSkipped(TestIdentifier id, String reason) {
        if (id.isTest()) {
            count(id, 2);
        } else if (isTopClass(id)) {
            classesDone++;
            print(String.format("[%3d/%d] %s: skipped (%s)", classesDone, classes, className(id), reason));
        }
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        boolean failed = result.getStatus() != TestExecutionResult.Status.SUCCESSFUL;
        if (id.isTest()) {
            count(id, failed ? 1 : 0);
        }
        if (failed && (id.isTest() || isClass(id))) {
            String why = result.getThrowable().map(t -> t.getClass().getSimpleName()
                    + (t.getMessage() == null ? "" : ": " + firstLines(t.getMessage()))).orElse("");
            print("FAILED " + where(id) + "\n    " + why.replace("\n", "\n    "));
        }
        if (isTopClass(id)) {
            classesDone++;
            int[] c = counts.getOrDefault(id.getUniqueId(), new int[3]);
            Long t0 = started.remove(id.getUniqueId());
            double seconds = t0 == null ? 0 : (System.nanoTime() - t0) / 1e9;
            // Not "N passed, N failed": CI reads a line of that shape as the run's closing count.
            print(String.format("[%3d/%d] %s (%.1f s): %d tests%s%s", classesDone, classes, className(id), seconds,
                    c[0] + c[1] + c[2], c[1] > 0 ? ", " + c[1] + " FAILED" : "", c[2] > 0 ? ", " + c[2] + " skipped" : ""));
        }
    }

    /** Counts a test for its top-level class: 0 passed, 1 failed, 2 skipped. */
    private void count(TestIdentifier test, int kind) {
        topClass(test).ifPresent(c -> counts.computeIfAbsent(c.getUniqueId(), k -> new int[3])[kind]++);
    }

    private Optional<TestIdentifier> topClass(TestIdentifier id) {
        Optional<TestIdentifier> found = Optional.empty();
        for (Optional<TestIdentifier> at = Optional.of(id); at.isPresent(); at = plan.getParent(at.get())) {
            if (isClass(at.get())) {
                found = at;
            }
        }
        return found;
    }

    private boolean isTopClass(TestIdentifier id) {
        return isClass(id) && plan != null && plan.getParent(id).map(p -> !isClass(p)).orElse(true);
    }

    private static boolean isClass(TestIdentifier id) {
        return id.isContainer() && id.getSource().filter(s -> s instanceof ClassSource).isPresent();
    }

    private static String className(TestIdentifier id) {
        return id.getSource().filter(s -> s instanceof ClassSource).map(s -> ((ClassSource) s).getClassName())
                .orElse(id.getDisplayName());
    }

    private String where(TestIdentifier id) {
        StringBuilder path = new StringBuilder(id.getDisplayName());
        for (Optional<TestIdentifier> at = plan.getParent(id); at.isPresent(); at = plan.getParent(at.get())) {
            if (isTopClass(at.get())) {
                return className(at.get()) + " > " + path;
            }
            if (at.get().getSource().isPresent()) {
                path.insert(0, at.get().getDisplayName() + " > ");
            }
        }
        return path.toString();
    }

    private static String firstLines(String message) {
        String[] lines = message.strip().split("\n", 6);
        return lines.length <= 5 ? message.strip() : String.join("\n", java.util.Arrays.copyOf(lines, 5)) + "\n...";
    }

    private void print(String text) {
        if (!on) {
            return;
        }
        synchronized (out) {
            for (String line : text.split("\n")) {
                out.println(MARK + line);
            }
            out.flush();
        }
    }
}
