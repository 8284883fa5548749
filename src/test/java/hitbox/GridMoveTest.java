package hitbox;

import hitbox.internal.GridMove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;

/**
 * Grid.move: a pixel box through the solid cells, exactly Sweep.move against every solid
 * cell's rectangle (row by row, the cells beyond the edges solid), but looking only at the
 * cells under the box the move sweeps.
 */
class GridMoveTest {

    /** A platform level, 12.5 px cells: a floor, a ledge and a wall. */
    private static final String LEVEL = """
            ..........
            ..........
            ......###.
            ...#......
            ...#......
            ##########
            """;

    private static Grid level() {
        return Grid.parse(LEVEL, 12.5f);
    }

    /** The reference: Sweep.move against every solid cell of a window wider than the grid and the whole move, row by row. */
    static Sweep.Move oracle(Grid g, Rect m, float vx, float vy) {
        int c0 = Math.min(0, g.colAt(Math.min(m.x(), m.x() + vx))) - 2;
        int c1 = Math.max(g.cols() - 1, g.colAt(Math.max(m.right(), m.right() + vx))) + 2;
        int r0 = Math.min(0, g.rowAt(Math.min(m.y(), m.y() + vy))) - 2;
        int r1 = Math.max(g.rows() - 1, g.rowAt(Math.max(m.bottom(), m.bottom() + vy))) + 2;
        List<Rect> cells = new ArrayList<>();
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                if (g.isSolid(col, row)) {
                    cells.add(g.cellRect(col, row));
                }
            }
        }
        return Sweep.move(m, vx, vy, cells);
    }

    /**
     * Found by the property below: the double sums put the move's end a hair above row 0,
     * while the float move Sweep makes ends touching it, which stops the fall.
     */
    @Test
    void move_endingTouchingACellPastTheDoubleSum_stillLands() {
        Grid g = tallCells(Grid.parse("........2\n...#....#"), 3.0f, 13.3f);
        Rect m = new Rect(25.5f, -19.95f, 2.25f, 13.3f);
        Sweep.Move want = oracle(g, m, -4.5f, 6.65f);
        assertEquals(0f, want.vy(), "the oracle lands on cell (8, 0)");
        assertEquals(want, g.move(m, -4.5f, 6.65f));
    }

    @Test
    void move_fallingOntoTheFloor_lands() {
        Grid g = level();
        Rect player = new Rect(10, 20, 10, 15);
        Sweep.Move m = g.move(player, 3, 40);
        assertEquals(62.5f - 15, m.y(), "standing on the floor's top, y 62.5");
        assertTrue(m.landed());
        assertEquals(0f, m.vy());
        assertEquals(13f, m.x(), "and it kept going across");
        assertEquals(oracle(g, player, 3, 40), m);
    }

    @Test
    void move_runningAlongTheFloor_neverCatchesOnSeams_andStopsAtTheWall() {
        Grid g = level();
        Rect standing = new Rect(0, 47.5f, 10, 15);
        Sweep.Move m = g.move(standing, 60, 1);
        assertEquals(37.5f - 10, m.x(), "stopped against the wall cell (3, 3)");
        assertEquals(47.5f, m.y());
        assertTrue(m.hit(Side.LEFT) || m.hit(Side.RIGHT));
        assertTrue(m.landed());
        assertEquals(oracle(g, standing, 60, 1), m);
    }

    @Test
    void move_headIntoTheLedge() {
        Grid g = level();
        Rect under = new Rect(80, 45, 10, 10);
        Sweep.Move m = g.move(under, 0, -30);
        assertEquals(37.5f, m.y());
        assertTrue(m.hit(Side.BOTTOM));
    }

    @Test
    void move_outsideTheGridIsSolid() {
        Grid open = new Grid(4, 3, 10);
        Sweep.Move down = open.move(new Rect(5, 5, 8, 8), 0, 100);
        assertEquals(22f, down.y(), "stopped by the row of cells below the grid");
        assertTrue(down.landed());
        Sweep.Move left = open.move(new Rect(5, 5, 8, 8), -100, 0);
        assertEquals(0f, left.x());
        assertTrue(left.hit(Side.RIGHT));
    }

    @Test
    void move_startingPartlyOutside_walksBackIn_butNotFurtherOut() {
        Grid open = new Grid(4, 3, 10);
        Rect half = new Rect(-4, 5, 8, 8);
        assertEquals(-4f + 20, open.move(half, 20, 0).x(), "the cell it overlaps is ignored for this move");
        Sweep.Move out = open.move(half, -30, 0);
        assertEquals(-10f, out.x(), "it stops at the next cell beyond, like any stuck box");
        assertEquals(oracle(open, half, -30, 0), out);
    }

    @Test
    void move_looksAtTheSolidCellsUnderTheSweptBox() {
        Grid g = level();
        Rect player = new Rect(40, 40, 10, 10);
        List<Rect> cells = GridMove.obstacles(g, player, 2, 3);
        // Swept box: x 40 to 52, y 40 to 53, over columns 3 and 4 and rows 3 and 4: solid (3, 3) and (3, 4).
        assertEquals(List.of(g.cellRect(3, 3), g.cellRect(3, 4)), cells);
        assertTrue(GridMove.obstacles(g, new Rect(40, 40, 10, 10), 0, 0).size() <= 2);
    }

    /** The map's cells in a grid of cells {@code w} by {@code h} (a map is read with square cells). */
    static Grid tallCells(Grid map, float w, float h) {
        Grid g = new Grid(map.cols(), map.rows(), w, h);
        for (int row = 0; row < map.rows(); row++) {
            for (int col = 0; col < map.cols(); col++) {
                g.set(col, row, map.get(col, row));
            }
        }
        return g;
    }

    @Test
    void move_badInput_isNamed() {
        Grid g = level();
        assertEquals("mover must not be null",
                assertThrows(IllegalArgumentException.class, () -> g.move(null, 1, 1)).getMessage());
        assertEquals("vx must be a finite number, was NaN",
                assertThrows(IllegalArgumentException.class, () -> g.move(new Rect(0, 0, 5, 5), Float.NaN, 1)).getMessage());
        assertEquals("vy must be a finite number, was Infinity",
                assertThrows(IllegalArgumentException.class,
                        () -> g.move(new Rect(0, 0, 5, 5), 1, Float.POSITIVE_INFINITY)).getMessage());
        IllegalArgumentException far = assertThrows(IllegalArgumentException.class,
                () -> new Grid(10, 10, 1).move(new Rect(0, 0, 5, 5), 1e7f, 1e7f));
        assertTrue(far.getMessage().contains("more than the 4194304 that Grid.move looks at"), far.getMessage());
        IllegalArgumentException farther = assertThrows(IllegalArgumentException.class,
                () -> new Grid(10, 10, 1).move(new Rect(0, 0, 5, 5), 1e30f, 0));
        assertTrue(farther.getMessage().contains("cells from the grid"), farther.getMessage());
    }

    // ---- against Sweep.move on every cell ------------------------------------------------

    @Property(tries = 3000)
    void move_matchesSweepMoveOnEverySolidCell(@ForAll long seed) {
        Random random = new Random(seed);
        Grid g = GridSightTest.randomGrid(random);
        float cw = g.cellWidth(), ch = g.cellHeight();
        for (int i = 0; i < 10; i++) {
            float w = size(random, cw), h = size(random, ch);
            float[] at = GridSightTest.randomPoint(random, g);
            float vx = speed(random, cw), vy = speed(random, ch);
            switch (random.nextInt(4)) {
                case 0 -> vx = 0;
                case 1 -> vy = 0;
                default -> { }
            }
            Rect mover = new Rect(at[0], at[1], w, h);
            Sweep.Move want = oracle(g, mover, vx, vy);
            assertEquals(want, g.move(mover, vx, vy), mover + " by (" + vx + ", " + vy + ") on\n" + g);
        }
    }

    /** A box side: as big as a cell, bigger, smaller, or flat. */
    private static float size(Random random, float cell) {
        return switch (random.nextInt(6)) {
            case 0 -> cell;
            case 1 -> 2 * cell;
            case 2 -> cell * (1 + random.nextInt(8) / 4f);
            case 3 -> cell * random.nextInt(4) / 4f;
            case 4 -> 0;
            default -> random.nextFloat() * 3 * cell;
        };
    }

    /** A speed of up to three cells a frame: whole cells, quarters, or anything. */
    private static float speed(Random random, float cell) {
        return switch (random.nextInt(3)) {
            case 0 -> cell * (random.nextInt(13) - 6) / 2f;
            case 1 -> random.nextInt(25) - 12 + random.nextInt(4) / 4f;
            default -> (random.nextFloat() * 2 - 1) * 3 * cell;
        };
    }

    @Test
    void move_aPlatformerRun_staysOutOfWalls() {
        // Many frames of gravity, running and jumping on the level, each frame against the reference.
        Grid g = level();
        Rect p = new Rect(1, 1, 9, 11);
        float vx = 2.5f, vy = 0;
        Random random = new Random(9);
        for (int frame = 0; frame < 2000; frame++) {
            vy = Math.min(vy + 0.6f, 12);
            Sweep.Move m = g.move(p, vx, vy);
            assertEquals(oracle(g, p, vx, vy), m, "frame " + frame);
            p = new Rect(m.x(), m.y(), p.w(), p.h());
            assertFalse(g.overlapsSolid(new Rect(p.x(), p.y(), p.w(), p.h())), "frame " + frame + ": inside a wall at " + p);
            vx = m.vx() == 0 ? -Math.signum(vx + 0.1f) * 2.5f : vx;
            vy = m.vy();
            if (m.landed() && random.nextInt(30) == 0) {
                vy = -7;
            }
        }
    }
}
