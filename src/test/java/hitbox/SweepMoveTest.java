package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;

/** Sweep.move: a box walked through a level in one frame, stopping and sliding. */
class SweepMoveTest {

    private static final Rect BOX = new Rect(0, 0, 10, 10);

    @Test
    void move_nothingInTheWay_goesTheWholeWay() {
        Sweep.Move m = Sweep.move(BOX, 7, -3, List.of(new Rect(100, 100, 10, 10)));
        assertEquals(new Sweep.Move(7, -3, 7, -3, Set.of()), m);
        assertFalse(m.hitAnything());
        assertTrue(m.hit(Side.NONE));
    }

    @Test
    void move_fallingOntoAFloor_landsAndKeepsRunning() {
        Sweep.Move m = Sweep.move(BOX, 4, 20, List.of(new Rect(-100, 15, 200, 10)));
        // Lands at t = 0.25 (x = 1), then slides the rest of the way along the floor.
        assertEquals(4f, m.x());
        assertEquals(5f, m.y());
        assertEquals(4f, m.vx());
        assertEquals(0f, m.vy());
        assertTrue(m.landed());
        assertFalse(m.hit(Side.LEFT) || m.hit(Side.RIGHT));
        assertFalse(m.hit(Side.BOTTOM));
    }

    @Test
    void move_standingWithGravity_slidesWithoutSinking() {
        Rect standing = new Rect(0, 5, 10, 10);
        Sweep.Move m = Sweep.move(standing, 7, 3, List.of(new Rect(-100, 15, 200, 10)));
        assertEquals(new Sweep.Move(7, 5, 7, 0, Set.of(Side.TOP)), m);
    }

    @Test
    void move_alongARowOfTiles_neverCatchesOnTheSeams() {
        List<Rect> tiles = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            tiles.add(new Rect(i * 10, 15, 10, 10));
        }
        Sweep.Move m = Sweep.move(new Rect(0, 5, 10, 10), 55, 2, tiles);
        assertEquals(55f, m.x());
        assertEquals(5f, m.y());
        assertTrue(m.landed());
        assertFalse(m.hit(Side.LEFT) || m.hit(Side.RIGHT), "a seam between tiles is not a wall");
    }

    @Test
    void move_intoAWall_stopsAndSlidesDown() {
        Sweep.Move m = Sweep.move(BOX, 20, 10, List.of(new Rect(15, -100, 10, 200)));
        assertEquals(5f, m.x());
        assertEquals(10f, m.y());
        assertEquals(0f, m.vx());
        assertEquals(10f, m.vy());
        assertTrue(m.hit(Side.LEFT));
        assertTrue(m.hit(Side.LEFT) || m.hit(Side.RIGHT));
        assertFalse(m.landed());
    }

    @Test
    void move_fromTheRight_hitsTheRightSide() {
        Sweep.Move m = Sweep.move(new Rect(30, 0, 10, 10), -20, 0, List.of(new Rect(15, -100, 10, 200)));
        assertEquals(25f, m.x());
        assertTrue(m.hit(Side.RIGHT));
    }

    @Test
    void move_upIntoACeiling_hitsItsHead() {
        Sweep.Move m = Sweep.move(new Rect(0, 30, 10, 10), 3, -20, List.of(new Rect(-100, 15, 200, 10)));
        assertEquals(25f, m.y());
        assertEquals(3f, m.x());
        assertEquals(0f, m.vy());
        assertTrue(m.hit(Side.BOTTOM));
    }

    @Test
    void move_intoAnInsideCorner_stopsAtTheCornerOnBothSides() {
        List<Rect> level = List.of(new Rect(-100, 15, 200, 10), new Rect(15, -100, 10, 200));
        Sweep.Move m = Sweep.move(BOX, 20, 20, level);
        assertEquals(5f, m.x());
        assertEquals(5f, m.y());
        assertEquals(0f, m.vx());
        assertEquals(0f, m.vy());
        assertTrue(m.landed());
        assertTrue(m.hit(Side.LEFT) || m.hit(Side.RIGHT));
    }

    @Test
    void move_veryFastIntoAThinWall_stopsAgainstIt() {
        Sweep.Move m = Sweep.move(new Rect(0, 0, 2, 2), 10_000, 0, List.of(new Rect(5000, -10, 0.5f, 20)));
        assertEquals(4998f, m.x());
        assertTrue(m.hit(Side.LEFT) || m.hit(Side.RIGHT));
    }

    @Test
    void move_startingInsideAnObstacle_ignoresIt() {
        Rect stuckIn = new Rect(-5, -5, 20, 20);
        Rect wall = new Rect(40, -100, 10, 200);
        Sweep.Move m = Sweep.move(BOX, 50, 0, List.of(stuckIn, wall));
        assertEquals(30f, m.x(), "walks out of the first and stops at the second");
        assertTrue(m.hit(Side.LEFT) || m.hit(Side.RIGHT));
    }

    @Test
    void move_touchingAndMovingAway_isFree() {
        Sweep.Move m = Sweep.move(new Rect(0, 5, 10, 10), 0, -10, List.of(new Rect(-100, 15, 200, 10)));
        assertEquals(new Sweep.Move(0, -5, 0, -10, Set.of()), m);
    }

    @Test
    void move_badArguments_throwWithTheirNames() {
        assertEquals("obstacles must not be null",
                assertThrows(IllegalArgumentException.class, () -> Sweep.move(BOX, 1, 1, null)).getMessage());
        assertEquals("obstacles[1] must not be null",
                assertThrows(IllegalArgumentException.class, () -> Sweep.move(BOX, 1, 1, Arrays.asList(BOX, null))).getMessage());
        assertEquals("vy must be a finite number, was Infinity",
                assertThrows(IllegalArgumentException.class, () -> Sweep.move(BOX, 1, Float.POSITIVE_INFINITY, List.of())).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Sweep.Move(0, 0, 0, 0, null));
    }

    /**
     * Wherever a box is thrown, fractional positions and sizes included, it never ends inside
     * an obstacle it did not start in, and never moves farther than its velocity.
     */
    @Property(tries = 2000)
    void move_neverEndsInsideAnObstacle(@ForAll @IntRange(min = -80, max = 80) int x8, @ForAll @IntRange(min = -80, max = 80) int y8,
                                        @ForAll @IntRange(min = 0, max = 80) int w8, @ForAll @IntRange(min = 0, max = 80) int h8,
                                        @ForAll @IntRange(min = -3000, max = 3000) int vx8, @ForAll @IntRange(min = -3000, max = 3000) int vy8,
                                        @ForAll @IntRange(min = 0, max = 1000) int seed) {
        float x = x8 / 8f + 0.1f, y = y8 / 8f - 0.3f, w = w8 / 8f + 0.7f, h = h8 / 8f;
        float vx = vx8 / 7f, vy = vy8 / 3f;
        java.util.Random random = new java.util.Random(seed);
        List<Rect> level = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            level.add(new Rect(random.nextInt(400) / 3f - 60, random.nextInt(400) / 3f - 60,
                    random.nextInt(120) / 3f, random.nextInt(120) / 3f));
        }
        Sweep.Move m = Sweep.move(new Rect(x, y, w, h), vx, vy, level);
        for (Rect o : level) {
            boolean startedIn = Collide.rectRect(x, y, w, h, o.x(), o.y(), o.w(), o.h());
            assertFalse(!startedIn && Collide.rectRect(m.x(), m.y(), w, h, o.x(), o.y(), o.w(), o.h()),
                    () -> "ended inside " + o + " at " + m);
        }
        // Up to rounding the end position to a float.
        assertTrue(Math.abs((double) m.x() - x) <= Math.abs(vx) + 2 * Math.ulp(Math.max(Math.abs(x), Math.abs(m.x()))),
                () -> "x went too far: " + m);
        assertTrue(Math.abs((double) m.y() - y) <= Math.abs(vy) + 2 * Math.ulp(Math.max(Math.abs(y), Math.abs(m.y()))),
                () -> "y went too far: " + m);
    }
}
