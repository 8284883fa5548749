package hitbox.processing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import org.junit.jupiter.api.Test;

import hitbox.Body;
import hitbox.BroadPhase;
import hitbox.Circle;
import hitbox.Collision;
import hitbox.Grid;
import hitbox.Polygon;
import hitbox.Reaction;
import hitbox.Rect;
import hitbox.Shape;
import hitbox.World;
import processing.awt.PGraphicsJava2D;

/**
 * {@link WorldDraw} draws, off-screen into a Java2D {@code PGraphics} without smoothing, what
 * the world says: each body where {@link Body#shape()} says it stands (a grid's body as its
 * solid cells), each body's box, the broad phase's cells, and each collision's normal from
 * the mover into the other.
 */
class WorldDrawTest {
    private static final int W = 200, H = 160;
    private static final int BLACK = 0xFF000000;
    /** How far from an outline a pixel may go either way: rasterising rules. */
    private static final float BAND = 1.5f;

    /** Draws on black and returns the pixels. */
    private static int[] draw(Consumer<PGraphicsJava2D> drawing) {
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(W, H);
        g.beginDraw();
        g.noSmooth();
        g.background(0);
        drawing.accept(g);
        g.endDraw();
        g.loadPixels();
        return g.pixels.clone();
    }

    private static int at(int[] pixels, float x, float y) {
        return pixels[(int) y * W + (int) x];
    }

    @Test
    void bodies_drawEachBodyWhereItStands_turnedOrNot_andAGridAsItsSolidCells() {
        World world = new World();
        world.add(new Rect(10, 10, 50, 30));
        Body turned = world.add(new Rect(-30, -10, 60, 20), 120, 50, 0.6f);   // translate(120, 50); rotate(0.6)
        Body ball = world.add(new Circle(40, 110, 22));
        ball.moveTo(ball.pivotX() + 5, ball.pivotY() + 3);
        Grid grid = Grid.parse("""
                ..........
                ..........
                ..........
                ..........
                ..........
                ..........
                ....##....
                ....#.....
                """, 20);
        world.add(grid);
        List<Shape> shapes = new ArrayList<>();
        for (Body b : world.bodies()) {
            if (b.grid() == null) {
                shapes.add(b.shape());
            }
        }
        for (int row = 0; row < grid.rows(); row++) {
            for (int col = 0; col < grid.cols(); col++) {
                if (grid.isSolid(col, row)) {
                    shapes.add(grid.cellRect(col, row));
                }
            }
        }
        assertTrue(turned.shape() instanceof Polygon, "a turned rect stands as a polygon");

        int[] pixels = draw(g -> {
            g.fill(255);
            g.noStroke();
            WorldDraw.bodies(g, world);
        });

        int checked = 0;
        List<String> wrong = new ArrayList<>();
        for (int py = 0; py < H; py++) {
            for (int px = 0; px < W; px++) {
                float x = px + 0.5f, y = py + 0.5f;
                if (nearAnOutline(shapes, x, y)) {
                    continue;
                }
                checked++;
                boolean inside = shapes.stream().anyMatch(s -> s.contains(x, y));
                boolean drawn = (pixels[py * W + px] & 0xff) > 127;
                if (drawn != inside) {
                    wrong.add("(" + px + ", " + py + ") " + (drawn ? "drawn" : "not drawn"));
                }
            }
        }
        assertTrue(checked > W * H / 2, "too few pixels away from the outlines: " + checked);
        assertEquals(List.of(), wrong.size() > 10 ? wrong.subList(0, 10) : wrong, wrong.size() + " pixels differ from the bodies");
        assertTrue((at(pixels, 95, 150) & 0xff) > 127, "the grid's solid cell (4, 7) is drawn");
        assertEquals(BLACK, at(pixels, 115, 150), "the grid's open cell (5, 7) is not");
    }

    @Test
    void bodies_keepTheSketchsStyle() {
        World world = new World();
        world.add(new Rect(10, 10, 50, 30));
        int[] pixels = draw(g -> {
            g.fill(0xFF336699);
            g.noStroke();
            g.rectMode(PGraphicsJava2D.CENTER);
            WorldDraw.bodies(g, world);
            g.rect(150, 100, 20, 20);   // still in CENTER mode: 140..160
        });
        assertEquals(0xFF336699, at(pixels, 30, 20), "the body in the sketch's fill");
        assertEquals(0xFF336699, at(pixels, 142, 92), "the sketch's rectMode is as it was");
    }

    @Test
    void boxes_outlineEachBodysBox_whichATurnedBodyGrows() {
        World world = new World();
        Body turned = world.add(new Rect(-30, -10, 60, 20), 100, 80, 0.6f);
        Rect box = turned.bounds();
        int[] pixels = draw(g -> WorldDraw.boxes(g, world));
        float midY = box.y() + box.h() / 2;
        assertTrue(near(pixels, box.x(), midY, WorldDraw.BOX), "the box's left edge");
        assertTrue(near(pixels, box.x() + box.w() / 2, box.y(), WorldDraw.BOX), "the box's top edge");
        assertTrue(near(pixels, box.x() + box.w(), midY, WorldDraw.BOX), "the box's right edge");
        assertEquals(BLACK, at(pixels, 100, 80), "an outline only");
        assertEquals(BLACK, at(pixels, box.x() - 3, midY), "nothing outside it");
    }

    @Test
    void cells_outlineTheBroadPhasesCells_andNothingForAStructureWithout() {
        World world = new World(BroadPhase.grid());
        world.add(new Rect(50, 50, 20, 20));
        world.add(new Rect(130, 90, 30, 30));
        List<float[]> cells = new ArrayList<>();
        world.cells((key, x, y, w, h) -> cells.add(new float[] {x, y, w, h}));
        assertTrue(!cells.isEmpty(), "the grid has occupied cells");
        int[] pixels = draw(g -> WorldDraw.cells(g, world));
        for (float[] c : cells) {
            if (c[0] >= 0 && c[1] + c[3] / 2 < H && c[0] < W) {
                assertTrue(at(pixels, c[0], c[1] + c[3] / 2) != BLACK, "the left edge of the cell at (" + c[0] + ", " + c[1] + ")");
            }
        }
        assertEquals(BLACK, at(pixels, 10, 150), "no cell where no body is");

        World sweep = new World(BroadPhase.sweepAndPrune());
        sweep.add(new Rect(50, 50, 20, 20));
        int[] none = draw(g -> WorldDraw.cells(g, sweep));
        for (int p : none) {
            assertEquals(BLACK, p, "sweep and prune has no cells");
        }
    }

    @Test
    void contacts_drawEachNormal_fromTheMoverIntoTheOther_yellowWhenBlocked_greenWhenCrossed() {
        World world = new World();
        Body floor = world.add(new Rect(0, 100, 200, 20));
        Body coin = world.add(new Circle(60, 60, 8)).sensor(true);
        Body player = world.add(new Rect(90, 40, 20, 20));
        List<Collision> landed = world.move(player, 0, 50);
        assertEquals(1, landed.size());
        assertEquals(floor, landed.get(0).other());
        assertEquals(1, landed.get(0).ny(), "the normal points down, into the floor");
        int[] pixels = draw(g -> WorldDraw.contacts(g, world));
        assertEquals(WorldDraw.CONTACT, at(pixels, 100, 112), "the normal, down into the floor from the player's foot");
        assertEquals(WorldDraw.CONTACT, at(pixels, 100, 100), "the dot at its foot, on the player's bottom edge");
        assertEquals(BLACK, at(pixels, 100, 90), "nothing up inside the player");

        Body runner = world.add(new Rect(10, 52, 16, 16));
        List<Collision> crossed = world.move(runner, 80, 0, (m, o) -> o == floor ? null : Reaction.SLIDE);
        assertEquals(coin, crossed.get(0).other(), "the sensor is met");
        assertEquals(Reaction.CROSS, crossed.get(0).reaction(), "and crossed");
        int[] green = draw(g -> WorldDraw.contacts(g, crossed));
        assertTrue(count(green, WorldDraw.CROSSED) > 10, "a crossed contact is drawn in its own colour");
        assertEquals(0, count(green, WorldDraw.CONTACT), "and not in the blocking one");

        int[] empty = draw(g -> WorldDraw.contacts(g, List.of()));
        assertEquals(W * H, count(empty, BLACK), "no collisions, nothing drawn");
    }

    @Test
    void debug_drawsCellsBoxesAndContacts_andNullIsRefused() {
        World world = new World();
        world.add(new Rect(0, 100, 200, 20));
        Body player = world.add(new Rect(90, 40, 20, 20));
        world.move(player, 0, 50);
        int[] pixels = draw(g -> WorldDraw.debug(g, world));
        assertTrue(count(pixels, WorldDraw.BOX) > 100, "boxes");
        assertTrue(count(pixels, WorldDraw.CONTACT) > 20, "the contact");
        assertThrows(IllegalArgumentException.class, () -> draw(g -> WorldDraw.debug(g, null)));
        assertThrows(IllegalArgumentException.class, () -> draw(g -> WorldDraw.bodies(g, null)));
        assertThrows(IllegalArgumentException.class, () -> draw(g -> WorldDraw.body(g, null)));
        assertThrows(IllegalArgumentException.class, () -> draw(g -> WorldDraw.contacts(g, (List<Collision>) null)));
    }

    /** Has a pixel within one of (x, y) this colour (a line at a fractional coordinate may fall either side)? */
    private static boolean near(int[] pixels, float x, float y, int argb) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int px = (int) x + dx, py = (int) y + dy;
                if (px >= 0 && py >= 0 && px < W && py < H && pixels[py * W + px] == argb) {
                    return true;
                }
            }
        }
        return false;
    }

    private static int count(int[] pixels, int argb) {
        int n = 0;
        for (int p : pixels) {
            n += p == argb ? 1 : 0;
        }
        return n;
    }

    /** Is the point within {@link #BAND} of any shape's outline (points on a ring about it disagree)? */
    private static boolean nearAnOutline(List<Shape> shapes, float x, float y) {
        for (Shape s : shapes) {
            boolean in = s.contains(x, y);
            for (int i = 0; i < 16; i++) {
                double t = 2 * Math.PI * i / 16;
                if (s.contains(x + BAND * (float) Math.cos(t), y + BAND * (float) Math.sin(t)) != in) {
                    return true;
                }
            }
        }
        return false;
    }
}
