package sketches;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.Edges;
import hitbox.Motion;
import hitbox.Rect;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/** One box among a list of obstacles: clicks add obstacles, the box never goes into any, the hit ones light up. */
class S08_ManyObjectsTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void click_addsAnObstacleWhereTheMouseIs() {
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(5).click(2, 520, 40)).run();
        S08_ManyObjects s = r.sketch();
        assertEquals(9, s.obstacles.size(), "8 obstacles, then 9");
        Rect added = s.obstacles.get(8);
        assertEquals(520, added.centerX(), "centred on the mouse across");
        assertEquals(40, added.centerY(), "and down");
    }

    @Test
    void clickOnTheBox_isRefused() {
        // The box starts at (20, 20), 30 x 30, and moves about 3 px a frame: at frame 2 it covers (35, 35).
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(5).click(2, 35, 35)).run();
        assertEquals(8, r.sketch().obstacles.size(), "no obstacle on top of the box");
        assertTrue(r.sketch().message.startsWith("not added"), "and it says so: " + r.sketch().message);
    }

    @Test
    void tenThousandFrames_withAddedObstacles_neverOverlapsAny_andStaysInTheWindow() {
        // Clicks that squeeze gaps narrower than one move next to the first obstacles.
        Script script = new Script().frames(10_000)
                .click(300, 130, 135).click(1300, 330, 95).click(2300, 160, 285).click(3300, 440, 160)
                .click(4300, 540, 345).click(5300, 215, 180);
        Set<Integer> lit = new HashSet<>();
        int[] moves = new int[1];
        float[] last = new float[2];
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects()).script(script).everyFrame(s -> {
            for (int i = 0; i < s.obstacles.size(); i++) {
                Rect o = s.obstacles.get(i);
                assertFalse(Collide.rectRect(s.x, s.y, s.w, s.h, o.x(), o.y(), o.w(), o.h()),
                        "the box at (" + s.x + ", " + s.y + ") overlaps obstacle " + i);
            }
            assertEquals(Edges.NONE, Edges.rectCrossed(s.x, s.y, s.w, s.h, s.width, s.height), "inside the window");
            for (int i : s.hitsX) {
                lit.add(i);
            }
            for (int i : s.hitsY) {
                lit.add(i);
            }
            if (s.x != last[0] || s.y != last[1]) {
                moves[0]++;
            }
            last[0] = s.x;
            last[1] = s.y;
        }).run();
        assertTrue(r.sketch().obstacles.size() > 8, "the clicks added obstacles");
        assertTrue(moves[0] > 9000, "it kept moving: " + moves[0] + " frames of 10,000");
        assertTrue(lit.size() >= 6, "it bounced off many different obstacles: " + lit);
    }

    @Test
    void squeezedBetweenTwoObstacles_waitsInsteadOfBouncingIntoTheOther() {
        // Where the box is after frame 40; then the same run with two obstacles clicked in
        // beside it, each 2 to 3 px away: less than one move (3.3 px), so reversing off
        // one points it straight into the other.
        S08_ManyObjects before = SketchRun.of(new S08_ManyObjects()).frames(40).run().sketch();
        int cy = Math.round(before.y + before.h / 2);
        int left = (int) Math.floor(before.x) - 32;                 // right edge 2 to 3 px left of the box
        int right = (int) Math.ceil(before.x + before.w) + 32;      // left edge 2 to 3 px right of it
        int[] waited = new int[1];
        float[] last = new float[2];
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(200).click(40, left, cy).click(40, right, cy))
                .everyFrame(s -> {
                    for (int i = 0; i < s.obstacles.size(); i++) {
                        Rect o = s.obstacles.get(i);
                        assertFalse(Collide.rectRect(s.x, s.y, s.w, s.h, o.x(), o.y(), o.w(), o.h()),
                                "the box at (" + s.x + ", " + s.y + ") overlaps obstacle " + i);
                    }
                    if (s.frameCount > 41 && s.x == last[0] && s.y != last[1]) {
                        waited[0]++;
                    }
                    last[0] = s.x;
                    last[1] = s.y;
                }).run();
        assertEquals(10, r.sketch().obstacles.size(), "both clicks added an obstacle");
        assertTrue(waited[0] > 0, "it waited across (moving only down) while squeezed");
    }

    @Test
    void hitObstacles_areNamedAndLitUp() {
        // Frame 13: moved across only, the box would hit obstacle 0 (see the screenshot's frame 130 for 5).
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects()).frames(13).run();
        S08_ManyObjects s = r.sketch();
        assertEquals(Motion.X, s.blocked, "blocked across");
        assertArrayEquals(new int[] {0}, s.hitsX, "by obstacle 0");
        assertArrayEquals(new int[0], s.hitsY, "nothing down");
        Rect o = s.obstacles.get(0);
        assertEquals(Palette.HIT, r.lastFrame().get((int) o.centerX(), (int) o.bottom() - 3), "obstacle 0 is red");
        Rect other = s.obstacles.get(2);
        assertEquals(Palette.OBSTACLE, r.lastFrame().get((int) other.centerX(), (int) other.centerY()), "obstacle 2 is not");
    }

    @Test
    void overlay_drawsIndicesAndNextPositionBoxes() {
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(24).key(10, 'p').key(20, 'd'))
                .capture(20).capture(24).run();
        PImage off = r.frame(20);
        PImage on = r.frame(24);
        assertTrue(SketchPixels.differing(off, on) > 1000, "the overlay changes what is drawn");
        assertEquals(0, SketchPixels.count(off, Overlay.MISS), "no green without the overlay");
        assertTrue(SketchPixels.count(on, Overlay.MISS) > 100, "the free next-position boxes are green");
    }


}
