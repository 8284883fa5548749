package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import hitbox.Grid;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * A 20 x 20 maze of 20 px cells, as the tutorial's boolean[][] (t) or Hitbox's Grid (the
 * default, exactly 20% solid and the player's cell kept free); the arrows move the player only
 * into free cells.
 */
class S09_GridTest {

    private static final String[] ARROWS = {"UP", "DOWN", "LEFT", "RIGHT"};
    private static final int[][] STEPS = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** Is this cell solid in the grid the sketch shows, read from its own data. */
    private static boolean solid(S09_Grid s, int column, int row) {
        if (s.hitboxDecides) {
            assertEquals(s.maze.isSolid(column, row), s.grid[row][column], "Hitbox's Grid is copied into grid");
        }
        return s.grid[row][column];
    }

    @Test
    void hitboxGrid_hasEightySolidCellsOfFourHundred_andThePlayerStartsOnAFreeOne() {
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).script(new Script().frames(3).key(1, 'l')).run();
        S09_Grid s = r.sketch();
        Grid maze = s.maze;
        assertTrue(s.hitboxDecides);
        assertEquals(20, maze.cols());
        assertEquals(20, maze.rows());
        assertEquals(80, solidCells(maze), "20% of 400");
        assertEquals(10, s.playerIndexX);
        assertEquals(10, s.playerIndexY);
        assertFalse(maze.isSolid(10, 10), "the start cell is kept free");
        assertDrawnAsTheGrid(r.lastFrame(), s);
    }

    @Test
    void byDefault_theTutorialsFill_aTwentyPercentChancePerCell_rowByRow_andItsStartAt10_10() {
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).frames(4).run();
        S09_Grid s = r.sketch();
        assertFalse(s.hitboxDecides);
        assertEquals(10, s.playerIndexX, "the tutorial's start");
        assertEquals(10, s.playerIndexY);
        assertEquals(20f, s.cellWidth);
        assertEquals(20f, s.cellHeight);
        // randomSeed(1), then random(1) < 0.2 for each cell, rows outside, columns inside.
        Random random = new Random(1);
        int count = 0;
        for (int row = 0; row < 20; row++) {
            for (int column = 0; column < 20; column++) {
                boolean expected = random.nextFloat() < 0.2f;
                assertEquals(expected, s.grid[row][column], "grid[" + row + "][" + column + "]");
                count += expected ? 1 : 0;
            }
        }
        assertNotEquals(80, count, "a coin flip per cell: not exactly 20% (" + count + ")");
        assertDrawnAsTheGrid(r.lastFrame(), s);
    }

    /** A solid cell grey, a free one background, the player blue: what is drawn is the grid. */
    private static void assertDrawnAsTheGrid(PImage frame, S09_Grid s) {
        int checkedSolid = 0;
        int checkedFree = 0;
        for (int column = 0; column < 20; column++) {
            for (int row = 0; row < 20; row++) {
                if (column == s.playerIndexX && row == s.playerIndexY) {
                    continue;
                }
                int colour = solid(s, column, row) ? Palette.OBSTACLE : Palette.BACKGROUND;
                SketchPixels.assertColour(frame, column * 20 + 10, row * 20 + 10, colour, "cell (" + column + ", " + row + ")");
                checkedSolid += solid(s, column, row) ? 1 : 0;
                checkedFree += solid(s, column, row) ? 0 : 1;
            }
        }
        assertTrue(checkedSolid > 50 && checkedFree > 250);
        SketchPixels.assertColour(frame, s.playerIndexX * 20 + 10, s.playerIndexY * 20 + 10, Palette.PLAYER, "the player");
    }

    @ParameterizedTest(name = "the tutorial''s ifs: {0}")
    @ValueSource(booleans = {true, false})
    void arrows_moveOnlyIntoFreeCells_neverOffTheMap(boolean tutorial) {
        // 600 random arrow presses, three frames apart; l hands the moves to Hitbox's Grid.
        Random random = new Random(3);
        Script script = new Script().frames(1805);
        if (!tutorial) {
            script.key(1, 'l');
        }
        int[] pressed = new int[601];
        for (int i = 1; i <= 600; i++) {
            pressed[i] = random.nextInt(4);
            script.hold(3 * i, ARROWS[pressed[i]], 1);
        }
        List<int[]> at = new ArrayList<>();  // (column, row) after each frame
        at.add(null);
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).script(script).everyFrame(s -> {
            assertTrue(s.playerIndexX >= 0 && s.playerIndexX < 20 && s.playerIndexY >= 0 && s.playerIndexY < 20,
                    "on the map: " + s.playerIndexX + ", " + s.playerIndexY);
            assertFalse(solid(s, s.playerIndexX, s.playerIndexY), "never on a solid cell: " + s.playerIndexX + ", " + s.playerIndexY);
            at.add(new int[] {s.playerIndexX, s.playerIndexY});
        }).run();
        S09_Grid s = r.sketch();
        assertEquals(!tutorial, s.hitboxDecides);
        int moved = 0;
        int refusedSolid = 0;
        int refusedEdge = 0;
        for (int i = 1; i <= 600; i++) {
            int[] before = at.get(3 * i - 1);
            int[] after = at.get(3 * i + 1);
            int[] step = STEPS[pressed[i]];
            int c = before[0] + step[0];
            int row = before[1] + step[1];
            boolean inGrid = c >= 0 && c < 20 && row >= 0 && row < 20;
            boolean free = inGrid && !solid(s, c, row);
            String press = "press " + i + " (" + ARROWS[pressed[i]] + ")";
            if (free) {
                assertEquals(c, after[0], press + " into a free cell moves");
                assertEquals(row, after[1], press + " into a free cell moves");
                moved++;
            } else {
                assertEquals(before[0], after[0], press + " into a wall stays");
                assertEquals(before[1], after[1], press + " into a wall stays");
                if (inGrid) {
                    refusedSolid++;
                } else {
                    refusedEdge++;
                }
            }
        }
        assertTrue(moved > 100, "it walked: " + moved + " steps");
        assertTrue(refusedSolid > 10, "solid cells stopped it: " + refusedSolid);
        assertTrue(refusedEdge > 0, "the map's edge stopped it: " + refusedEdge);
    }

    /** r four times: seed 5, whose coin flip for the player's cell (10, 10) comes up "obstacle". */
    private static Script newMazes(boolean tutorial) {
        Script script = new Script().frames(14).key(2, 'r').key(4, 'r').key(6, 'r').key(8, 'r');
        return tutorial ? script : script.key(1, 'l');
    }

    @Test
    void r_hitboxGrid_makesANewMaze_keepingThePlayersCellFree() {
        SketchRun.Result<S09_Grid> before = SketchRun.of(new S09_Grid()).script(newMazes(false)).frames(5).run();
        SketchRun.Result<S09_Grid> after = SketchRun.of(new S09_Grid()).script(newMazes(false)).run();
        S09_Grid s = after.sketch();
        assertEquals(5, s.seed);
        assertEquals(10, s.playerIndexY, "the player stays where it was");
        assertNotEquals(before.sketch().maze.toMap(), s.maze.toMap(), "a different maze");
        assertEquals(80, solidCells(s.maze), "still 20%");
        assertFalse(s.maze.isSolid(10, 10), "with the player's cell free");
        assertFalse(s.grid[10][10], "and so is the array drawn");
        assertEquals(0, SketchPixels.count(after.lastFrame(), 200, 200, 219, 219, Palette.HIT), "no red ring");
    }

    @Test
    void r_tutorialGrid_canDropAnObstacleOnThePlayer_andSaysSo() {
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).script(newMazes(true)).run();
        S09_Grid s = r.sketch();
        assertEquals(5, s.seed);
        assertEquals(10, s.playerIndexX);
        assertEquals(10, s.playerIndexY);
        assertTrue(s.grid[10][10], "the tutorial's fill does not keep the player's cell free");
        // The player is ringed red on its cell, (200, 200) to (220, 220).
        assertTrue(SketchPixels.count(r.lastFrame(), 200, 200, 219, 219, Palette.HIT) > 40, "a red ring round the player");
    }

    @Test
    void overlay_writesTheMouseCellAndMarksTheNeighbours_andPressingAgainHidesIt() {
        // Player at (10, 10): its right neighbour (11, 10) is free with seed 1.
        Script script = new Script().frames(8).mouse(1, 254, 172).key(2, 'd').key(5, 'd');
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).script(script).capture(2).capture(4).run();
        PImage off = r.frame(2);
        PImage on = r.frame(4);
        assertTrue(SketchPixels.differing(off, on) > 1000, "the overlay changes what is drawn");
        // The mouse's cell, (12, 8), is outlined; its left edge is at x 240.
        assertTrue(SketchPixels.count(on, 238, 165, 243, 175, Overlay.GUIDE) > 0, "the mouse's cell is outlined");
        assertEquals(0, SketchPixels.count(off, 238, 165, 243, 175, Overlay.GUIDE), "not without the overlay");
        // The right neighbour of (10, 10) is free: outlined green (its right side at x 240).
        assertFalse(r.sketch().grid[10][11]);
        assertTrue(SketchPixels.count(on, 237, 205, 243, 215, Overlay.MISS) > 0, "the free neighbour (11, 10) is outlined green");
        assertEquals(0, SketchPixels.count(off, 237, 205, 243, 215, Overlay.MISS), "not without the overlay");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "d again hides it");
    }

    /** How many of the grid's cells are solid, cell by cell. */
    private static int solidCells(Grid g) {
        int n = 0;
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                n += g.isSolid(col, row) ? 1 : 0;
            }
        }
        return n;
    }
}
