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

/** Grass, water and forest: water stops the player, forest slows it, and the two routes are the shortest and the cheapest. */
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
        assertFalse(g.isSolidTerrain(s.FOREST), "forest can be walked through");
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
            assertFalse(s.grid.rectOverlapsSolid(p.x(), p.y(), p.w(), p.h()), "in the water or off the map at " + p);
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
        int x = (int) g.cellX(12), y = (int) g.cellY(17);
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame(), x, y, x + 20, y + 20) > 5, "the cell's number is written");
    }
}
