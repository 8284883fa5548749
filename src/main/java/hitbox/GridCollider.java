package hitbox;

import hitbox.internal.Extents;

/**
 * A grid's body in a {@link World}: what a point, a shape and a ray meet among its solid cells
 * (cells inside the grid only; beyond its edges is open). {@link World}'s queries and contacts
 * ask it; the move's walk gathers a grid's cells itself ({@code Mover}), since it keeps them as
 * obstacles of its legs.
 *
 * <p>Each answer looks only at the cells it could meet: a shape's cells under its box, a ray's
 * cells along it, column by column (or row by row, along the ray's longer axis), so a ray costs
 * in proportion to its length in cells, not to the area of its box. {@link #cellsVisited()}
 * counts the cells looked at, for the tests that pin that growth.
 */
final class GridCollider {
    /**
     * How far past a cell's edge a ray still looks at the cell, relative to the cell's size:
     * a millionth, far above the rounding of the cells' edges and of the ray's distances.
     */
    private static final double CELL_PAD = 1e-6;

    /** How many cells the answers looked at, since the world was made: an operation count for tests. */
    private long visited;

    /** The ray's times inside the grid's rectangle, while one ray is cast. */
    private final double[] span = new double[2];

    /** @return how many cells the answers have looked at so far */
    long cellsVisited() {
        return visited;
    }

    /** Is a point inside a solid cell of a grid's body (the cell's {@link Rect#contains}, as a shape's body)? */
    boolean holds(Grid g, float x, float y) {
        int col = g.colAt(x), row = g.rowAt(y);
        visited++;
        return g.inGrid(col, row) && g.isSolid(col, row) && g.cellRect(col, row).contains(x, y);
    }

    /** Does a shape overlap a solid cell of a grid? */
    boolean meets(Grid g, Shape s) {
        return firstCell(g, s) >= 0;
    }

    /** The first solid cell (row by row) of a grid that a shape overlaps, or -1. */
    int firstCell(Grid grid, Shape s) {
        double pad = World.pad(Extents.minX(s), Extents.minY(s), Extents.maxX(s), Extents.maxY(s));
        int c0 = Math.max(0, grid.colAt((float) (Extents.minX(s) - pad))), c1 = Math.min(grid.cols() - 1, grid.colAt((float) (Extents.maxX(s) + pad)));
        int r0 = Math.max(0, grid.rowAt((float) (Extents.minY(s) - pad))), r1 = Math.min(grid.rows() - 1, grid.rowAt((float) (Extents.maxY(s) + pad)));
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                visited++;
                if (grid.isSolid(col, row) && s.overlaps(grid.cellRect(col, row))) {
                    return row * grid.cols() + col;
                }
            }
        }
        return -1;
    }

    /**
     * The nearest solid cell of a grid's body that a ray meets within its reach ({@link Ray#cast}
     * of the cell's rectangle), equal distances going to the cell first row by row; null if none.
     *
     * <p>The walk goes along the ray's longer axis, one column (or row) at a time in the order
     * the ray crosses them, and looks at the cells of that column the ray passes, grown by a
     * few float steps so that a ray along a cell's edge or through its corner sees every cell
     * it touches. It stops at the first column that begins beyond the nearest hit found, so a
     * ray that meets a wall early looks at the cells before the wall only.
     */
    BodyHit ray(Body b, Grid g, Ray ray) {
        double len = Math.hypot(ray.dx(), ray.dy());
        double ux = ray.dx() / len, uy = ray.dy() / len;
        double ox = ray.ox(), oy = ray.oy();
        double w = g.width(), h = g.height();
        // A few float steps of the largest coordinate involved, and a millionth of a cell: the
        // rounding of the cells' edges and of Ray.cast's distances stays inside it.
        double pad = World.pad(Math.min(ox, 0), Math.min(oy, 0), Math.max(ox, w), Math.max(oy, h))
                + CELL_PAD * Math.max(g.cellWidth(), g.cellHeight());
        // The part of the ray inside the grid's rectangle (grown by the pad): [t0, t1].
        double t0 = 0, t1 = Math.min(ray.maxDistance(), Double.MAX_VALUE);
        span[0] = t0;
        span[1] = t1;
        if (!slab(ox, ux, -pad, w + pad, span) || !slab(oy, uy, -pad, h + pad, span)) {
            return null;
        }
        t0 = span[0];
        t1 = span[1];
        boolean alongX = Math.abs(ux) >= Math.abs(uy);
        // Along the major axis: the ray's position p(t) = o + u t; the minor axis likewise.
        double om = alongX ? ox : oy, um = alongX ? ux : uy, on = alongX ? oy : ox, un = alongX ? uy : ux;
        int lines = alongX ? g.cols() : g.rows(), across = alongX ? g.rows() : g.cols();
        double m0 = om + um * t0, m1 = om + um * t1;
        int first = clamp(cellOf(g, alongX, Math.min(m0, m1) - pad), lines);
        int last = clamp(cellOf(g, alongX, Math.max(m0, m1) + pad), lines);
        int step = um >= 0 ? 1 : -1;
        int from = step > 0 ? first : last, to = step > 0 ? last : first;
        BodyHit best = null;
        int bestCell = Integer.MAX_VALUE;
        for (int line = from; ; line += step) {
            // The ray's times across this line's cells, the line grown by the pad.
            double lo = edge(g, alongX, line) - pad, hi = edge(g, alongX, line + 1) + pad;
            double ta = (lo - om) / um, tb = (hi - om) / um;
            double enter = Math.max(t0, Math.min(ta, tb)), exit = Math.min(t1, Math.max(ta, tb));
            if (best != null && enter > best.distance()) {
                break;  // every cell from here on is farther than the hit found
            }
            if (enter <= exit) {
                double n0 = on + un * enter, n1 = on + un * exit;
                int k0 = clamp(cellOf(g, !alongX, Math.min(n0, n1) - pad), across);
                int k1 = clamp(cellOf(g, !alongX, Math.max(n0, n1) + pad), across);
                for (int k = k0; k <= k1; k++) {
                    int col = alongX ? line : k, row = alongX ? k : line;
                    visited++;
                    if (!g.isSolid(col, row)) {
                        continue;
                    }
                    RayHit hit = ray.cast(g.cellRect(col, row));
                    int cell = row * g.cols() + col;
                    if (hit != null && (best == null || hit.distance() < best.distance()
                            || hit.distance() == best.distance() && cell < bestCell)) {
                        best = new BodyHit(b, hit, cell);
                        bestCell = cell;
                    }
                }
            }
            if (line == to) {
                break;
            }
        }
        return best;
    }

    /** Clips [span[0], span[1]] to the times where o + u t lies in [lo, hi]; false if nothing is left. */
    private static boolean slab(double o, double u, double lo, double hi, double[] span) {
        if (u == 0) {
            return lo <= o && o <= hi && span[0] <= span[1];
        }
        double ta = (lo - o) / u, tb = (hi - o) / u;
        span[0] = Math.max(span[0], Math.min(ta, tb));
        span[1] = Math.min(span[1], Math.max(ta, tb));
        return span[0] <= span[1];
    }

    private static int cellOf(Grid g, boolean x, double p) {
        float f = (float) Math.max(-Float.MAX_VALUE, Math.min(Float.MAX_VALUE, p));
        return x ? g.colAt(f) : g.rowAt(f);
    }

    private static double edge(Grid g, boolean x, int i) {
        return x ? (double) i * g.cellWidth() : (double) i * g.cellHeight();
    }

    private static int clamp(int i, int n) {
        return Math.max(0, Math.min(n - 1, i));
    }
}
