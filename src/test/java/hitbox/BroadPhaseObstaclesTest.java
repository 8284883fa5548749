package hitbox;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;
import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Obstacles in a {@link BroadPhase} give exactly the answers of a list of them (the list's index
 * is the box's id): {@link BroadPhase#query(float, float, float, float, java.util.function.IntConsumer)}
 * as every listed box the query box {@link Shape#overlaps}, for every structure, random worlds,
 * touching and far-away boxes, and boxes far out, huge or flat. (Motion's broad-phase forms,
 * tested here against their list forms, went in issue 30: a sketch with thousands of
 * obstacles asks a World.)
 */
class BroadPhaseObstaclesTest {

    static final List<Supplier<BroadPhase>> STRUCTURES = List.of(BroadPhase::grid, BroadPhase::quadtree,
            BroadPhase::sweepAndPrune, BroadPhase::dynamicTree, BroadPhase::bruteForce);

    @ParameterizedTest(name = "structure {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4})
    void hitsAndMotion_agreeWithTheListVersions(int structure) {
        Random random = new Random(11 + structure);
        for (int world = 0; world < 40; world++) {
            List<Rect> rects = new ArrayList<>();
            BroadPhase b = STRUCTURES.get(structure).get();
            int n = 1 + random.nextInt(60);
            float scale = world % 5 == 4 ? 1e6f : 1;
            for (int i = 0; i < n; i++) {
                // Whole numbers half the time, so boxes share edges and touch exactly.
                float x = coordinate(random, world) * scale;
                float y = coordinate(random, world) * scale;
                float w = random.nextInt(4) == 0 ? 0 : 1 + random.nextInt(30);
                float h = random.nextInt(4) == 0 ? 0 : 1 + random.nextInt(30);
                rects.add(new Rect(x, y, w, h));
                b.put(i, x, y, w, h);
            }
            for (int q = 0; q < 60; q++) {
                float x = coordinate(random, world) * scale;
                float y = coordinate(random, world) * scale;
                float w = random.nextInt(30);
                float h = random.nextInt(30);
                float vx = random.nextInt(21) - 10;
                float vy = random.nextInt(21) - 10;
                check(b, rects, x, y, w, h, vx, vy);
            }
        }
    }

    @Test
    void unusualMovers_agreeWithTheListVersions() {
        List<Rect> rects = List.of(new Rect(0, 0, 10, 10), new Rect(20, 0, 10, 10), new Rect(-1e30f, -5, 1e30f, 10));
        BroadPhase b = BroadPhase.grid();
        for (int i = 0; i < rects.size(); i++) {
            b.put(i, rects.get(i).x(), rects.get(i).y(), rects.get(i).w(), rects.get(i).h());
        }
        float[] odd = {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, -1, Float.MAX_VALUE, -Float.MAX_VALUE, 0};
        for (float v : odd) {
            // A mover the Rect constructor refuses (NaN, infinite, negative size) is no mover
            // since the raw-float forms went (issue 30); the rest must agree.
            checkIfARect(b, rects, v, 2, 5, 5, 1, 1);
            checkIfARect(b, rects, 2, v, 5, 5, 1, 1);
            checkIfARect(b, rects, 2, 2, v, 5, 1, 1);
            checkIfARect(b, rects, 2, 2, 5, v, 1, 1);
            check(b, rects, 2, 2, 5, 5, v, 1);
            check(b, rects, 2, 2, 5, 5, 1, v);
        }
    }

    private static float coordinate(Random random, int world) {
        return world % 2 == 0 ? random.nextInt(200) : random.nextFloat() * 200;
    }

    private static void checkIfARect(BroadPhase b, List<Rect> rects, float x, float y, float w, float h, float vx, float vy) {
        boolean made;
        try {
            new Rect(x, y, w, h);
            made = true;
        } catch (IllegalArgumentException refused) {
            made = false;
        }
        if (made) {
            check(b, rects, x, y, w, h, vx, vy);
        }
    }

    private static void check(BroadPhase b, List<Rect> rects, float x, float y, float w, float h, float vx, float vy) {
        String where = "(" + x + ", " + y + ", " + w + ", " + h + ") moving (" + vx + ", " + vy + ")";
        List<Integer> found = new ArrayList<>();
        b.query(x, y, w, h, found::add);
        int[] ids = found.stream().mapToInt(Integer::intValue).sorted().toArray();
        Rect box = new Rect(x, y, w, h);
        int[] want = IntStream.range(0, rects.size()).filter(i -> box.overlaps(rects.get(i))).toArray();
        assertArrayEquals(want, ids, "all " + where);
    }
}
