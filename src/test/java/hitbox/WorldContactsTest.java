package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/**
 * The contacts kept from step to step ({@link World#step(List)} and the readers): the changes
 * against brute force over every pair, each ENTER and EXIT once; nothing redone that did not
 * change (the pairs a step tests grow with the bodies moved, not with the contacts that stand);
 * an idle step allocates nothing.
 */
class WorldContactsTest {

    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    private static String key(Body a, Body b) {
        int x = System.identityHashCode(a), y = System.identityHashCode(b);
        return Math.min(x, y) + "-" + Math.max(x, y);
    }

    /** Brute force over every pair: accepted and overlapping (a grid's body: one of its solid cells, cell by cell). */
    private static boolean meets(Body a, Body b) {
        if (!a.accepts(b) || a.grid() != null && b.grid() != null) {
            return false;
        }
        if (a.grid() != null || b.grid() != null) {
            Grid g = a.grid() != null ? a.grid() : b.grid();
            Shape s = a.grid() != null ? b.shape() : a.shape();
            for (int row = 0; row < g.rows(); row++) {
                for (int col = 0; col < g.cols(); col++) {
                    if (g.isSolid(col, row) && s.overlaps(g.cellRect(col, row))) {
                        return true;
                    }
                }
            }
            return false;
        }
        return a.shape().overlaps(b.shape());
    }

    @Test
    void theChanges_matchBruteForce_andTheContactsReadBackAsTheyStand() {
        SplittableRandom rnd = new SplittableRandom(2929);
        int enters = 0, exits = 0, standing = 0;
        for (int round = 0; round < 40; round++) {
            World w = WorldBruteForceTest.randomWorld(rnd, 20 + rnd.nextInt(60));
            Grid grid = new Grid(10, 10, 30);
            grid.fillRandom(0.1f, rnd.nextLong(), 0, 0);
            if (rnd.nextBoolean()) {
                w.add(grid);
            }
            TreeMap<String, Body[]> last = new TreeMap<>();
            List<BodyEvent> changes = new ArrayList<>();
            changes.add(new BodyEvent(BodyEvent.Kind.STAY, w.bodies().get(0), w.bodies().get(1)));  // cleared by the step
            for (int frame = 0; frame < 12; frame++) {
                Set<String> met = new HashSet<>();
                TreeMap<String, Body[]> metPairs = new TreeMap<>();
                for (Body b : w.bodies()) {
                    if (b.grid() != null) {
                        continue;
                    }
                    switch (rnd.nextInt(12)) {
                        case 0 -> {
                            for (Collision c : w.move(b, rnd.nextInt(41) - 20, rnd.nextInt(41) - 20)) {
                                met.add(key(c.mover(), c.other()));
                                metPairs.put(key(c.mover(), c.other()), new Body[] {c.mover(), c.other()});
                            }
                        }
                        case 1 -> b.turnBy(0.3f);
                        case 2 -> b.moveTo(b.pivotX() + rnd.nextInt(9) - 4, b.pivotY() + rnd.nextInt(9) - 4);
                        case 3 -> b.layers(1 << rnd.nextInt(3), rnd.nextInt(3) == 0 ? 1 << rnd.nextInt(3) : -1);
                        case 4 -> {
                            if (rnd.nextInt(6) == 0) {
                                w.remove(b);
                            }
                        }
                        default -> { }  // most stand
                    }
                }
                if (rnd.nextInt(3) == 0) {
                    w.add(WorldBruteForceTest.local(rnd), rnd.nextInt(300), rnd.nextInt(300), 0);
                }
                if (rnd.nextInt(3) == 0) {
                    // The grid changes under standing bodies: the world reads it as it is.
                    grid.set(rnd.nextInt(10), rnd.nextInt(10), rnd.nextBoolean() ? Grid.SOLID : Grid.EMPTY);
                }
                TreeMap<String, Body[]> now = new TreeMap<>();
                List<Body> all = w.bodies();
                for (int i = 0; i < all.size(); i++) {
                    for (int j = i + 1; j < all.size(); j++) {
                        if (meets(all.get(i), all.get(j))) {
                            now.put(key(all.get(i), all.get(j)), new Body[] {all.get(i), all.get(j)});
                        }
                    }
                }
                for (var e : metPairs.entrySet()) {
                    Body[] p = e.getValue();
                    if (p[0].alive() && p[1].alive() && p[0].accepts(p[1])) {
                        now.put(e.getKey(), p);
                    }
                }
                TreeMap<String, BodyEvent.Kind> want = new TreeMap<>();
                for (String k : now.keySet()) {
                    if (!last.containsKey(k)) {
                        want.put(k, BodyEvent.Kind.ENTER);
                    }
                }
                for (String k : last.keySet()) {
                    if (!now.containsKey(k)) {
                        want.put(k, BodyEvent.Kind.EXIT);
                    }
                }
                w.step(changes);
                TreeMap<String, BodyEvent.Kind> got = new TreeMap<>();
                BodyEvent before = null;
                for (BodyEvent e : changes) {
                    assertTrue(e.kind() != BodyEvent.Kind.STAY, "only changes: " + e);
                    assertTrue(got.put(key(e.a(), e.b()), e.kind()) == null, "each pair once a step: " + e);
                    assertTrue(all.indexOf(e.a()) < all.indexOf(e.b()) || !e.a().alive() || !e.b().alive(),
                            "the body added first first: " + e);
                    if (before != null) {
                        assertTrue(ContactTracker.BY_PAIR.compare(before, e) < 0, "ordered by pair: " + before + ", " + e);
                    }
                    before = e;
                    if (e.kind() == BodyEvent.Kind.ENTER) {
                        enters++;
                    } else {
                        exits++;
                    }
                }
                assertEquals(want, got, "round " + round + " frame " + frame);
                // The contacts that stand, read on demand.
                assertEquals(now.size(), w.contactCount());
                TreeSet<String> read = new TreeSet<>();
                w.contacts((a, b) -> {
                    assertTrue(all.indexOf(a) < all.indexOf(b), "the body added first first");
                    assertTrue(read.add(key(a, b)), "each pair once");
                });
                assertEquals(now.keySet(), read);
                for (Body b : all) {
                    List<Body> touching = new ArrayList<>();
                    w.contacts(b, touching);
                    Set<String> mine = new TreeSet<>();
                    for (Body o : touching) {
                        mine.add(key(b, o));
                        assertTrue(w.inContact(b, o) && w.inContact(o, b));
                    }
                    Set<String> wantMine = new TreeSet<>();
                    for (var e : now.entrySet()) {
                        if (e.getValue()[0] == b || e.getValue()[1] == b) {
                            wantMine.add(e.getKey());
                        }
                    }
                    assertEquals(wantMine, mine, "contacts of " + b);
                }
                standing += now.size();
                last = now;
            }
        }
        assertTrue(enters > 500 && exits > 200 && standing > 2000, enters + " " + exits + " " + standing);
    }

    @Test
    void enterAndExit_areReportedOnceEach() {
        World w = new World();
        Body a = w.add(new Circle(0, 0, 10));
        Body b = w.add(new Circle(50, 0, 10));
        List<BodyEvent> changes = new ArrayList<>();
        w.step(changes);
        assertEquals(List.of(), changes);
        b.moveTo(15, 0);
        w.step(changes);
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.ENTER, a, b)), changes);
        for (int i = 0; i < 3; i++) {
            b.moveTo(b.pivotX(), b.pivotY() + 1);  // still in contact: nothing to report
            w.step(changes);
            assertEquals(List.of(), changes);
            assertTrue(w.inContact(a, b));
        }
        b.moveTo(100, 0);
        w.step(changes);
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.EXIT, a, b)), changes);
        w.step(changes);
        assertEquals(List.of(), changes);
        assertFalse(w.inContact(a, b));
        assertEquals(0, w.contactCount());
        assertThrows(IllegalArgumentException.class, () -> w.step(null));
        b.moveTo(15, 0);
        w.step(changes);
        assertThrows(IllegalStateException.class, () -> w.contacts((p, q) -> w.remove(q)), "a reader may not change the world");
        assertThrows(IllegalArgumentException.class, () -> w.contacts((p, q) -> {
            throw new ArithmeticException("boom");
        }));
        assertTrue(a.alive() && b.alive() && w.inContact(a, b), "refused calls changed nothing");
        assertThrows(IllegalArgumentException.class, () -> w.contacts(a, null));
        World other = new World();
        assertThrows(IllegalArgumentException.class, () -> w.inContact(a, other.add(new Circle(0, 0, 1))));
    }

    /** Circles in a square lattice, each overlapping its four neighbours: n * n bodies, 2 n (n - 1) contacts. */
    private static Body[] lattice(World w, int n) {
        Body[] out = new Body[n * n];
        for (int i = 0; i < n * n; i++) {
            out[i] = w.add(new Circle(0, 0, 5), (i % n) * 9.5f, (i / n) * 9.5f, 0);
        }
        return out;
    }

    /** The pairs a step tests grow with the bodies that moved, not with the contacts that stand. */
    @Test
    void thePairsTested_growWithTheBodiesMoved_notWithTheContactsThatStand() {
        long[] perMoved = new long[2];
        int[] sides = {50, 100};
        for (int s = 0; s < sides.length; s++) {
            int n = sides[s];
            World w = new World();
            Body[] bodies = lattice(w, n);
            List<BodyEvent> changes = new ArrayList<>();
            w.step(changes);
            assertEquals(2 * n * (n - 1), changes.size(), "every contact entered");
            assertEquals(2 * n * (n - 1), w.contactCount());
            long before = w.tracker().pairTests();
            w.step(changes);
            assertEquals(List.of(), changes);
            assertEquals(0, w.tracker().pairTests() - before, "an idle step tests no pair");
            long[] tested = new long[3];
            int[] moved = {10, 40, 160};
            for (int k = 0; k < moved.length; k++) {
                // A few bodies nudge and come back: their contacts stand, yet must be tested again.
                for (int i = 0; i < moved[k]; i++) {
                    Body b = bodies[(i * 7919) % bodies.length];
                    b.moveTo(b.pivotX() + 0.25f, b.pivotY());
                }
                w.step(changes);
                assertEquals(List.of(), changes, "nudged, still in contact with the same neighbours");
                long start = w.tracker().pairTests();
                for (int i = 0; i < moved[k]; i++) {
                    Body b = bodies[(i * 7919) % bodies.length];
                    b.moveTo(b.pivotX() - 0.25f, b.pivotY());
                }
                w.step(changes);
                assertEquals(List.of(), changes);
                tested[k] = w.tracker().pairTests() - start;
                assertTrue(tested[k] >= 2 * moved[k], "each moved body's contacts are tested: " + tested[k]);
                assertTrue(tested[k] <= 13 * moved[k], moved[k] + " moved: " + tested[k] + " pairs tested");
            }
            for (int k = 1; k < moved.length; k++) {
                double growth = (double) tested[k] / tested[k - 1];
                assertTrue(growth > 3 && growth < 5, "4 times the bodies moved, " + growth + " times the pairs tested");
            }
            perMoved[s] = tested[2];
        }
        // Four times the bodies and contacts standing, the same bodies moved: about the same work.
        double ratio = (double) perMoved[1] / perMoved[0];
        assertTrue(ratio > 0.8 && ratio < 1.25, "the standing contacts changed the work by " + ratio);
    }

    /** Pairs that never move cost nothing: a grid's body and the bodies on it, walls on walls. */
    @Test
    void bodiesThatNeverMove_costNothing_evenOnAGrid() {
        World w = new World();
        Grid g = new Grid(40, 40, 10);
        g.fill(Grid.SOLID);
        w.add(g);
        lattice(w, 30);
        List<BodyEvent> changes = new ArrayList<>();
        w.step(changes);
        assertEquals(2 * 30 * 29 + 30 * 30, changes.size());
        long before = w.tracker().pairTests();
        for (int i = 0; i < 5; i++) {
            w.step(changes);
            assertEquals(List.of(), changes);
        }
        assertEquals(0, w.tracker().pairTests() - before);
        g.set(39, 39, Grid.EMPTY);  // the grid changed where no body is: its contacts are looked at once
        w.step(changes);
        assertEquals(List.of(), changes);
        assertTrue(w.tracker().pairTests() - before >= 30 * 30, "the grid's contacts were tested again");
        g.fill(Grid.EMPTY);
        w.step(changes);
        assertEquals(30 * 30, changes.size());
        assertTrue(changes.stream().allMatch(e -> e.kind() == BodyEvent.Kind.EXIT && e.a().grid() == g));
    }

    /** An idle step at 10,000 bodies in about 20,000 resting contacts allocates nothing, nor does reading them. */
    @Test
    void anIdleStep_allocatesNothing() {
        World w = new World();
        lattice(w, 100);
        List<BodyEvent> changes = new ArrayList<>();
        w.step(changes);
        assertEquals(2 * 100 * 99, w.contactCount());
        int[] count = new int[1];
        java.util.function.BiConsumer<Body, Body> counter = (a, b) -> count[0]++;
        int clean = 0;
        long least = Long.MAX_VALUE;
        for (int round = 0; round < 240; round++) {
            long before = THREADS.getCurrentThreadAllocatedBytes();
            w.step(changes);
            count[0] = 0;
            w.contacts(counter);
            long bytes = THREADS.getCurrentThreadAllocatedBytes() - before;
            assertEquals(2 * 100 * 99, count[0]);
            if (round >= 200) {
                least = Math.min(least, bytes);
                clean += bytes == 0 ? 1 : 0;
            }
        }
        // Every one of the last 40 rounds makes nothing, but for a few the JIT's recompiling may disturb.
        assertEquals(0, least, "bytes an idle step and a read of its contacts made");
        assertTrue(clean >= 36, clean + " of the last 40 rounds made nothing");
        assertEquals(List.of(), changes);
    }
    /**
     * The simple {@code step()} lists a STAY for every contact that goes on, yet makes no new
     * event for it each frame: the same event object, step after step, while the contact lasts
     * (a new one once it ends and begins again), and the bytes of a step are the list's, well
     * under an event (24 bytes) a contact.
     */
    @Test
    void theSimpleStep_makesNoNewEventPerStandingContact() {
        World w = new World();
        Body[] bodies = lattice(w, 60);
        int contacts = 2 * 60 * 59;
        w.step();
        List<BodyEvent> first = w.step();
        assertEquals(contacts, first.size());
        assertTrue(first.stream().allMatch(e -> e.kind() == BodyEvent.Kind.STAY));
        long least = Long.MAX_VALUE;
        List<BodyEvent> last = first;
        for (int round = 0; round < 60; round++) {
            long before = THREADS.getCurrentThreadAllocatedBytes();
            last = w.step();
            least = Math.min(least, THREADS.getCurrentThreadAllocatedBytes() - before);
        }
        for (int i = 0; i < contacts; i++) {
            assertSame(first.get(i), last.get(i), "the same STAY event, step after step: " + first.get(i));
        }
        assertTrue(least < 16L * contacts, least + " bytes for a step of " + contacts + " standing contacts");
        // A contact that ends and begins again is a new contact: a new STAY after its ENTER.
        BodyEvent old = first.stream().filter(e -> e.a() == bodies[0] || e.b() == bodies[0]).findFirst().orElseThrow();
        bodies[0].moveTo(bodies[0].pivotX() - 100, bodies[0].pivotY());
        w.step();
        bodies[0].moveTo(bodies[0].pivotX() + 100, bodies[0].pivotY());
        w.step();
        BodyEvent again = w.step().stream().filter(e -> e.a() == old.a() && e.b() == old.b()).findFirst().orElseThrow();
        assertEquals(BodyEvent.Kind.STAY, again.kind());
        assertNotSame(old, again, "a contact that ended and began again is reported by a new event");
    }
    /**
     * A pair scan ({@code World.pairs}) of bodies that stand makes nothing: no sink captured
     * anew, no shape made again (a body's shape is kept until it moves). Turned bodies too.
     */
    @Test
    void aPairScanOfStandingBodies_allocatesNothing() {
        World w = new World();
        Body[] bodies = lattice(w, 100);
        for (int i = 0; i < bodies.length; i += 3) {
            bodies[i].turnTo(0.5f);
            w.add(Polygon.of(Rect.centered(0, 0, 6, 3)), bodies[i].pivotX(), bodies[i].pivotY(), 0.3f);
        }
        int[] count = new int[1];
        java.util.function.BiConsumer<Body, Body> counter = (a, b) -> count[0]++;
        w.pairs(counter);
        int pairs = count[0];
        assertTrue(pairs > 2 * 100 * 99, "the lattice's contacts and the polygons': " + pairs);
        long least = Long.MAX_VALUE;
        for (int round = 0; round < 60; round++) {
            count[0] = 0;
            long before = THREADS.getCurrentThreadAllocatedBytes();
            w.pairs(counter);
            least = Math.min(least, THREADS.getCurrentThreadAllocatedBytes() - before);
            assertEquals(pairs, count[0]);
        }
        assertEquals(0, least, "bytes a pair scan of standing bodies made");
    }

    /**
     * A frame of the stress scene's kind ({@code docs/world-benchmark.md}): every body of every
     * kind the world keeps as numbers (circles, turned ellipses, turned boxes, turned segments,
     * convex quads, turned capsules, boxes and ellipses at angle 0) moved and half of them turned by hand, then a
     * pair scan. Once the world has grown it makes nothing: no shape is made for a moved body's
     * pair tests. The pairs handed over are those of brute force over the bodies' shapes.
     */
    @Test
    void aFrameOfMovingAndTurningBodies_allocatesNothing() {
        World w = new World();
        java.util.Random random = new java.util.Random(29);
        int n = 2000;
        Body[] bodies = new Body[n];
        float[] vx = new float[n], vy = new float[n], spin = new float[n];
        for (int i = 0; i < n; i++) {
            float s = 4 + 3 * random.nextFloat(), t = 4 + 3 * random.nextFloat();
            Shape home = switch (i % 8) {
                case 0 -> new Circle(0, 0, s);
                case 1 -> new Ellipse(0, 0, s, t, 0);
                case 2 -> new Rect(-s / 2, -t / 2, s, t);
                case 3 -> new Segment(-s, -t, s, t);
                case 4 -> Polygon.of(-s, -t, s, -t / 2, s / 2, t, -s, t / 2);
                case 5 -> new Rect(-s, -t, 2 * s, 2 * t);
                case 6 -> new Capsule(-s, 0, s, 0, t / 3);
                default -> new Ellipse(0, 0, t, s, 0.4f);
            };
            float angle = i % 8 == 5 || i % 8 == 7 ? 0 : (float) (2 * Math.PI * random.nextDouble());
            bodies[i] = w.add(home, 400 * random.nextFloat(), 300 * random.nextFloat(), angle);
            vx[i] = random.nextFloat() - 0.5f;
            vy[i] = random.nextFloat() - 0.5f;
            spin[i] = angle != 0 && i % 2 == 0 ? 0.05f * (random.nextFloat() - 0.5f) : 0;
        }
        int[] count = new int[1];
        java.util.function.BiConsumer<Body, Body> counter = (a, b) -> count[0]++;
        int clean = 0;
        long least = Long.MAX_VALUE;
        for (int round = 0; round < 300; round++) {
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < n; i++) {
                Body b = bodies[i];
                float x = b.pivotX() + vx[i], y = b.pivotY() + vy[i];
                if (x < 0 || x > 400) {
                    vx[i] = -vx[i];
                }
                if (y < 0 || y > 300) {
                    vy[i] = -vy[i];
                }
                if (spin[i] != 0) {
                    b.moveTo(x, y, b.angle() + spin[i]);
                } else {
                    b.moveTo(x, y);
                }
            }
            count[0] = 0;
            w.pairs(counter);
            long bytes = THREADS.getCurrentThreadAllocatedBytes() - before;
            if (round >= 260) {
                least = Math.min(least, bytes);
                clean += bytes == 0 ? 1 : 0;
            }
        }
        // The last frame's pairs, from the numbers its pair scan placed (asked before any shape
        // is made), against brute force over the shapes.
        Set<String> found = new HashSet<>();
        w.pairs((a, b) -> found.add(key(a, b)));
        Set<String> brute = new HashSet<>();
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                if (bodies[i].shape().overlaps(bodies[j].shape())) {
                    brute.add(key(bodies[i], bodies[j]));
                }
            }
        }
        assertEquals(brute, found, "the pairs of the last frame, against brute force over the shapes");
        assertTrue(brute.size() > 1000, brute.size() + " overlapping pairs");
        assertEquals(0, least, "bytes a frame of moves and a pair scan made");
        assertTrue(clean >= 36, clean + " of the last 40 frames made nothing");
    }
}
