package hitbox;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link Hits} and {@link Motion} with their obstacles in a {@link BroadPhase} give exactly the
 * answers of their list versions over the same boxes (the list's index is the box's id), for
 * every structure, random worlds, touching and far-away boxes, and NaN, infinite and negative
 * movers.
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
            check(b, rects, v, 2, 5, 5, 1, 1);
            check(b, rects, 2, v, 5, 5, 1, 1);
            check(b, rects, 2, 2, v, 5, 1, 1);
            check(b, rects, 2, 2, 5, v, 1, 1);
            check(b, rects, 2, 2, 5, 5, v, 1);
            check(b, rects, 2, 2, 5, 5, 1, v);
        }
    }

    @Test
    void nullObstacles_areRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Hits.any(0, 0, 1, 1, (BroadPhase) null));
        assertEquals(true, e.getMessage().contains("obstacles"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Motion.bounce(0, 0, 1, 1, 1, 1, (BroadPhase) null, 100, 100));
        assertEquals(true, e.getMessage().contains("obstacles"), e.getMessage());
    }

    private static float coordinate(Random random, int world) {
        return world % 2 == 0 ? random.nextInt(200) : random.nextFloat() * 200;
    }

    private static void check(BroadPhase b, List<Rect> rects, float x, float y, float w, float h, float vx, float vy) {
        String where = "(" + x + ", " + y + ", " + w + ", " + h + ") moving (" + vx + ", " + vy + ")";
        assertArrayEquals(Hits.all(x, y, w, h, rects), Hits.all(x, y, w, h, b), "all " + where);
        assertEquals(Hits.first(x, y, w, h, rects), Hits.first(x, y, w, h, b), "first " + where);
        assertEquals(Hits.count(x, y, w, h, rects), Hits.count(x, y, w, h, b), "count " + where);
        assertEquals(Hits.any(x, y, w, h, rects), Hits.any(x, y, w, h, b), "any " + where);
        assertEquals(Motion.rectBlocked(x, y, w, h, vx, vy, rects), Motion.rectBlocked(x, y, w, h, vx, vy, b), "rectBlocked " + where);
        assertEquals(Motion.bounce(x, y, w, h, vx, vy, rects, 300, 300), Motion.bounce(x, y, w, h, vx, vy, b, 300, 300), "bounce " + where);
    }
}
