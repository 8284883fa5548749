package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * What the world and its bodies hand back: an unturned body's box exactly its shape's, a
 * removed body refusing its data, and every list the world returns unmodifiable.
 */
class WorldAnswersTest {

    @Test
    void anUnturnedBodysBounds_areItsShapesExactly() {
        World w = new World();
        Body floor = w.add(new Rect(0, 400, 800, 20));
        assertEquals(new Rect(0, 400, 800, 20), floor.bounds(), "a floor's top reads 400");
        floor.moveTo(floor.pivotX() + 0.1f, floor.pivotY() + 0.3f);
        assertEquals(floor.shape().bounds(), floor.bounds());
        SplittableRandom rnd = new SplittableRandom(5);
        for (int i = 0; i < 2000; i++) {
            Body b = w.add(WorldBruteForceTest.local(rnd), (float) rnd.nextDouble() * 1e4f, (float) rnd.nextDouble() * 1e4f, 0);
            assertEquals(b.shape().bounds(), b.bounds(), "unturned " + b);
            b.turnTo((float) rnd.nextDouble() * 6);
            Rect box = b.bounds(), exact = b.shape().bounds();
            assertTrue(box.x() <= exact.x() && box.y() <= exact.y()
                    && (double) box.x() + box.w() >= (double) exact.x() + exact.w()
                    && (double) box.y() + box.h() >= (double) exact.y() + exact.h(), "a turned body's box holds its shape: " + b);
            b.turnTo(0);
            assertEquals(b.shape().bounds(), b.bounds(), "turned back " + b);
        }
        Body grid = w.add(new Grid(4, 3, 10));
        assertEquals(new Rect(0, 0, 40, 30), grid.bounds());
    }

    @Test
    void aRemovedBody_refusesItsData() {
        World w = new World();
        Body b = w.add(new Circle(0, 0, 5)).data("coin");
        w.remove(b);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> b.data("gem"));
        assertTrue(e.getMessage().contains("removed"), e.getMessage());
        assertEquals("coin", b.data(), "reading still works");
    }

    @Test
    void theListsTheWorldHandsBack_areUnmodifiable() {
        World w = new World();
        Body a = w.add(new Circle(0, 0, 10));
        Body b = w.add(new Circle(5, 0, 10));
        w.move(b, 1, 0);
        Grid g = new Grid(2, 2, 10);
        g.fill(Grid.SOLID);
        w.add(g);
        List<List<?>> lists = List.of(w.bodies(), w.queryPoint(0, 0), w.queryShape(new Circle(0, 0, 3)),
                w.overlapping(a), w.raycast(new Ray(-50, 0, 1, 0)), w.move(a, 0, 1), w.collisions(), w.step());
        for (List<?> list : lists) {
            assertTrue(!list.isEmpty(), "each list has something in it: " + lists);
            assertThrows(UnsupportedOperationException.class, list::clear, "unmodifiable: " + list);
        }
    }

    @Test
    void aListTheWorldCannotAddTo_isRefusedNamingIt() {
        World w = new World();
        Body a = w.add(new Circle(0, 0, 10));
        w.add(new Circle(5, 0, 10));
        List<Body> fixed = List.of();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> w.queryPoint(1, 0, b -> true, fixed));
        assertTrue(e.getMessage().startsWith("out"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> w.queryShape(new Circle(0, 0, 1), b -> true, fixed));
        assertThrows(IllegalArgumentException.class, () -> w.overlapping(a, b -> true, fixed));
        assertThrows(IllegalArgumentException.class, () -> w.raycast(new Ray(-50, 0, 1, 0), b -> true, List.of()));
        e = assertThrows(IllegalArgumentException.class, () -> w.step(List.of()));
        assertTrue(e.getMessage().startsWith("changes"), e.getMessage());
        List<BodyEvent> changes = new java.util.ArrayList<>();
        w.step(changes);
        assertEquals(1, changes.size(), "the refused step changed nothing: the contact enters now");
        assertThrows(IllegalArgumentException.class, () -> w.contacts(a, fixed));
    }
}
