package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;

/**
 * The world's answers against brute force over every body: the queries (point, box, shape,
 * ray, overlapping), the layers and the events, over random worlds of every kind, turned and
 * moved, on every broad phase.
 */
class WorldBruteForceTest {

    static final String[] KINDS = {"Rect", "Circle", "Segment", "Polygon", "Ellipse", "Capsule"};

    /** A random shape of a random kind, in its own frame around (0, 0). */
    static Shape local(SplittableRandom rnd) {
        float a = 2 + rnd.nextInt(30), b = 2 + rnd.nextInt(30);
        return switch (KINDS[rnd.nextInt(KINDS.length)]) {
            case "Rect" -> new Rect(-a / 2, -b / 2, a, b);
            case "Circle" -> new Circle(0, 0, a / 2);
            case "Segment" -> new Segment(-a / 2, -b / 2, a / 2, b / 2);
            case "Polygon" -> TestShapes.convexRing(rnd, 3 + rnd.nextInt(6), 0, 0, false);
            case "Ellipse" -> new Ellipse(0, 0, a / 2, b / 2, (float) rnd.nextDouble());
            default -> new Capsule(-a / 2, 0, a / 2, b / 4, b / 4);
        };
    }

    static World randomWorld(SplittableRandom rnd, int n) {
        BroadPhase[] phases = {BroadPhase.grid(), BroadPhase.dynamicTree(), BroadPhase.quadtree(), BroadPhase.sweepAndPrune(),
            BroadPhase.bruteForce()};
        World w = new World(phases[rnd.nextInt(phases.length)]);
        for (int i = 0; i < n; i++) {
            float angle = rnd.nextInt(3) == 0 ? 0 : (float) (rnd.nextDouble() * 7 - 3.5);
            Body b = w.add(local(rnd), rnd.nextInt(300), rnd.nextInt(300), angle);
            b.layers(1 << rnd.nextInt(3), rnd.nextInt(4) == 0 ? 1 << rnd.nextInt(3) : -1);
            if (rnd.nextInt(8) == 0) {
                b.sensor(true);
            }
        }
        return w;
    }

    @Test
    void queries_matchBruteForce() {
        SplittableRandom rnd = new SplittableRandom(11);
        int found = 0;
        for (int round = 0; round < 150; round++) {
            // Big worlds put their moved bodies' boxes into the broad phase as they go, small ones
            // keep them waiting in the dirty list until a step: both are asked.
            World w = randomWorld(rnd, round % 3 == 0 ? 150 + rnd.nextInt(100) : 5 + rnd.nextInt(40));
            if (rnd.nextBoolean()) {
                w.step();
            }
            if (rnd.nextBoolean()) {
                Grid g = new Grid(10, 10, 30);
                g.fillRandom(0.2f, rnd.nextLong(), 0, 0);
                w.add(g);
            }
            // Some bodies removed, some teleported and turned.
            for (Body b : w.bodies()) {
                if (b.grid() == null) {
                    switch (rnd.nextInt(6)) {
                        case 0 -> w.remove(b);
                        case 1 -> b.moveTo(b.pivotX() + rnd.nextInt(41) - 20, b.pivotY() + rnd.nextInt(41) - 20);
                        case 2 -> b.turnBy((float) rnd.nextDouble());
                        default -> { }
                    }
                }
            }
            List<Body> all = w.bodies();
            Predicate<Body> odd = b -> all.indexOf(b) % 2 == 1;
            for (int q = 0; q < 20; q++) {
                float x = rnd.nextInt(320) - 10 + 0.5f * rnd.nextInt(2), y = rnd.nextInt(320) - 10;
                List<Body> want = new ArrayList<>();
                for (Body b : all) {
                    if (b.grid() != null ? solidAt(b.grid(), x, y) : b.shape().contains(x, y)) {
                        want.add(b);
                    }
                }
                assertEquals(want, w.queryPoint(x, y), "point " + x + ", " + y);
                List<Body> kept = new ArrayList<>();
                w.queryPoint(x, y, odd, kept);
                assertEquals(want.stream().filter(odd).toList(), kept);
                found += want.size();

                Shape probe = local(rnd).translated(x, y);
                want = new ArrayList<>();
                for (Body b : all) {
                    if (meets(b, probe)) {
                        want.add(b);
                    }
                }
                assertEquals(want, w.queryShape(probe), "shape " + probe);
                kept.clear();
                w.queryShape(probe, odd, kept);
                assertEquals(want.stream().filter(odd).toList(), kept);
                Rect box = new Rect(x, y, rnd.nextInt(50), rnd.nextInt(50));
                assertEquals(all.stream().filter(b -> meets(b, box)).toList(), w.queryShape(box));

                Body some = all.get(rnd.nextInt(all.size()));
                if (some.grid() == null) {
                    assertEquals(all.stream().filter(b -> b != some && meets(b, some.shape())).toList(), w.overlapping(some),
                            "overlapping " + some);
                }

                double dir = rnd.nextDouble() * 2 * Math.PI;
                Ray ray = new Ray(x, y, (float) Math.cos(dir), (float) Math.sin(dir), rnd.nextBoolean() ? Float.POSITIVE_INFINITY : 200);
                TreeMap<Float, List<Body>> byDistance = new TreeMap<>();
                Map<Body, Float> distance = new HashMap<>();
                for (Body b : all) {
                    Float d = rayDistance(b, ray);
                    if (d != null) {
                        byDistance.computeIfAbsent(d, k -> new ArrayList<>()).add(b);
                        distance.put(b, d);
                    }
                }
                List<Body> order = new ArrayList<>();
                byDistance.values().forEach(order::addAll);
                List<BodyHit> hits = w.raycast(ray);
                assertEquals(order, hits.stream().map(BodyHit::body).toList(), "ray " + ray);
                for (BodyHit h : hits) {
                    assertEquals(distance.get(h.body()), h.distance());
                }
                BodyHit first = w.raycastFirst(ray, odd);
                List<Body> oddOrder = order.stream().filter(odd).toList();
                if (oddOrder.isEmpty()) {
                    assertNull(first);
                } else {
                    assertEquals(oddOrder.get(0), first.body());
                }
            }
        }
        assertTrue(found > 300, "the points found too few bodies: " + found);
    }

    @Test
    void layersAndEvents_matchBruteForce() {
        SplittableRandom rnd = new SplittableRandom(5);
        int enters = 0, exits = 0, stays = 0;
        for (int round = 0; round < 60; round++) {
            World w = randomWorld(rnd, 10 + rnd.nextInt(30));
            Map<String, BodyEvent.Kind> last = new HashMap<>();
            for (int frame = 0; frame < 25; frame++) {
                Map<String, Body[]> met = new HashMap<>();
                for (Body b : w.bodies()) {
                    switch (rnd.nextInt(5)) {
                        case 0 -> {
                            List<int[]> asked = new ArrayList<>();
                            List<Collision> got = w.move(b, rnd.nextInt(41) - 20, rnd.nextInt(41) - 20, (m, o) -> {
                                assertTrue(m.accepts(o), "the filter is asked only about bodies whose layers accept");
                                assertTrue(!m.isSensor() && !o.isSensor(), "nor about sensors");
                                return Reaction.values()[rnd.nextInt(4)];
                            });
                            for (Collision c : got) {
                                assertTrue(c.mover().accepts(c.other()));
                                met.put(key(c.mover(), c.other()), pair(c.mover(), c.other()));
                            }
                        }
                        case 1 -> b.turnBy(0.3f);
                        case 2 -> {
                            if (rnd.nextInt(10) == 0) {
                                w.remove(b);
                            }
                        }
                        default -> { }
                    }
                }
                if (rnd.nextInt(4) == 0) {
                    w.add(local(rnd), rnd.nextInt(300), rnd.nextInt(300), 0);
                }
                // Brute force: every pair whose layers accept that overlaps, or that a move met.
                Map<String, Body[]> now = new HashMap<>(met);
                List<Body> all = w.bodies();
                for (int i = 0; i < all.size(); i++) {
                    for (int j = i + 1; j < all.size(); j++) {
                        Body a = all.get(i), b = all.get(j);
                        if (a.accepts(b) && a.shape().overlaps(b.shape())) {
                            now.put(key(a, b), pair(a, b));
                        }
                    }
                }
                now.values().removeIf(p -> !p[0].alive() || !p[1].alive() || !p[0].accepts(p[1]));
                java.util.Set<String> overlapping = new java.util.TreeSet<>();
                for (int i = 0; i < all.size(); i++) {
                    for (int j = i + 1; j < all.size(); j++) {
                        if (all.get(i).accepts(all.get(j)) && all.get(i).shape().overlaps(all.get(j).shape())) {
                            overlapping.add(key(all.get(i), all.get(j)));
                        }
                    }
                }
                java.util.Set<String> pairs = new java.util.TreeSet<>();
                w.pairs((a, b) -> {
                    assertTrue(all.indexOf(a) < all.indexOf(b), "the body added first first");
                    assertTrue(pairs.add(key(a, b)), "each pair once");
                });
                assertEquals(overlapping, pairs, "pairs");
                Map<String, BodyEvent.Kind> want = new TreeMap<>();
                for (String k : now.keySet()) {
                    want.put(k, last.containsKey(k) ? BodyEvent.Kind.STAY : BodyEvent.Kind.ENTER);
                }
                for (String k : last.keySet()) {
                    if (!now.containsKey(k)) {
                        want.put(k, BodyEvent.Kind.EXIT);
                    }
                }
                Map<String, BodyEvent.Kind> got = new TreeMap<>();
                for (BodyEvent e : w.step()) {
                    assertTrue(got.put(key(e.a(), e.b()), e.kind()) == null, "each pair once a step: " + e);
                    switch (e.kind()) {
                        case ENTER -> enters++;
                        case EXIT -> exits++;
                        default -> stays++;
                    }
                }
                assertEquals(want, got, "round " + round + " frame " + frame);
                last = new HashMap<>();
                for (String k : now.keySet()) {
                    last.put(k, BodyEvent.Kind.STAY);
                }
            }
        }
        assertTrue(enters > 100 && exits > 50 && stays > 100, enters + " " + exits + " " + stays);
    }

    @Test
    void aRemovedBody_exitsOnce() {
        World w = new World();
        Body a = w.add(new Circle(0, 0, 10));
        Body b = w.add(new Circle(5, 0, 10));
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.ENTER, a, b)), w.step());
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.STAY, a, b)), w.step());
        w.remove(b);
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.EXIT, a, b)), w.step());
        assertEquals(List.of(), w.step());
    }

    @Test
    void aSensorsContacts_areReported() {
        World w = new World();
        Body coin = w.add(new Circle(100, 0, 5)).sensor(true);
        Body player = w.add(new Rect(0, -5, 10, 10));
        w.move(player, 93, 0);
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.ENTER, coin, player)), w.step());
        w.move(player, 50, 0);
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.STAY, coin, player)), w.step(), "crossed during the step");
        w.move(player, 50, 0);
        assertEquals(List.of(new BodyEvent(BodyEvent.Kind.EXIT, coin, player)), w.step());
    }

    private static String key(Body a, Body b) {
        int x = System.identityHashCode(a), y = System.identityHashCode(b);
        return Math.min(x, y) + "-" + Math.max(x, y);
    }

    private static Body[] pair(Body a, Body b) {
        return new Body[] {a, b};
    }

    private static boolean solidAt(Grid g, float x, float y) {
        int c = g.colAt(x), r = g.rowAt(y);
        return g.inGrid(c, r) && g.isSolid(c, r) && g.cellRect(c, r).contains(x, y);
    }

    private static boolean meets(Body b, Shape s) {
        if (b.grid() == null) {
            return b.shape().overlaps(s);
        }
        Grid g = b.grid();
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                if (g.isSolid(c, r) && s.overlaps(g.cellRect(c, r))) {
                    return true;
                }
            }
        }
        return false;
    }

    private static Float rayDistance(Body b, Ray ray) {
        if (b.grid() == null) {
            RayHit h = ray.cast(b.shape());
            return h == null ? null : h.distance();
        }
        Grid g = b.grid();
        Float best = null;
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                if (g.isSolid(c, r)) {
                    RayHit h = ray.cast(g.cellRect(c, r));
                    if (h != null && (best == null || h.distance() < best)) {
                        best = h.distance();
                    }
                }
            }
        }
        return best;
    }
}
