package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Supplier;

/**
 * The reference for the broad-phase tests: the boxes in a plain map, and every answer by a
 * direct double loop over {@link Collide#rectRect}, {@link Shape#overlaps} and
 * {@link Ray#distanceToRect}. Also the list of structures under test and the checks that
 * compare one of them with the model.
 */
final class BroadPhaseModel {

    /** Every structure the contract covers, by name. grid(7.0) has cells that are not a power of two; each name is the structure's toString. */
    static final Map<String, Supplier<BroadPhase>> STRUCTURES = structures();

    private static Map<String, Supplier<BroadPhase>> structures() {
        Map<String, Supplier<BroadPhase>> m = new LinkedHashMap<>();
        m.put("bruteForce", BroadPhase::bruteForce);
        m.put("grid", BroadPhase::grid);
        // the grid's cell arithmetic at a fixed size that is no power of two (its factory picks the size itself)
        m.put("grid(7.0)", () -> new hitbox.internal.HashGridBroadPhase(7));
        m.put("quadtree", BroadPhase::quadtree);
        m.put("sweepAndPrune", BroadPhase::sweepAndPrune);
        m.put("dynamicTree", BroadPhase::dynamicTree);
        return m;
    }

    final Map<Integer, float[]> boxes = new LinkedHashMap<>();

    void put(int id, float x, float y, float w, float h) {
        boxes.put(id, new float[] {x, y, w, h});
    }

    void remove(int id) {
        boxes.remove(id);
    }

    /** Every overlapping pair as "a,b" with a &lt; b, sorted. */
    Set<String> pairs() {
        Set<String> out = new TreeSet<>();
        List<Map.Entry<Integer, float[]>> list = new ArrayList<>(boxes.entrySet());
        for (int i = 0; i < list.size(); i++) {
            for (int j = i + 1; j < list.size(); j++) {
                float[] p = list.get(i).getValue(), q = list.get(j).getValue();
                if (Collide.rectRect(p[0], p[1], p[2], p[3], q[0], q[1], q[2], q[3])) {
                    int a = list.get(i).getKey(), b = list.get(j).getKey();
                    out.add(Math.min(a, b) + "," + Math.max(a, b));
                }
            }
        }
        return out;
    }

    Set<Integer> query(float x, float y, float w, float h) {
        Set<Integer> out = new TreeSet<>();
        boxes.forEach((id, b) -> {
            if (Collide.rectRect(x, y, w, h, b[0], b[1], b[2], b[3])) {
                out.add(id);
            }
        });
        return out;
    }

    Set<Integer> query(Shape shape) {
        Set<Integer> out = new TreeSet<>();
        boxes.forEach((id, b) -> {
            if (shape.overlaps(new Rect(b[0], b[1], b[2], b[3]))) {
                out.add(id);
            }
        });
        return out;
    }

    /** The ray's hits as "id@distance", nearest first, ties by id. */
    List<String> ray(Ray ray) {
        List<long[]> hits = new ArrayList<>();
        boxes.forEach((id, b) -> {
            float d = Ray.distanceToRect(ray.ox(), ray.oy(), ray.dx(), ray.dy(), ray.maxDistance(), b[0], b[1], b[2], b[3]);
            if (d != Float.POSITIVE_INFINITY) {
                hits.add(new long[] {Float.floatToIntBits(d), id});
            }
        });
        hits.sort((p, q) -> p[0] != q[0] ? Long.compare(p[0], q[0]) : Long.compare(p[1], q[1]));
        List<String> out = new ArrayList<>();
        for (long[] h : hits) {
            out.add(h[1] + "@" + Float.intBitsToFloat((int) h[0]));
        }
        return out;
    }

    // ---------------------------------------------------------------- reading a structure

    /** The structure's pairs, failing on a pair in the wrong order or reported twice. */
    static Set<String> pairsOf(BroadPhase bp) {
        Set<String> out = new TreeSet<>();
        bp.pairs((a, b) -> {
            if (a >= b) {
                fail(bp + " reported (" + a + ", " + b + "): the smaller id must come first");
            }
            if (!out.add(a + "," + b)) {
                fail(bp + " reported (" + a + ", " + b + ") twice");
            }
        });
        return out;
    }

    static Set<Integer> queryOf(BroadPhase bp, float x, float y, float w, float h) {
        Set<Integer> out = new TreeSet<>();
        bp.query(x, y, w, h, id -> assertTrue(out.add(id), bp + " reported " + id + " twice"));
        return out;
    }

    /**
     * The boxes a shape overlaps, asked as a sketch asks: the box query over the shape's
     * bounds, then {@link Shape#overlaps} on each box found (read back with forEachBox).
     */
    static Set<Integer> queryOf(BroadPhase bp, Shape shape) {
        Map<Integer, Rect> stored = new HashMap<>();
        bp.forEachBox((id, x, y, w, h) -> stored.put(id, new Rect(x, y, w, h)));
        Rect b = shape.bounds();
        Set<Integer> out = new TreeSet<>();
        bp.query(b.x(), b.y(), b.w(), b.h(), id -> {
            assertTrue(stored.containsKey(id), bp + " reported " + id + ", which it does not store");
            if (shape.overlaps(stored.get(id))) {
                assertTrue(out.add(id), bp + " reported " + id + " twice for " + shape);
            }
        });
        return out;
    }

    static List<String> rayOf(BroadPhase bp, Ray ray) {
        List<String> out = new ArrayList<>();
        bp.raycast(ray, (id, d) -> out.add(id + "@" + d));
        return out;
    }

    /** Everything the structure stores: "id:x,y,w,h", sorted. */
    static Set<String> contentsOf(BroadPhase bp) {
        Set<String> out = new TreeSet<>();
        bp.forEachBox((id, x, y, w, h) -> out.add(id + ":" + x + "," + y + "," + w + "," + h));
        return out;
    }

    Set<String> contents() {
        Set<String> out = new TreeSet<>();
        boxes.forEach((id, b) -> out.add(id + ":" + b[0] + "," + b[1] + "," + b[2] + "," + b[3]));
        return out;
    }

    /** The structure agrees with the model: same boxes, same pairs. */
    void assertSame(BroadPhase bp, String when) {
        assertEquals(boxes.size(), bp.size(), bp + " size, " + when);
        assertEquals(contents(), contentsOf(bp), bp + " contents, " + when);
        Set<Integer> ids = new HashSet<>();
        bp.forEachBox((id, x, y, w, h) -> assertTrue(ids.add(id), bp + " forEachBox gave " + id + " twice"));
        assertEquals(boxes.keySet(), ids, bp + " forEachBox, " + when);
        Set<String> want = pairs(), got = pairsOf(bp);
        if (!want.equals(got)) {
            Set<String> missing = new TreeSet<>(want), extra = new TreeSet<>(got);
            missing.removeAll(got);
            extra.removeAll(want);
            fail(bp + " pairs differ " + when + ": missing " + first(missing) + ", extra " + first(extra)
                    + " (" + want.size() + " expected)" + describe(missing) + describe(extra));
        }
    }

    private static String first(Set<String> s) {
        return s.size() <= 10 ? s.toString() : new ArrayList<>(s).subList(0, 10) + "... (" + s.size() + ")";
    }

    private String describe(Set<String> pairs) {
        if (pairs.isEmpty()) {
            return "";
        }
        String[] ab = pairs.iterator().next().split(",");
        return "; e.g. " + ab[0] + "=" + Arrays.toString(boxes.get(Integer.parseInt(ab[0])))
                + " " + ab[1] + "=" + Arrays.toString(boxes.get(Integer.parseInt(ab[1])));
    }
}
