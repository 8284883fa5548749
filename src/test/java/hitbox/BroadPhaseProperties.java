package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.PropertyDefaults;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;

/**
 * Generated histories for every broad phase ({@link BroadPhaseModel#STRUCTURES}), checked
 * against the model (a double loop over {@link Collide#rectRect}):
 *
 * <ul>
 *   <li>after any sequence of puts (new ids and moves), removals and clears, every structure
 *       reports exactly the model's pairs, each once, smaller id first ({@link BroadPhaseModel#pairsOf}
 *       fails on a reversed or repeated pair);</li>
 *   <li>a query finds exactly the stored boxes that rectRect says overlap it, each once.</li>
 * </ul>
 *
 * <p>Coordinates come from a small set of whole numbers, halves, and values near a million, so
 * touching edges, shared corners, zero sizes and piles are common, and from any float in a
 * range, so that rounding has its say too.
 */
@PropertyDefaults(tries = 300, shrinking = ShrinkingMode.OFF)
class BroadPhaseProperties {

    /** One step of a history, by kind: 0 put (add or move), 6 remove, 8 clear, 9 check every structure now. */
    record Op(int kind, int id, float x, float y, float w, float h) {
    }

    @Property
    void sameLikeBruteForce_afterAnyHistory(@ForAll("histories") List<Op> history) {
        Map<String, BroadPhase> all = new LinkedHashMap<>();
        BroadPhaseModel.STRUCTURES.forEach((name, make) -> all.put(name, make.get()));
        BroadPhaseModel model = new BroadPhaseModel();
        List<String> done = new ArrayList<>();
        for (Op op : history) {
            done.add(op.toString());
            if (op.kind <= 5) {
                model.put(op.id, op.x, op.y, op.w, op.h);
                all.values().forEach(bp -> bp.put(op.id, op.x, op.y, op.w, op.h));
            } else if (op.kind <= 7) {
                boolean present = model.boxes.containsKey(op.id);
                model.remove(op.id);
                all.values().forEach(bp -> assertEquals(present, bp.remove(op.id), bp + " remove " + op.id));
            } else if (op.kind == 8) {
                model.boxes.clear();
                all.values().forEach(BroadPhase::clear);
            } else {
                all.values().forEach(bp -> model.assertSame(bp, "after " + done));
            }
        }
        all.values().forEach(bp -> model.assertSame(bp, "at the end of " + done));
    }

    @Property
    void query_isTheStoredBoxesThatOverlapIt(@ForAll("boxLists") List<float[]> boxes, @ForAll("boxes") float[] q) {
        BroadPhaseModel model = new BroadPhaseModel();
        for (int i = 0; i < boxes.size(); i++) {
            float[] b = boxes.get(i);
            model.put(i * 7 + 3, b[0], b[1], b[2], b[3]);
        }
        Set<Integer> want = model.query(q[0], q[1], q[2], q[3]);
        BroadPhaseModel.STRUCTURES.forEach((name, make) -> {
            BroadPhase bp = make.get();
            model.boxes.forEach((id, b) -> bp.put(id, b[0], b[1], b[2], b[3]));
            assertEquals(want, BroadPhaseModel.queryOf(bp, q[0], q[1], q[2], q[3]), name + " query " + java.util.Arrays.toString(q));
        });
    }

    // ---------------------------------------------------------------- generators

    @Provide
    Arbitrary<List<Op>> histories() {
        Arbitrary<Integer> kinds = Arbitraries.frequency(
                net.jqwik.api.Tuple.of(60, 0), net.jqwik.api.Tuple.of(15, 6),
                net.jqwik.api.Tuple.of(1, 8), net.jqwik.api.Tuple.of(10, 9));
        Arbitrary<Integer> ids = Arbitraries.oneOf(Arbitraries.integers().between(0, 12),
                Arbitraries.integers().between(0, Integer.MAX_VALUE));
        Arbitrary<Op> op = Combinators.combine(kinds, ids, boxes())
                .as((k, id, b) -> new Op(k, id, b[0], b[1], b[2], b[3]));
        return op.list().ofMinSize(1).ofMaxSize(80);
    }

    @Provide
    Arbitrary<List<float[]>> boxLists() {
        return boxes().list().ofMaxSize(60);
    }

    /** A box: a corner and a size, from one of three scales. */
    @Provide
    Arbitrary<float[]> boxes() {
        Arbitrary<Float> small = Arbitraries.integers().between(-4, 12).map(i -> i / 2f);
        Arbitrary<Float> smallSize = Arbitraries.integers().between(0, 8).map(i -> i / 2f);
        Arbitrary<Float> far = Arbitraries.integers().between(-6, 6).map(i -> 1_000_000f + i * 0.0625f);
        Arbitrary<Float> farSize = Arbitraries.integers().between(0, 6).map(i -> i * 0.0625f);
        Arbitrary<Float> any = Arbitraries.floats().between(-50, 50);
        Arbitrary<Float> anySize = Arbitraries.floats().between(0, 30);
        return Arbitraries.oneOf(
                Combinators.combine(small, small, smallSize, smallSize).as((x, y, w, h) -> new float[] {x, y, w, h}),
                Combinators.combine(far, far, farSize, farSize).as((x, y, w, h) -> new float[] {x, y, w, h}),
                Combinators.combine(any, any, anySize, anySize).as((x, y, w, h) -> new float[] {x, y, w, h}));
    }
}
