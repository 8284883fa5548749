package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.function.IntConsumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The broad-phase contract, for every structure ({@link BroadPhaseModel#STRUCTURES}): each
 * scenario is run on each structure and every answer compared with {@link BroadPhaseModel},
 * which loops over {@link Collide#rectRect}, {@link Shape#overlaps} and
 * {@link Ray#distanceToRect} directly. Worlds move for many frames, with boxes removed, put
 * back and added under sparse ids, so each structure is checked after every kind of history.
 */
class BroadPhaseContractTest {

    static Stream<String> structures() {
        return BroadPhaseModel.STRUCTURES.keySet().stream();
    }

    private static BroadPhase make(String name) {
        return BroadPhaseModel.STRUCTURES.get(name).get();
    }

    /** A structure and the model, changed together. */
    private static final class Both {
        final BroadPhase bp;
        final BroadPhaseModel model = new BroadPhaseModel();

        Both(String name) {
            bp = make(name);
        }

        void put(int id, float x, float y, float w, float h) {
            bp.put(id, x, y, w, h);
            model.put(id, x, y, w, h);
        }

        void remove(int id) {
            assertEquals(model.boxes.containsKey(id), bp.remove(id), "remove(" + id + ")");
            model.remove(id);
        }

        void check(String when) {
            model.assertSame(bp, when);
        }
    }

    // ---------------------------------------------------------------- worlds in motion

    /** How a world places and sizes its boxes. */
    enum World { UNIFORM, CLUSTERED, HEAVY_TAILED, FAR_1E6, FAR_3E7, FAR_NEGATIVE, FLAT }

    static Stream<Object[]> worlds() {
        return structures().flatMap(s -> Stream.of(World.values()).map(w -> new Object[] {s, w}));
    }

    /**
     * 300 boxes in a 300 x 300 world, moving up to 2 pixels a frame and bouncing off the walls,
     * for 40 frames; every 4th frame some boxes are removed, some removed ones come back
     * elsewhere and some new ids arrive. Checked against the model after every frame, with
     * box, shape and ray queries every 8th.
     */
    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("worlds")
    void movingWorld_sameAsModelEveryFrame(String name, World world) {
        Random random = new Random(world.ordinal() * 1000L + name.hashCode());
        Both both = new Both(name);
        int n = 300;
        float side = 300, origin = origin(world);
        float[] x = new float[n], y = new float[n], w = new float[n], h = new float[n], vx = new float[n], vy = new float[n];
        int[] id = new int[n];
        Set<Integer> used = new HashSet<>();
        for (int i = 0; i < n; i++) {
            id[i] = sparseId(random, used);
            w[i] = size(world, random);
            h[i] = size(world, random);
            if (world == World.FLAT) {
                int kind = random.nextInt(4);  // flat across, flat down, a point, or a box
                w[i] = kind == 1 || kind == 2 ? 0 : w[i];
                h[i] = kind == 0 || kind == 2 ? 0 : h[i];
            }
            if (world == World.CLUSTERED) {
                int c = random.nextInt(4);
                x[i] = origin + 40 + 180 * (c % 2) + random.nextInt(40);
                y[i] = origin + 40 + 180 * (c / 2) + random.nextInt(40);
            } else {
                x[i] = origin + random.nextFloat() * side;
                y[i] = origin + random.nextFloat() * side;
            }
            vx[i] = step(world, random);
            vy[i] = step(world, random);
            both.put(id[i], x[i], y[i], w[i], h[i]);
        }
        both.check("at the start");
        List<Integer> removed = new ArrayList<>();
        for (int frame = 1; frame <= 40; frame++) {
            for (int i = 0; i < n; i++) {
                if (!both.model.boxes.containsKey(id[i])) {
                    continue;
                }
                x[i] += vx[i];
                y[i] += vy[i];
                if (x[i] < origin || x[i] > origin + side) {
                    vx[i] = -vx[i];
                }
                if (y[i] < origin || y[i] > origin + side) {
                    vy[i] = -vy[i];
                }
                both.put(id[i], x[i], y[i], w[i], h[i]);
            }
            if (frame % 4 == 0) {
                for (int k = 0; k < 15; k++) {
                    int i = random.nextInt(n);
                    both.remove(id[i]);
                    removed.add(i);
                }
                for (int k = 0; k < 10 && !removed.isEmpty(); k++) {
                    int i = removed.remove(random.nextInt(removed.size()));
                    x[i] = origin + random.nextFloat() * side;
                    both.put(id[i], x[i], y[i], w[i], h[i]);
                }
                both.put(sparseId(random, used), origin + random.nextFloat() * side, origin + random.nextFloat() * side,
                        size(world, random), size(world, random));
                both.remove(sparseId(random, used));  // never stored: false
            }
            both.check("after frame " + frame);
            if (frame % 8 == 0) {
                checkQueries(both, random, origin, side);
            }
        }
        both.bp.clear();
        both.model.boxes.clear();
        both.check("after clear");
        both.put(7, origin, origin, 10, 10);
        both.put(3, origin + 5, origin + 5, 10, 10);
        both.check("after clear and two new boxes");
    }

    /**
     * One box moved at a time, mostly a little (as a body moves from one frame to the next,
     * within its cell of a grid, which then updates the box where it stands instead of
     * rebuilding), and a question after every move: pairs, a box query around the moved box
     * and a ray across it, each against the model. A structure that answered from the box as
     * it stood before the move would fail here, where a whole frame of moves (above) would
     * hide it behind a rebuild.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void oneSmallMoveAtATime_sameAsModelAfterEach(String name) {
        Random random = new Random(name.hashCode() * 31L + 5);
        Both both = new Both(name);
        int n = 120;
        float[] x = new float[n], y = new float[n], w = new float[n], h = new float[n];
        for (int i = 0; i < n; i++) {
            x[i] = random.nextFloat() * 200;
            y[i] = random.nextFloat() * 200;
            w[i] = 2 + random.nextFloat() * 10;
            h[i] = 2 + random.nextFloat() * 10;
            both.put(i, x[i], y[i], w[i], h[i]);
        }
        both.check("at the start");
        for (int step = 0; step < 1500; step++) {
            int i = random.nextInt(n);
            boolean lowest = step % 25 == 0;
            if (lowest) {
                // The lowest box a little further down: past where every box lay before, so a
                // ray along its new bottom edge, below all of them as they were, must find it.
                for (int k = 0; k < n; k++) {
                    i = y[k] + h[k] > y[i] + h[i] ? k : i;
                }
                y[i] += 0.7f;
            } else {
                float reach = step % 10 == 0 ? 30 : 1.5f;  // now and then a move far enough to change cell
                x[i] += (random.nextFloat() - 0.5f) * reach;
                y[i] += (random.nextFloat() - 0.5f) * reach;
            }
            if (step % 7 == 0) {
                w[i] = 2 + random.nextFloat() * 10;  // a new size too
            }
            both.put(i, x[i], y[i], w[i], h[i]);
            String when = "after move " + step + " of box " + i;
            both.check(when);
            float qx = x[i] - 5, qy = y[i] - 5, qw = w[i] + 10, qh = h[i] + 10;
            assertEquals(both.model.query(qx, qy, qw, qh), BroadPhaseModel.queryOf(both.bp, qx, qy, qw, qh),
                    both.bp + " query around the moved box, " + when);
            float along = lowest ? y[i] + h[i] - 0.1f : y[i] + h[i] / 2;
            for (Ray r : new Ray[] {new Ray(x[i] - 20, along, 1, 0, 40 + w[i]), new Ray(-50, along, 1, 0)}) {
                assertEquals(both.model.ray(r), BroadPhaseModel.rayOf(both.bp, r), both.bp + " " + r + ", " + when);
            }
        }
    }

    private static float origin(World world) {
        switch (world) {
            case FAR_1E6: return 1_000_000.5f;
            case FAR_3E7: return 3e7f;        // floats 2 apart here
            case FAR_NEGATIVE: return -1.2e6f;
            default: return 0;
        }
    }

    private static float size(World world, Random random) {
        if (world == World.HEAVY_TAILED) {
            return (float) Math.min(2 / Math.pow(1 - random.nextDouble(), 1 / 1.2), 900);  // Pareto, some wider than the world
        }
        if (world == World.FAR_3E7) {
            return 2 * (1 + random.nextInt(5));
        }
        return 2 + random.nextFloat() * 8;
    }

    private static float step(World world, Random random) {
        return world == World.FAR_3E7 ? 2 * (random.nextInt(3) - 1) : (random.nextFloat() - 0.5f) * 4;
    }

    private static int sparseId(Random random, Set<Integer> used) {
        int id;
        do {
            id = random.nextInt(4) == 0 ? random.nextInt(1000) : random.nextInt(Integer.MAX_VALUE);
        } while (!used.add(id));
        return id;
    }

    /** Box, shape and ray queries against the model. */
    private static void checkQueries(Both both, Random random, float origin, float side) {
        BroadPhase bp = both.bp;
        BroadPhaseModel model = both.model;
        List<float[]> stored = new ArrayList<>(model.boxes.values());
        for (int k = 0; k < 12; k++) {
            float x, y, w, h;
            if (k < 4 && !stored.isEmpty()) {  // exactly a stored box: its touching neighbours are not found
                float[] b = stored.get(random.nextInt(stored.size()));
                x = b[0];
                y = b[1];
                w = b[2];
                h = b[3];
            } else {
                x = origin + random.nextFloat() * side;
                y = origin + random.nextFloat() * side;
                w = k % 5 == 0 ? 0 : random.nextFloat() * 60;
                h = k % 7 == 0 ? 0 : random.nextFloat() * 60;
            }
            assertEquals(model.query(x, y, w, h), BroadPhaseModel.queryOf(bp, x, y, w, h),
                    bp + " query(" + x + ", " + y + ", " + w + ", " + h + ")");
            float u = Math.max(1, 4 * Math.ulp(x));
            Shape[] shapes = {
                new Circle(x, y, w / 2),
                new Circle(x, y, 0),
                new Segment(x, y, x + w, y + h),
                new Segment(x, y, x + w, y),
                Polygon.of(x, y, x + w + u, y, x, y + h + u),
                new Rect(x, y, w, h),
                new Ellipse(x, y, w / 2 + u, h / 3),
                new Capsule(x, y, x + w, y + h / 2, h / 4),
            };
            for (Shape s : shapes) {
                assertEquals(model.query(s), BroadPhaseModel.queryOf(bp, s), bp + " query(" + s + ")");
            }
            float angle = random.nextFloat() * 6.3f;
            float max = k % 3 == 0 ? Float.POSITIVE_INFINITY : random.nextFloat() * side;
            Ray[] rays = {
                new Ray(x, y, (float) Math.cos(angle), (float) Math.sin(angle), max),
                new Ray(x, y, 1, 0, max),
                new Ray(x, y, 0, -3, max),
                new Ray(origin - 5, y, 1, 0),  // from outside every box, across the world
            };
            for (Ray r : rays) {
                List<String> want = model.ray(r);
                assertEquals(want, BroadPhaseModel.rayOf(bp, r), bp + " " + r);
                List<String> firstTwo = new ArrayList<>();
                bp.raycast(r, (i, d) -> firstTwo.add(i + "@" + d) && firstTwo.size() < 2);
                assertEquals(want.subList(0, Math.min(2, want.size())), firstTwo, bp + " stopping after two hits, " + r);
            }
        }
    }

    // ---------------------------------------------------------------- fixed scenes

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void pileOnOneSpot_everyPair(String name) {
        Both both = new Both(name);
        for (int i = 0; i < 150; i++) {
            both.put(i * 3, 5, 5, 10, 10);
        }
        for (int i = 0; i < 40; i++) {
            both.put(1000 + i, 10, 10, 0, 0);   // points strictly inside every box, never in a pair with each other
        }
        both.check("a pile");
        assertEquals(150 * 149 / 2 + 150 * 40, BroadPhaseModel.pairsOf(both.bp).size());
        for (int i = 0; i < 150; i += 2) {
            both.put(i * 3, 15, 5, 10, 10);  // half of them slide off to just touch the rest
        }
        both.check("half slid to touch");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void touchingTiles_noPairs(String name) {
        Both both = new Both(name);
        for (int i = 0; i < 30; i++) {
            for (int j = 0; j < 30; j++) {
                both.put(i * 30 + j, i * 10, j * 10, 10, 10);
            }
        }
        assertEquals(Set.of(), BroadPhaseModel.pairsOf(both.bp), name + ": tiles side by side only touch");
        both.check("tiles");
        assertEquals(Set.of(31 * 5), BroadPhaseModel.queryOf(both.bp, 50, 50, 10, 10), "a tile's own box finds only it");
        assertEquals(Set.of(31 * 5, 31 * 5 + 1, 31 * 5 + 30, 31 * 5 + 31), BroadPhaseModel.queryOf(both.bp, 55, 55, 10, 10));
        both.put(5000, 55, 55, 10, 10);  // a tile across four others
        both.check("a tile across four");
        assertEquals(4, BroadPhaseModel.pairsOf(both.bp).size());
        // Tiles 0.1 wide at i * 0.1 in float: rounding decides which touch, and only the model knows.
        Both fine = new Both(name);
        for (int i = 0; i < 200; i++) {
            fine.put(i, i * 0.1f, (i % 7) * 0.3f, 0.1f, 0.3f);
        }
        fine.check("tenth-of-a-pixel tiles");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void integerCoordinates_sharedEdgesAndCorners(String name) {
        Random random = new Random(11);
        Both both = new Both(name);
        for (int i = 0; i < 400; i++) {
            both.put(i, random.nextInt(16), random.nextInt(16), random.nextInt(5), random.nextInt(5));
        }
        both.check("a small lattice");
        for (int frame = 0; frame < 10; frame++) {
            for (int i = 0; i < 400; i += 3) {
                both.put(i, random.nextInt(16), random.nextInt(16), random.nextInt(5), random.nextInt(5));
            }
            both.check("frame " + frame);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void farFromTheOrigin(String name) {
        Both both = new Both(name);
        float[] places = {1e6f, 1e6f + 0.25f, -1e6f, 16_777_216f, 1e8f, -1e8f, 1e12f, 1e15f, 1e30f, -1e30f, 3e38f};
        int id = 0;
        for (float p : places) {
            float ulp = Math.ulp(p);
            for (int i = 0; i < 6; i++) {
                for (int j = 0; j < 3; j++) {
                    // Boxes a few floats wide, side by side and overlapping, at each place.
                    both.put(id++, p + i * 3 * ulp, p + j * 2 * ulp, (i % 3 + 1) * ulp * 2, 4 * ulp);
                }
            }
            both.put(id++, p, p, 0, 10 * ulp);       // flat, along the first column's left edge
            both.put(id++, p - ulp, p + ulp, 6 * ulp, 0);  // flat, across
        }
        both.put(id++, -Float.MAX_VALUE, -Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE);  // a quarter of the plane
        both.put(id++, -1, -1, Float.MAX_VALUE, Float.MAX_VALUE);                             // and another, over the far ones
        both.put(id++, Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE, 1);                // past the largest float
        both.put(id++, 0, 0, 1e-30f, 1e-30f);
        both.put(id++, 0, 0, Float.MIN_VALUE, Float.MIN_VALUE);
        both.put(id++, Float.MIN_VALUE, 0, Float.MIN_VALUE, Float.MIN_VALUE);
        both.check("far places");
        Random random = new Random(5);
        for (int frame = 0; frame < 5; frame++) {
            for (int i = 0; i < id; i += 2) {
                float[] b = both.model.boxes.get(i);
                float moved = b[0] + Math.ulp(b[0]) * (random.nextInt(5) - 2);
                if (Float.isFinite(moved)) {
                    both.put(i, moved, b[1], b[2], b[3]);
                }
            }
            both.check("far places, frame " + frame);
            checkQueries(both, random, 1e6f, 10);
            checkQueries(both, random, 3e38f, 1e37f);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void flatBoxes_asRectRectAnswers(String name) {
        Both both = new Both(name);
        both.put(0, 0, 5, 10, 0);    // flat across
        both.put(1, 5, 0, 0, 10);    // flat down, crossing it: a plus sign, a pair
        both.put(2, 2, 5, 10, 0);    // along 0: no pair with it; crossing 1: a pair
        both.put(3, 10, 5, 10, 0);   // meets 0 at its end: no pair
        both.put(4, 20, 0, 10, 10);  // a box
        both.put(5, 20, 5, 10, 0);   // flat across the box's inside, from its left edge: a pair
        both.put(6, 20, 0, 10, 0);   // along the box's top edge: no pair with it (9 crosses it: a pair)
        both.put(7, 25, 5, 0, 0);    // a point inside the box: a pair (and none with 5, on which it lies)
        both.put(8, 30, 5, 0, 0);    // a point on the box's right edge: no pair
        both.put(9, 25, -5, 0, 20);  // flat down through the box: pairs with 4 and 5
        both.put(10, 25, 5, 0, 0);   // a point on point 7: no pair with it, but one with the box
        both.check("flat boxes");
        assertEquals(Set.of("0,1", "1,2", "4,5", "4,7", "4,9", "4,10", "5,9", "6,9"), BroadPhaseModel.pairsOf(both.bp));
    }

    // ---------------------------------------------------------------- reading

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void accessors_andChecksCount(String name) {
        BroadPhase bp = make(name);
        assertEquals(name, bp.toString());
        assertEquals(0, bp.checks());
        bp.put(42, 1, 2, 3, 4);
        bp.put(7, new Circle(10, 10, 5));
        assertTrue(bp.contains(42));
        assertFalse(bp.contains(43));
        Set<String> stored = BroadPhaseModel.contentsOf(bp);
        assertTrue(stored.contains("42:1.0,2.0,3.0,4.0"), stored.toString());
        assertTrue(stored.contains("7:5.0,5.0,10.0,10.0"), "a shape's bounds: " + stored);
        Random random = new Random(3);
        for (int i = 0; i < 2000; i++) {
            bp.put(100 + i, random.nextFloat() * 3000, random.nextFloat() * 3000, 4, 4);
        }
        int[] found = {0};
        bp.pairs((a, b) -> found[0]++);
        long n = bp.size(), all = n * (n - 1) / 2;
        assertTrue(bp.checks() >= found[0], name + ": every pair found needs a test");
        if (name.equals("bruteForce")) {
            assertEquals(all, bp.checks());
        } else {
            assertTrue(bp.checks() < all / 20, name + " made " + bp.checks() + " tests of " + all);
        }
        bp.query(100, 100, 50, 50, id -> { });
        assertTrue(bp.checks() < (name.equals("bruteForce") ? n + 1 : n / 10), name + " query made " + bp.checks());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void cells_holdEveryBoxCorner(String name) {
        BroadPhase bp = make(name);
        Random random = new Random(9);
        for (int i = 0; i < 500; i++) {
            bp.put(i, random.nextFloat() * 500, random.nextFloat() * 500, random.nextFloat() * 20, random.nextFloat() * 20);
        }
        List<float[]> cells = new ArrayList<>();
        bp.cells((depth, x, y, w, h) -> cells.add(new float[] {x, y, w, h}));
        if (name.equals("bruteForce") || name.equals("sweepAndPrune")) {
            assertEquals(0, cells.size());
            return;
        }
        assertFalse(cells.isEmpty());
        bp.forEachBox((id, x, y, w, h) -> {
            assertTrue(cells.stream().anyMatch(c -> c[0] <= x && x <= c[0] + c[2] && c[1] <= y && y <= c[1] + c[3]),
                    name + ": box " + id + "'s corner is in no cell");
        });
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void callbacks_mayReadButNotChange(String name) {
        BroadPhase bp = make(name);
        BroadPhaseModel model = new BroadPhaseModel();
        for (int i = 0; i < 50; i++) {
            bp.put(i, i * 3, 0, 10, 10);
            model.put(i, i * 3, 0, 10, 10);
        }
        Set<String> before = BroadPhaseModel.contentsOf(bp);
        List<String> inner = new ArrayList<>();
        bp.pairs((a, b) -> {
            inner.add(BroadPhaseModel.queryOf(bp, a * 3, 0, 1, 1) + "" + BroadPhaseModel.contentsOf(bp).size());   // reading inside is fine
            assertThrows(IllegalStateException.class, () -> bp.put(a, 0, 0, 1, 1));
            assertThrows(IllegalStateException.class, () -> bp.remove(b));
            assertThrows(IllegalStateException.class, bp::clear);
        });
        assertFalse(inner.isEmpty());
        bp.query(0, 0, 100, 100, id -> assertEquals(model.pairs(), BroadPhaseModel.pairsOf(bp)));
        bp.raycast(new Ray(-5, 5, 1, 0), (id, d) -> BroadPhaseModel.rayOf(bp, new Ray(-5, 5, 1, 0)).size() > 0);
        bp.forEachBox((id, x, y, w, h) -> assertThrows(IllegalStateException.class, () -> bp.put(id + 1000, 0, 0, 1, 1)));
        assertEquals(before, BroadPhaseModel.contentsOf(bp));
        model.assertSame(bp, "after changes refused in callbacks");
        bp.put(999, 0, 0, 1, 1);  // and changing works again afterwards
        assertTrue(bp.contains(999));
    }

    // ---------------------------------------------------------------- bad input

    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void badInput_namesTheParameter_andChangesNothing(String name) {
        BroadPhase bp = make(name);
        bp.put(1, 0, 0, 10, 10);
        bp.put(2, 5, 5, 10, 10);
        bp.pairs((a, b) -> { });
        Set<String> before = BroadPhaseModel.contentsOf(bp);
        IntConsumer ids = id -> { };
        refused(bp, before, "id must be >= 0, was -1", () -> bp.put(-1, 0, 0, 1, 1));
        refused(bp, before, "x must be a finite number, was NaN", () -> bp.put(1, Float.NaN, 0, 1, 1));
        refused(bp, before, "y must be a finite number, was Infinity", () -> bp.put(1, 0, Float.POSITIVE_INFINITY, 1, 1));
        refused(bp, before, "x must be a finite number, was -Infinity", () -> bp.put(3, Float.NEGATIVE_INFINITY, 0, 1, 1));
        refused(bp, before, "w must be >= 0, was -1.0", () -> bp.put(1, 0, 0, -1, 1));
        refused(bp, before, "h must be >= 0, was -0.5", () -> bp.put(2, 0, 0, 1, -0.5f));
        refused(bp, before, "w must be a finite number, was Infinity", () -> bp.put(3, 0, 0, Float.POSITIVE_INFINITY, 1));
        refused(bp, before, "h must be a finite number, was NaN", () -> bp.put(3, 0, 0, 1, Float.NaN));
        refused(bp, before, "shape must not be null", () -> bp.put(1, (Shape) null));
        refused(bp, before, "id must be >= 0, was -5", () -> bp.put(-5, new Circle(0, 0, 1)));
        refused(bp, before, "id must be >= 0, was -1", () -> bp.remove(-1));
        refused(bp, before, "id must be >= 0, was -2", () -> bp.contains(-2));
        refused(bp, before, "out must not be null", () -> bp.pairs(null));
        refused(bp, before, "out must not be null", () -> bp.forEachBox(null));
        refused(bp, before, "out must not be null", () -> bp.cells(null));
        refused(bp, before, "x must be a finite number, was NaN", () -> bp.query(Float.NaN, 0, 1, 1, ids));
        refused(bp, before, "w must be >= 0, was -2.0", () -> bp.query(0, 0, -2, 1, ids));
        refused(bp, before, "out must not be null", () -> bp.query(0, 0, 1, 1, null));
        refused(bp, before, "direction (dx, dy) must not be (0, 0)", () -> bp.raycast(new Ray(0, 0, 0, 0, 10), (i, d) -> true));
        refused(bp, before, "maxDistance must be >= 0", () -> bp.raycast(new Ray(0, 0, 1, 0, -1), (i, d) -> true));
        refused(bp, before, "ox must be a finite number, was NaN", () -> bp.raycast(new Ray(Float.NaN, 0, 1, 0, 1), (i, d) -> true));
        refused(bp, before, "ray must not be null", () -> bp.raycast(null, (i, d) -> true));
        refused(bp, before, "out must not be null", () -> bp.raycast(new Ray(0, 0, 1, 0), null));
        assertEquals(Set.of("1,2"), BroadPhaseModel.pairsOf(bp), name + " still answers after the refusals");
    }

    private static void refused(BroadPhase bp, Set<String> before, String message, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call, message);
        assertTrue(e.getMessage().contains(message), "expected \"" + message + "\" in \"" + e.getMessage() + "\"");
        assertEquals(before, BroadPhaseModel.contentsOf(bp), bp + " changed after refusing: " + message);
    }

    // ---------------------------------------------------------------- no garbage

    /**
     * The steady state makes no garbage: after a few frames to grow, 20 more frames of moving
     * 3000 boxes and asking for their pairs and a query allocate nothing on this thread.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("structures")
    void steadyState_allocatesNothing(String name) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        BroadPhase bp = make(name);
        int n = name.equals("bruteForce") ? 1000 : 3000;
        Random random = new Random(1);
        float[] x = new float[n], y = new float[n], vx = new float[n], vy = new float[n];
        for (int i = 0; i < n; i++) {
            x[i] = random.nextFloat() * 1000;
            y[i] = random.nextFloat() * 1000;
            vx[i] = random.nextFloat() * 4 - 2;
            vy[i] = random.nextFloat() * 4 - 2;
        }
        long[] sum = {0};
        PairConsumer pairs = (a, b) -> sum[0] += a ^ b;
        IntConsumer found = id -> sum[0] += id;
        long thread = Thread.currentThread().getId();
        long before = 0;
        for (int frame = 0; frame < 40; frame++) {
            if (frame == 20) {
                before = threads.getThreadAllocatedBytes(thread);
            }
            for (int i = 0; i < n; i++) {
                x[i] += vx[i];
                y[i] += vy[i];
                if (x[i] < 0 || x[i] > 1000) {
                    vx[i] = -vx[i];
                }
                if (y[i] < 0 || y[i] > 1000) {
                    vy[i] = -vy[i];
                }
                bp.put(i, x[i], y[i], 6, 6);
            }
            bp.pairs(pairs);
            bp.query(400, 400, 50, 50, found);
        }
        long allocated = threads.getThreadAllocatedBytes(thread) - before;
        assertEquals(0, allocated, name + " allocated " + allocated + " bytes in 20 frames");
    }
}
