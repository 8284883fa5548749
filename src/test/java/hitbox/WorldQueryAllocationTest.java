package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;

/**
 * The forms of the queries that fill the caller's list make nothing once the list has grown:
 * bytes counted by the thread's allocation counter after the JIT has warmed up, in a world of
 * 10,000 bodies, a quarter of them moving and turning, each query finding a few of them.
 */
class WorldQueryAllocationTest {

    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    @Test
    void theFillingForms_allocateNothing() {
        World w = new World();
        Body[] bodies = new Body[10_000];
        for (int i = 0; i < bodies.length; i++) {
            Shape s = i % 2 == 0 ? new Circle(0, 0, 6) : new Rect(-5, -4, 10, 8);
            bodies[i] = w.add(s, (i % 100) * 10f, (i / 100) * 10f, i % 3 == 0 ? 0.5f : 0);
        }
        Shape probe = new Circle(500, 500, 25);
        Ray miss = new Ray(-50, -50, -1, 0);
        Ray between = new Ray(-20, 5, 1, 0, 10);  // reaches no body's shape
        Predicate<Body> keepAll = b -> true;
        List<Body> found = new ArrayList<>(1000);
        List<BodyHit> hits = new ArrayList<>(1000);
        // Steady state: every one of the last 40 rounds makes nothing, but for at most a few
        // that the JIT's recompiling disturbs (a round in the interpreter makes its objects).
        int clean = 0;
        long least = Long.MAX_VALUE;
        int count = 0;
        for (int round = 0; round < 340; round++) {
            long before = THREADS.getCurrentThreadAllocatedBytes();
            // Every fourth body moves and turns a little each round: the queries test moved
            // bodies without making their shapes.
            for (int i = 0; i < bodies.length; i += 4) {
                Body b = bodies[i];
                b.moveTo(b.pivotX() + (round % 2 == 0 ? 0.25f : -0.25f), b.pivotY(), b.angle() + 0.01f);
            }
            found.clear();
            w.queryPoint(503, 497, keepAll, found);
            w.queryShape(probe, keepAll, found);
            w.overlapping(bodies[5050], keepAll, found);
            w.overlapping(bodies[5048], keepAll, found);  // one that moves
            hits.clear();
            w.raycast(miss, keepAll, hits);
            w.raycast(between, keepAll, hits);
            long bytes = THREADS.getCurrentThreadAllocatedBytes() - before;
            count = found.size();
            if (round >= 300) {
                least = Math.min(least, bytes);
                clean += bytes == 0 ? 1 : 0;
            }
        }
        assertTrue(count > 20, "the queries found bodies: " + count);
        assertEquals(0, hits.size());
        assertEquals(0, least, "bytes the filling queries made");
        assertTrue(clean >= 36, clean + " of the last 40 rounds made nothing");
    }
}
