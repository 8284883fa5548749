package hitbox;

import hitbox.internal.*;

import java.util.Arrays;

/**
 * What a step costs on a {@link Grid}, for {@link Grid#path(int, int, int, int, PathCosts)}:
 * a cost per terrain number, and whether diagonal steps are allowed. The tutorial's terrain
 * types ("0 for grass, 1 for water, 2 for forest") become a cheapest route: walking through
 * forest costs more than walking on grass, so the route goes round the forest when that is
 * cheaper.
 *
 * <pre>{@code
 * PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 3);  // grass, water, forest
 * int[] route = grid.path(0, 0, 19, 14, costs);
 * int[] diagonal = grid.path(0, 0, 19, 14, costs.withDiagonals());
 * }</pre>
 *
 * <ul>
 *   <li><b>A step costs the cell it enters</b>: {@code cost(terrain)} of the cell stepped
 *       into; the start cell costs nothing. A diagonal step costs {@code sqrt(2)} times as much,
 *       as it is that much longer.</li>
 *   <li><b>Impassable</b>: a cost of {@link Float#POSITIVE_INFINITY} is never entered. The
 *       grid's own walls come first: a cell the grid calls solid ({@link Grid#isSolid}) is
 *       never entered whatever its cost, so a route only takes steps that
 *       {@link Grid#canMove} allows. Name your walkable terrain types in
 *       {@link Grid#passable(int...)} as usual.</li>
 *   <li><b>Diagonals never cut a corner</b>: with {@link #withDiagonals()}, a diagonal step
 *       needs both cells beside it (the two straight steps it replaces) to be enterable too,
 *       so a route never squeezes between two blocked cells that meet at a corner, nor clips
 *       the corner of one.</li>
 * </ul>
 * A {@code PathCosts} is an immutable value: {@link #withDiagonals()} returns a new one.
 */
public final class PathCosts {

    private static final PathCosts STEPS = new PathCosts(new float[] {1}, true, false);

    private final float[] costs;
    /** Every terrain not in the table costs 1: only for {@link #steps()}. */
    private final boolean uniform;
    private final boolean diagonals;
    private final float cheapest;

    private PathCosts(float[] costs, boolean uniform, boolean diagonals) {
        this.costs = costs;
        this.uniform = uniform;
        this.diagonals = diagonals;
        float min = Float.POSITIVE_INFINITY;
        for (float c : costs) {
            min = Math.min(min, c);
        }
        this.cheapest = min;
    }

    /**
     * Every open cell costs 1: the cheapest route is the one with the fewest steps, as
     * {@link Grid#path(int, int, int, int)} finds (and, with {@link #withDiagonals()}, diagonal
     * steps cost {@code sqrt(2)}).
     *
     * @return the costs of a plain shortest route, straight steps only, never null
     */
    public static PathCosts steps() {
        return STEPS;
    }

    /**
     * A cost per terrain number: {@code costByTerrain[t]} is the cost of stepping into a cell
     * of terrain {@code t}. A route may only reach cells whose terrain has a cost here: meeting
     * one that has none (a number below 0, or past the end of the table) is an error, so a
     * typo in a map does not quietly become a wall.
     *
     * @param costByTerrain the costs, from terrain 0 up: 0 or more, or
     *                      {@link Float#POSITIVE_INFINITY} for impassable; the array is copied
     * @return the costs, straight steps only, never null
     * @throws IllegalArgumentException if the array is null or empty, or a cost is NaN or
     *                                  below 0; the message names the terrain
     */
    public static PathCosts byTerrain(float... costByTerrain) {
        Check.notNull("costByTerrain", costByTerrain);
        if (costByTerrain.length == 0) {
            throw new IllegalArgumentException("costByTerrain is empty: give a cost for each terrain number, from 0 up");
        }
        for (int t = 0; t < costByTerrain.length; t++) {
            float c = costByTerrain[t];
            if (!(c >= 0)) {
                throw new IllegalArgumentException("the cost of terrain " + t + " must be 0 or more (or "
                        + "Float.POSITIVE_INFINITY for impassable), was " + c);
            }
        }
        return new PathCosts(costByTerrain.clone(), false, false);
    }

    /**
     * The same costs with diagonal steps allowed as well: 8 neighbours instead of 4. A
     * diagonal step costs {@code sqrt(2)} times the cell it enters, and needs both cells beside
     * it to be enterable, so it never cuts a corner.
     *
     * @return new costs that allow diagonal steps, never null
     */
    public PathCosts withDiagonals() {
        return new PathCosts(costs, uniform, true);
    }

    /** @return true if routes may take diagonal steps */
    public boolean diagonals() {
        return diagonals;
    }

    /**
     * The cost of a straight step into a cell of this terrain.
     *
     * @param terrain the terrain number
     * @return its cost, 0 or more; {@link Float#POSITIVE_INFINITY} for impassable
     * @throws IllegalArgumentException if the table has no cost for this terrain
     */
    public float cost(int terrain) {
        if (uniform) {
            return 1;
        }
        if (terrain < 0 || terrain >= costs.length) {
            throw new IllegalArgumentException("terrain " + terrain + " has no cost: the costs are for terrains 0 to "
                    + (costs.length - 1));
        }
        return costs[terrain];
    }

    /**
     * What a route costs: the sum of its steps, as the path search counts them.
     *
     * @param grid  the grid the route is on
     * @param route cell indices {@code row * cols() + col}, as {@link Grid#path} returns them
     * @return the total cost; 0 for a route of one cell or none
     * @throws IllegalArgumentException if an argument is null, a cell is not in the grid, a
     *                                  step is not to a neighbour (or is diagonal when these
     *                                  costs do not allow it), or a terrain has no cost
     */
    public double costOf(Grid grid, int[] route) {
        Check.notNull("grid", grid);
        Check.notNull("route", route);
        int cells = grid.cols() * grid.rows();
        double total = 0;
        for (int i = 0; i < route.length; i++) {
            if (route[i] < 0 || route[i] >= cells) {
                throw new IllegalArgumentException("route[" + i + "] is " + route[i] + ", not a cell of the "
                        + grid.cols() + " x " + grid.rows() + " grid");
            }
            if (i == 0) {
                continue;
            }
            int dc = Math.abs(route[i] % grid.cols() - route[i - 1] % grid.cols());
            int dr = Math.abs(route[i] / grid.cols() - route[i - 1] / grid.cols());
            if (dc + dr == 0 || dc > 1 || dr > 1 || (dc + dr == 2 && !diagonals)) {
                throw new IllegalArgumentException("route[" + (i - 1) + "] to route[" + i + "] is not a step to a "
                        + (diagonals ? "neighbour" : "neighbour across or down"));
            }
            float c = cost(grid.get(route[i] % grid.cols(), route[i] / grid.cols()));
            total += dc + dr == 2 ? GridPaths.DIAGONAL * c : c;
        }
        return total;
    }

    /**
     * The least cost of any step into a cell: what a path search's distance estimate assumes.
     *
     * @return the cheapest step's cost, never NaN
     */
    public float cheapest() {
        return cheapest;
    }

    /**
     * Costs are equal when they cost every terrain the same and agree on diagonals.
     *
     * @param o another object
     * @return true if it is equal costs
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof PathCosts p && p.uniform == uniform && p.diagonals == diagonals
                && Arrays.equals(p.costs, costs);
    }

    /** @return a hash code consistent with {@link #equals} */
    @Override
    public int hashCode() {
        return Arrays.hashCode(costs) * 31 + (uniform ? 2 : 0) + (diagonals ? 1 : 0);
    }

    /** @return the costs, for printing */
    @Override
    public String toString() {
        return (uniform ? "PathCosts.steps()" : "PathCosts.byTerrain" + Arrays.toString(costs))
                + (diagonals ? ".withDiagonals()" : "");
    }
}
