package hitbox;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Random;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Grid.path: the fewest straight steps canMove allows (against a plain breadth-first search),
 * and the cheapest route under PathCosts, with and without diagonals (against a plain
 * Dijkstra that tries every cell); every route is checked step by step.
 */
class GridPathTest {

    private static final float INF = Float.POSITIVE_INFINITY;

    /** 0 grass, 1 wall, 2 forest, 3 water; 10 px cells. */
    private static final String TERRAIN = """
            0000000
            0222220
            0211120
            0222220
            0000000
            """;

    private static Grid terrain() {
        return Grid.parse(TERRAIN, 10).passable(2, 3);
    }

    private static int cell(Grid g, int col, int row) {
        return row * g.cols() + col;
    }

    // ---- straight steps, fewest -------------------------------------------------------

    @Test
    void path_openRow_isEveryCellInOrder() {
        Grid g = new Grid(5, 1, 10);
        assertArrayEquals(new int[] {0, 1, 2, 3, 4}, g.path(0, 0, 4, 0));
        assertArrayEquals(new int[] {4, 3, 2, 1, 0}, g.path(4, 0, 0, 0));
    }

    @Test
    void path_startIsGoal_isThatCell() {
        Grid g = new Grid(3, 3, 10);
        assertArrayEquals(new int[] {4}, g.path(1, 1, 1, 1));
        assertArrayEquals(new int[] {4}, g.path(1, 1, 1, 1, PathCosts.steps()));
    }

    @Test
    void path_aroundAWall() {
        Grid g = Grid.parse("""
                .....
                .###.
                ...#.
                """, 10);
        int[] route = g.path(0, 2, 4, 2);
        assertEquals(9, route.length, "up, across the top and down: 8 steps");
        assertValidSteps(g, route, false);
        assertEquals(cell(g, 0, 2), route[0]);
        assertEquals(cell(g, 4, 2), route[route.length - 1]);
    }

    @Test
    void path_none_isEmpty() {
        Grid g = Grid.parse("""
                ..#..
                ..#..
                """, 10);
        assertEquals(0, g.path(0, 0, 4, 1).length, "walled off");
        assertEquals(0, g.path(2, 0, 0, 0).length, "the start is solid");
        assertEquals(0, g.path(0, 0, 2, 1).length, "the goal is solid");
        assertEquals(0, g.path(2, 0, 2, 0).length, "a solid start that is the goal");
        assertEquals(0, g.path(0, 0, 4, 1, PathCosts.steps().withDiagonals()).length, "no diagonal through a wall either");
    }

    @Test
    void path_passableTerrain_isWalkedOnlyOnceNamed() {
        Grid g = Grid.parse("..2..", 10);
        assertEquals(0, g.path(0, 0, 4, 0).length, "terrain 2 is solid until named passable");
        assertEquals(5, g.passable(2).path(0, 0, 4, 0).length);
    }

    @ParameterizedTest(name = "path({0}, {1}, {2}, {3}) on a 4 x 3 grid: {4}")
    // A cell outside the grid is an index out of range: IndexOutOfBoundsException, as for get
    // and set (issue 19's one exception per kind of mistake; it was IllegalArgumentException).
    @CsvSource(delimiter = '|', value = {
            "-1 | 0 | 0 | 0 | fromCol must be from 0 to 3 (a cell of the 4 x 3 grid), was -1",
            "4 | 0 | 0 | 0 | fromCol must be from 0 to 3 (a cell of the 4 x 3 grid), was 4",
            "0 | 3 | 0 | 0 | fromRow must be from 0 to 2 (a cell of the 4 x 3 grid), was 3",
            "0 | 0 | -2147483648 | 0 | toCol must be from 0 to 3 (a cell of the 4 x 3 grid), was -2147483648",
            "0 | 0 | 0 | -1 | toRow must be from 0 to 2 (a cell of the 4 x 3 grid), was -1",
    })
    void path_cellOutsideTheGrid_isNamed(int fromCol, int fromRow, int toCol, int toRow, String message) {
        Grid g = new Grid(4, 3, 10);
        assertEquals(message, assertThrows(IndexOutOfBoundsException.class,
                () -> g.path(fromCol, fromRow, toCol, toRow)).getMessage());
        assertEquals(message, assertThrows(IndexOutOfBoundsException.class,
                () -> g.path(fromCol, fromRow, toCol, toRow, PathCosts.steps())).getMessage());
    }

    @Test
    void path_bigOpenGrid_isTheManhattanDistance() {
        Grid g = new Grid(1000, 1000, 1);
        int[] route = g.path(0, 0, 999, 999);
        assertEquals(1999, route.length);
        assertValidSteps(g, route, false);
        int[] again = g.path(999, 0, 0, 999);
        assertEquals(1999, again.length, "the buffers are reused: a second search starts clean");
        assertValidSteps(g, again, false);
    }

    @Property(tries = 1500)
    void path_matchesBreadthFirstSearch(@ForAll long seed) {
        Random random = new Random(seed);
        Grid g = GridSightTest.randomGrid(random);
        for (int i = 0; i < 5; i++) {
            int fc = random.nextInt(g.cols()), fr = random.nextInt(g.rows());
            int tc = random.nextInt(g.cols()), tr = random.nextInt(g.rows());
            int want = bfsSteps(g, fc, fr, tc, tr);
            int[] route = g.path(fc, fr, tc, tr);
            String where = "(" + fc + ", " + fr + ") to (" + tc + ", " + tr + ") on\n" + g.toMap();
            assertEquals(want, route.length - 1, where);
            if (route.length > 0) {
                assertEquals(cell(g, fc, fr), route[0], where);
                assertEquals(cell(g, tc, tr), route[route.length - 1], where);
                assertValidSteps(g, route, false);
            }
            int[] steps = g.path(fc, fr, tc, tr, PathCosts.steps());
            assertEquals(want, steps.length - 1, "A* with every step costing 1, " + where);
        }
    }

    /** The reference: breadth-first search with a queue of cells and canMove; -1 if there is no route (or an end is solid). */
    private static int bfsSteps(Grid g, int fc, int fr, int tc, int tr) {
        if (g.isSolid(fc, fr) || g.isSolid(tc, tr)) {
            return -1;
        }
        int[] dist = new int[g.cols() * g.rows()];
        Arrays.fill(dist, -1);
        ArrayDeque<int[]> queue = new ArrayDeque<>();
        dist[cell(g, fc, fr)] = 0;
        queue.add(new int[] {fc, fr});
        int[][] steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        while (!queue.isEmpty()) {
            int[] at = queue.poll();
            for (int[] s : steps) {
                if (g.canMove(at[0], at[1], s[0], s[1])) {
                    int next = cell(g, at[0] + s[0], at[1] + s[1]);
                    if (dist[next] < 0) {
                        dist[next] = dist[cell(g, at[0], at[1])] + 1;
                        queue.add(new int[] {at[0] + s[0], at[1] + s[1]});
                    }
                }
            }
        }
        return dist[cell(g, tc, tr)];
    }

    // ---- costs ------------------------------------------------------------------------

    @Test
    void costs_cheapestRoute_goesRoundTheForest() {
        Grid g = terrain();
        PathCosts costs = PathCosts.byTerrain(1, INF, 5, INF);
        int[] shortest = g.path(0, 2, 6, 2);
        int[] cheapest = g.path(0, 2, 6, 2, costs);
        assertEquals(9, shortest.length, "the fewest steps go through the forest, round the wall in the middle");
        assertEquals(11, cheapest.length, "at 5 a forest cell, the cheapest route goes round the outside");
        assertEquals(10.0, costs.costOf(g, cheapest), 1e-9);
        assertTrue(costs.costOf(g, shortest) > 10, "the shortest route costs more: " + costs.costOf(g, shortest));
        for (int c : cheapest) {
            assertEquals(0, g.get(c % g.cols(), c / g.cols()), "only grass");
        }
        int[] same = g.path(0, 2, 6, 2, PathCosts.byTerrain(1, INF, 1, INF));
        assertEquals(9, same.length, "with forest as cheap as grass, the cheapest route is a shortest one");
    }

    @Test
    void costs_diagonal_neverCutsACorner() {
        Grid g = Grid.parse("""
                .#
                ..
                """, 10);
        int[] route = g.path(0, 0, 1, 1, PathCosts.steps().withDiagonals());
        assertArrayEquals(new int[] {0, 2, 3}, route, "down then right: the diagonal would clip the wall's corner");
        Grid open = new Grid(2, 2, 10);
        assertArrayEquals(new int[] {0, 3}, open.path(0, 0, 1, 1, PathCosts.steps().withDiagonals()));
        assertEquals(Math.sqrt(2), PathCosts.steps().withDiagonals().costOf(open, new int[] {0, 3}), 1e-12);
        // Impassable terrain is a corner too.
        Grid water = Grid.parse("""
                .3
                ..
                """, 10).passable(3);
        assertArrayEquals(new int[] {0, 2, 3}, water.path(0, 0, 1, 1, PathCosts.byTerrain(1, INF, 1, INF).withDiagonals()));
    }

    @Test
    void costs_impassableOrSolidEnds_giveNoRoute() {
        Grid g = terrain();
        assertEquals(0, g.path(0, 0, 2, 2, PathCosts.byTerrain(1, INF, 1, INF)).length, "the goal is a wall");
        assertEquals(0, g.path(1, 1, 0, 0, PathCosts.byTerrain(1, INF, INF, INF)).length, "the start is impassable forest");
        assertEquals(0, g.path(0, 0, 1, 1, PathCosts.byTerrain(1, INF, INF, INF)).length, "the goal is impassable forest");
    }

    @Test
    void costs_zeroCosts_stillFindARoute() {
        Grid g = terrain();
        int[] route = g.path(0, 0, 6, 4, PathCosts.byTerrain(0, INF, 0, INF).withDiagonals());
        assertTrue(route.length > 0);
        assertEquals(0.0, PathCosts.byTerrain(0, INF, 0, INF).withDiagonals().costOf(g, route));
        assertValidSteps(g, route, true);
    }

    @Test
    void costs_terrainWithoutACost_isNamedWithItsCell() {
        Grid g = terrain();
        g.set(3, 0, 7);
        g.passable(2, 3, 7);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> g.path(0, 0, 6, 0, PathCosts.byTerrain(1, INF, 5, INF)));
        assertEquals("cell (col 3, row 0): terrain 7 has no cost: the costs are for terrains 0 to 3", e.getMessage());
    }

    @Test
    void costs_solidCellsNeedNoCost() {
        Grid g = Grid.parse("""
                ....
                .##.
                ....
                """, 10);
        int[] route = g.path(0, 1, 3, 1, PathCosts.byTerrain(1));
        assertEquals(6, route.length, "terrain 1 is solid, so it is never costed");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "-1 | the cost of terrain 0 must be 0 or more (or Float.POSITIVE_INFINITY for impassable), was -1.0",
            "NaN | the cost of terrain 0 must be 0 or more (or Float.POSITIVE_INFINITY for impassable), was NaN",
    })
    void costs_badCost_isNamed(float bad, String message) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> PathCosts.byTerrain(bad, 1)).getMessage());
        assertEquals(message.replace("terrain 0", "terrain 2"),
                assertThrows(IllegalArgumentException.class, () -> PathCosts.byTerrain(1, 1, bad)).getMessage());
    }

    @Test
    void costs_badArguments_areNamed() {
        assertEquals("costByTerrain must not be null",
                assertThrows(IllegalArgumentException.class, () -> PathCosts.byTerrain((float[]) null)).getMessage());
        assertEquals("costByTerrain is empty: give a cost for each terrain number, from 0 up",
                assertThrows(IllegalArgumentException.class, PathCosts::byTerrain).getMessage());
        Grid g = new Grid(3, 3, 10);
        assertEquals("costs must not be null",
                assertThrows(IllegalArgumentException.class, () -> g.path(0, 0, 1, 1, null)).getMessage());
        PathCosts costs = PathCosts.byTerrain(1);
        assertEquals("route[1] is 9, not a cell of the 3 x 3 grid",
                assertThrows(IllegalArgumentException.class, () -> costs.costOf(g, new int[] {0, 9})).getMessage());
        assertEquals("route[0] to route[1] is not a step to a neighbour across or down",
                assertThrows(IllegalArgumentException.class, () -> costs.costOf(g, new int[] {0, 4})).getMessage());
        assertEquals("route[0] to route[1] is not a step to a neighbour across or down",
                assertThrows(IllegalArgumentException.class, () -> costs.costOf(g, new int[] {2, 3})).getMessage(),
                "from the end of one row to the start of the next is no step");
        assertEquals(0.0, costs.costOf(g, new int[0]));
    }

    @Test
    void costs_value() {
        PathCosts costs = PathCosts.byTerrain(1, INF, 3);
        float[] table = {1, INF, 3};
        PathCosts copy = PathCosts.byTerrain(table);
        table[0] = 100;
        assertEquals(1f, copy.cost(0), "the table is copied");
        assertFalse(costs.diagonals());
        assertTrue(costs.withDiagonals().diagonals());
        assertFalse(costs.diagonals(), "withDiagonals makes a new value");
        assertEquals(INF, costs.cost(1));
        assertEquals(PathCosts.byTerrain(1, INF, 3), costs);
        assertEquals(PathCosts.byTerrain(1, INF, 3).hashCode(), costs.hashCode());
        assertFalse(costs.equals(costs.withDiagonals()));
        assertFalse(costs.equals(PathCosts.byTerrain(1, INF, 4)));
        assertFalse(PathCosts.steps().equals(PathCosts.byTerrain(1)), "steps costs every terrain 1, byTerrain(1) only terrain 0");
        assertEquals(1f, PathCosts.steps().cost(12345), "steps: every terrain costs 1");
        assertEquals("PathCosts.byTerrain[1.0, Infinity, 3.0].withDiagonals()", costs.withDiagonals().toString());
        assertEquals("terrain -1 has no cost: the costs are for terrains 0 to 2",
                assertThrows(IllegalArgumentException.class, () -> costs.cost(-1)).getMessage());
    }

    @Property(tries = 1500)
    void costs_matchBruteForceDijkstra(@ForAll long seed) {
        Random random = new Random(seed);
        Grid g = GridSightTest.randomGrid(random);
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                if (g.get(col, row) == Grid.EMPTY && random.nextInt(4) == 0) {
                    g.set(col, row, 3);  // a fourth terrain, made passable below
                }
            }
        }
        g.passable(2, 3);
        float[] table = new float[4];
        for (int t = 0; t < 4; t++) {
            int kind = random.nextInt(6);
            table[t] = kind == 0 ? INF : kind == 1 ? 0 : kind == 2 ? 1 : 0.5f + random.nextInt(20) / 4f;
        }
        PathCosts costs = random.nextBoolean() ? PathCosts.byTerrain(table) : PathCosts.byTerrain(table).withDiagonals();
        for (int i = 0; i < 5; i++) {
            int fc = random.nextInt(g.cols()), fr = random.nextInt(g.rows());
            int tc = random.nextInt(g.cols()), tr = random.nextInt(g.rows());
            double want = dijkstra(g, costs, fc, fr, tc, tr);
            int[] route = g.path(fc, fr, tc, tr, costs);
            String where = costs + " (" + fc + ", " + fr + ") to (" + tc + ", " + tr + ") on\n" + g.toMap();
            if (Double.isInfinite(want)) {
                assertEquals(0, route.length, where);
                continue;
            }
            assertTrue(route.length > 0, where);
            assertEquals(cell(g, fc, fr), route[0], where);
            assertEquals(cell(g, tc, tr), route[route.length - 1], where);
            assertValidSteps(g, route, costs.diagonals());
            for (int c : route) {
                assertTrue(costs.cost(g.get(c % g.cols(), c / g.cols())) < INF, "no impassable cell, " + where);
            }
            assertEquals(want, costs.costOf(g, route), 1e-9 * (1 + want), where);
        }
    }

    /**
     * The reference: Dijkstra without a heap (the cheapest unfinished cell found by looking
     * at all of them), the same step rules written out again.
     */
    private static double dijkstra(Grid g, PathCosts costs, int fc, int fr, int tc, int tr) {
        int n = g.cols() * g.rows();
        double[] dist = new double[n];
        boolean[] done = new boolean[n];
        Arrays.fill(dist, Double.POSITIVE_INFINITY);
        if (!enterable(g, costs, fc, fr) || !enterable(g, costs, tc, tr)) {
            return Double.POSITIVE_INFINITY;
        }
        dist[cell(g, fc, fr)] = 0;
        while (true) {
            int best = -1;
            for (int i = 0; i < n; i++) {
                if (!done[i] && dist[i] < Double.POSITIVE_INFINITY && (best < 0 || dist[i] < dist[best])) {
                    best = i;
                }
            }
            if (best < 0) {
                return dist[cell(g, tc, tr)];
            }
            done[best] = true;
            int col = best % g.cols(), row = best / g.cols();
            for (int dc = -1; dc <= 1; dc++) {
                for (int dr = -1; dr <= 1; dr++) {
                    boolean diagonal = dc != 0 && dr != 0;
                    if ((dc == 0 && dr == 0) || (diagonal && !costs.diagonals())) {
                        continue;
                    }
                    int c = col + dc, r = row + dr;
                    if (!enterable(g, costs, c, r)
                            || diagonal && (!enterable(g, costs, c, row) || !enterable(g, costs, col, r))) {
                        continue;
                    }
                    double step = costs.cost(g.get(c, r)) * (diagonal ? Math.sqrt(2) : 1);
                    int next = cell(g, c, r);
                    dist[next] = Math.min(dist[next], dist[best] + step);
                }
            }
        }
    }

    private static boolean enterable(Grid g, PathCosts costs, int col, int row) {
        return !g.isSolid(col, row) && costs.cost(g.get(col, row)) < INF;
    }

    /** Every step is to a neighbour canMove allows (diagonals: both cells beside it free too). */
    private static void assertValidSteps(Grid g, int[] route, boolean diagonals) {
        for (int i = 1; i < route.length; i++) {
            int c0 = route[i - 1] % g.cols(), r0 = route[i - 1] / g.cols();
            int c1 = route[i] % g.cols(), r1 = route[i] / g.cols();
            int dc = c1 - c0, dr = r1 - r0;
            String step = "step " + i + " from (" + c0 + ", " + r0 + ") to (" + c1 + ", " + r1 + ")";
            assertTrue(Math.abs(dc) <= 1 && Math.abs(dr) <= 1 && (dc != 0 || dr != 0), step + " is to a neighbour");
            assertTrue(diagonals || dc == 0 || dr == 0, step + " is straight");
            assertTrue(g.canMove(c0, r0, dc, dr), step + " is allowed by canMove");
            if (dc != 0 && dr != 0) {
                assertTrue(g.canMove(c0, r0, dc, 0) && g.canMove(c0, r0, 0, dr), step + " cuts no corner");
            }
        }
    }
}
