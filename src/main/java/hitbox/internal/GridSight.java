package hitbox.internal;

import hitbox.*;

/**
 * Line of sight on a {@link Grid}: does a segment reach into a solid cell? Behind
 * {@link Grid#lineOfSight}.
 *
 * <p>The answer is defined cell by cell: the segment is blocked exactly when
 * {@link Collide#lineRect} says it hits the rectangle of some solid cell ({@link Grid#isSolid},
 * so the cells beyond the grid's edges count as solid). Only the cells along the segment are
 * looked at: the grid is walked column by column from the left end to the right end, and in
 * each column the rows between the heights where the segment enters and leaves it. Those are
 * the cells the traversal of Amanatides and Woo visits; each height is widened by a float
 * step, so that where the segment meets a grid line or passes through a corner the cells on
 * both sides are candidates too. Every candidate that is solid is then tested with
 * {@code RawTests.lineRect} itself, so the walk decides only which cells to look at, never the
 * answer.
 *
 * <p>Reference: John Amanatides and Andrew Woo, "A Fast Voxel Traversal Algorithm for Ray
 * Tracing", Eurographics 1987.
 */
public final class GridSight {

    private GridSight() {
    }

    /** See {@link Grid#lineOfSight}. */
    public static boolean lineOfSight(Grid grid, float x0, float y0, float x1, float y1) {
        if (Check.notFinite(x0, y0, x1, y1, 0)) {
            return false;  // the NaN rule: no result, so no sight
        }
        if (reachesOutside(grid, x0, y0) || reachesOutside(grid, x1, y1)) {
            // An end strictly outside the grid's rectangle: the segment runs through cells
            // beyond the edges, all solid, and reaches into one unless it lies on a grid line
            // (then it reaches into no cell at all, outside or in).
            return onGridLine(grid, x0, y0, x1, y1);
        }
        // Walk from left to right; lineRect gets the ends as given (it is symmetric anyway).
        float ax = x0, ay = y0, bx = x1, by = y1;
        if (bx < ax) {
            ax = x1;
            ay = y1;
            bx = x0;
            by = y0;
        }
        double dx = (double) bx - ax;
        double dy = (double) by - ay;
        float yMin = Math.min(ay, by);
        float yMax = Math.max(ay, by);
        int rowLo = clamp(grid.rowAt(Math.nextDown(yMin)), grid.rows());
        int rowHi = clamp(grid.rowAt(Math.nextUp(yMax)), grid.rows());
        int colLo = clamp(grid.colAt(Math.nextDown(ax)), grid.cols());
        int colHi = clamp(grid.colAt(Math.nextUp(bx)), grid.cols());
        // The rows a column spans run between the heights at its two sides; each side is
        // shared with the next column, so its rows are worked out once.
        double invDx = dx > 0 ? 1 / dx : 0;
        float h = heightAt(ax, ay, invDx, dy, ax);
        int lowLeft = grid.rowAt(Math.nextDown(h));
        int highLeft = grid.rowAt(Math.nextUp(h));
        for (int col = colLo; col <= colHi; col++) {
            float left = GridLines.edge(col, grid.cellWidth());
            float right = GridLines.edge(col + 1, grid.cellWidth());
            int r0 = rowLo;
            int r1 = rowHi;
            if (dx > 0) {
                h = heightAt(ax, ay, invDx, dy, Math.min(bx, right));
                int lowRight = grid.rowAt(Math.nextDown(h));
                int highRight = grid.rowAt(Math.nextUp(h));
                r0 = Math.max(rowLo, Math.min(lowLeft, lowRight));
                r1 = Math.min(rowHi, Math.max(highLeft, highRight));
                lowLeft = lowRight;
                highLeft = highRight;
            }
            float w = right - left;
            for (int row = r0; row <= r1; row++) {
                if (grid.isSolid(col, row)) {
                    float top = GridLines.edge(row, grid.cellHeight());
                    if (RawTests.lineRect(x0, y0, x1, y1, left, top, w, GridLines.edge(row + 1, grid.cellHeight()) - top)) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    /**
     * The segment's y at x, for x between its ends, rounded to a float: the true height is
     * within half a float step of it (the double arithmetic is off by far less), so one
     * float step down and up brackets it.
     */
    private static float heightAt(float ax, float ay, double invDx, double dy, float x) {
        double t = ((double) x - ax) * invDx;
        return (float) (ay + Math.min(1, Math.max(0, t)) * dy);
    }

    private static boolean reachesOutside(Grid grid, float x, float y) {
        return x < 0 || x > grid.width() || y < 0 || y > grid.height();
    }

    /**
     * Does the segment lie on a grid line: along a row line or a column line, or a point on
     * either? Such a segment reaches into no cell's inside.
     */
    private static boolean onGridLine(Grid grid, float x0, float y0, float x1, float y1) {
        boolean onRowLine = y0 == y1 && GridLines.edge(grid.rowAt(y0), grid.cellHeight()) == y0;
        boolean onColLine = x0 == x1 && GridLines.edge(grid.colAt(x0), grid.cellWidth()) == x0;
        return onRowLine || onColLine;
    }

    private static int clamp(int i, int count) {
        return Math.max(0, Math.min(count - 1, i));
    }
}
