package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import net.jqwik.api.Assume;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MotionTest {

    /** The four answers, as sets: a blocked axis names both its sides. */
    private static final Set<Side> NONE = Set.of(), X = Set.of(Side.LEFT, Side.RIGHT), Y = Set.of(Side.TOP, Side.BOTTOM),
            BOTH = Set.of(Side.LEFT, Side.RIGHT, Side.TOP, Side.BOTTOM);

    /** The table's names for exactly those four sets; any other set prints as itself (and fails). */
    private static String describe(Set<Side> blocked) {
        return blocked.equals(NONE) ? "NONE" : blocked.equals(X) ? "X" : blocked.equals(Y) ? "Y" : blocked.equals(BOTH) ? "BOTH" : blocked.toString();
    }

    // ---- rectangle mover --------------------------------------------------------------

    @ParameterizedTest(name = "[{0},{1},{2},{3}] moving ({4},{5}) at [{6},{7},{8},{9}]: {10}")
    @CsvSource({
            // mover          speed    obstacle          blocked
            "0, 0, 10, 10,   5, 0,    20, 0, 10, 10,    NONE",   // not there yet
            "0, 0, 10, 10,  10, 0,    20, 0, 10, 10,    NONE",   // would touch: allowed
            "0, 0, 10, 10,  11, 0,    20, 0, 10, 10,    X",
            "0, 0, 10, 10, -11, 0,    20, 0, 10, 10,    NONE",   // moving away
            "30, 0, 10, 10, -11, 0,   20, 0, 0, 10,     X",      // zero-width wall
            "0, 0, 10, 10,   0, 11,   0, 20, 10, 10,    Y",
            "0, 0, 10, 10,   0, 10,   0, 20, 10, 10,    NONE",
            "0, 0, 10, 10,   5, 3,  -100, 10, 300, 10,  Y",      // on the floor: slide along it
            "0, 0, 10, 10,   5, 5,    12, 12, 10, 10,   BOTH",   // straight at the corner
            "0, 0, 10, 10,   2, 2,    12, 12, 10, 10,   NONE",   // stops touching the corner
            "0, 0, 10, 10,   5, 5,  -100, 12, 300, 10,  Y",
            "5, 5, 0, 0,    10, 0,    10, 0, 10, 10,    X",      // a point mover
            "0, 0, 0, 0,    15, 5,    10, 0, 10, 10,    BOTH",   // a point missing both axes
            "0, 0, 10, 10,  15, 0,    20, 5, 0, 0,      X",      // a point obstacle
            "0, 0, 10, 10,  15, 0,    20, 0, 0, 0,      NONE",   // a point on the mover's edge
            "0, 0, 10, 10,   0, 0,    10, 0, 10, 10,    NONE",   // at rest, touching
            "1000000, 1000000, 10, 10, 11, 0, 1000020, 1000000, 10, 10, X",
    })
    void rectBlocked_table(float x, float y, float w, float h, float vx, float vy,
                           float ox, float oy, float ow, float oh, String expected) {
        Rect mover = new Rect(x, y, w, h);
        Rect obstacle = new Rect(ox, oy, ow, oh);
        assertEquals(expected, describe(Motion.blocked(mover, vx, vy, List.of(obstacle))));
        assertEquals(expected, describe(Motion.blocked(mover, vx, vy, List.of(obstacle, obstacle))), "the same obstacle twice");
        // The other order: the obstacle moving back at the mover sees the same axes.
        assertEquals(expected, describe(Motion.blocked(obstacle, -vx, -vy, List.of(mover))));
    }

    @Test
    void rectBlocked_cornerHitTheTutorialsTwoChecksMiss() {
        // Why BOTH is reported: the tutorial's two single-axis tests both say "free" ...
        float x = 0, y = 0, vx = 5, vy = 5;
        assertFalse(Collide.rectRect(x + vx, y, 10, 10, 12, 12, 10, 10));
        assertFalse(Collide.rectRect(x, y + vy, 10, 10, 12, 12, 10, 10));
        // ... yet moving would put the mover inside the obstacle.
        assertTrue(Collide.rectRect(x + vx, y + vy, 10, 10, 12, 12, 10, 10));
        Set<Side> blocked = Motion.blocked(new Rect(x, y, 10, 10), vx, vy, List.of(new Rect(12, 12, 10, 10)));
        assertEquals(BOTH, blocked);
        x += Motion.reverseX(blocked, vx);
        y += Motion.reverseY(blocked, vy);
        assertFalse(Collide.rectRect(x, y, 10, 10, 12, 12, 10, 10));
    }

    @Test
    void rectBlocked_alreadyInside_reportsBoth() {
        // Documented: the check assumes the mover starts outside.
        assertEquals(BOTH, Motion.blocked(new Rect(5, 5, 10, 10), 1, 1, List.of(new Rect(0, 0, 20, 20))));
    }

    @Test
    void rectBlocked_nan_isNone() {
        assertEquals(NONE, Motion.blocked(new Rect(0, 0, 10, 10), Float.NaN, Float.NaN, List.of(new Rect(5, 0, 10, 10))));
        assertEquals(NONE, Motion.blocked(new Circle(0, 0, 10), Float.NaN, Float.NaN, List.of(new Rect(5, 0, 10, 10))));
    }

    // ---- circle mover -----------------------------------------------------------------

    @ParameterizedTest(name = "circle ({0},{1}) r={2} moving ({3},{4}) at [{5},{6},{7},{8}]: {9}")
    @CsvSource({
            "0, 0, 5,   5, 0,   10, -20, 10, 40,  NONE",   // would touch the wall
            "0, 0, 5,   6, 0,   10, -20, 10, 40,  X",
            "0, 0, 5,   0, 6,  -20, 10, 40, 10,   Y",
            "0, 0, 5,   3, 3,   8, 8, 10, 10,     NONE",   // passes the rounded corner
            "0, 0, 5,   5, 5,   8, 8, 10, 10,     BOTH",   // into the corner diagonally
            "0, 0, 5,   4, 6,  -20, 10, 40, 10,   Y",      // falls onto a floor: slide
            "0, 5, 0,   11, 0,  10, 0, 10, 10,    X",      // radius 0: a point
            "0, 5, 0,   10, 0,  10, 0, 10, 10,    NONE",   // point lands on the edge
            "0, 0, 0,   11, 5,  10, 0, 10, 10,    BOTH",   // a point missing both single axes
            "1000000, 0, 5, 6, 0, 1000010, -20, 10, 40, X",
    })
    void circleBlocked_table(float cx, float cy, float r, float vx, float vy,
                             float ox, float oy, float ow, float oh, String expected) {
        Circle mover = new Circle(cx, cy, r);
        Rect obstacle = new Rect(ox, oy, ow, oh);
        assertEquals(expected, describe(Motion.blocked(mover, vx, vy, List.of(obstacle))));
        assertEquals(expected, describe(Motion.blocked(mover, vx, vy, List.of(obstacle, obstacle))), "the same obstacle twice");
    }

    // ---- many obstacles ---------------------------------------------------------------

    @Test
    void blocked_severalObstacles_isTheOr() {
        Rect wall = new Rect(20, -50, 10, 100);
        Rect floor = new Rect(-50, 20, 100, 10);
        Rect far = new Rect(500, 500, 10, 10);
        Rect mover = new Rect(0, 0, 10, 10);
        assertTrue(Motion.blocked(mover, 15, 15, List.of(wall)).containsAll(X));
        assertEquals(BOTH, Motion.blocked(mover, 15, 15, List.of(far, wall, floor)));
        assertEquals(BOTH, Motion.blocked(new Rect(0, 0, 10, 10), 15, 15, List.of(wall, floor)));
        assertEquals(NONE, Motion.blocked(mover, 15, 15, List.of(far)));
        assertEquals(NONE, Motion.blocked(mover, 15, 15, List.of()));
        assertEquals(BOTH, Motion.blocked(new Circle(5, 5, 5), 15, 15, List.of(wall, floor)));
        assertEquals(X, Motion.blocked(new Circle(5, 5, 5), 15, 0, List.of(far, wall)));
    }

    @Property
    void blocked_listIsTheOrOfEachObstacle(@ForAll @IntRange(min = -100, max = 100) int x,
                                           @ForAll @IntRange(min = -100, max = 100) int y,
                                           @ForAll @IntRange(min = -30, max = 30) int vx,
                                           @ForAll @IntRange(min = -30, max = 30) int vy,
                                           @ForAll @Size(max = 6) List<@IntRange(min = -100, max = 100) Integer> corners) {
        List<Rect> obstacles = new ArrayList<>();
        Set<Side> rects = EnumSet.noneOf(Side.class), circles = EnumSet.noneOf(Side.class);
        for (int i = 0; i + 1 < corners.size(); i += 2) {
            Rect o = new Rect(corners.get(i), corners.get(i + 1), 25, 15);
            obstacles.add(o);
            rects.addAll(Motion.blocked(new Rect(x, y, 20, 10), vx, vy, List.of(o)));
            circles.addAll(Motion.blocked(new Circle(x, y, 8), vx, vy, List.of(o)));
        }
        assertEquals(rects, Motion.blocked(new Rect(x, y, 20, 10), vx, vy, obstacles));
        assertEquals(circles, Motion.blocked(new Circle(x, y, 8), vx, vy, obstacles));
    }

    @Test
    void blocked_nullArguments_nameTheParameter() {
        Rect r = new Rect(0, 0, 10, 10);
        assertEquals("mover must not be null",
                assertThrows(IllegalArgumentException.class, () -> Motion.blocked((Rect) null, 1, 1, List.of(r))).getMessage());
        assertEquals("mover must not be null",
                assertThrows(IllegalArgumentException.class, () -> Motion.blocked((Circle) null, 1, 1, List.of(r))).getMessage());
        assertEquals("obstacles must not be null",
                assertThrows(IllegalArgumentException.class, () -> Motion.blocked(r, 1, 1, (List<Rect>) null)).getMessage());
        assertEquals("obstacles must not be null",
                assertThrows(IllegalArgumentException.class, () -> Motion.blocked(new Circle(0, 0, 1), 1, 1, (List<Rect>) null)).getMessage());
        List<Rect> withHole = Arrays.asList(r, null);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Motion.blocked(new Rect(100, 100, 1, 1), 1, 1, withHole));
        assertTrue(e.getMessage().startsWith("obstacles[1] is null"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> Motion.blocked(new Circle(100, 100, 1), 1, 1, Arrays.asList((Rect) null)));
        assertTrue(e.getMessage().startsWith("obstacles[0] is null"), e.getMessage());
    }

    // ---- reading the answer -----------------------------------------------------------

    @ParameterizedTest(name = "reverse({0}) of (3, -4)")
    @CsvSource({
            "NONE, 3, -4",
            "X, -3, -4",    // LEFT and RIGHT
            "Y, 3, 4",      // TOP and BOTTOM
            "BOTH, -3, 4",
            "LEFT, -3, -4", // either side of an axis reverses it
            "BOTTOM, 3, 4",
    })
    void reverse_table(String blocked, float vx, float vy) {
        Set<Side> sides = switch (blocked) {
            case "NONE" -> NONE;
            case "X" -> X;
            case "Y" -> Y;
            case "BOTH" -> BOTH;
            default -> Set.of(Side.valueOf(blocked));
        };
        assertEquals(vx, Motion.reverseX(sides, 3));
        assertEquals(vy, Motion.reverseY(sides, -4));
    }

    @Test
    void answers_areTheSidesOfTheBlockedAxes_unmodifiable() {
        Set<Side> both = Motion.blocked(new Rect(0, 0, 10, 10), 5, 5, List.of(new Rect(12, 12, 10, 10)));
        assertEquals(BOTH, both);
        assertFalse(both.contains(Side.NONE));
        assertThrows(UnsupportedOperationException.class, () -> both.add(Side.NONE));
        assertThrows(UnsupportedOperationException.class, () -> Motion.blocked(new Rect(0, 0, 1, 1), 0, 0, List.of()).add(Side.TOP));
        assertThrows(IllegalArgumentException.class, () -> Motion.reverseX(null, 1));
    }

    // ---- properties -------------------------------------------------------------------

    @Property
    void rectBlocked_symmetric_obstacleMovingBackSeesTheSameAxes(
            @ForAll @IntRange(min = -60, max = 60) int x, @ForAll @IntRange(min = -60, max = 60) int y,
            @ForAll @IntRange(min = 0, max = 40) int w, @ForAll @IntRange(min = 0, max = 40) int h,
            @ForAll @IntRange(min = -30, max = 30) int vx, @ForAll @IntRange(min = -30, max = 30) int vy,
            @ForAll @IntRange(min = 0, max = 40) int ow, @ForAll @IntRange(min = 0, max = 40) int oh) {
        assertEquals(Motion.blocked(new Rect(x, y, w, h), vx, vy, List.of(new Rect(0, 0, ow, oh))),
                Motion.blocked(new Rect(0, 0, ow, oh), -vx, -vy, List.of(new Rect(x, y, w, h))));
    }

    @Property
    void blocked_translationInvariant(
            @ForAll @IntRange(min = -60, max = 60) int x, @ForAll @IntRange(min = -60, max = 60) int y,
            @ForAll @IntRange(min = -30, max = 30) int vx, @ForAll @IntRange(min = -30, max = 30) int vy,
            @ForAll @IntRange(min = 0, max = 30) int r,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        assertEquals(Motion.blocked(new Rect(x, y, 20, 15), vx, vy, List.of(new Rect(0, 0, 30, 25))),
                Motion.blocked(new Rect(x + dx, y + dy, 20, 15), vx, vy, List.of(new Rect(dx, dy, 30, 25))));
        assertEquals(Motion.blocked(new Circle(x, y, r), vx, vy, List.of(new Rect(0, 0, 30, 25))),
                Motion.blocked(new Circle(x + dx, y + dy, r), vx, vy, List.of(new Rect(dx, dy, 30, 25))));
    }

    @Property
    void blocked_agreesWithAnIntegerReference(
            @ForAll @IntRange(min = -60, max = 60) int x, @ForAll @IntRange(min = -60, max = 60) int y,
            @ForAll @IntRange(min = 1, max = 30) int w, @ForAll @IntRange(min = 1, max = 30) int h,
            @ForAll @IntRange(min = -30, max = 30) int vx, @ForAll @IntRange(min = -30, max = 30) int vy) {
        // An independent reference: open boxes on whole numbers, compared in int arithmetic
        // (not through the library's overlap tests), and the class's rule in words: an axis is
        // blocked if moving along it alone overlaps; if neither is but the whole move is, both.
        int ox = 0, oy = 0, ow = 30, oh = 20;
        boolean alongX = x + vx < ox + ow && ox < x + vx + w && y < oy + oh && oy < y + h;
        boolean alongY = x < ox + ow && ox < x + w && y + vy < oy + oh && oy < y + vy + h;
        boolean diagonal = x + vx < ox + ow && ox < x + vx + w && y + vy < oy + oh && oy < y + vy + h;
        Set<Side> expected = EnumSet.noneOf(Side.class);
        if (alongX || (!alongY && diagonal)) {
            expected.addAll(EnumSet.of(Side.LEFT, Side.RIGHT));
        }
        if (alongY || (!alongX && diagonal)) {
            expected.addAll(EnumSet.of(Side.TOP, Side.BOTTOM));
        }
        assertEquals(expected, Motion.blocked(new Rect(x, y, w, h), vx, vy, List.of(new Rect(ox, oy, ow, oh))));
    }

    /** A box that moves like a sketch's: bounce off the window, then the obstacle check, then move. */
    @Property(tries = 500)
    void rectSimulation_reversingTheReportedAxesNeverEndsInside(
            @ForAll @IntRange(min = 0, max = 200) int x, @ForAll @IntRange(min = 0, max = 200) int y,
            @ForAll @IntRange(min = 0, max = 40) int w, @ForAll @IntRange(min = 0, max = 40) int h,
            @ForAll @IntRange(min = -25, max = 25) int startVx, @ForAll @IntRange(min = -25, max = 25) int startVy,
            @ForAll @IntRange(min = 20, max = 150) int ox, @ForAll @IntRange(min = 20, max = 150) int oy,
            @ForAll @IntRange(min = 0, max = 80) int ow, @ForAll @IntRange(min = 0, max = 80) int oh) {
        Assume.that(!Collide.rectRect(x, y, w, h, ox, oy, ow, oh));
        float px = x, py = y, vx = startVx, vy = startVy;
        for (int frame = 0; frame < 300; frame++) {
            Set<Side> crossed = Edges.crossed(new Rect(px, py, w, h), 240, 240);
            vx = Edges.bounceX(crossed, vx);
            vy = Edges.bounceY(crossed, vy);
            Set<Side> blocked = Motion.blocked(new Rect(px, py, w, h), vx, vy, List.of(new Rect(ox, oy, ow, oh)));
            vx = Motion.reverseX(blocked, vx);
            vy = Motion.reverseY(blocked, vy);
            px += vx;
            py += vy;
            assertFalse(Collide.rectRect(px, py, w, h, ox, oy, ow, oh),
                    "frame " + frame + ": mover at (" + px + ", " + py + ") went into the obstacle");
        }
    }

    @Property(tries = 500)
    void circleSimulation_reversingTheReportedAxesNeverEndsInside(
            @ForAll @IntRange(min = 0, max = 200) int x, @ForAll @IntRange(min = 0, max = 200) int y,
            @ForAll @IntRange(min = 0, max = 25) int r,
            @ForAll @IntRange(min = -25, max = 25) int startVx, @ForAll @IntRange(min = -25, max = 25) int startVy,
            @ForAll @IntRange(min = 20, max = 150) int ox, @ForAll @IntRange(min = 20, max = 150) int oy,
            @ForAll @IntRange(min = 0, max = 80) int ow, @ForAll @IntRange(min = 0, max = 80) int oh) {
        Assume.that(!Collide.circleRect(x, y, r, ox, oy, ow, oh));
        float cx = x, cy = y, vx = startVx, vy = startVy;
        for (int frame = 0; frame < 300; frame++) {
            Set<Side> crossed = Edges.crossed(new Circle(cx, cy, r), 240, 240);
            vx = Edges.bounceX(crossed, vx);
            vy = Edges.bounceY(crossed, vy);
            Set<Side> blocked = Motion.blocked(new Circle(cx, cy, r), vx, vy, List.of(new Rect(ox, oy, ow, oh)));
            vx = Motion.reverseX(blocked, vx);
            vy = Motion.reverseY(blocked, vy);
            cx += vx;
            cy += vy;
            assertFalse(Collide.circleRect(cx, cy, r, ox, oy, ow, oh),
                    "frame " + frame + ": mover at (" + cx + ", " + cy + ") went into the obstacle");
        }
    }

    @Test
    void simulation_withoutTheCornerRuleTheMoverGetsIn() {
        // The property above can fail: the tutorial's two checks alone let this box in.
        float x = 0, y = 0, vx = 5, vy = 5;
        boolean bx = Collide.rectRect(x + vx, y, 10, 10, 12, 12, 10, 10);
        boolean by = Collide.rectRect(x, y + vy, 10, 10, 12, 12, 10, 10);
        x += bx ? -vx : vx;
        y += by ? -vy : vy;
        assertTrue(Collide.rectRect(x, y, 10, 10, 12, 12, 10, 10));
    }

    // ---------------------------------------------------------------- bounce: one safe frame

    @Test
    void bounce_freePath_movesByItsSpeed() {
        Motion.Step step = Motion.bounce(new Rect(10, 10, 8, 8), 3, 2, List.of(new Rect(100, 100, 10, 10)), 200, 200);
        assertEquals(new Motion.Step(13, 12, 3, 2, NONE, NONE), step);
        assertFalse(step.hitObstacle());
    }

    @Test
    void bounce_wallAhead_reversesTheBlockedSpeedAndMovesAway() {
        // The next x (16..24) overlaps the wall at 20; y is free.
        Motion.Step step = Motion.bounce(new Rect(10, 10, 8, 8), 6, 2, List.of(new Rect(20, 0, 10, 100)), 200, 200);
        assertEquals(new Motion.Step(4, 12, -6, 2, X, NONE), step);
        assertTrue(step.hitObstacle());
    }

    @Test
    void bounce_squeezedBetweenTwoObstacles_waitsInsteadOfMovingIntoTheOther() {
        // 2 px free on each side: reversing the blocked speed points at the other obstacle.
        List<Rect> obstacles = List.of(new Rect(0, 0, 10, 100), new Rect(30, 0, 10, 100));
        Motion.Step step = Motion.bounce(new Rect(12, 50, 16, 8), 5, 1, obstacles, 200, 200);
        assertEquals(12f, step.x(), "waits across");
        assertEquals(-5f, step.vx(), "but its speed is reversed");
        assertEquals(51f, step.y(), "and it still moves down");
        assertEquals(X, step.blocked());
    }

    @Test
    void bounce_windowEdgeAhead_bouncesBackInside() {
        Motion.Step step = Motion.bounce(new Rect(190, 50, 8, 8), 5, 0, List.of(), 200, 200);
        assertEquals(-5f, step.vx());
        assertEquals(185f, step.x());
        assertEquals(Set.of(Side.RIGHT), step.crossed());
    }

    @Property(tries = 300)
    void bounce_manyFrames_neverEndsInsideAnObstacleOrOutsideTheWindow(
            @ForAll @Size(max = 12) List<@IntRange(min = 0, max = 180) Integer> corners,
            @ForAll @IntRange(min = 0, max = 190) int x0, @ForAll @IntRange(min = 0, max = 190) int y0,
            @ForAll @IntRange(min = -9, max = 9) int vx0, @ForAll @IntRange(min = -9, max = 9) int vy0) {
        List<Rect> obstacles = new ArrayList<>();
        for (int i = 0; i + 1 < corners.size(); i += 2) {
            obstacles.add(new Rect(corners.get(i), corners.get(i + 1), 6 + i, 14 - i));
        }
        Assume.that(Hits.first(new Rect(x0, y0, 8, 8), obstacles) < 0);
        float x = x0, y = y0, vx = vx0, vy = vy0;
        for (int frame = 1; frame <= 400; frame++) {
            Motion.Step step = Motion.bounce(new Rect(x, y, 8, 8), vx, vy, obstacles, 200, 200);
            x = step.x();
            y = step.y();
            vx = step.vx();
            vy = step.vy();
            assertEquals(-1, Hits.first(new Rect(x, y, 8, 8), obstacles), "inside an obstacle on frame " + frame);
            assertEquals(NONE, Edges.crossed(new Rect(x, y, 8, 8), 200, 200), "outside the window on frame " + frame);
        }
    }
}
