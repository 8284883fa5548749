package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A world used bump.lua's way, moved every frame and never stepped (the README's first world
 * sketch reads the moves' answers and the character's state, and never calls {@code step()}):
 * it keeps a bounded number of the collisions met, not one per move for as long as it runs.
 */
class WorldUnsteppedTest {

    @Test
    void movedAndNeverStepped_keepsTheLatestCollisionsOnly() {
        World w = new World();
        Body floor = w.add(new Rect(0, 100, 400, 20));
        Body box = w.add(new Rect(10, 80, 20, 20));  // resting on the floor
        int moves = 5 * World.UNSTEPPED_COLLISIONS;
        Collision last = null;
        for (int i = 0; i < moves; i++) {
            Collisions met = w.move(box, i % 2 == 0 ? 1 : -1, 1);  // pressed into the floor: one collision a move
            assertEquals(1, met.size(), "move " + i);
            last = met.get(0);
        }
        List<Collision> kept = w.collisions();
        assertTrue(kept.size() <= 2 * World.UNSTEPPED_COLLISIONS,
                "kept " + kept.size() + " of " + moves + " collisions, more than twice " + World.UNSTEPPED_COLLISIONS);
        assertTrue(kept.size() >= World.UNSTEPPED_COLLISIONS, "kept only " + kept.size());
        assertSame(last, kept.get(kept.size() - 1), "the latest collision is kept, last");
        assertSame(floor, kept.get(0).other());

        // Stepped at last: the contact the moves met (touching, not overlapping) is reported.
        List<BodyEvent> events = w.step();
        assertEquals(1, events.size(), events.toString());
        assertEquals(BodyEvent.Kind.ENTER, events.get(0).kind());
        assertTrue(w.inContact(box, floor));
    }

    @Test
    void steppedEveryFrame_keepsEveryCollisionOfTheFrame() {
        World w = new World();
        w.add(new Rect(0, 100, 400, 20));
        Body[] boxes = new Body[10];
        for (int i = 0; i < boxes.length; i++) {
            boxes[i] = w.add(new Rect(30 * i, 80, 20, 20));
        }
        for (int frame = 0; frame < 3 * World.UNSTEPPED_COLLISIONS / boxes.length; frame++) {
            for (Body b : boxes) {
                w.move(b, 0, 1);
            }
            assertEquals(boxes.length, w.collisions().size(), "frame " + frame);
            w.step();
        }
    }
}
