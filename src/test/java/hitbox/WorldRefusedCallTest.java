package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * Bad input to the world: every refused call throws a clear exception naming the parameter or
 * the rule, and the world stays exactly as it was: every body's pose, shape and box, and every
 * box of the broad phase, checked after each refused call.
 */
class WorldRefusedCallTest {

    private World w;
    private Body player;
    private Body wall;
    private Body platform;
    private Body rider;
    private Body turned;

    private void build() {
        w = new World();
        wall = w.add(new Rect(100, 0, 10, 200));
        player = w.add(new Circle(50, 50, 10));
        platform = w.add(new Rect(0, 300, 100, 10)).carrier(true);
        rider = w.add(new Rect(40, 280, 10, 20));
        turned = w.add(Polygon.of(0, 0, 10, 0, 5, 8), 200, 200, 0.7f);
        w.add(Grid.parse("#..\n..#", 16));
        w.move(player, 10, 0);
        w.add(new Circle(65, 55, 8));  // overlaps the player
    }

    /** Everything observable about the world, as text. */
    private String snapshot() {
        StringBuilder s = new StringBuilder(w.toString()).append('\n');
        for (Body b : w.bodies()) {
            s.append(b).append(' ').append(b.pivotX()).append(',').append(b.pivotY()).append(',').append(b.angle()).append(' ')
                    .append(b.shape()).append(' ').append(b.bounds()).append(' ').append(b.category()).append('/')
                    .append(b.mask()).append(b.isSensor()).append(b.oneWay()).append(b.isCarrier()).append('\n');
        }
        BroadPhase bp = w.broadPhase();
        List<String> boxes = new ArrayList<>();
        bp.forEachBox((id, x, y, bw, bh) -> boxes.add(id + ":" + x + "," + y + "," + bw + "," + bh));
        boxes.sort(null);
        s.append(bp.size()).append(' ').append(boxes).append(' ').append(w.collisions());
        return s.toString();
    }

    private <T extends Throwable> void refused(Class<T> type, String words, Executable call) {
        build();
        String before = snapshot();
        T e = assertThrows(type, call);
        assertTrue(e.getMessage() != null && e.getMessage().contains(words), "message " + e.getMessage() + " lacks " + words);
        assertEquals(before, snapshot(), "the world changed after a refused call: " + e);
    }

    @Test
    void badNumbers() {
        refused(IllegalArgumentException.class, "dx", () -> w.move(player, Float.NaN, 0));
        refused(IllegalArgumentException.class, "dy", () -> w.move(player, 0, Float.POSITIVE_INFINITY));
        refused(IllegalArgumentException.class, "dx", () -> w.move(player, -Float.MAX_VALUE, 0));
        refused(IllegalArgumentException.class, "x", () -> player.moveTo(Float.NaN, 0));
        refused(IllegalArgumentException.class, "y", () -> player.moveTo(0, Float.NEGATIVE_INFINITY));
        refused(IllegalArgumentException.class, "float range", () -> player.moveTo(Float.MAX_VALUE, 0));
        refused(IllegalArgumentException.class, "float range", () -> turned.moveTo(-Float.MAX_VALUE, 0));
        refused(IllegalArgumentException.class, "angle", () -> turned.turnTo(Float.NaN));
        refused(IllegalArgumentException.class, "angle", () -> turned.moveTo(5, 5, Float.NaN));
        refused(IllegalArgumentException.class, "y", () -> turned.moveTo(5, Float.NaN, 1));
        refused(IllegalArgumentException.class, "float range", () -> turned.moveTo(Float.MAX_VALUE, 0, 1));
        refused(IllegalArgumentException.class, "da", () -> turned.turnBy(Float.POSITIVE_INFINITY));
        refused(IllegalArgumentException.class, "x", () -> w.add(new Circle(0, 0, 1), Float.NaN, 0, 0));
        refused(IllegalArgumentException.class, "angle", () -> w.add(new Circle(0, 0, 1), 0, 0, Float.NaN));
        refused(IllegalArgumentException.class, "float range", () -> w.add(new Circle(0, 0, 1), Float.MAX_VALUE, 0, 0));
        refused(IllegalArgumentException.class, "x", () -> w.queryPoint(Float.NaN, 0));
        refused(IllegalArgumentException.class, "w", () -> w.queryShape(new Rect(0, 0, -1, 0)));
    }

    @Test
    void badBodies() {
        refused(IllegalArgumentException.class, "body", () -> w.move(null, 1, 1));
        refused(IllegalArgumentException.class, "filter", () -> w.move(player, 1, 1, null));
        refused(IllegalArgumentException.class, "another world", () -> w.move(new World().add(new Circle(0, 0, 1)), 1, 1));
        refused(IllegalArgumentException.class, "another world", () -> w.remove(new World().add(new Circle(0, 0, 1))));
        // A removed body is one kind of refusal wherever it is used: the world's methods and its own.
        refused(IllegalStateException.class, "removed", () -> {
            World other = new World();
            Body dead = other.add(new Circle(0, 0, 1));
            other.remove(dead);
            w.move(dead, 1, 1);
        });
        build();
        w.remove(rider);
        String before = snapshot();
        assertThrows(IllegalStateException.class, () -> w.remove(rider));
        assertThrows(IllegalStateException.class, () -> w.move(rider, 1, 1));
        assertThrows(IllegalStateException.class, () -> rider.moveTo(1, 1));
        assertThrows(IllegalStateException.class, () -> rider.data("x"));
        assertThrows(IllegalStateException.class, () -> w.overlapping(rider));
        assertThrows(IllegalStateException.class, () -> w.contacts(rider, new java.util.ArrayList<>()));
        assertThrows(IllegalStateException.class, () -> w.inContact(rider, player));
        assertEquals(before, snapshot());
        refused(IllegalArgumentException.class, "grid", () -> w.move(w.bodies().get(5), 1, 1));
        refused(IllegalStateException.class, "grid", () -> w.bodies().get(5).moveTo(1, 1));
        refused(IllegalArgumentException.class, "shape", () -> w.add((Shape) null));
        refused(IllegalArgumentException.class, "side", () -> wall.oneWay(null));
    }

    @Test
    void filtersThatThrow_orChangeTheWorld() {
        refused(IllegalArgumentException.class, "filter threw", () -> w.move(player, 100, 0, (m, o) -> {
            throw new RuntimeException("boom");
        }));
        refused(IllegalStateException.class, "inside a filter", () -> w.move(player, 100, 0, (m, o) -> {
            w.remove(o);
            return Reaction.SLIDE;
        }));
        refused(IllegalStateException.class, "inside a filter", () -> w.move(player, 100, 0, (m, o) -> {
            w.add(new Circle(0, 0, 3));
            return Reaction.SLIDE;
        }));
        refused(IllegalStateException.class, "inside a filter", () -> w.move(player, 100, 0, (m, o) -> {
            o.moveTo(o.pivotX() + 1, o.pivotY() + 1);
            return Reaction.SLIDE;
        }));
        refused(IllegalStateException.class, "inside a filter", () -> w.move(player, 100, 0, (m, o) -> {
            w.move(o, 1, 1);
            return Reaction.SLIDE;
        }));
        Predicate<Body> adds = b -> w.add(new Circle(0, 0, 3)) != null;
        refused(IllegalStateException.class, "inside a filter", () -> w.queryPoint(105, 50, adds, new ArrayList<>()));
        refused(IllegalStateException.class, "inside a filter", () -> w.queryShape(new Circle(100, 50, 50), b -> {
            w.remove(b);
            return true;
        }, new ArrayList<>()));
        refused(IllegalArgumentException.class, "filter threw", () -> w.raycast(new Ray(0, 50, 1, 0), b -> {
            throw new ArithmeticException("boom");
        }, new ArrayList<>()));
        refused(IllegalStateException.class, "inside a filter", () -> w.overlapping(player, b -> {
            w.step();
            return true;
        }, new ArrayList<>()));
    }

    @Test
    void aCarrierWhoseFilterThrows_leavesItsRidersWhereTheyWere() {
        // Going up, the riders move first: they must be put back when the platform's filter throws.
        refused(IllegalArgumentException.class, "filter threw", () -> w.move(platform, 5, -130, (m, o) -> {
            throw new IllegalArgumentException("no");
        }));
        build();
        w.add(new Rect(0, 200, 100, 10));  // a ceiling the platform meets going up
        String before = snapshot();
        assertThrows(IllegalArgumentException.class, () -> w.move(platform, 0, -200, (m, o) -> {
            throw new IllegalArgumentException("no");
        }));
        assertEquals(before, snapshot());
        w.move(platform, 0, -30);
        assertEquals(260, rider.pivotY(), 1e-4);
    }

    @Test
    void aCarrierRefusedRightAfterAStep_leavesTheFramesCollisionsAsTheyWere() {
        // Right after a step, collisions() is the frame it ended (the player met the wall);
        // a carrier's move that is refused must leave that, and one that goes on replaces it.
        build();
        w.move(player, 50, 0);
        w.step();
        List<Collision> lastFrame = w.collisions();
        assertTrue(lastFrame.stream().anyMatch(c -> c.other() == wall), lastFrame.toString());
        String before = snapshot();
        assertThrows(IllegalArgumentException.class, () -> w.move(platform, 5, -130, (m, o) -> {
            throw new IllegalArgumentException("no");
        }));
        assertEquals(before, snapshot());
        assertEquals(lastFrame, w.collisions());
        w.add(new Rect(0, 200, 100, 10));  // a ceiling the platform and its rider meet going up
        w.move(platform, 0, -200);
        List<Collision> now = w.collisions();
        assertTrue(now.stream().noneMatch(c -> c.other() == wall), "the last frame's collisions gave way: " + now);
        assertTrue(now.stream().anyMatch(c -> c.mover() == rider) && now.stream().anyMatch(c -> c.mover() == platform),
                "the rider's and the platform's collisions are kept for the step: " + now);
    }
}
