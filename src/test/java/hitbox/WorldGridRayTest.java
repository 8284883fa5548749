package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A ray against a grid's body walks the grid's cells along the ray: the answer is brute force
 * over every cell ({@link Ray#cast} of each solid cell's rectangle, the nearest, equal
 * distances to the cell first row by row), and the cells looked at grow with the ray's length,
 * not with the area of its box.
 */
class WorldGridRayTest {

    /** The brute force: every solid cell cast, the nearest kept, ties to the lower index. */
    private static BodyHit bruteForce(Body body, Grid g, Ray ray) {
        BodyHit best = null;
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                if (g.isSolid(col, row)) {
                    RayHit h = ray.cast(g.cellRect(col, row));
                    if (h != null && (best == null || h.distance() < best.distance())) {
                        best = new BodyHit(body, h, row * g.cols() + col);
                    }
                }
            }
        }
        return best;
    }

    private static BodyHit cast(World w, Ray ray) {
        List<BodyHit> hits = w.raycast(ray);
        assertTrue(hits.size() <= 1, "one grid body, one hit at most: " + hits);
        return hits.isEmpty() ? null : hits.get(0);
    }

    @Test
    void randomRays_matchBruteForce() {
        SplittableRandom rnd = new SplittableRandom(29);
        int hits = 0, misses = 0;
        for (int round = 0; round < 300; round++) {
            int cols = 1 + rnd.nextInt(30), rows = 1 + rnd.nextInt(30);
            float cw = rnd.nextBoolean() ? 10 : 1 + (float) rnd.nextDouble() * 20;
            float ch = rnd.nextBoolean() ? cw : 1 + (float) rnd.nextDouble() * 20;
            Grid g = new Grid(cols, rows, cw, ch);
            g.fillRandom(rnd.nextInt(4) == 0 ? 0.02f : 0.25f, rnd.nextLong(), 0, 0);
            World w = new World();
            Body body = w.add(g);
            for (int k = 0; k < 40; k++) {
                Ray ray = randomRay(rnd, g);
                BodyHit want = bruteForce(body, g, ray);
                BodyHit got = cast(w, ray);
                assertEquals(want, got, "grid " + cols + "x" + rows + " of " + cw + "x" + ch + ", " + ray);
                if (want == null) {
                    misses++;
                } else {
                    hits++;
                }
            }
        }
        assertTrue(hits > 3000 && misses > 1000, hits + " hits, " + misses + " misses");
    }

    /**
     * Rays from inside and outside the grid: along cell edges, through cell corners, at any
     * angle, short and endless.
     */
    private static Ray randomRay(SplittableRandom rnd, Grid g) {
        float w = g.width(), h = g.height();
        float ox, oy;
        switch (rnd.nextInt(3)) {
            case 0 -> {  // on a cell corner
                ox = g.cellRect(rnd.nextInt(g.cols() + 3) - 1, 0).x();
                oy = g.cellRect(0, rnd.nextInt(g.rows() + 3) - 1).y();
            }
            case 1 -> {  // on a cell edge
                ox = g.cellRect(rnd.nextInt(g.cols() + 1), 0).x();
                oy = (float) (rnd.nextDouble() * (h + 40) - 20);
            }
            default -> {
                ox = (float) (rnd.nextDouble() * (w + 40) - 20);
                oy = (float) (rnd.nextDouble() * (h + 40) - 20);
            }
        }
        float dx, dy;
        switch (rnd.nextInt(4)) {
            case 0 -> {  // along an axis
                dx = rnd.nextBoolean() ? 0 : rnd.nextBoolean() ? 1 : -1;
                dy = dx != 0 ? 0 : rnd.nextBoolean() ? 1 : -1;
            }
            case 1 -> {  // a diagonal: through the corners of square cells
                dx = rnd.nextBoolean() ? 1 : -1;
                dy = rnd.nextBoolean() ? 1 : -1;
            }
            case 2 -> {  // to another corner
                dx = g.cellRect(rnd.nextInt(g.cols() + 1), 0).x() - ox;
                dy = g.cellRect(0, rnd.nextInt(g.rows() + 1)).y() - oy;
                if (dx == 0 && dy == 0) {
                    dx = 1;
                }
            }
            default -> {
                double a = rnd.nextDouble() * 2 * Math.PI;
                dx = (float) Math.cos(a);
                dy = (float) Math.sin(a);
                if (dx == 0 && dy == 0) {
                    dx = 1;
                }
            }
        }
        float reach = rnd.nextInt(3) == 0 ? Float.POSITIVE_INFINITY : (float) (rnd.nextDouble() * (w + h));
        return new Ray(ox, oy, dx, dy, reach);
    }

    @Test
    void aRayThroughAWall_stopsAtItsNearestCell() {
        Grid g = Grid.parse("""
                .....
                ..#..
                ..#..
                .....
                """, 10);
        World w = new World();
        Body body = w.add(g);
        BodyHit hit = cast(w, new Ray(0, 15, 1, 0));
        assertNotNull(hit);
        assertEquals(20, hit.distance());
        assertEquals(1 * 5 + 2, hit.cell());
        // Down the wall's column from above: its top cell, row 1.
        BodyHit down = cast(w, new Ray(25, 0, 0, 1));
        assertEquals(10, down.distance());
        assertEquals(1 * 5 + 2, down.cell());
        // Along the wall's left edge, as Ray.cast of each cell says.
        assertEquals(bruteForce(body, g, new Ray(20, 0, 0, 1)), cast(w, new Ray(20, 0, 0, 1)));
        assertNull(cast(w, new Ray(0, 5, 1, 0)), "the top row is open");
    }

    /**
     * The cells looked at grow with the ray's length: a ray across an empty grid of a million
     * cells looks at a few cells per column it crosses, where the ray's box holds the square
     * of that many.
     */
    @Test
    void theCellsLookedAt_growWithTheRaysLength() {
        Grid g = new Grid(1000, 1000, 10);
        World w = new World();
        w.add(g);
        long[] seen = new long[4];
        int[] lengths = {50, 100, 200, 400};  // in cells along x
        for (int i = 0; i < lengths.length; i++) {
            int n = lengths[i];
            long before = w.grids().cellsVisited();
            // A ray that rises 3 cells for every 4 across, ending n cells across.
            assertNull(cast(w, Ray.between(5, 5, 5 + 10 * n, 5 + 7.5f * n)));
            seen[i] = w.grids().cellsVisited() - before;
            long columns = n + 1, rows = (long) Math.ceil(0.75 * n) + 1;
            assertTrue(seen[i] <= 3 * (columns + rows), n + " columns across: looked at " + seen[i] + " cells");
            assertTrue(seen[i] >= columns + rows - 1, "the cells the ray crosses at least: " + seen[i]);
        }
        // Doubling the length doubles the cells (the box's area would quadruple).
        for (int i = 1; i < lengths.length; i++) {
            double growth = (double) seen[i] / seen[i - 1];
            assertTrue(growth > 1.6 && growth < 2.4, "growth " + growth + " from " + seen[i - 1] + " to " + seen[i]);
        }
        // An endless ray across the whole grid looks at no more than a few cells a column.
        long before = w.grids().cellsVisited();
        assertNull(cast(w, new Ray(0.5f, 0.5f, 1, 0.8f)));
        long endless = w.grids().cellsVisited() - before;
        assertTrue(endless <= 3 * (1000 + 800) && endless < 1_000_000 / 100, "endless ray: " + endless + " cells");
    }

    /** A ray that meets a wall early stops there: the cells beyond are never looked at. */
    @Test
    void aRayThatMeetsAWall_looksNoFurther() {
        Grid g = new Grid(1000, 10, 10);
        g.set(5, 3, Grid.SOLID);
        World w = new World();
        w.add(g);
        long before = w.grids().cellsVisited();
        BodyHit hit = cast(w, new Ray(1, 35, 1, 0));
        assertEquals(49, hit.distance());
        assertTrue(w.grids().cellsVisited() - before <= 3 * 7, "looked at " + (w.grids().cellsVisited() - before));
    }
}
