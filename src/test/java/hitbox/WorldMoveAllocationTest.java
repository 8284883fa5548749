package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;

/**
 * Issue 28's promise on garbage: a move that meets nothing hands back the shared empty
 * {@link Collisions#NONE} and makes no object but the body's new shape (which
 * {@link Body#shape()} then returns), for a plain body and a character alike. Bytes counted
 * by the thread's allocation counter, after the JIT has warmed up.
 */
class WorldMoveAllocationTest {

    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    /** A circle's record: the object header and three floats, padded to 8 bytes. */
    private static final long CIRCLE_BYTES = 24;

    @Test
    void aMoveThatMeetsNothing_makesOnlyTheBodysNewShape() {
        World w = new World();
        for (int i = 0; i < 2000; i++) {
            w.add(new Rect((i % 50) * 40, (i / 50) * 40, 10, 10));  // standing bodies, never met
        }
        Body[] plain = new Body[200];
        CharacterBody[] hero = new CharacterBody[200];
        for (int i = 0; i < 200; i++) {
            plain[i] = w.add(new Circle(25 + (i % 50) * 40, 25 + (i / 50) * 40, 3));
            hero[i] = w.addCharacter(new Circle(25 + (i % 50) * 40, 25 + (i / 50 + 10) * 40, 3)).up(0, 0);
        }
        long perPlain = 0, perHero = 0;
        for (int round = 0; round < 30; round++) {
            float dx = round % 2 == 0 ? 1 : -1;
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (Body b : plain) {
                assertSame(Collisions.NONE, w.move(b, dx, 0));
            }
            long mid = THREADS.getCurrentThreadAllocatedBytes();
            for (CharacterBody h : hero) {
                assertSame(Collisions.NONE, h.move(dx, 0));
            }
            long after = THREADS.getCurrentThreadAllocatedBytes();
            perPlain = (mid - before) / plain.length;
            perHero = (after - mid) / hero.length;
        }
        assertEquals(CIRCLE_BYTES, perPlain, "bytes a plain move made");
        assertEquals(CIRCLE_BYTES, perHero, "bytes a character's move made");
    }
}
