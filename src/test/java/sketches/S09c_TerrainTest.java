package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Grid;
import hitbox.PathCosts;
import hitbox.Rect;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * Grass, water and forest in an int[][]: water stops the player, forest slows it, and the two
 * routes are the shortest and the cheapest. Coins lie in the cells' lists, several to a cell
 * in places, and only the lists under the player are looked at.
 */
class S09c_TerrainTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void map_isTheTutorialsNumbers_drawnInTheirColours() {
        SketchRun.Result<S09c_Terrain> r = SketchRun.of(new S09c_Terrain()).frames(2).run();
        S09c_Terrain s = r.sketch();
        Grid g = s.grid;
        assertEquals(30, g.cols());
        assertEquals(20, g.rows());
        assertEquals(0, s.GRASS);
        assertEquals(Grid.SOLID, s.WATER, "water is the grid's solid terrain");
        assertEquals(2, s.FOREST);
        int forest = 0;
        for (int row = 0; row < g.rows(); row++) {
            for (int col = 0; col < g.cols(); col++) {
                if (g.get(col, row) == s.FOREST) {
                    assertFalse(g.isSolid(col, row), "forest can be walked through");
                    forest++;
                }
            }
        }
        assertTrue(forest > 0, "the map has forest");
        PImage frame = r.lastFrame();
        assertEquals(s.WATER, g.get(5, 11));
        assertEquals(s.waterColour, frame.get((int) g.cellCenterX(5), (int) g.cellCenterY(11)));
        assertEquals(s.FOREST, g.get(14, 2));
        assertEquals(s.forestColour, frame.get((int) g.cellCenterX(14), (int) g.cellCenterY(2) + 5));
        assertEquals(s.GRASS, g.get(3, 7));
        assertEquals(s.grassColour, frame.get((int) g.cellCenterX(3), (int) g.cellCenterY(7)));
    }

    @Test
    void forest_slowsThePlayer_grassDoesNot() {
        // Hold RIGHT along row 3: grass up to x 200, then forest.
        List<Float> xs = new ArrayList<>();
        List<Integer> terrain = new ArrayList<>();
        SketchRun.of(new S09c_Terrain()).script(new Script().frames(120).hold(1, "RIGHT", 118)).everyFrame(s -> {
            xs.add(s.player.x());
            terrain.add(s.grid.get(s.grid.colAt(s.player.x() + s.player.w() / 2), s.grid.rowAt(s.player.y() + s.player.h() / 2)));
        }).run();
        int grassFrames = 0;
        int forestFrames = 0;
        for (int f = 2; f < 118; f++) {
            float moved = xs.get(f) - xs.get(f - 1);
            if (terrain.get(f - 1) == 2) {
                assertEquals(1f, moved, 1e-4, "in the forest, 1 px a frame (frame " + f + ")");
                forestFrames++;
            } else {
                assertEquals(3f, moved, 1e-4, "on grass, 3 px a frame (frame " + f + ")");
                grassFrames++;
            }
        }
        assertTrue(grassFrames > 10 && forestFrames > 10, "walked on both: " + grassFrames + " and " + forestFrames);
    }

    @Test
    void water_isNeverEntered() {
        Random random = new Random(4);
        String[] arrows = {"UP", "DOWN", "LEFT", "RIGHT"};
        Script script = new Script().frames(5000);
        for (int f = 1; f < 4950; ) {
            int length = 5 + random.nextInt(80);
            script.hold(f, arrows[random.nextInt(4)], length);
            if (random.nextBoolean()) {
                script.hold(f + random.nextInt(length), arrows[random.nextInt(4)], random.nextInt(30) + 1);
            }
            f += length + random.nextInt(5);
        }
        int[] besideWater = new int[1];
        SketchRun.of(new S09c_Terrain()).script(script).everyFrame(s -> {
            Rect p = s.player;
            assertFalse(s.grid.overlapsSolid(new Rect(p.x(), p.y(), p.w(), p.h())), "in the water or off the map at " + p);
            Rect around = new Rect(p.x() - 1, p.y() - 1, p.w() + 2, p.h() + 2);
            besideWater[0] += s.grid.overlapsSolid(around) ? 1 : 0;
        }).run();
        assertTrue(besideWater[0] > 50, "it spent time right at the water's edge or the map's: " + besideWater[0]);
    }

    @Test
    void routes_areTheShortestAndTheCheapest_sideBySide() {
        Script script = new Script().frames(6).click(2, 570, 70);
        SketchRun.Result<S09c_Terrain> r = SketchRun.of(new S09c_Terrain()).script(script).run();
        S09c_Terrain s = r.sketch();
        Grid g = s.grid;
        assertEquals(28, s.goalCol);
        assertEquals(3, s.goalRow);
        PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 3);
        assertEquals(28, s.shortest.length, "27 steps straight along row 3, through the forest");
        assertEquals(36, s.cheapest.length, "35 steps: down to row 7, under the forest, and up");
        assertEquals(17 + 10 * 3, costs.costOf(g, s.shortest), 1e-9);
        assertEquals(35, costs.costOf(g, s.cheapest), 1e-9);
        assertEquals(g.path(1, 3, 28, 3).length, s.shortest.length, "the shortest is grid.path's");
        // Side by side: the shortest 3 px above the centre line of row 3, the cheapest 3 px below it.
        int y = (int) g.cellCenterY(3);
        int x = (int) g.cellCenterX(5);
        assertTrue(SketchPixels.count(r.lastFrame(), x, y - 5, x + 1, y - 1, Palette.NEUTRAL) > 0, "the shortest route is drawn");
        assertTrue(SketchPixels.count(r.lastFrame(), x, y + 1, x + 1, y + 5, Palette.ACCENT) > 0, "the cheapest route is drawn");
        int fx = (int) g.cellCenterX(15);
        assertTrue(SketchPixels.count(r.lastFrame(), fx, y - 5, fx + 1, y - 1, Palette.NEUTRAL) > 0, "the shortest goes through the forest");
        assertEquals(0, SketchPixels.count(r.lastFrame(), fx, y + 1, fx + 1, y + 5, Palette.ACCENT), "the cheapest does not");
    }

    @Test
    void diagonals_keyEight_givesEightNeighbourRoutes() {
        Script script = new Script().frames(6).click(2, 570, 70).key(3, '8');
        S09c_Terrain s = SketchRun.of(new S09c_Terrain()).script(script).run().sketch();
        assertTrue(s.diagonals);
        PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 3).withDiagonals();
        assertEquals(costs.costOf(s.grid, s.grid.path(1, 3, 28, 3, costs)), costs.costOf(s.grid, s.cheapest), 1e-9);
        assertTrue(costs.costOf(s.grid, s.cheapest) < 35, "diagonal steps make the way round cheaper");
    }

    @Test
    void overlay_writesTheTerrainNumbers() {
        SketchRun.Result<S09c_Terrain> off = SketchRun.of(new S09c_Terrain()).frames(4).run();
        SketchRun.Result<S09c_Terrain> on = SketchRun.of(new S09c_Terrain()).script(new Script().frames(4).key(2, 'd')).run();
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame()) > 1000, "the overlay changes what is drawn");
        Grid g = on.sketch().grid;
        // The digit in a water cell far from the routes and labels: cell (12, 17).
        int x = (int) g.cellRect(12, 0).x(), y = (int) g.cellRect(0, 17).y();
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame(), x, y, x + 20, y + 20) > 5, "the cell's number is written");
    }

    @Test
    void terrain_isAnIntArray_ofTheSectionsNumbers_agreeingWithTheGrid() {
        S09c_Terrain s = SketchRun.of(new S09c_Terrain()).frames(1).run().sketch();
        assertEquals(20, s.terrain.length);
        assertEquals(30, s.terrain[0].length);
        for (int row = 0; row < 20; row++) {
            for (int col = 0; col < 30; col++) {
                assertEquals(s.map[row].charAt(col) - '0', s.terrain[row][col]);
                assertEquals(s.grid.get(col, row), s.terrain[row][col], "cell " + col + ", " + row);
            }
        }
        assertEquals(1, s.terrain[11][5], "water");
        assertEquals(2, s.terrain[2][14], "forest");
        assertEquals(0, s.terrain[7][3], "grass");
    }

    @Test
    void coins_lieInTheirCellsLists_severalToACellInPlaces() {
        S09c_Terrain s = SketchRun.of(new S09c_Terrain()).frames(1).run().sketch();
        int total = 0;
        int crowded = 0;
        for (int row = 0; row < 20; row++) {
            for (int col = 0; col < 30; col++) {
                for (S09c_Terrain.Coin coin : s.coins[row][col]) {
                    assertEquals(col, s.grid.colAt(coin.x), "a coin in its own cell's list, across");
                    assertEquals(row, s.grid.rowAt(coin.y), "and down");
                    assertTrue(s.terrain[row][col] != s.WATER, "not in the water");
                }
                total += s.coins[row][col].size();
                crowded += s.coins[row][col].size() > 1 ? 1 : 0;
            }
        }
        assertEquals(s.placed, total);
        assertTrue(crowded >= 3, "several cells hold more than one coin: " + crowded);
    }

    @Test
    void coins_arePickedUpOnTouch_lookingOnlyInTheCellsUnderThePlayer() {
        // Two coins put in cell (5, 3), the only ones on row 3's first cells, ahead of the player walking right along row 3.
        S09c_Terrain s = new S09c_Terrain();
        int[] before = new int[1];
        float[] touchedAt = new float[2];
        SketchRun.Result<S09c_Terrain> r = SketchRun.of(s).script(new Script().frames(60).hold(2, "RIGHT", 57)).everyFrame(k -> {
            if (k.frameCount == 1) {
                for (int col = 0; col < 10; col++) {
                    k.coins[3][col].clear();   // no placed coin on the way to these two
                }
                k.coins[3][5].add(k.new Coin(106, 70));
                k.coins[3][5].add(k.new Coin(114, 68));
                before[0] = k.collected;
                return;
            }
            int under = 0;
            for (int row = k.grid.rowAt(k.player.y()); row <= k.grid.rowAt(k.player.bottom()); row++) {
                for (int col = k.grid.colAt(k.player.x()); col <= k.grid.colAt(k.player.right()); col++) {
                    under += k.grid.inGrid(col, row) ? k.coins[row][col].size() : 0;
                }
            }
            assertTrue(k.looked <= under + (k.collected - before[0]), "frame " + k.frameCount + ": looked only under the player");
            assertTrue(k.looked < k.placed - k.collected, "never at every coin");
            if (touchedAt[0] == 0 && k.collected - before[0] >= 1) {
                touchedAt[0] = k.player.right();
            }
            if (touchedAt[1] == 0 && k.collected - before[0] >= 2) {
                touchedAt[1] = k.player.right();
            }
        }).run();
        // r.sketch(), not s: the instance that ran (another one if the window race made the run start again).
        assertEquals(0, r.sketch().coins[3][5].size(), "both coins in the cell were picked up");
        assertTrue(touchedAt[0] > 106 - 3 && touchedAt[0] < 106 + 3 + 3, "the first when the box reached it: " + touchedAt[0]);
        assertTrue(touchedAt[1] > touchedAt[0], "the second later, at " + touchedAt[1]);
    }
}
