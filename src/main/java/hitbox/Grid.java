package hitbox;

import hitbox.internal.*;

import java.util.Arrays;

/**
 * A grid of cells, each holding a terrain number: the tutorial's grid, for maze and platform
 * games.
 *
 * <p>The grid has {@code cols} columns and {@code rows} rows of cells, each
 * {@code cellWidth} by {@code cellHeight} pixels, with cell (0, 0) at the top-left corner of
 * the window, so cell ({@code col}, {@code row}) covers the pixels of
 * {@link #cellRect cellRect(col, row)}, from {@code col * cellWidth} across and
 * {@code row * cellHeight} down to the next cell's corner. A cell's
 * terrain is an {@code int}: {@link #EMPTY} (0) is open floor, {@link #SOLID} (1) is wall,
 * and any other number is a terrain type of your own (water, a door, the goal), solid unless
 * you name it in {@link #passable(int...)}.
 *
 * <p>Two ways to move through it:
 * <ul>
 *   <li>Cell by cell, like a maze game's player: {@link #canMove(int, int, int, int)} says
 *       whether the step to a neighbouring cell is free.</li>
 *   <li>In pixels, the tutorial's hybrid check: {@link #overlapsSolid} says whether a
 *       shape anywhere on screen overlaps a solid cell, testing only the cells it covers,
 *       by the <a href="package-summary.html#touching">touching rule</a> (standing right
 *       against a wall is not hitting it).</li>
 * </ul>
 *
 * <p><b>Outside the grid counts as solid</b>, as if the map had a wall all around it:
 * {@link #isSolid} says true for a cell beyond the edges, {@link #canMove} will not step off
 * the map, and a shape that reaches past the grid's edges overlaps solid.
 *
 * <p>A map can be written as text and read with {@link #parse(String, float)}:
 * <pre>{@code
 * Grid maze = Grid.parse("""
 *     #########
 *     #..#....#
 *     #..#.##.#
 *     #....#..#
 *     #########
 *     """, 32);
 * }</pre>
 * Or filled at random, reproducibly, with {@link #fillRandom}.
 *
 * <p>A grid is the sketch's level, not a value: {@link #set} and the fill methods change it.
 * It is not safe to change from one thread while another reads it. Reading and writing maps
 * as text and filling them at random live in a class of their own; this class keeps the
 * cells, their terrain, and the pixel tests. It is still longer than most (about 800 lines):
 * it is the public face of all of those and of sight, routes, pixel moves and picture maps,
 * each method with its full javadoc; the work of those is in GridMaps, GridSight, GridPaths,
 * GridMove and GridImages, and the pixel tests share the cell arithmetic that must stay
 * next to the cells.
 */
public final class Grid {
    // First of the static initialisers: the map readers (GridMaps) write the cells through this.
    static {
        HiddenParts.grant((HiddenParts.GridAccess) g -> g.cells);
    }


    /** The terrain of an empty cell: open floor. Never solid. */
    public static final int EMPTY = 0;
    /** The terrain of a wall. Always solid. */
    public static final int SOLID = 1;

    private static final int MAX_CELLS = Integer.MAX_VALUE - 8;

    private final int cols;
    private final int rows;
    private final float cellWidth;
    private final float cellHeight;
    /** The cells' terrains, row by row; read and written by GridMaps too (through HiddenParts). */
    private final int[] cells;
    private int[] passable = new int[0];
    /** Counts the changes to the cells and the passable terrains ({@link #changes()}). */
    private int changes;

    /**
     * Makes an empty grid: every cell {@link #EMPTY}.
     *
     * <p>A NaN or infinite {@code float} argument throws, naming it
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cols       the number of columns, 1 or more
     * @param rows       the number of rows, 1 or more
     * @param cellWidth  a cell's width in pixels, more than 0
     * @param cellHeight a cell's height in pixels, more than 0
     * @throws IllegalArgumentException if a count is 0 or less, the grid would have more than
     *                                  about two billion cells, or a cell size is not a
     *                                  finite number more than 0
     */
    public Grid(int cols, int rows, float cellWidth, float cellHeight) {
        if (cols <= 0) {
            throw new IllegalArgumentException("cols must be > 0, was " + cols);
        }
        if (rows <= 0) {
            throw new IllegalArgumentException("rows must be > 0, was " + rows);
        }
        if ((long) cols * rows > MAX_CELLS) {
            throw new IllegalArgumentException("a grid of cols x rows = " + cols + " x " + rows + " cells is too big: at most "
                    + MAX_CELLS + " cells fit in one grid");
        }
        this.cols = cols;
        this.rows = rows;
        this.cellWidth = Check.positive("cellWidth", cellWidth);
        this.cellHeight = Check.positive("cellHeight", cellHeight);
        this.cells = new int[cols * rows];
    }

    /**
     * Makes an empty grid of square cells: every cell {@link #EMPTY}.
     *
     * <p>A NaN or infinite {@code float} argument throws, naming it
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param cols     the number of columns, 1 or more
     * @param rows     the number of rows, 1 or more
     * @param cellSize a cell's width and height in pixels, more than 0
     * @throws IllegalArgumentException if a count is 0 or less, or the cell size is not a
     *                                  finite number more than 0
     */
    public Grid(int cols, int rows, float cellSize) {
        this(cols, rows, checkedCellSize(cellSize), cellSize);
    }

    private static float checkedCellSize(float cellSize) {
        return Check.positive("cellSize", cellSize);
    }

    // ---- reading a map from text ------------------------------------------------------

    /**
     * Reads a map from text, with cells 1 pixel in size (so pixels and cells are the same
     * numbers); see {@link #parse(String, float)} for the format.
     *
     * @param map the map, one line per row
     * @return a new grid holding the map, never null
     * @throws IllegalArgumentException if the map is null or empty, its rows are not all the
     *                                  same width, or it holds an unknown character; the
     *                                  message names the line and column
     */
    public static Grid parse(String map) {
        return GridMaps.parse(map, 1, 1);
    }

    /**
     * Reads a map from text, with square cells: one line per row, one character per cell.
     *
     * <ul>
     *   <li>{@code '#'} is {@link #SOLID};</li>
     *   <li>{@code '.'} and {@code ' '} (a space) are {@link #EMPTY};</li>
     *   <li>a digit {@code '0'} to {@code '9'} is that terrain number ({@code '0'} is empty,
     *       {@code '1'} is solid, the others are your own types).</li>
     * </ul>
     * Line ends may be {@code \n}, {@code \r\n} or {@code \r}. Empty lines before the first row
     * and after the last are ignored, so a Java text block works as it is; every other line is
     * a row, and all rows must have the same width. Prefer {@code '.'} to spaces at the end of
     * a row: editors and text blocks often strip trailing spaces.
     *
     * <p>A NaN or infinite {@code float} argument throws, naming it
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param map      the map, one line per row
     * @param cellSize a cell's width and height in pixels, more than 0
     * @return a new grid holding the map, never null
     * @throws IllegalArgumentException if the map is null or empty, its rows are not all the
     *                                  same width, it holds an unknown character (the message
     *                                  names the line and column, counting from 1), or the cell
     *                                  size is bad
     */
    public static Grid parse(String map, float cellSize) {
        return GridMaps.parse(map, checkedCellSize(cellSize), cellSize);
    }


    /**
     * The map as text, in the format {@link #parse(String, float)} reads: {@code '.'}
     * for {@link #EMPTY}, {@code '#'} for {@link #SOLID}, the digit for terrains 2 to 9 and
     * {@code '?'} for any other number; rows separated by {@code \n}.
     *
     * @return the map, one line per row, never null
     */
    public String toMap() {
        return GridMaps.toMap(this);
    }

    /** @return the grid's size and its map, for printing */
    @Override
    public String toString() {
        return "Grid " + cols + " x " + rows + ", cells " + cellWidth + " x " + cellHeight + " px\n" + toMap();
    }

    // ---- size -------------------------------------------------------------------------

    /** @return the number of columns */
    public int cols() {
        return cols;
    }

    /** @return the number of rows */
    public int rows() {
        return rows;
    }

    /** @return a cell's width in pixels */
    public float cellWidth() {
        return cellWidth;
    }

    /** @return a cell's height in pixels */
    public float cellHeight() {
        return cellHeight;
    }

    /** @return the grid's width in pixels, {@code cols() * cellWidth()} */
    public float width() {
        return GridLines.edge(cols, cellWidth);
    }

    /** @return the grid's height in pixels, {@code rows() * cellHeight()} */
    public float height() {
        return GridLines.edge(rows, cellHeight);
    }

    // ---- cells ------------------------------------------------------------------------

    /**
     * Is (col, row) a cell of this grid?
     *
     * @param col the column
     * @param row the row
     * @return true if {@code 0 <= col < cols()} and {@code 0 <= row < rows()}
     */
    public boolean inGrid(int col, int row) {
        return col >= 0 && col < cols && row >= 0 && row < rows;
    }

    /**
     * The terrain of a cell.
     *
     * @param col the column, from 0 to {@code cols() - 1}
     * @param row the row, from 0 to {@code rows() - 1}
     * @return the cell's terrain number
     * @throws IndexOutOfBoundsException if the cell is not in the grid; the message names the
     *                                   cell and the grid's size
     */
    public int get(int col, int row) {
        return cells[index(col, row)];
    }

    /**
     * Sets the terrain of a cell.
     *
     * @param col     the column, from 0 to {@code cols() - 1}
     * @param row     the row, from 0 to {@code rows() - 1}
     * @param terrain the terrain number: {@link #EMPTY}, {@link #SOLID} or one of your own
     * @throws IndexOutOfBoundsException if the cell is not in the grid; the message names the
     *                                   cell and the grid's size
     */
    public void set(int col, int row, int terrain) {
        cells[index(col, row)] = terrain;
        changes++;
    }

    /**
     * How many times the cells or the passable terrains were changed: a world reads it to know
     * that a grid's body's contacts need a look, and otherwise leaves them as they stood.
     */
    int changes() {
        return changes;
    }

    private int index(int col, int row) {
        if (!inGrid(col, row)) {
            throw new IndexOutOfBoundsException("cell (col " + col + ", row " + row + ") is outside the "
                    + cols + " x " + rows + " grid: col goes from 0 to " + (cols - 1)
                    + " and row from 0 to " + (rows - 1));
        }
        return row * cols + col;
    }

    /**
     * Is the cell solid? A cell outside the grid is: the map has a wall all around it.
     *
     * @param col the column, any number
     * @param row the row, any number
     * @return true if the cell is outside the grid or its terrain is solid: {@link #SOLID}
     *         or any other number but {@link #EMPTY} not named in {@link #passable(int...)}
     */
    public boolean isSolid(int col, int row) {
        return !inGrid(col, row) || isSolidTerrain(cells[row * cols + col]);
    }

    /**
     * Is this terrain number solid in this grid? {@link #EMPTY} never is, {@link #SOLID}
     * always is, and any other number is unless it was named in {@link #passable(int...)}.
     */
    private boolean isSolidTerrain(int terrain) {
        if (terrain == EMPTY) {
            return false;
        }
        for (int p : passable) {
            if (p == terrain) {
                return false;
            }
        }
        return true;
    }

    /**
     * Names the terrain types, besides {@link #EMPTY}, that can be walked through, such as a
     * goal or an open door. Replaces any earlier list; with no arguments, every non-empty
     * terrain is solid again.
     *
     * @param terrains the terrain numbers that are not solid
     * @return this grid, for chaining, never null
     * @throws IllegalArgumentException if {@code terrains} is null or includes {@link #SOLID}
     */
    public Grid passable(int... terrains) {
        Check.notNull("terrains", terrains);
        for (int t : terrains) {
            if (t == SOLID) {
                throw new IllegalArgumentException("SOLID (1) is always solid; give your passable terrain types "
                        + "other numbers, such as 2 for water");
            }
        }
        passable = terrains.clone();
        changes++;
        return this;
    }

    /**
     * May a player that moves cell by cell step from (col, row) by (dCol, dRow)? It may when
     * the cell it steps into is in the grid and not solid. The cell it stands on is not
     * checked. A diagonal step is checked only at its target, so it may squeeze between two
     * solid cells that meet at a corner; check the two straight steps as well if your game
     * forbids that.
     *
     * @param col  the player's column
     * @param row  the player's row
     * @param dCol the step across: -1 for left, 1 for right, 0 for none
     * @param dRow the step down: -1 for up, 1 for down, 0 for none
     * @return true if the target cell is free
     */
    public boolean canMove(int col, int row, int dCol, int dRow) {
        long c = (long) col + dCol;
        long r = (long) row + dRow;
        // A sum outside the int range is far outside the grid, and outside is solid.
        return c == (int) c && r == (int) r && !isSolid((int) c, (int) r);
    }

    /**
     * Sets every cell to the same terrain.
     *
     * <p>Any int is taken as a terrain number.
     *
     * @param terrain the terrain number for every cell
     * @return this grid, for chaining, never null
     */
    public Grid fill(int terrain) {
        Arrays.fill(cells, terrain);
        changes++;
        return this;
    }

    /**
     * Fills the grid at random, keeping a start cell free: exactly
     * {@code Math.round(fraction * cols() * rows())} cells become {@link #SOLID} (at most every
     * cell but the free one), chosen at random, and all the others {@link #EMPTY}, the free
     * cell among them.
     *
     * <p>The same seed and size give the same grid on every run and every Java version, since
     * {@link java.util.Random}'s algorithm is fixed by its specification. The tutorial
     * gives each cell a 20% chance ({@code random(1) < .2}), so its count of obstacles changes from
     * run to run and one may land on the player; this makes exactly the asked share solid,
     * e.g. {@code new Grid(20, 20, cellSize).fillRandom(0.2f, seed, 0, 0)}: 80 solid cells,
     * the top-left one kept free.
     *
     * <p>A NaN {@code fraction} throws, naming it
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param fraction the share of cells to make solid, from 0 to 1 (0.2 for 20%)
     * @param seed     the random seed: the same seed gives the same grid
     * @param freeCol  the column of the cell to keep empty
     * @param freeRow  the row of the cell to keep empty
     * @return this grid, for chaining, never null
     * @throws IllegalArgumentException  if {@code fraction} is not between 0 and 1
     * @throws IndexOutOfBoundsException if the free cell is not in the grid
     */
    public Grid fillRandom(float fraction, long seed, int freeCol, int freeRow) {
        GridMaps.fillRandom(cells, fraction, seed, index(freeCol, freeRow));
        changes++;
        return this;
    }

    // ---- pixels and cells -------------------------------------------------------------

    /**
     * The column under a pixel x. A pixel exactly on the line between two columns belongs to
     * the one on its right, so the column of a cell's left edge ({@link #cellRect}) is the
     * cell's. The answer may be outside the grid (negative, or {@code cols()} or more), where
     * {@link #isSolid} says solid.
     *
     * @param px the x in pixels
     * @return the column whose cell spans px, left edge included; -1 for NaN
     */
    public int colAt(float px) {
        return GridLines.cellIndex(px, cellWidth);
    }

    /**
     * The row under a pixel y. A pixel exactly on the line between two rows belongs to the
     * one below it, so the row of a cell's top edge ({@link #cellRect}) is the cell's. The
     * answer may be outside the grid.
     *
     * @param py the y in pixels
     * @return the row whose cell spans py, top edge included; -1 for NaN
     */
    public int rowAt(float py) {
        return GridLines.cellIndex(py, cellHeight);
    }

    /**
     * The x of the centre of a column's cells, in pixels: where to draw a player that stands in
     * that column.
     *
     * <p>Any int is taken, inside the grid or not: the formula does not check it.
     *
     * @param col the column
     * @return {@code (col + 0.5) * cellWidth()}
     */
    public float cellCenterX(int col) {
        return (float) ((col + 0.5) * cellWidth);
    }

    /**
     * The y of the centre of a row's cells, in pixels.
     *
     * <p>Any int is taken, inside the grid or not: the formula does not check it.
     *
     * @param row the row
     * @return {@code (row + 0.5) * cellHeight()}
     */
    public float cellCenterY(int row) {
        return (float) ((row + 0.5) * cellHeight);
    }

    /**
     * A cell as a rectangle in pixels, for drawing or for testing against shapes: its left
     * edge is the float nearest {@code col * cellWidth()}, its top the float nearest
     * {@code row * cellHeight()}, and it reaches to the next cell's, so cells tile without
     * gaps, the lines every pixel test of the grid goes by. Works for cells outside the grid
     * too, any int column and row; a cell beyond the float range (about 3e38 pixels away) is
     * held back at its edge.
     *
     * @param col the column
     * @param row the row
     * @return the rectangle the cell covers, never null
     */
    public Rect cellRect(int col, int row) {
        // The same float boundaries every pixel test uses; the next index in long, so that the
        // last column does not overflow. A cell beyond the float range is held at it.
        float x = edge(col, cellWidth), y = edge(row, cellHeight);
        float w = edge(col + 1L, cellWidth) - x, h = edge(row + 1L, cellHeight) - y;
        if (Float.isFinite(x) && Float.isFinite(y) && Float.isFinite(w) && Float.isFinite(h)) {
            return new Rect(x, y, w, h);
        }
        return Bounds.enclosing((double) col * cellWidth, (double) row * cellHeight,
                (col + 1L) * (double) cellWidth, (row + 1L) * (double) cellHeight);
    }

    /**
     * {@link #cellRect}'s numbers (x, y, w, h) into {@code out}, no rectangle made where the
     * cell is within the float range: for a world's walk, which meets cells every leg.
     */
    void cellBox(int col, int row, float[] out) {
        float x = edge(col, cellWidth), y = edge(row, cellHeight);
        float w = edge(col + 1L, cellWidth) - x, h = edge(row + 1L, cellHeight) - y;
        if (!(Float.isFinite(x) && Float.isFinite(y) && Float.isFinite(w) && Float.isFinite(h))) {
            Rect r = cellRect(col, row);  // held at the float range, as cellRect holds it
            x = r.x();
            y = r.y();
            w = r.w();
            h = r.h();
        }
        out[0] = x;
        out[1] = y;
        out[2] = w;
        out[3] = h;
    }

    /** Cell boundaries: the float nearest i * size. Every pixel test goes through this. */
    private static float edge(long i, float size) {
        return GridLines.edge(i, size);
    }

    private float cellX(int col) {
        return edge(col, cellWidth);
    }

    private float cellY(int row) {
        return edge(row, cellHeight);
    }

    // ---- shapes in pixels against solid cells -----------------------------------------

    /**
     * A rectangle against the solid cells it covers, each by {@link Collide#rectRect}: the
     * tutorial's hybrid check, allocating nothing.
     */
    private boolean rectOverlaps(float x, float y, float w, float h) {
        double right = (double) x + w;
        double bottom = (double) y + h;
        if (reachesOutside(x, right, y, bottom)) {
            return true;
        }
        int c0 = clampCol(colAt(x));
        int c1 = clampCol(colAt(Math.nextUp((float) right)));
        int r0 = clampRow(rowAt(y));
        int r1 = clampRow(rowAt(Math.nextUp((float) bottom)));
        for (int row = r0; row <= r1; row++) {
            float cy = cellY(row);
            float ch = cellY(row + 1) - cy;
            for (int col = c0; col <= c1; col++) {
                if (isSolidTerrain(cells[row * cols + col])) {
                    float cx = cellX(col);
                    if (Collide.rectRect(x, y, w, h, cx, cy, cellX(col + 1) - cx, ch)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /**
     * A circle against the solid cells under its bounds, each by {@link Collide#circleRect},
     * allocating nothing.
     */
    private boolean circleOverlaps(float cx, float cy, float r) {
        double left = (double) cx - r;
        double right = (double) cx + r;
        double top = (double) cy - r;
        double bottom = (double) cy + r;
        if (reachesOutside(left, right, top, bottom)) {
            return true;
        }
        int c0 = clampCol(colAt(Math.nextDown((float) left)));
        int c1 = clampCol(colAt(Math.nextUp((float) right)));
        int r0 = clampRow(rowAt(Math.nextDown((float) top)));
        int r1 = clampRow(rowAt(Math.nextUp((float) bottom)));
        for (int row = r0; row <= r1; row++) {
            float y = cellY(row);
            float h = cellY(row + 1) - y;
            for (int col = c0; col <= c1; col++) {
                if (isSolidTerrain(cells[row * cols + col])) {
                    float x = cellX(col);
                    if (Collide.circleRect(cx, cy, r, x, y, cellX(col + 1) - x, h)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /**
     * Does a shape in pixels overlap a solid cell? The tutorial's hybrid check: only the cells
     * under the shape's bounds are visited, and each solid one is tested as
     * {@link Shape#overlaps} tests the shape against the cell's rectangle ({@link #cellRect}),
     * so touching a solid cell's edge does not count: a player standing exactly on a floor of
     * solid cells, or right against a wall, is not overlapping it. Reaching past the grid's
     * edges counts as overlapping solid. A circle or a rectangle allocates nothing.
     *
     * @param shape the shape, not null
     * @return true if the shape overlaps a solid cell or the outside of the grid
     * @throws IllegalArgumentException if {@code shape} is null
     */
    public boolean overlapsSolid(Shape shape) {
        return switch (ShapeKind.of(Check.notNull("shape", shape))) {
            case CIRCLE -> {
                Circle c = (Circle) shape;
                yield circleOverlaps(c.x(), c.y(), c.r());
            }
            case RECT -> {
                Rect r = (Rect) shape;
                yield rectOverlaps(r.x(), r.y(), r.w(), r.h());
            }
            case ELLIPSE, CAPSULE, SEGMENT, POLYGON -> cellsOverlap(shape);
        };
    }

    /** Any shape, by {@link Shape#overlaps} against each solid cell under its bounds. */
    private boolean cellsOverlap(Shape shape) {
        // The shape reaches as far as its bounds, so the outside test is theirs.
        Rect b = shape.bounds();
        if (reachesOutside(b.x(), (double) b.x() + b.w(), b.y(), (double) b.y() + b.h())) {
            return true;
        }
        int c0 = clampCol(colAt(b.x()));
        int c1 = clampCol(colAt(Math.nextUp(b.right())));
        int r0 = clampRow(rowAt(b.y()));
        int r1 = clampRow(rowAt(Math.nextUp(b.bottom())));
        for (int row = r0; row <= r1; row++) {
            for (int col = c0; col <= c1; col++) {
                if (isSolidTerrain(cells[row * cols + col]) && shape.overlaps(cellRect(col, row))) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Does a shape spanning [left, right] x [top, bottom] reach past the grid's edges? */
    private boolean reachesOutside(double left, double right, double top, double bottom) {
        return left < 0 || right > width() || top < 0 || bottom > height();
    }

    private int clampCol(int col) {
        return Math.max(0, Math.min(cols - 1, col));
    }

    private int clampRow(int row) {
        return Math.max(0, Math.min(rows - 1, row));
    }

    // ---- sight, routes, pixel moves and picture maps (the work is in GridSight, GridPaths,
    // ---- GridMove and GridImages; these only hand it over) ---------------------------

    /**
     * Can one point see another: does the segment between them reach into no solid cell? A
     * guard sees the player when {@code grid.lineOfSight(guardX, guardY, playerX, playerY)}.
     *
     * <p>Exactly {@link Collide#lineRect} against the rectangle of every solid cell, so the
     * <a href="package-summary.html#touching">touching rule</a> holds: a line that grazes a
     * solid cell's corner, or runs along its edge, is not blocked. Only the cells along the
     * segment are looked at (a grid traversal in the manner of Amanatides and Woo), so a line
     * across a 2000 x 2000 grid costs a few thousand cells, not four million.
     *
     * <p>Outside the grid counts as solid, cell by cell, as {@link #isSolid} says: a segment
     * with an end beyond the grid's edges is blocked, except one lying exactly on a grid line
     * (which reaches into no cell at all). A segment along the grid's border is not blocked.
     *
     * @param x0 the first point's x, in pixels
     * @param y0 the first point's y
     * @param x1 the second point's x
     * @param y1 the second point's y
     * @return true if no solid cell is in the way; false for a NaN or infinite coordinate
     *         (the package's NaN rule: no result, so no sight; never throws)
     */
    public boolean lineOfSight(float x0, float y0, float x1, float y1) {
        return GridSight.lineOfSight(this, x0, y0, x1, y1);
    }

    /**
     * A shortest route for a player that moves cell by cell: straight steps (up, down, left,
     * right) that {@link #canMove} allows, from one cell to another. Breadth-first search,
     * visiting each cell at most once; on a 1000 x 1000 grid it takes milliseconds.
     *
     * <p>The route is the cells in order as indices {@code row * cols() + col} (so a cell's
     * column is {@code index % cols()} and its row {@code index / cols()}), the start first
     * and the goal last; a start that is the goal gives that one cell. When several routes are
     * equally short, which one comes back is not specified.
     *
     * @param fromCol the start's column, from 0 to {@code cols() - 1}
     * @param fromRow the start's row, from 0 to {@code rows() - 1}
     * @param toCol   the goal's column, from 0 to {@code cols() - 1}
     * @param toRow   the goal's row, from 0 to {@code rows() - 1}
     * @return the route, or an empty array if there is none (the goal is walled off, or the
     *         start or the goal is solid), never null
     * @throws IndexOutOfBoundsException if a cell is not in the grid, as for {@link #get};
     *                                   the message names the parameter
     */
    public int[] path(int fromCol, int fromRow, int toCol, int toRow) {
        return GridPaths.path(this, fromCol, fromRow, toCol, toRow);
    }

    /**
     * A cheapest route under a cost per terrain type, with diagonal steps if the costs allow
     * them: A* with a distance estimate that never overestimates, so the route is exactly a
     * cheapest one. See {@link PathCosts} for what a step costs, what is impassable and how
     * diagonals avoid corners; the route is given as in {@link #path(int, int, int, int)}, and
     * {@link PathCosts#costOf} adds it up.
     *
     * @param fromCol the start's column, from 0 to {@code cols() - 1}
     * @param fromRow the start's row, from 0 to {@code rows() - 1}
     * @param toCol   the goal's column, from 0 to {@code cols() - 1}
     * @param toRow   the goal's row, from 0 to {@code rows() - 1}
     * @param costs   what each step costs, not null
     * @return a cheapest route, or an empty array if there is none (or the start or the goal
     *         is solid or impassable), never null
     * @throws IndexOutOfBoundsException if a cell is not in the grid, as for {@link #get};
     *                                   the message names the parameter
     * @throws IllegalArgumentException  if {@code costs} is null, or the search meets a cell
     *                                   whose terrain has no cost (the message names the cell)
     */
    public int[] path(int fromCol, int fromRow, int toCol, int toRow, PathCosts costs) {
        return GridPaths.path(this, fromCol, fromRow, toCol, toRow, costs);
    }

    /**
     * Moves a box in pixels through the grid's solid cells this frame: the tutorial's hybrid
     * approach, obstacles in a grid and the player in pixels, as in the original Super Mario
     * Brothers. The box goes until it hits a solid cell, stops touching it and slides along it,
     * so it never tunnels through a wall and never ends inside one.
     *
     * <p>The result is exactly {@link Sweep#move Sweep.move(mover, vx, vy, cells)} with
     * {@code cells} the rectangles of every solid cell, row by row, the cells beyond the
     * grid's edges included (they are solid, as {@link #isSolid} says); but only the solid
     * cells under the box swept this frame, from where the box starts to where the whole
     * motion would take it, are looked at. As with
     * {@code Sweep.move}, a cell the box already overlaps at the start is ignored for this
     * move, so a box stuck in a wall can walk out of it.
     *
     * @param mover the box, where it starts
     * @param vx    its motion this frame, x part
     * @param vy    its motion this frame, y part
     * @return where the box ends, the velocity to keep, and the sides of the cells it hit, never null
     * @throws IllegalArgumentException if {@code mover} is null, the velocity is NaN or
     *                                  infinite, or the box and its move span more than about
     *                                  four million cells
     */
    public Sweep.Move move(Rect mover, float vx, float vy) {
        return GridMove.move(this, mover, vx, vy);
    }

    /**
     * Reads a map from a picture, so a map can be drawn in any paint program: every
     * {@code pixelsPerCell x pixelsPerCell} block of pixels, from the top-left corner, is one
     * cell, and its colour says the cell's terrain through the key. With a PImage, use
     * {@code hitbox.processing.Maps.fromImage}.
     *
     * <p>A NaN or infinite {@code float} argument throws, naming it
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param pixels        the picture's colours, ARGB, row by row from the top-left (a
     *                      {@code PImage}'s {@code pixels} after {@code loadPixels()})
     * @param width         the picture's width in pixels
     * @param height        the picture's height in pixels
     * @param pixelsPerCell how many pixels across (and down) one cell is drawn, 1 or more
     * @param colors        which colour is which terrain
     * @param cellSize      a cell's width and height in the grid, in pixels, more than 0
     * @return a new grid of {@code width / pixelsPerCell} by {@code height / pixelsPerCell}
     *         cells, never null
     * @throws IllegalArgumentException if an argument is null, the sizes do not fit together
     *                                  (the picture is not a whole number of cells, or
     *                                  {@code pixels} is not {@code width * height} long), or
     *                                  the picture is inconsistent: a pixel that is not opaque
     *                                  or not one of the key's colours (the message names its
     *                                  x and y), or a block of two terrains (the message names
     *                                  the cell and both pixels)
     */
    public static Grid fromPixels(int[] pixels, int width, int height, int pixelsPerCell, TerrainColors colors,
                                  float cellSize) {
        return GridImages.read(pixels, width, height, pixelsPerCell, colors, checkedCellSize(cellSize), cellSize);
    }
}
