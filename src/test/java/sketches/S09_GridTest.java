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

import hitbox.Grid;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/** A seeded 20 x 20 maze with 20% solid cells; the arrows move the player only into free cells. */
class S09_GridTest {

    private static final String[] ARROWS = {"UP", "DOWN", "LEFT", "RIGHT"};
    private static final int[][] STEPS = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void grid_hasEightySolidCellsOfFourHundred_andThePlayerStartsOnAFreeOne() {
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).frames(3).run();
        Grid grid = r.sketch().grid;
        assertEquals(20, grid.cols());
        assertEquals(20, grid.rows());
        assertEquals(80, grid.countSolid(), "20% of 400");
        assertEquals(0, r.sketch().col);
        assertEquals(0, r.sketch().row);
        assertFalse(grid.isSolid(0, 0), "the start cell is kept free");
        // What is drawn is the grid: a solid cell grey, a free one not, the player blue.
        int solidCol = -1, solidRow = -1, freeCol = -1, freeRow = -1;
        for (int c = 0; c < 20; c++) {
            for (int row = 0; row < 20; row++) {
                if (grid.isSolid(c, row)) {
                    solidCol = c;
                    solidRow = row;
                } else if (c + row > 0) {
                    freeCol = c;
                    freeRow = row;
                }
            }
        }
        PImage frame = r.lastFrame();
        assertEquals(Palette.OBSTACLE, frame.get((int) grid.cellCenterX(solidCol), (int) grid.cellCenterY(solidRow)));
        assertEquals(Palette.BACKGROUND, frame.get((int) grid.cellCenterX(freeCol), (int) grid.cellCenterY(freeRow)));
        assertEquals(Palette.PLAYER, frame.get((int) grid.cellCenterX(0), (int) grid.cellCenterY(0)));
    }

    @Test
    void arrows_moveOnlyIntoFreeCells_neverOffTheMap() {
        // 600 random arrow presses, three frames apart.
        Random random = new Random(3);
        Script script = new Script().frames(1805);
        int[] pressed = new int[601];
        for (int i = 1; i <= 600; i++) {
            pressed[i] = random.nextInt(4);
            script.hold(3 * i, ARROWS[pressed[i]], 1);
        }
        List<int[]> at = new ArrayList<>();  // (col, row) after each frame
        at.add(null);
        SketchRun.Result<S09_Grid> r = SketchRun.of(new S09_Grid()).script(script).everyFrame(s -> {
            assertTrue(s.grid.inGrid(s.col, s.row), "on the map: " + s.col + ", " + s.row);
            assertFalse(s.grid.isSolid(s.col, s.row), "never on a solid cell: " + s.col + ", " + s.row);
            at.add(new int[] {s.col, s.row});
        }).run();
        Grid grid = r.sketch().grid;
        int moved = 0;
        int refusedSolid = 0;
        int refusedEdge = 0;
        for (int i = 1; i <= 600; i++) {
            int[] before = at.get(3 * i - 1);
            int[] after = at.get(3 * i + 1);
            int[] step = STEPS[pressed[i]];
            int c = before[0] + step[0];
            int row = before[1] + step[1];
            boolean free = grid.inGrid(c, row) && !grid.isSolid(c, row);
            if (free) {
                assertEquals(c, after[0], "press " + i + " (" + ARROWS[pressed[i]] + ") into a free cell moves");
                assertEquals(row, after[1], "press " + i + " (" + ARROWS[pressed[i]] + ") into a free cell moves");
                moved++;
            } else {
                assertEquals(before[0], after[0], "press " + i + " (" + ARROWS[pressed[i]] + ") into a wall stays");
                assertEquals(before[1], after[1], "press " + i + " (" + ARROWS[pressed[i]] + ") into a wall stays");
                if (grid.inGrid(c, row)) {
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

    @Test
    void r_makesANewMaze_keepingThePlayersCellFree() {
        Script script = new Script().frames(20).hold(2, "RIGHT", 1).hold(4, "RIGHT", 1).key(8, 'r');
        SketchRun.Result<S09_Grid> before = SketchRun.of(new S09_Grid()).frames(6).script(script).run();
        SketchRun.Result<S09_Grid> after = SketchRun.of(new S09_Grid()).script(script).run();
        S09_Grid s = after.sketch();
        assertEquals(2, s.col, "the player stays where it was");
        assertNotEquals(before.sketch().grid.toMap(), s.grid.toMap(), "a different maze");
        assertEquals(80, s.grid.countSolid(), "still 20%");
        assertFalse(s.grid.isSolid(s.col, s.row), "with the player's cell free");
    }

    @Test
    void overlay_writesTheMouseCellAndMarksTheNeighbours() {
        // Player at (0, 0): up and left are the map's edge (solid), right and down free with seed 1.
        Script plain = new Script().frames(5).mouse(1, 254, 172);
        Script maths = new Script().frames(5).mouse(1, 254, 172).key(2, 'd');
        SketchRun.Result<S09_Grid> off = SketchRun.of(new S09_Grid()).script(plain).run();
        SketchRun.Result<S09_Grid> on = SketchRun.of(new S09_Grid()).script(maths).run();
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame()) > 1000, "the overlay changes what is drawn");
        Grid grid = on.sketch().grid;
        // The mouse's cell, (12, 8), is outlined; its left edge is at x 240.
        assertEquals(12, grid.colAt(254));
        assertTrue(SketchPixels.count(on.lastFrame(), 238, 165, 243, 175, Overlay.GUIDE) > 0, "the mouse's cell is outlined");
        assertEquals(0, SketchPixels.count(off.lastFrame(), 238, 165, 243, 175, Overlay.GUIDE), "not without the overlay");
        // The right neighbour of (0, 0) is free: outlined green.
        assertTrue(grid.canMove(0, 0, 1, 0));
        assertTrue(SketchPixels.count(on.lastFrame(), 37, 5, 43, 15, Overlay.MISS) > 0, "the free neighbour (1, 0) is outlined green");
        assertEquals(0, SketchPixels.count(off.lastFrame(), 37, 5, 43, 15, Overlay.MISS), "not without the overlay");
    }


}
