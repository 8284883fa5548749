package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Grid.lineOfSight: exactly Collide.lineRect against every solid cell, the cells beyond the
 * grid's edges included, by walking only the cells along the line.
 */
class GridSightTest {

    /** 10 px cells; solid cells at (2, 1), (3, 1) and (1, 3). */
    private static final String MAP = """
            .....
            ..##.
            .....
            .#...
            .....
            """;

    private static Grid map() {
        return Grid.parse(MAP, 10);
    }

    /** The slow reference: lineRect against every solid cell of a window that covers the grid and the segment. */
    static boolean oracle(Grid g, float x0, float y0, float x1, float y1) {
        int c0 = Math.min(0, g.colAt(Math.min(x0, x1))) - 1;
        int c1 = Math.max(g.cols() - 1, g.colAt(Math.max(x0, x1))) + 1;
        int r0 = Math.min(0, g.rowAt(Math.min(y0, y1))) - 1;
        int r1 = Math.max(g.rows() - 1, g.rowAt(Math.max(y0, y1))) + 1;
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                Rect cell = g.cellRect(col, row);
                if (g.isSolid(col, row) && Collide.lineRect(x0, y0, x1, y1, cell.x(), cell.y(), cell.w(), cell.h())) {
                    return false;
                }
            }
        }
        return true;
    }

    @ParameterizedTest(name = "({0}, {1}) to ({2}, {3}): {4}")
    @CsvSource({
            "5, 5, 45, 5, true",          // along the open top row
            "5, 15, 45, 15, false",       // through the two solid cells
            "0, 10, 50, 10, true",        // along the top edge of (2, 1) and (3, 1): touching
            "0, 20, 50, 20, true",        // along their bottom edge
            "20, 0, 20, 50, true",        // along the left edge of (2, 1) and the right edge of (1, 3)
            "10, 0, 30, 20, false",       // the diagonal of (2, 1): through its inside
            "0, 0, 20, 20, true",         // from a corner to (2, 1)'s top-left corner: grazes it
            "10, 20, 20, 10, true",       // corner to corner, between (1, 1) and (2, 1)... touching (2, 1) only
            "15, 25, 25, 15, false",      // across the corner of (2, 1) into it
            "25, 15, 25, 15, false",      // a point inside a solid cell
            "20, 15, 20, 15, true",       // a point on a solid cell's edge
            "30, 10, 30, 10, true",       // a point on the corner between the two solid cells
            "5, 45, 45, 45, true",
            "15, 45, 15, 25, false",      // up into (1, 3)
            "15, 45, 15, 40, true",       // up to (1, 3)'s bottom edge: touching
    })
    void lineOfSight_table(float x0, float y0, float x1, float y1, boolean expected) {
        Grid g = map();
        assertEquals(expected, g.lineOfSight(x0, y0, x1, y1));
        assertEquals(expected, g.lineOfSight(x1, y1, x0, y0), "either way round");
        assertEquals(expected, oracle(g, x0, y0, x1, y1), "the reference agrees");
    }

    @ParameterizedTest(name = "({0}, {1}) to ({2}, {3}): {4}")
    @CsvSource({
            "0, 0, 50, 50, true",         // the grid's diagonal, corner to corner, misses every solid cell
            "0, 0, 50, 0, true",          // along the grid's top border
            "50, 0, 50, 50, true",        // along its right border
            "-1, 5, 5, 5, false",         // starting outside: through a cell beyond the edge, solid
            "5, 5, 5, 51, false",         // ending below the grid
            "-10, -10, -10, 30, true",    // along a column line beyond the grid: no cell's inside
            "-25, 0, 70, 0, true",        // along the top border line, beyond both ends
            "-25, -10, 70, -10, true",    // along a row line above the grid
            "-25, -5, 70, -5, false",     // through the row of cells above the grid
            "-5, -5, -5, -5, false",      // a point inside a cell beyond the edge
            "-10, -5, -10, -5, true",     // a point on a column line beyond the edge
            "60, 70, 60, 70, true",       // a point on a corner far beyond the edge
    })
    void lineOfSight_outsideTheGridIsSolid_cellByCell(float x0, float y0, float x1, float y1, boolean expected) {
        Grid g = map();
        assertEquals(expected, g.lineOfSight(x0, y0, x1, y1));
        assertEquals(expected, g.lineOfSight(x1, y1, x0, y0), "either way round");
        assertEquals(expected, oracle(g, x0, y0, x1, y1), "the reference agrees");
    }

    @Test
    void lineOfSight_passableTerrain_doesNotBlock() {
        Grid g = Grid.parse("""
                ....
                .22.
                ....
                """, 10);
        assertFalse(g.lineOfSight(5, 15, 35, 15), "terrain 2 is solid until named passable");
        assertTrue(g.passable(2).lineOfSight(5, 15, 35, 15));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"x0", "y0", "x1", "y1"})
    void lineOfSight_nanOrInfinity_seesNothing(String name) {
        // The package's NaN rule: a method on plain floats never throws; no sight is the
        // no-result of this answer (issue 10; it threw naming the coordinate before).
        Grid g = map();
        for (float bad : new float[] {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY}) {
            float[] p = {5, 5, 25, 25};
            p["x0 y0 x1 y1".indexOf(name) / 3] = bad;
            assertFalse(g.lineOfSight(p[0], p[1], p[2], p[3]), name + " = " + bad);
        }
    }

    // ---- against the reference, on random grids ----------------------------------------

    /** Cell sizes, most of them not powers of two, some not whole. */
    static final float[] CELL_SIZES = {1, 3, 7, 10, 12.5f, 13.3f, 16, 0.7f, 23.1f};

    /** A random grid of up to 12 x 12 cells with some solid cells, some passable terrain, and cells of its own size. */
    static Grid randomGrid(Random random) {
        float cw = CELL_SIZES[random.nextInt(CELL_SIZES.length)];
        float ch = random.nextInt(3) == 0 ? CELL_SIZES[random.nextInt(CELL_SIZES.length)] : cw;
        Grid g = new Grid(1 + random.nextInt(12), 1 + random.nextInt(12), cw, ch);
        double solid = random.nextDouble() * 0.6;
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                double u = random.nextDouble();
                g.set(col, row, u < solid ? Grid.SOLID : u < solid + 0.1 ? 2 : Grid.EMPTY);
            }
        }
        return random.nextBoolean() ? g.passable(2) : g;
    }

    /**
     * A point near the grid, of one of several kinds: a grid corner, a point on a grid line, a
     * cell's centre, or anywhere; within two cells of the grid, sometimes beyond it.
     */
    static float[] randomPoint(Random random, Grid g) {
        int col = random.nextInt(g.cols() + 4) - 2;
        int row = random.nextInt(g.rows() + 4) - 2;
        float anyX = (float) (-2 * g.cellWidth() + random.nextDouble() * (g.width() + 4 * g.cellWidth()));
        float anyY = (float) (-2 * g.cellHeight() + random.nextDouble() * (g.height() + 4 * g.cellHeight()));
        return switch (random.nextInt(5)) {
            case 0 -> new float[] {g.cellRect(col, 0).x(), g.cellRect(0, row).y()};
            case 1 -> new float[] {g.cellRect(col, 0).x(), anyY};
            case 2 -> new float[] {anyX, g.cellRect(0, row).y()};
            case 3 -> new float[] {g.cellCenterX(col), g.cellCenterY(row)};
            default -> new float[] {anyX, anyY};
        };
    }

    @Property(tries = 3000)
    void lineOfSight_matchesLineRectOnEveryCell(@ForAll long seed) {
        Random random = new Random(seed);
        Grid g = randomGrid(random);
        for (int i = 0; i < 20; i++) {
            float[] a = randomPoint(random, g);
            float[] b = randomPoint(random, g);
            switch (random.nextInt(6)) {
                case 0 -> b = a.clone();                          // a point
                case 1 -> b[1] = a[1];                            // level: often along a row line
                case 2 -> b[0] = a[0];                            // upright: often along a column line
                case 3 -> {                                       // at 45 degrees through corners
                    float d = g.cellWidth() * (random.nextInt(9) - 4);
                    b = new float[] {a[0] + d, a[1] + (random.nextBoolean() ? d : -d)};
                }
                default -> { }
            }
            boolean want = oracle(g, a[0], a[1], b[0], b[1]);
            String where = "(" + a[0] + ", " + a[1] + ") to (" + b[0] + ", " + b[1] + ") on\n" + g;
            assertEquals(want, g.lineOfSight(a[0], a[1], b[0], b[1]), where);
            assertEquals(want, g.lineOfSight(b[0], b[1], a[0], a[1]), "reversed, " + where);
        }
    }

    @Property(tries = 20)
    void lineOfSight_bigGrid_matchesLineRectAlongTheLine(@ForAll long seed) {
        Random random = new Random(seed);
        Grid g = new Grid(400, 300, 7.3f, 5).fillRandom(0.02f, seed, 0, 0);
        for (int i = 0; i < 50; i++) {
            float x0 = random.nextFloat() * g.width();
            float y0 = random.nextFloat() * g.height();
            float x1 = random.nextFloat() * g.width();
            float y1 = random.nextFloat() * g.height();
            // lineRect is false for a cell outside the segment's bounds, so those bounds are enough here.
            boolean want = true;
            for (int row = g.rowAt(Math.min(y0, y1)); row <= g.rowAt(Math.max(y0, y1)) && want; row++) {
                for (int col = g.colAt(Math.min(x0, x1)); col <= g.colAt(Math.max(x0, x1)); col++) {
                    Rect c = g.cellRect(col, row);
                    if (g.isSolid(col, row) && Collide.lineRect(x0, y0, x1, y1, c.x(), c.y(), c.w(), c.h())) {
                        want = false;
                        break;
                    }
                }
            }
            assertEquals(want, g.lineOfSight(x0, y0, x1, y1), "(" + x0 + ", " + y0 + ") to (" + x1 + ", " + y1 + ")");
        }
    }
}
