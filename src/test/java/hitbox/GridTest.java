package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.LongRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class GridTest {

    /** A small level, 32 px cells: walls around, a pillar, water (2) and a goal (3). */
    private static final String LEVEL = """
            ######
            #....#
            #.#2.#
            #...3#
            ######
            """;

    private static Grid level() {
        return Grid.parse(LEVEL, 32);
    }

    // ---- construction -----------------------------------------------------------------

    @ParameterizedTest(name = "Grid({0}, {1}, {2}, {3}): {4}")
    @CsvSource(delimiter = '|', value = {
            "0 | 5 | 32 | 32 | cols must be > 0, was 0",
            "5 | -1 | 32 | 32 | rows must be > 0, was -1",
            "5 | 5 | 0 | 32 | cellWidth must be > 0, was 0.0",
            "5 | 5 | 32 | -2 | cellHeight must be > 0, was -2.0",
            "5 | 5 | NaN | 32 | cellWidth must be a finite number, was NaN",
            "5 | 5 | 32 | Infinity | cellHeight must be a finite number, was Infinity",
            "100000 | 100000 | 1 | 1 | a grid of cols x rows = 100000 x 100000 cells is too big: at most 2147483639 cells fit in one grid",
    })
    void constructor_badInput_isNamed(int cols, int rows, float cw, float ch, String message) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> new Grid(cols, rows, cw, ch)).getMessage());
    }

    @Test
    void constructor_squareCells() {
        Grid g = new Grid(20, 15, 32);
        assertEquals(20, g.cols());
        assertEquals(15, g.rows());
        assertEquals(32, g.cellWidth());
        assertEquals(32, g.cellHeight());
        assertEquals(640, g.width());
        assertEquals(480, g.height());
        assertEquals(0, solidCells(g));
        assertEquals("cellSize must be > 0, was 0.0",
                assertThrows(IllegalArgumentException.class, () -> new Grid(2, 2, 0)).getMessage());
    }

    // ---- get, set, solid --------------------------------------------------------------

    @Test
    void getSet_roundTrip() {
        Grid g = new Grid(4, 3, 10, 20);
        assertEquals(Grid.EMPTY, g.get(3, 2));
        g.set(3, 2, Grid.SOLID);
        g.set(0, 0, 7);
        g.set(1, 0, -5);
        assertEquals(Grid.SOLID, g.get(3, 2));
        assertEquals(7, g.get(0, 0));
        assertEquals(-5, g.get(1, 0));
        assertEquals(3, solidCells(g));
    }

    @ParameterizedTest(name = "cell ({0}, {1}) of a 4 x 3 grid")
    @CsvSource({"4, 0", "-1, 0", "0, 3", "0, -1", "2147483647, 0", "-2147483648, -2147483648"})
    void getSet_outside_namesTheCellAndTheGrid(int col, int row) {
        Grid g = new Grid(4, 3, 10);
        String message = "cell (col " + col + ", row " + row + ") is outside the 4 x 3 grid: col goes from 0 to 3"
                + " and row from 0 to 2";
        assertEquals(message, assertThrows(IndexOutOfBoundsException.class, () -> g.get(col, row)).getMessage());
        assertEquals(message, assertThrows(IndexOutOfBoundsException.class, () -> g.set(col, row, 1)).getMessage());
        assertFalse(g.inGrid(col, row));
        assertTrue(g.isSolid(col, row), "outside counts as solid");
    }

    @Test
    void isSolid_terrainTypes() {
        Grid g = level();
        assertTrue(g.isSolid(0, 0));
        assertFalse(g.isSolid(1, 1));
        assertTrue(g.isSolid(3, 2), "any non-zero terrain is solid by default");
        assertTrue(g.isSolid(4, 3));
        assertSame(g, g.passable(3));
        assertFalse(g.isSolid(4, 3), "the goal is passable now");
        assertTrue(g.isSolid(3, 2));
        g.passable(2, 3);
        assertFalse(g.isSolid(3, 2));
        assertFalse(g.isSolid(1, 1), "EMPTY is never solid");
        assertTrue(g.isSolid(0, 0), "SOLID always is");
        g.passable();
        assertTrue(g.isSolid(3, 2) && g.isSolid(4, 3), "no arguments: all non-empty terrain solid again");
    }

    @Test
    void passable_rejectsSolidAndNull() {
        Grid g = level();
        assertTrue(assertThrows(IllegalArgumentException.class, () -> g.passable(2, Grid.SOLID))
                .getMessage().startsWith("SOLID (1) is always solid"));
        assertEquals("terrains must not be null",
                assertThrows(IllegalArgumentException.class, () -> g.passable((int[]) null)).getMessage());
    }

    @Test
    void passable_copiesItsArgument() {
        Grid g = level();
        int[] types = {2};
        g.passable(types);
        types[0] = 3;
        assertFalse(g.isSolid(3, 2));
        assertTrue(g.isSolid(4, 3));
    }

    // ---- moving cell by cell ----------------------------------------------------------

    @ParameterizedTest(name = "from ({0}, {1}) by ({2}, {3}): {4}")
    @CsvSource({
            "1, 1, 1, 0, true",
            "1, 1, -1, 0, false",     // into the outer wall
            "1, 1, 0, -1, false",
            "1, 1, 0, 1, true",
            "1, 2, 1, 0, false",      // into the pillar
            "4, 2, -1, 0, false",     // into water (solid by default)
            "4, 2, 0, 1, false",      // onto the goal (solid by default)
            "1, 1, 1, 1, false",      // diagonal onto the pillar
            "1, 3, 1, -1, false",
            "2, 1, 1, 1, false",      // diagonal into water
            "1, 1, 0, 0, true",       // staying put on a free cell
            "0, 0, -1, 0, false",     // off the map: outside is solid
            "2147483647, 0, 1, 0, false",
            "-2147483648, 0, -1, 0, false",
    })
    void canMove_table(int col, int row, int dCol, int dRow, boolean expected) {
        assertEquals(expected, level().canMove(col, row, dCol, dRow));
    }

    @Test
    void canMove_ontoPassableTerrain() {
        Grid g = level().passable(3);
        assertTrue(g.canMove(4, 2, 0, 1));
        assertFalse(g.canMove(4, 2, -1, 0));
    }

    @Test
    void canMove_offTheEdgeOfAnOpenMap() {
        Grid open = new Grid(3, 3, 10);
        assertTrue(open.canMove(1, 1, 1, 0));
        assertFalse(open.canMove(2, 1, 1, 0));
        assertFalse(open.canMove(0, 0, 0, -1));
    }

    // ---- pixels and cells -------------------------------------------------------------

    @ParameterizedTest(name = "colAt({0}) with {1} px cells = {2}")
    @CsvSource({
            "0, 32, 0",
            "31.99, 32, 0",
            "32, 32, 1",          // on the line: the cell to the right
            "-0.01, 32, -1",
            "-32, 32, -1",
            "-32.01, 32, -2",
            "1000000, 32, 31250",
            "0.3, 0.1, 3",        // 0.1 is not exact in binary: boundaries follow cellRect
            "NaN, 32, -1",
            "Infinity, 32, 2147483647",
            "-Infinity, 32, -2147483648",
            "3e38, 0.001, 2147483647",
    })
    void colAt_rowAt_table(float px, float cell, int expected) {
        Grid g = new Grid(10, 10, cell, cell);
        assertEquals(expected, g.colAt(px));
        assertEquals(expected, g.rowAt(px));
    }

    @Test
    void cellGeometry() {
        Grid g = new Grid(10, 8, 32, 16);
        assertEquals(64, g.cellRect(2, 0).x());
        assertEquals(32, g.cellRect(0, 2).y());
        assertEquals(-32, g.cellRect(-1, 0).x());
        assertEquals(80, g.cellCenterX(2));
        assertEquals(40, g.cellCenterY(2));
        assertEquals(new Rect(64, 32, 32, 16), g.cellRect(2, 2));
        assertEquals(new Rect(-32, -16, 32, 16), g.cellRect(-1, -1));
        assertEquals(320, g.width());
        assertEquals(128, g.height());
    }

    @Property
    void pixelCell_roundTrip(@ForAll @IntRange(min = -10_000, max = 10_000) int col,
                             @ForAll @FloatRange(min = 0.5f, max = 100) float cellWidth) {
        Grid g = new Grid(3, 3, cellWidth, 1);
        assertEquals(col, g.colAt(g.cellRect(col, 0).x()), "a cell's left edge is in the cell");
        assertEquals(col, g.colAt(g.cellCenterX(col)));
        assertEquals(col - 1, g.colAt(Math.nextDown(g.cellRect(col, 0).x())), "just left of it is the previous cell");
        Rect cell = g.cellRect(col, 0);
        assertEquals(g.cellRect(col + 1, 0).x(), cell.x() + cell.w(), "cells tile without gaps");
    }

    @Property
    void colAt_spansThePixel(@ForAll @FloatRange(min = -1e5f, max = 1e5f) float px,
                             @ForAll @FloatRange(min = 0.5f, max = 100) float cellWidth) {
        Grid g = new Grid(3, 3, cellWidth, cellWidth);
        int col = g.colAt(px);
        assertTrue(g.cellRect(col, 0).x() <= px && px < g.cellRect(col + 1, 0).x(), () -> px + " not in column " + col);
        assertEquals(col, g.rowAt(px));
    }

    // ---- the hybrid check -------------------------------------------------------------

    @ParameterizedTest(name = "rect ({0}, {1}, {2}, {3}): {4}")
    @CsvSource({
            "40, 40, 20, 20, false",     // inside the free cell (1, 1)
            "32, 32, 32, 32, false",     // exactly the free cell, touching walls all round
            "31, 40, 10, 10, true",      // 1 px into the left wall
            "32, 40, 32, 10, false",
            "33, 40, 32, 10, false",     // in cells 1 and 2 of row 1, both free
            "60, 60, 10, 10, true",      // into the pillar at (2, 2)
            "64, 63, 32, 1, false",      // along the top of the pillar, touching it
            "64, 63, 32, 1.5, true",
            "40, 40, 0, 0, false",       // a point in a free cell
            "64, 70, 0, 0, false",       // a point on the pillar's left edge
            "65, 70, 0, 0, true",        // a point just inside it
            "-1, 40, 10, 10, true",      // past the grid's left edge
            "0, 0, 192, 160, true",      // the whole map
            "1000000, 1000000, 10, 10, true",
    })
    void rectOverlapsSolid_table(float x, float y, float w, float h, boolean expected) {
        Grid g = level();
        assertEquals(expected, g.overlapsSolid(new Rect(x, y, w, h)));
    }

    @Test
    void rectOverlapsSolid_touchingTheOutsideIsNotHittingIt() {
        Grid open = new Grid(4, 4, 10);
        assertFalse(open.overlapsSolid(new Rect(0, 0, 40, 40)));
        assertTrue(open.overlapsSolid(new Rect(0, 0, 40.5f, 40)));
        assertFalse(open.overlapsSolid(new Rect(40, 20, 0, 0)), "a point on the right edge");
        assertTrue(open.overlapsSolid(new Rect(40.5f, 20, 0, 0)));
    }

    @ParameterizedTest(name = "circle ({0}, {1}) r={2}: {3}")
    @CsvSource({
            "48, 48, 16, false",        // fills the free cell (1, 1), touching its walls
            "48, 48, 16.5, true",
            "80, 48, 16, false",        // free cell (2, 1); the pillar below only touches
            "80, 48, 16.01, true",
            "56, 56, 11.3, false",      // near the pillar's corner (64, 64): distance 11.31
            "56, 56, 11.4, true",
            "48, 48, 0, false",
            "-5, 48, 4, true",          // outside the grid
    })
    void circleOverlapsSolid_table(float cx, float cy, float r, boolean expected) {
        Grid g = level();
        assertEquals(expected, g.overlapsSolid(new Circle(cx, cy, r)));
    }

    @Test
    void overlapsSolid_otherShapes_outsideAndOverEmptyCells() {
        Grid open = new Grid(4, 4, 10);
        assertTrue(open.overlapsSolid(new Segment(5, 5, 45, 5)), "reaches past the right edge");
        assertFalse(open.overlapsSolid(new Segment(5, 5, 35, 35)), "only empty cells under it");
        assertEquals("shape must not be null",
                assertThrows(IllegalArgumentException.class, () -> open.overlapsSolid(null)).getMessage());
    }

    /** How many cells of the grid are solid, cell by cell by {@link Grid#isSolid}. */
    static int solidCells(Grid g) {
        int n = 0;
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                n += g.isSolid(col, row) ? 1 : 0;
            }
        }
        return n;
    }

    /** The slow reference: every cell of the grid, and the outside as a wall. */
    private static boolean slowRect(Grid g, float x, float y, float w, float h) {
        if (x < 0 || (double) x + w > g.width() || y < 0 || (double) y + h > g.height()) {
            return true;
        }
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                Rect c = g.cellRect(col, row);
                if (g.isSolid(col, row) && Collide.rectRect(x, y, w, h, c.x(), c.y(), c.w(), c.h())) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean slowCircle(Grid g, float cx, float cy, float r) {
        if ((double) cx - r < 0 || (double) cx + r > g.width() || (double) cy - r < 0 || (double) cy + r > g.height()) {
            return true;
        }
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                Rect c = g.cellRect(col, row);
                if (g.isSolid(col, row) && Collide.circleRect(cx, cy, r, c.x(), c.y(), c.w(), c.h())) {
                    return true;
                }
            }
        }
        return false;
    }

    @Property
    void rectOverlapsSolid_agreesWithEveryCell(@ForAll @LongRange(min = 0, max = 20) long seed,
                                               @ForAll @FloatRange(min = -10, max = 130) float x,
                                               @ForAll @FloatRange(min = -10, max = 110) float y,
                                               @ForAll @FloatRange(min = 0, max = 40) float w,
                                               @ForAll @FloatRange(min = 0, max = 40) float h,
                                               @ForAll boolean wholeNumbers) {
        Grid g = new Grid(12, 10, 10, 10).fillRandom(0.25f, seed, 0, 0);
        if (wholeNumbers) {
            // Whole numbers land on cell edges, where the touching rule decides.
            x = Math.round(x);
            y = Math.round(y);
            w = Math.round(w);
            h = Math.round(h);
        }
        assertEquals(slowRect(g, x, y, w, h), g.overlapsSolid(new Rect(x, y, w, h)));
    }

    @Property
    void circleOverlapsSolid_agreesWithEveryCell(@ForAll @LongRange(min = 0, max = 20) long seed,
                                                 @ForAll @FloatRange(min = -10, max = 130) float cx,
                                                 @ForAll @FloatRange(min = -10, max = 110) float cy,
                                                 @ForAll @IntRange(min = 0, max = 25) int r,
                                                 @ForAll boolean wholeNumbers) {
        Grid g = new Grid(12, 10, 10, 10).fillRandom(0.25f, seed, 0, 0);
        if (wholeNumbers) {
            cx = Math.round(cx);
            cy = Math.round(cy);
        }
        assertEquals(slowCircle(g, cx, cy, r), g.overlapsSolid(new Circle(cx, cy, r)));
    }

    @Property
    void rectOverlapsSolid_oddCellSizes_agreesWithEveryCell(@ForAll @FloatRange(min = 0.1f, max = 7) float cell,
                                                            @ForAll @FloatRange(min = 0, max = 60) float x,
                                                            @ForAll @FloatRange(min = 0, max = 60) float y,
                                                            @ForAll @FloatRange(min = 0, max = 9) float w) {
        Grid g = new Grid(9, 9, cell, cell * 1.5f).fillRandom(0.3f, 7, 0, 0);
        assertEquals(slowRect(g, x, y, w, w), g.overlapsSolid(new Rect(x, y, w, w)));
        // On a cell's own edges: touching its solid neighbours only.
        int col = Math.min(g.colAt(x), 8), row = Math.min(g.rowAt(y), 8);
        Rect c = g.cellRect(col, row);
        assertEquals(slowRect(g, c.x(), c.y(), c.w(), c.h()), g.overlapsSolid(new Rect(c.x(), c.y(), c.w(), c.h())));
    }

    // ---- counting and filling ---------------------------------------------------------

    @Test
    void isSolid_countsPassableTerrainOut() {
        Grid g = level();
        assertEquals(21, solidCells(g), "18 wall cells, the pillar, the water and the goal");
        assertEquals(19, solidCells(g.passable(2, 3)));
    }

    @Test
    void fill_setsEveryCell() {
        Grid g = new Grid(3, 2, 10).fill(Grid.SOLID);
        assertEquals(6, solidCells(g));
        assertEquals("###\n###", g.toMap());
        g.fill(Grid.EMPTY);
        assertEquals(0, solidCells(g));
    }

    @Test
    void fillRandom_theTutorialsGrid() {
        Grid g = new Grid(20, 20, 20).fillRandom(0.2f, 1234, 0, 0);
        assertEquals(80, solidCells(g));
        assertEquals(Grid.EMPTY, g.get(0, 0));
    }

    @Test
    void fillRandom_isPinnedForASeed() {
        // Reproducible across runs and Java versions: java.util.Random is specified exactly.
        // The map was worked out apart from the library, by java.util.Random's formulas and
        // the partial shuffle of every cell but the free one (the last index swapped in for it).
        assertEquals(PINNED, new Grid(8, 4, 10).fillRandom(0.25f, 42, 0, 0).toMap());
    }

    private static final String PINNED = """
            ..#.#.#.
            ...#.#..
            .....##.
            ...#....""";

    @Test
    void fillRandom_extremes() {
        assertEquals(0, solidCells(new Grid(5, 5, 1).fill(Grid.SOLID).fillRandom(0, 9, 0, 0)));
        Grid g = new Grid(5, 5, 1).fillRandom(1, 9, 4, 2);
        assertEquals(24, solidCells(g), "every cell but the free one");
        assertFalse(g.isSolid(4, 2));
        assertEquals(0, solidCells(new Grid(1, 1, 1).fillRandom(1, 3, 0, 0)));
    }

    @ParameterizedTest(name = "fraction {0}")
    @CsvSource({"-0.1", "1.01", "NaN", "Infinity"})
    void fillRandom_badFraction(float fraction) {
        assertEquals("fraction must be between 0 and 1, was " + fraction + " (for 20% solid cells write 0.2)",
                assertThrows(IllegalArgumentException.class, () -> new Grid(3, 3, 1).fillRandom(fraction, 1, 0, 0)).getMessage());
    }

    @Test
    void fillRandom_freeCellOutside() {
        assertTrue(assertThrows(IndexOutOfBoundsException.class, () -> new Grid(3, 3, 1).fillRandom(0.5f, 1, 3, 0))
                .getMessage().startsWith("cell (col 3, row 0) is outside the 3 x 3 grid"));
    }

    @Property
    void fillRandom_reproducibleAndExact(@ForAll @IntRange(min = 1, max = 40) int cols,
                                         @ForAll @IntRange(min = 1, max = 40) int rows,
                                         @ForAll @FloatRange(min = 0, max = 1) float fraction,
                                         @ForAll long seed) {
        Grid a = new Grid(cols, rows, 8).fillRandom(fraction, seed, 0, 0);
        Grid b = new Grid(cols, rows, 8).fill(5).fillRandom(fraction, seed, 0, 0);
        assertEquals(a.toMap(), b.toMap(), "same seed, same grid, whatever was there before");
        assertEquals(Math.min(Math.round((double) fraction * cols * rows), cols * rows - 1), solidCells(a));
    }

    @Property
    void fillRandom_keepsTheFreeCellFree(@ForAll @IntRange(min = 1, max = 30) int cols,
                                         @ForAll @IntRange(min = 1, max = 30) int rows,
                                         @ForAll @FloatRange(min = 0, max = 1) float fraction,
                                         @ForAll long seed) {
        int freeCol = (int) Math.floorMod(seed, (long) cols);
        int freeRow = (int) Math.floorMod(seed >> 20, (long) rows);
        Grid g = new Grid(cols, rows, 8).fillRandom(fraction, seed, freeCol, freeRow);
        assertFalse(g.isSolid(freeCol, freeRow));
        assertEquals(Math.min(Math.round((double) fraction * cols * rows), cols * rows - 1), solidCells(g));
    }

    @Test
    void fillRandom_differentSeedsDiffer() {
        assertNotEquals(new Grid(20, 20, 1).fillRandom(0.5f, 1, 0, 0).toMap(), new Grid(20, 20, 1).fillRandom(0.5f, 2, 0, 0).toMap());
    }

    @Test
    void fillRandom_spreadsOverTheGrid() {
        // Not clumped in one corner: each quarter of a 40 x 40 grid gets close to its share.
        Grid g = new Grid(40, 40, 1).fillRandom(0.2f, 77, 0, 0);
        for (int q = 0; q < 4; q++) {
            int count = 0;
            for (int row = (q / 2) * 20; row < (q / 2) * 20 + 20; row++) {
                for (int col = (q % 2) * 20; col < (q % 2) * 20 + 20; col++) {
                    count += g.isSolid(col, row) ? 1 : 0;
                }
            }
            assertTrue(count > 50 && count < 110, "quarter " + q + " has " + count + " of 400");
        }
    }

    // ---- parsing ----------------------------------------------------------------------

    @Test
    void parse_textBlock() {
        Grid g = level();
        assertEquals(6, g.cols());
        assertEquals(5, g.rows());
        assertEquals(32, g.cellWidth());
        assertEquals(Grid.SOLID, g.get(0, 0));
        assertEquals(Grid.EMPTY, g.get(1, 1));
        assertEquals(Grid.SOLID, g.get(2, 2));
        assertEquals(2, g.get(3, 2));
        assertEquals(3, g.get(4, 3));
        assertEquals(LEVEL.strip(), g.toMap());
    }

    @ParameterizedTest(name = "parse({0})")
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
            "#.#\\n. #\\n012 | #.#\\n..#\\n.#2",
            "\\n\\n##\\n..\\n\\n | ##\\n..",                 // blank lines before and after
            "#.\\r\\n.#\\r\\n | #.\\n.#",                    // Windows line ends
            "#.\\r.# | #.\\n.#",                             // old Mac line ends
            "\"   \" | ...",                                // a row of spaces
            "9 | 9",
    })
    void parse_formats(String escaped, String expected) {
        Grid g = Grid.parse(unescape(escaped));
        assertEquals(unescape(expected), g.toMap());
        assertEquals(1, g.cellWidth(), "parse(map) uses 1 px cells");
    }

    private static String unescape(String s) {
        return s.replace("\\n", "\n").replace("\\r", "\r").replace("\\t", "\t");
    }

    @ParameterizedTest(name = "parse({0}) fails")
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
            "###\\n##\\n### | map line 2 has 2 cells, but line 1 has 3: every row needs the same width",
            "\\n###\\n\\n### | map line 3 has 0 cells, but line 2 has 3: every row needs the same width",
            "#.#\\n#x# | map line 2, column 2: unknown character 'x'; use '#' for solid",
            "#\\t# | map line 1, column 2: unknown character (code 9, a tab or other invisible character)",
            "\"\" | map has no rows",
            "\\n\\n | map has no rows",
    })
    void parse_errors_nameLineAndColumn(String escaped, String messageStart) {
        String message = assertThrows(IllegalArgumentException.class, () -> Grid.parse(unescape(escaped))).getMessage();
        assertTrue(message.startsWith(messageStart), message);
    }

    @Test
    void parse_badArguments() {
        assertEquals("map must not be null",
                assertThrows(IllegalArgumentException.class, () -> Grid.parse(null)).getMessage());
        assertEquals("cellSize must be > 0, was -1.0",
                assertThrows(IllegalArgumentException.class, () -> Grid.parse("#", -1)).getMessage());
    }

    @Property
    void parse_toMap_roundTrip(@ForAll @IntRange(min = 1, max = 12) int cols,
                               @ForAll @IntRange(min = 1, max = 12) int rows,
                               @ForAll long seed) {
        Grid g = new Grid(cols, rows, 4);
        java.util.Random random = new java.util.Random(seed);
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                g.set(col, row, random.nextInt(10));
            }
        }
        Grid back = Grid.parse(g.toMap(), 4);
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                assertEquals(g.get(col, row), back.get(col, row));
            }
        }
        assertEquals(g.toString(), back.toString());
    }

    @Test
    void toMap_unknownTerrainsShowAsQuestionMarks() {
        Grid g = new Grid(3, 1, 1);
        g.set(0, 0, 10);
        g.set(1, 0, -1);
        assertEquals("??.", g.toMap());
        assertEquals("Grid 3 x 1, cells 1.0 x 1.0 px\n??.", g.toString());
    }
}
