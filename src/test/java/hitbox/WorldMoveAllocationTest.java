package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
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

    /**
     * Issue 29's promise for a box (the rectangles' walk, read from the body's numbers): its
     * move makes nothing but the collisions it hands back, met or not. The oracle is the
     * handed-back objects made again (each collision and its hit, the list and its array),
     * counted by the same counter; the boxes must also have slid the whole way.
     */
    @Test
    void aBoxsMove_makesNothingButTheCollisionsItHandsBack() {
        World w = new World();
        for (int i = 0; i < 400; i++) {
            w.add(new Rect(i * 40, 500, 40, 20));  // a floor of tiles
        }
        for (int i = 0; i < 2000; i++) {
            w.add(new Rect((i % 50) * 40, (i / 50) * 10 - 1000, 10, 5));  // standing bodies far above, never met
        }
        Body[] sliding = new Body[200], flying = new Body[200];
        for (int i = 0; i < 200; i++) {
            sliding[i] = w.add(new Rect(20 + i * 70, 490, 10, 10));  // on the floor
            flying[i] = w.add(new Rect(20 + i * 70, 300, 10, 10));  // in the air
        }
        List<Collision> copies = new ArrayList<>(64);
        Collisions[] got = new Collisions[sliding.length + flying.length];
        long moveBytes = 0, remadeBytes = 0, met = 0;
        for (int round = 0; round < 40; round++) {
            float dx = round % 2 == 0 ? 3 : -3;
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < sliding.length; i++) {
                got[i] = w.move(sliding[i], dx, 1);  // pressed down onto the floor: it slides along it
            }
            for (int i = 0; i < flying.length; i++) {
                got[sliding.length + i] = w.move(flying[i], dx, 1);
            }
            long after = THREADS.getCurrentThreadAllocatedBytes();
            long remadeBefore = THREADS.getCurrentThreadAllocatedBytes();
            for (Collisions c : got) {
                copies.clear();
                for (int k0 = 0; k0 < c.size(); k0++) {  // by index: an iterator would count too
                    Collision k = c.get(k0);
                    Hit h = k.hit();
                    copies.add(new Collision(k.mover(), k.other(), k.reaction(), new Hit(h.t(), h.nx(), h.ny(), h.side()),
                            k.x(), k.y(), k.cell()));
                }
                Collisions.of(copies, c.finished());
            }
            long remadeAfter = THREADS.getCurrentThreadAllocatedBytes();
            moveBytes = after - before;
            remadeBytes = remadeAfter - remadeBefore;
            met = 0;
            for (Collisions c : got) {
                met += c.size();
            }
            w.step(new ArrayList<>());
        }
        assertEquals(sliding.length, met, "each sliding box met the floor once, the flying ones nothing");
        assertEquals(remadeBytes, moveBytes, "bytes the moves made, against their collisions made again");
        for (int i = 0; i < 200; i++) {
            assertEquals(20 + i * 70, sliding[i].shape().bounds().x(), "slid back and forth along the floor");
            assertEquals(490, sliding[i].shape().bounds().y(), "stands on the floor");
            assertEquals(300 + 40, flying[i].shape().bounds().y(), "fell freely");
        }
    }
}
