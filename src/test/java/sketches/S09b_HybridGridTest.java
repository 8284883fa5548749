package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Grid;
import hitbox.Rect;
import hitbox.Side;
import hitbox.Sweep;
import hitbox.processing.Overlay;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import hitbox.internal.GridMove;

/**
 * A pixel player on a tile map. By default, the section's hybrid written out: the pixel turned
 * into a cell by floor(x / cellWidth), the cells at the next position looked up, and a snap to
 * the cell's edge; it lands, jumps, stops at walls and keeps out of the tiles, but steps over
 * a thin platform when it falls fast. With l, Grid.move every frame, which never tunnels.
 */
class S09b_HybridGridTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void falling_landsOnATileTop_andStays() {
        List<Float> ys = new ArrayList<>();
        List<Boolean> ground = new ArrayList<>();
        S09b_HybridGrid s = SketchRun.of(new S09b_HybridGrid()).frames(90).everyFrame(k -> {
            ys.add(k.player.y());
            ground.add(k.onGround);
        }).run().sketch();
        assertFalse(ground.get(0), "it starts in the air");
        assertTrue(s.onGround, "it has landed");
        float bottom = s.player.bottom();
        assertEquals(bottom, s.grid.cellRect(0, s.grid.rowAt(bottom)).y(), "standing exactly on a row line: " + bottom);
        assertTrue(s.grid.isSolid(s.grid.colAt(s.player.x()), s.grid.rowAt(bottom))
                || s.grid.isSolid(s.grid.colAt(s.player.right() - 0.01f), s.grid.rowAt(bottom)), "on a solid tile");
        assertEquals(0f, s.vy, "and stopped falling");
        int landed = ground.indexOf(true);
        for (int f = landed; f < 90; f++) {
            assertTrue(ground.get(f), "once down it stays down, frame " + (f + 1));
            assertEquals(ys.get(landed), ys.get(f), "without sinking, frame " + (f + 1));
        }
    }

    @Test
    void lKey_longRunWithJumps_neverEndsAFrameInsideATile_andEveryStepIsGridMove() {
        Random random = new Random(5);
        Script script = new Script().frames(6000).key(1, 'l');
        for (int f = 2; f < 5900; ) {
            int length = 5 + random.nextInt(70);
            script.hold(f, random.nextBoolean() ? "LEFT" : "RIGHT", length);
            if (random.nextInt(3) > 0) {
                script.hold(f + random.nextInt(length), random.nextBoolean() ? "UP" : "SPACE", 1);
            }
            f += length + 1 + random.nextInt(8);
        }
        Set<Integer> rowsStoodOn = new HashSet<>();
        int[] walls = new int[1];
        int[] heads = new int[1];
        Rect[] previous = new Rect[1];
        SketchRun.of(new S09b_HybridGrid()).script(script).everyFrame(s -> {
            Grid g = s.grid;
            Rect p = s.player;
            if (s.frameCount < 2) {
                previous[0] = p;
                return;   // frame 1 ran the default, before l
            }
            assertTrue(s.hitboxDecides);
            assertFalse(g.overlapsSolid(new Rect(p.x(), p.y(), p.w(), p.h())), "frame " + s.frameCount + ": inside a tile at " + p);
            // The frame's move is exactly Grid.move from where the player was.
            Sweep.Move expected = g.move(s.before, s.movedX, s.movedY);
            assertEquals(expected, s.last, "frame " + s.frameCount);
            int checked = GridMove.obstacles(g, s.before, s.movedX, s.movedY).size();
            assertTrue(checked <= 9, "a move of a few pixels checks a few tiles: " + checked);
            if (previous[0] != null) {
                assertEquals(previous[0], s.before, "each move starts where the last one ended");
            }
            previous[0] = p;
            if (s.onGround) {
                rowsStoodOn.add(g.rowAt(p.bottom()));
            }
            walls[0] += (s.last.hit(Side.LEFT) || s.last.hit(Side.RIGHT)) ? 1 : 0;
            heads[0] += s.last.hit(Side.BOTTOM) ? 1 : 0;
        }).run();
        assertTrue(rowsStoodOn.size() >= 2, "stood on the floor and at least one platform: rows " + rowsStoodOn);
        assertTrue(walls[0] > 0, "ran into a wall");
        assertTrue(heads[0] > 0, "bumped its head");
    }

    @Test
    void gridMove_fastFall_neverTunnels() {
        // A fall of up to 60 px a frame, more than two tiles: still lands on the first floor below.
        S09b_HybridGrid s = new S09b_HybridGrid();
        s.hitboxDecides = true;
        s.maxFall = 60;
        s.gravity = 6;
        s.player = new Rect(400, 0, 18, 28);
        SketchRun.of(s).frames(40).everyFrame(k -> assertFalse(
                k.grid.overlapsSolid(new Rect(k.player.x(), k.player.y(), k.player.w(), k.player.h())), "inside a tile")).run();
        assertTrue(s.onGround);
        assertEquals(8 * 24f, s.player.bottom(), "on the first tiles below x 400: row 8's top");
    }

    @Test
    void gridMoveOverlay_outlinesTheCheckedTiles() {
        Script plain = new Script().frames(60).key(1, 'l');
        Script maths = new Script().frames(60).key(1, 'l').key(2, 'd');
        SketchRun.Result<S09b_HybridGrid> off = SketchRun.of(new S09b_HybridGrid()).script(plain).run();
        SketchRun.Result<S09b_HybridGrid> on = SketchRun.of(new S09b_HybridGrid()).script(maths).run();
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame()) > 1000, "the overlay changes what is drawn");
        S09b_HybridGrid k = on.sketch();
        Rect tile = GridMove.obstacles(k.grid, k.before, k.movedX, k.movedY).get(0);
        int x = (int) tile.x() + 1;
        int y = (int) tile.bottom();  // its bottom edge: the top may be under the player's red landed line
        assertTrue(SketchPixels.count(on.lastFrame(), x, y - 1, x + 10, y + 1, Overlay.GUIDE) > 0, "a checked tile is outlined");
        assertEquals(0, SketchPixels.count(off.lastFrame(), x, y - 1, x + 10, y + 1, Overlay.GUIDE), "not without the overlay");
    }

    @Test
    void pixelToCell_isFloorOfTheDivision_andTheLookAgreesWithTheGrid() {
        S09b_HybridGrid s = SketchRun.of(new S09b_HybridGrid()).frames(1).run().sketch();
        Random random = new Random(9);
        for (int i = 0; i < 2000; i++) {
            float x = -50 + random.nextFloat() * 700;
            float y = -50 + random.nextFloat() * 500;
            assertEquals(s.grid.colAt(x), s.columnAt(x), "column under x " + x);
            assertEquals(s.grid.rowAt(y), s.rowAt(y), "row under y " + y);
        }
        assertEquals(2, s.columnAt(48), "a pixel on a cell line belongs to the cell right of it");
        assertEquals(1, s.columnAt(47.9f));
        for (int row = -1; row <= s.grid.rows(); row++) {
            for (int col = -1; col <= s.grid.cols(); col++) {
                assertEquals(s.grid.isSolid(col, row), s.obstacleAt(col, row), "cell " + col + ", " + row);
            }
        }
    }

    @Test
    void byDefault_cellsMove_longRunWithJumps_landsOnRowLines_stopsAtWalls_andIsNeverInsideATile() {
        Random random = new Random(6);
        Script script = new Script().frames(4000);
        for (int f = 2; f < 3900; ) {
            int length = 5 + random.nextInt(70);
            script.hold(f, random.nextBoolean() ? "LEFT" : "RIGHT", length);
            if (random.nextInt(3) > 0) {
                script.hold(f + random.nextInt(length), random.nextBoolean() ? "UP" : "SPACE", 1);
            }
            f += length + 1 + random.nextInt(8);
        }
        Set<Integer> rowsStoodOn = new HashSet<>();
        int[] walls = new int[1];
        int[] heads = new int[1];
        SketchRun.of(new S09b_HybridGrid()).script(script).everyFrame(s -> {
            assertFalse(s.hitboxDecides);
            Grid g = s.grid;
            Rect p = s.player;
            assertFalse(g.overlapsSolid(new Rect(p.x(), p.y(), p.w(), p.h())), "frame " + s.frameCount + ": inside a tile at " + p);
            assertEquals(s.cellsMove(s.before, s.movedX, s.movedY), s.last, "frame " + s.frameCount + ": the cells' move");
            if (s.onGround) {
                assertEquals(p.bottom(), g.cellRect(0, g.rowAt(p.bottom())).y(), "frame " + s.frameCount + ": snapped onto a row line");
                rowsStoodOn.add(g.rowAt(p.bottom()));
            }
            walls[0] += (s.last.hit(Side.LEFT) || s.last.hit(Side.RIGHT)) ? 1 : 0;
            heads[0] += s.last.hit(Side.BOTTOM) ? 1 : 0;
        }).run();
        assertTrue(rowsStoodOn.size() >= 2, "stood on the floor and at least one platform: rows " + rowsStoodOn);
        assertTrue(walls[0] > 0, "ran into a wall");
        assertTrue(heads[0] > 0, "bumped its head");
    }

    @Test
    void byDefault_fastFall_stepsOverAThinPlatform_butGridMoveLands() {
        // 60 px a frame onto the one-cell-thick platform of row 8 (x 400): the next position
        // the default looks at is already below it.
        S09b_HybridGrid tutorial = new S09b_HybridGrid();
        tutorial.maxFall = 60;
        tutorial.gravity = 60;
        tutorial.player = new Rect(400, 8 * 24 - 28 - 1, 18, 28);
        SketchRun.of(tutorial).frames(1).run();
        assertTrue(tutorial.player.y() > 9 * 24, "it went through row 8: " + tutorial.player);
        S09b_HybridGrid sweep = new S09b_HybridGrid();
        sweep.maxFall = 60;
        sweep.gravity = 60;
        sweep.player = new Rect(400, 8 * 24 - 28 - 1, 18, 28);
        sweep.hitboxDecides = true;
        SketchRun.of(sweep).frames(1).run();
        assertEquals(8 * 24f, sweep.player.bottom(), "grid.move stops on row 8's top");
    }
}
