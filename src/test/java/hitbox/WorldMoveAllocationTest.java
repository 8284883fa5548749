package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The promises on garbage of issues 28 and 29: a move that meets nothing hands back the shared
 * empty {@link Collisions#NONE} and makes nothing (a box or a circle is walked and left as
 * numbers: its shape is made only when asked), and a move that meets something makes nothing
 * but the collisions it hands back; for a plain body and a character alike. Bytes counted by
 * the thread's allocation counter, after the JIT has warmed up.
 */
class WorldMoveAllocationTest {

    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    @Test
    void aMoveThatMeetsNothing_makesNothing() {
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
        assertEquals(0, perPlain, "bytes a plain move made");
        assertEquals(0, perHero, "bytes a character's move made");
        assertEquals(new Circle(25, 25, 3), plain[0].shape(), "the shape, made when asked, where the moves left it");
    }

    /**
     * Issue 29's promise for moves that meet something: boxes (the rectangles' walk), circles
     * (the general walk) and characters sliding along a floor, and characters walking up and
     * down a ramp, make nothing but the collisions they hand back. The oracle is the handed-back
     * objects made again (each collision and its hit, the list and its array), counted by the
     * same counter; the movers must also have gone the whole way.
     */
    @Test
    void aMoveThatMeetsSomething_makesNothingButTheCollisionsItHandsBack() {
        World w = new World();
        for (int i = 0; i < 400; i++) {
            w.add(new Rect(i * 40, 500, 40, 20));  // a floor of tiles
        }
        for (int i = 0; i < 2000; i++) {
            w.add(new Rect((i % 50) * 40, (i / 50) * 10 - 1000, 10, 5));  // standing bodies far above, never met
        }
        int n = 50;
        Body[] box = new Body[n], ball = new Body[n];
        CharacterBody[] hero = new CharacterBody[n], climber = new CharacterBody[n];
        for (int i = 0; i < n; i++) {
            float x = 20 + i * 300;
            box[i] = w.add(new Rect(x, 490, 10, 10));  // on the floor
            ball[i] = w.add(new Circle(x + 60, 495, 5));
            hero[i] = w.addCharacter(new Rect(x + 100, 480, 10, 20));
            w.add(Polygon.of(x + 160, 500, x + 260, 460, x + 260, 500));  // a ramp up to the right, 22 degrees
            climber[i] = w.addCharacter(new Rect(x + 180, 480, 10, 20));
        }
        for (int f = 0; f < 5; f++) {
            for (CharacterBody c : climber) {
                c.move(0, 2);  // settle onto the ramp
            }
        }
        float[] climberStartX = new float[n];
        float[] climberStartY = new float[n];
        for (int i = 0; i < n; i++) {
            climberStartX[i] = climber[i].body().pivotX();
            climberStartY[i] = climber[i].body().pivotY();
        }
        List<Collision> copies = new ArrayList<>(64);
        Collisions[] got = new Collisions[4 * n];
        long moveBytes = 0, remadeBytes = 0;
        int met = 0;
        float climbedX = 0, climbedY = 0;
        for (int round = 0; round < 40; round++) {
            float dx = round % 2 == 0 ? 3 : -3;
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < n; i++) {
                got[i] = w.move(box[i], dx, 1);  // pressed down onto the floor: it slides along it
                got[n + i] = w.move(ball[i], dx, 1);
                got[2 * n + i] = hero[i].move(dx, 1);
                got[3 * n + i] = climber[i].move(dx, 2);  // pressed enough to follow the ramp down (1.2 for 3)
            }
            long after = THREADS.getCurrentThreadAllocatedBytes();
            moveBytes = after - before;
            remadeBytes = bytesToMakeAgain(got, copies);
            met = 0;
            for (Collisions c : got) {
                met += c.size();
            }
            if (round == 0) {
                climbedX = climber[0].body().pivotX() - climberStartX[0];
                climbedY = climber[0].body().pivotY() - climberStartY[0];
            }
            w.step(new ArrayList<>());
        }
        assertEquals(true, met >= 4 * n, met + " collisions in the last round: each mover met the floor or the ramp");
        assertEquals(remadeBytes, moveBytes, "bytes the moves made, against their collisions made again");
        assertEquals(3, climbedX, 1e-3, "a climber went 3 to the right on the ramp in one move");
        assertEquals(-3 * 0.4f, climbedY, 0.05, "and rose with the ramp");
        for (int i = 0; i < n; i++) {
            float x = 20 + i * 300;
            assertEquals(new Rect(x, 490, 10, 10), box[i].shape(), "a box slid back and forth along the floor");
            assertEquals(new Circle(x + 60, 495, 5), ball[i].shape(), "a circle slid back and forth along the floor");
            assertEquals(new Rect(x + 100, 480, 10, 20), hero[i].body().shape(), "a character walked back and forth");
            assertEquals(climberStartX[i], climber[i].body().pivotX(), 0.01, "a climber walked up and down the ramp");
            assertEquals(climberStartY[i], climber[i].body().pivotY(), 0.05, "and stands on it where it began");
        }
    }

    /**
     * The same promise where the obstacles are a grid's cells (a maze's walls, met as numbers,
     * no cell's rectangle made) and other movers (boxes a walk left as numbers, their shapes
     * not made for the walk that meets them).
     */
    @Test
    void aMoveAmongGridCellsAndOtherMovers_makesNothingButTheCollisionsItHandsBack() {
        World w = new World();
        Grid g = new Grid(400, 30, 20);
        for (int col = 0; col < 400; col++) {
            g.set(col, 25, 1);  // a floor of cells, top at 500
        }
        w.add(g);
        int n = 50;
        Body[] box = new Body[n], ball = new Body[n], carried = new Body[n];
        for (int i = 0; i < n; i++) {
            float x = 20 + i * 150;
            box[i] = w.add(new Rect(x, 490, 10, 10));  // on the grid's floor
            ball[i] = w.add(new Circle(x + 60, 495, 5));
            carried[i] = w.add(new Circle(x + 5, 485, 5));  // resting on the box
        }
        List<Collision> copies = new ArrayList<>(64);
        Collisions[] got = new Collisions[3 * n];
        long moveBytes = 0, remadeBytes = 0;
        int met = 0;
        for (int round = 0; round < 40; round++) {
            float dx = round % 2 == 0 ? 3 : -3;
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < n; i++) {
                got[i] = w.move(box[i], dx, 1);
                got[n + i] = w.move(ball[i], dx, 1);
                got[2 * n + i] = w.move(carried[i], dx, 1);  // presses on the box, moved as numbers just before
            }
            long after = THREADS.getCurrentThreadAllocatedBytes();
            moveBytes = after - before;
            remadeBytes = bytesToMakeAgain(got, copies);
            met = 0;
            for (int i = 0; i < 3 * n; i++) {
                met += got[i].size();
                if (got[i].size() > 0 && i >= 2 * n) {
                    assertEquals(box[i - 2 * n], got[i].get(0).other(), "the carried circle pressed on its box");
                }
            }
            w.step(new ArrayList<>());
        }
        assertEquals(true, met >= 3 * n, met + " collisions in the last round: each mover met the grid or its box");
        assertEquals(remadeBytes, moveBytes, "bytes the moves made, against their collisions made again");
        for (int i = 0; i < n; i++) {
            float x = 20 + i * 150;
            assertEquals(new Rect(x, 490, 10, 10), box[i].shape(), "a box slid back and forth along the grid's floor");
            assertEquals(new Circle(x + 60, 495, 5), ball[i].shape(), "a circle slid back and forth along it");
            assertEquals(new Circle(x + 5, 485, 5), carried[i].shape(), "a circle slid back and forth along its box");
        }
    }

    /**
     * The form that fills the caller's list ({@link World#move(Body, float, float,
     * CollisionFilter, List)}) makes nothing but each collision and its hit: no list, no array,
     * once the caller's list has grown. Boxes, circles and characters' bodies on a floor.
     */
    @Test
    void aMoveIntoTheCallersList_makesNothingButEachCollisionAndItsHit() {
        World w = new World();
        for (int i = 0; i < 400; i++) {
            w.add(new Rect(i * 40, 500, 40, 20));  // a floor of tiles
        }
        int n = 50;
        Body[] movers = new Body[3 * n];
        for (int i = 0; i < n; i++) {
            float x = 20 + i * 300;
            movers[i] = w.add(new Rect(x, 490, 10, 10));
            movers[n + i] = w.add(new Circle(x + 60, 495, 5));
            movers[2 * n + i] = w.addCharacter(new Rect(x + 100, 480, 10, 20)).body();
        }
        CollisionFilter slide = (m, o) -> Reaction.SLIDE;
        List<Collision> out = new ArrayList<>(8 * movers.length);
        long moveBytes = 0, remadeBytes = 0;
        for (int round = 0; round < 40; round++) {
            float dx = round % 2 == 0 ? 3 : -3;
            out.clear();
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (Body m : movers) {
                assertEquals(true, w.move(m, dx, 1, slide, out), "the move finished");
            }
            long after = THREADS.getCurrentThreadAllocatedBytes();
            moveBytes = after - before;
            long remadeBefore = THREADS.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < out.size(); i++) {
                Collision k = out.get(i);
                Hit h = k.hit();
                new Collision(k.mover(), k.other(), k.reaction(), new Hit(h.t(), h.nx(), h.ny(), h.side()), k.x(), k.y(), k.cell());
            }
            remadeBytes = THREADS.getCurrentThreadAllocatedBytes() - remadeBefore;
            w.step(new ArrayList<>());
        }
        assertEquals(true, out.size() >= movers.length, out.size() + " collisions in the last round: each mover met the floor");
        assertEquals(remadeBytes, moveBytes, "bytes the moves made, against their collisions made again (no list)");
        assertEquals(new Rect(20, 490, 10, 10), movers[0].shape(), "a box slid back and forth along the floor");
        assertEquals(new Rect(120, 480, 10, 20), movers[2 * n].shape(), "a character walked back and forth");
    }

    /**
     * A carrier that moves every frame with riders on it (a character and a box) makes
     * nothing when it meets nothing: its riders are found, moved and kept to put back in
     * storage the world keeps (it made about 480 bytes a move before), and their own
     * collisions are kept for the step, not handed back.
     */
    @Test
    void aCarrierWithRiders_makesNothingWhenItMeetsNothing() {
        World w = new World();
        int n = 50;
        Body[] platform = new Body[n];
        CharacterBody[] hero = new CharacterBody[n];
        Body[] crate = new Body[n];
        for (int i = 0; i < n; i++) {
            platform[i] = w.add(new Rect(i * 300, 300, 100, 10)).carrier(true);
            hero[i] = w.addCharacter(new Rect(i * 300 + 10, 270, 20, 30));
            crate[i] = w.add(new Rect(i * 300 + 60, 290, 10, 10));
        }
        CollisionFilter slide = (m, o) -> Reaction.SLIDE;
        List<Collision> out = new ArrayList<>();
        long perMove = -1;
        for (int round = 0; round < 40; round++) {
            float dx = (round / 4) % 2 == 0 ? 2 : -2, dy = round % 2 == 0 ? -1 : 1;
            out.clear();
            long before = THREADS.getCurrentThreadAllocatedBytes();
            for (Body p : platform) {
                w.move(p, dx, dy, slide, out);
            }
            perMove = (THREADS.getCurrentThreadAllocatedBytes() - before) / n;
            for (CharacterBody h : hero) {
                h.move(0, 1);  // stands on its platform
            }
            w.step(new ArrayList<>());
        }
        assertEquals(List.of(), out, "the platforms met nothing");
        assertEquals(0, perMove, "bytes a carrier's move made");
        assertEquals(new Rect(10, 270, 20, 30), hero[0].body().shape(), "the character rode its platform there and back");
        assertEquals(new Rect(60, 290, 10, 10), crate[0].shape(), "and so did the box");
        assertEquals(true, hero[0].onGround());
    }

    /**
     * The oracle of the bytes a round of moves may make: the bytes of making its collisions
     * again, each collision and its hit, and each move's list with its array, by the same
     * counter (by index: an iterator would count too).
     */
    private static long bytesToMakeAgain(Collisions[] got, List<Collision> copies) {
        long before = THREADS.getCurrentThreadAllocatedBytes();
        for (Collisions c : got) {
            copies.clear();
            for (int i = 0; i < c.size(); i++) {
                Collision k = c.get(i);
                Hit h = k.hit();
                copies.add(new Collision(k.mover(), k.other(), k.reaction(), new Hit(h.t(), h.nx(), h.ny(), h.side()),
                        k.x(), k.y(), k.cell()));
            }
            Collisions.of(copies, c.finished());
        }
        return THREADS.getCurrentThreadAllocatedBytes() - before;
    }
}
