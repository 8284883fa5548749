package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import hitbox.Grid;
import hitbox.PathCosts;
import hitbox.Rect;
import hitbox.TerrainColors;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/** The town maze: read from a picture (or the same town as text), walked cell by cell or in pixels, routed, and watched by guards. */
class H01_MazeTest {

    private static final String[] ARROWS = {"UP", "DOWN", "LEFT", "RIGHT"};

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void town_pictureAndText_areTheSameMap() throws Exception {
        File data = new File(SketchRun.sketchFolder(new H01_Maze()), "data");
        Grid text = Grid.parse(Files.readString(new File(data, "town.txt").toPath()));
        BufferedImage png = ImageIO.read(new File(data, "town.png"));
        int[] pixels = png.getRGB(0, 0, png.getWidth(), png.getHeight(), null, 0, png.getWidth());
        TerrainColors key = new TerrainColors().put(0xD8D2C4, 0).put(0x6B4F3F, 1).put(0x6DB35A, 2).put(0x4A86D0, 3);
        Grid picture = Grid.fromPixels(pixels, png.getWidth(), png.getHeight(), 8, key, 1);
        assertEquals(text.toMap(), picture.toMap());
        assertEquals(40, picture.cols());
        assertEquals(26, picture.rows());

        // The sketch reads the picture, and m switches to the text: the same town either way.
        SketchRun.Result<H01_Maze> r = SketchRun.of(new H01_Maze()).frames(2).run();
        assertEquals(text.toMap(), r.sketch().grid.toMap());
        assertTrue(r.sketch().fromPicture);
        assertEquals(16, r.sketch().grid.cellWidth(), "40 x 26 cells of 16 px fill the 640 x 416 map area");
        SketchRun.Result<H01_Maze> m = SketchRun.of(new H01_Maze()).script(new Script().frames(4).key(2, 'm')).run();
        assertFalse(m.sketch().fromPicture);
        assertEquals(text.toMap(), m.sketch().grid.toMap());
        assertEquals(r.sketch().townColours.colorOf(1), r.lastFrame().get(30, 30), "a building drawn in its key colour");
    }

    @ParameterizedTest(name = "l pressed: {0}")
    @ValueSource(booleans = {false, true})
    void walkingCellByCell_sectionNinesIfs_orCanMoveAfterL_onlyIntoCellsThatAreNotSolid(boolean l) {
        // Section 9's ifs by default, Grid.canMove after l: the same steps, checked here
        // against the grid's cells (not at the edge, and the next cell not solid).
        Random random = new Random(6);
        Script script = new Script().frames(1803);
        if (l) {
            script.key(1, 'l');
        }
        int[] pressed = new int[601];
        for (int i = 1; i <= 600; i++) {
            pressed[i] = random.nextInt(4);
            script.hold(3 * i, ARROWS[pressed[i]], 1);
        }
        List<int[]> at = new ArrayList<>();
        at.add(null);
        SketchRun.Result<H01_Maze> r = SketchRun.of(new H01_Maze()).script(script).everyFrame(s -> {
            assertEquals(l, s.hitboxDecides);
            assertFalse(s.grid.isSolid(s.playerIndexX, s.playerIndexY), "in a building at " + s.playerIndexX + ", " + s.playerIndexY);
            at.add(new int[] {s.playerIndexX, s.playerIndexY});
        }).run();
        Grid g = r.sketch().grid;
        int[][] steps = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};
        int moved = 0;
        int refused = 0;
        for (int i = 1; i <= 600; i++) {
            int[] before = at.get(3 * i - 1);
            int[] after = at.get(3 * i + 1);
            int c = before[0] + steps[pressed[i]][0];
            int row = before[1] + steps[pressed[i]][1];
            boolean free = c >= 0 && c < g.cols() && row >= 0 && row < g.rows() && !g.isSolid(c, row);
            assertEquals(g.canMove(before[0], before[1], steps[pressed[i]][0], steps[pressed[i]][1]), free, "canMove asks the same");
            assertEquals(free ? before[0] + steps[pressed[i]][0] : before[0], after[0], "press " + i);
            assertEquals(free ? before[1] + steps[pressed[i]][1] : before[1], after[1], "press " + i);
            moved += free ? 1 : 0;
            refused += free ? 0 : 1;
        }
        assertTrue(moved > 100 && refused > 20, "walked " + moved + " steps, refused " + refused);
    }

    @Test
    void route_isTheCheapest_andTakesABridgeOverTheRiver() {
        SketchRun.Result<H01_Maze> r = SketchRun.of(new H01_Maze()).script(new Script().frames(5).click(2, 632, 8)).run();
        H01_Maze s = r.sketch();
        Grid g = s.grid;
        assertEquals(39, s.goalCol);
        assertEquals(0, s.goalRow);
        PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 2, 10);
        int[] route = s.route;
        assertEquals(g.cols() * 25, route[0], "from the player's cell, (0, 25)");
        assertEquals(39, route[route.length - 1], "to the goal");
        assertEquals(costs.costOf(g, g.path(0, 25, 39, 0, costs)), costs.costOf(g, route), 1e-9);
        boolean crossed = false;
        for (int cell : route) {
            assertTrue(g.get(cell % g.cols(), cell / g.cols()) != s.RIVER, "the route never wades through the river");
            crossed |= cell / g.cols() == 11;
        }
        assertTrue(crossed, "it crosses the river's row on a bridge");
        assertTrue(costs.costOf(g, route) > route.length - 1 - 0.5, "and is costed as streets and parks");
    }

    @Test
    void guards_walkTheStreets_andSeeThePlayerExactlyByLineOfSight() {
        Random random = new Random(8);
        Script script = new Script().frames(3000);
        for (int f = 2; f < 2990; f += 2 + random.nextInt(6)) {
            script.hold(f, ARROWS[random.nextInt(4)], 1);
        }
        int[] seenFrames = new int[1];
        int[] blockedClose = new int[1];
        // A key moves the player just after draw(), so the guards looked at where it was a frame ago.
        float[] looked = new float[2];
        SketchRun.Result<H01_Maze> r = SketchRun.of(new H01_Maze()).script(script).everyFrame(s -> {
            boolean any = false;
            float px = s.frameCount == 1 ? s.playerX() : looked[0];
            float py = s.frameCount == 1 ? s.playerY() : looked[1];
            looked[0] = s.playerX();
            looked[1] = s.playerY();
            for (H01_Maze.Guard guard : s.guards) {
                Grid g = s.grid;
                assertFalse(g.isSolid(g.colAt(guard.x), g.rowAt(guard.y)), "a guard in a building at " + guard.x + ", " + guard.y);
                float d = processing.core.PApplet.dist(guard.x, guard.y, px, py);
                boolean clear = g.lineOfSight(guard.x, guard.y, px, py);
                assertEquals(d < s.guardView && clear, guard.seeing, "guard at " + guard.x + ", " + guard.y);
                any |= guard.seeing;
                blockedClose[0] += d < s.guardView && !clear ? 1 : 0;
            }
            assertEquals(any, s.seen);
            seenFrames[0] += any ? 1 : 0;
        }).run();
        assertTrue(seenFrames[0] > 0, "the player was seen at some point");
        assertTrue(blockedClose[0] > 0, "and hidden by a building from a guard close by at another");
        assertTrue(r.sketch().sightings > 0);
        assertTrue(r.sketch().guards.get(0).next != 1 || r.sketch().guards.get(1).next != 1, "the guards got round their beats");
    }

    @Test
    void pixelMode_movesInPixels_neverIntoABuilding() {
        Random random = new Random(2);
        Script script = new Script().frames(3000).key(2, 'p');
        for (int f = 4; f < 2950; ) {
            int length = 5 + random.nextInt(60);
            script.hold(f, ARROWS[random.nextInt(4)], length);
            f += length + random.nextInt(4);
        }
        float[] start = new float[2];
        SketchRun.Result<H01_Maze> r = SketchRun.of(new H01_Maze()).script(script).everyFrame(s -> {
            Rect b = s.box;
            assertFalse(s.grid.overlapsSolid(new Rect(b.x(), b.y(), b.w(), b.h())), "the box overlaps a building at " + b);
            assertEquals(s.grid.colAt(s.playerX()), s.playerIndexX);
            if (s.frameCount == 3) {
                start[0] = b.x();
                start[1] = b.y();
            }
        }).run();
        assertTrue(r.sketch().pixelMode);
        Rect end = r.sketch().box;
        assertTrue(end.x() != start[0] || end.y() != start[1], "it moved");
        assertEquals(2f, r.sketch().boxSpeed, "2 px a frame, less than a cell");
    }

    @Test
    void overlay_drawsTheGuardsView() {
        SketchRun.Result<H01_Maze> off = SketchRun.of(new H01_Maze()).frames(5).run();
        SketchRun.Result<H01_Maze> on = SketchRun.of(new H01_Maze()).script(new Script().frames(5).key(2, 'd')).run();
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame()) > 2000, "the guards' view changes what is drawn");
        H01_Maze.Guard guard = on.sketch().guards.get(0);
        int gx = (int) guard.x, gy = (int) guard.y;
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame(), gx + 20, gy, gx + 40, gy + 4) > 0,
                "the view is drawn next to the first guard");
    }
}
