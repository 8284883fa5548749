package hitbox.web;

import hitbox.Circle;
import hitbox.Grid;
import hitbox.Rect;
import hitbox.Sweep;
import hitbox.internal.SideSets;
import org.teavm.jso.JSBody;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;
import org.teavm.jso.JSObject;
import org.teavm.jso.JSProperty;

/** A grid of cells for JavaScript: {@link Grid}'s cells, tests, moves and paths. */
@JSClass(name = "Grid")
public final class GridJs {
    final Grid grid;

    /**
     * Makes an empty grid.
     *
     * @param cols     the columns
     * @param rows     the rows
     * @param cellSize the side of a cell
     */
    @JSExport
    public GridJs(int cols, int rows, float cellSize) {
        this(new Grid(cols, rows, cellSize));
    }

    GridJs(Grid grid) {
        this.grid = grid;
    }

    /**
     * Reads a grid from a map: one line a row, '#' solid, '.' empty, digits for terrains.
     *
     * @param map      the map
     * @param cellSize the side of a cell
     * @return the grid
     */
    @JSExport
    public static GridJs parse(String map, float cellSize) {
        return new GridJs(Grid.parse(map, cellSize));
    }

    /** @return the columns */
    @JSExport
    @JSProperty
    public int getCols() {
        return grid.cols();
    }

    /** @return the rows */
    @JSExport
    @JSProperty
    public int getRows() {
        return grid.rows();
    }

    /** @return a cell's width */
    @JSExport
    @JSProperty
    public float getCellWidth() {
        return grid.cellWidth();
    }

    /** @return a cell's height */
    @JSExport
    @JSProperty
    public float getCellHeight() {
        return grid.cellHeight();
    }

    /**
     * @param col the column
     * @param row the row
     * @return the cell's terrain
     */
    @JSExport
    public int get(int col, int row) {
        return grid.get(col, row);
    }

    /**
     * @param col     the column
     * @param row     the row
     * @param terrain the cell's new terrain
     */
    @JSExport
    public void set(int col, int row, int terrain) {
        grid.set(col, row, terrain);
    }

    /**
     * @param col the column
     * @param row the row
     * @return whether the cell is solid (outside the grid counts as solid)
     */
    @JSExport
    public boolean isSolid(int col, int row) {
        return grid.isSolid(col, row);
    }

    /**
     * @param x a point's x
     * @return the column it is in
     */
    @JSExport
    public int colAt(float x) {
        return grid.colAt(x);
    }

    /**
     * @param y a point's y
     * @return the row it is in
     */
    @JSExport
    public int rowAt(float y) {
        return grid.rowAt(y);
    }

    /**
     * @param x the rectangle's left
     * @param y the rectangle's top
     * @param w its width
     * @param h its height
     * @return whether it overlaps a solid cell ({@code Grid.overlapsSolid} of the rectangle)
     * @throws IllegalArgumentException if a value is NaN or infinite, or a size negative
     */
    @JSExport
    public boolean rectOverlapsSolid(float x, float y, float w, float h) {
        return grid.overlapsSolid(new Rect(x, y, w, h));
    }

    /**
     * @param cx the circle's centre x
     * @param cy its centre y
     * @param r  its radius
     * @return whether it overlaps a solid cell ({@code Grid.overlapsSolid} of the circle)
     * @throws IllegalArgumentException if a value is NaN or infinite, or the radius negative
     */
    @JSExport
    public boolean circleOverlapsSolid(float cx, float cy, float r) {
        return grid.overlapsSolid(new Circle(cx, cy, r));
    }

    /**
     * @param x0 one end's x
     * @param y0 its y
     * @param x1 the other end's x
     * @param y1 its y
     * @return whether no solid cell lies between
     */
    @JSExport
    public boolean lineOfSight(float x0, float y0, float x1, float y1) {
        return grid.lineOfSight(x0, y0, x1, y1);
    }

    /**
     * The fewest straight steps between two cells, as cell indices (row * cols + col), or an
     * empty array when there is no way.
     *
     * @param fromCol the start's column
     * @param fromRow its row
     * @param toCol   the goal's column
     * @param toRow   its row
     * @return the cells
     */
    @JSExport
    public int[] path(int fromCol, int fromRow, int toCol, int toRow) {
        return grid.path(fromCol, fromRow, toCol, toRow);
    }

    @JSBody(params = {"x", "y", "vx", "vy", "sides"}, script = "return {x: x, y: y, vx: vx, vy: vy, sides: sides};")
    private static native JSObject move(float x, float y, float vx, float vy, int sides);

    /**
     * Moves a rectangle by (vx, vy) through the grid, sliding along solid cells: {x, y, vx,
     * vy, sides}, where it ended, what is left of its velocity, and the sides it touched (bits).
     *
     * @param x  the rectangle's left
     * @param y  its top
     * @param w  its width
     * @param h  its height
     * @param vx the move, x part
     * @param vy the move, y part
     * @return the move
     */
    @JSExport
    public JSObject move(float x, float y, float w, float h, float vx, float vy) {
        Sweep.Move m = grid.move(new Rect(x, y, w, h), vx, vy);
        // JavaScript keeps its bits (LEFT 1, RIGHT 2, TOP 4, BOTTOM 8); the library gives a set.
        return move(m.x(), m.y(), m.vx(), m.vy(), SideSets.bits(m.sides()));
    }
}
