package sketches;

import hitbox.Rect;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.Edges;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * One box among the tutorial's list of Rectangle objects (four walls, eight blocks; 5 and 6 are
 * pillars with a 32 px slot, where s puts the box). The tutorial's loop moves the box by
 * default: it flips inside the loop, and in the slot moves the box into a pillar. Hitbox's loop
 * (l: combine, reverse once, ask again) never lets the box into a rectangle.
 */
class S08_ManyObjectsTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The obstacle the box overlaps, or -1. */
    private static int inside(S08_ManyObjects s) {
        for (int i = 0; i < s.rectangles.size(); i++) {
            S08_ManyObjects.Rectangle o = s.rectangles.get(i);
            if (Collide.rectRect(s.bouncingRectX, s.bouncingRectY, s.bouncingRectWidth, s.bouncingRectHeight, o.x, o.y, o.rectWidth, o.rectHeight)) {
                return i;
            }
        }
        return -1;
    }

    @Test
    void setup_isTheTutorialsFourWallsAndBlocks_andSPutsTheBoxInTheSlot() {
        S08_ManyObjects s = SketchRun.of(new S08_ManyObjects()).frames(1).run().sketch();
        assertEquals(12, s.rectangles.size(), "4 walls and 8 blocks");
        assertFalse(s.hitboxDecides, "the tutorial's loop moves the box");
        assertEquals(-1, inside(s), "the box starts in the open");
        S08_ManyObjects t = SketchRun.of(new S08_ManyObjects()).script(new Script().frames(1).key(1, 's')).run().sketch();
        S08_ManyObjects.Rectangle left = t.rectangles.get(5);
        S08_ManyObjects.Rectangle right = t.rectangles.get(6);
        float slot = right.x - (left.x + left.rectWidth);
        assertTrue(slot > t.bouncingRectWidth && slot - t.bouncingRectWidth < Math.abs(t.bouncingRectSpeedX),
                "the slot is wider than the box by less than one move: " + slot);
        assertTrue(t.bouncingRectX >= left.x + left.rectWidth && t.bouncingRectX + t.bouncingRectWidth <= right.x, "s put the box in the slot");
    }

    @Test
    void byDefault_theTutorialsLoop_movesTheBox_flipByFlip_andDrawsIt() {
        // Each frame, the tutorial's loop as section 8 writes it, run here on the box as it was:
        // the sketch must land exactly where it says, with the speeds it says.
        float[] was = new float[4];
        int[] flips = new int[1];
        SketchRun.of(new S08_ManyObjects()).script(new Script().frames(1500).click(600, 430, 300)).everyFrame(s -> {
            if (s.frameCount > 1) {
                float x = was[0], y = was[1], vx = was[2], vy = was[3];
                for (S08_ManyObjects.Rectangle o : s.rectangles) {
                    if (x + 30 + vx > o.x && x + vx < o.x + o.rectWidth && y + 30 > o.y && y < o.y + o.rectHeight) {
                        vx *= -1;
                    }
                    if (x + 30 > o.x && x < o.x + o.rectWidth && y + 30 + vy > o.y && y + vy < o.y + o.rectHeight) {
                        vy *= -1;
                    }
                }
                flips[0] += (vx != was[2] ? 1 : 0) + (vy != was[3] ? 1 : 0);
                assertEquals(vx, s.bouncingRectSpeedX, "frame " + s.frameCount + ": the speed across");
                assertEquals(vy, s.bouncingRectSpeedY, "frame " + s.frameCount + ": the speed down");
                assertEquals(x + vx, s.bouncingRectX, "frame " + s.frameCount + ": x");
                assertEquals(y + vy, s.bouncingRectY, "frame " + s.frameCount + ": y");
                if (inside(s) < 0 && s.bouncingRectY > 40) {   // not under the label at the top
                    int px = Math.round(s.bouncingRectX + 15);
                    int py = Math.round(s.bouncingRectY + 15);
                    assertEquals(Integer.toHexString(Palette.PLAYER), Integer.toHexString(s.get(px, py) | 0xFF000000),
                            "frame " + s.frameCount + ": the box, drawn where the tutorial's loop put it");
                }
            }
            was[0] = s.bouncingRectX;
            was[1] = s.bouncingRectY;
            was[2] = s.bouncingRectSpeedX;
            was[3] = s.bouncingRectSpeedY;
        }).run();
        assertTrue(flips[0] > 20, "it bounced: " + flips[0] + " flips");
    }

    @Test
    void click_addsAnObstacleWhereTheMouseIs() {
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(5).click(2, 520, 40)).run();
        S08_ManyObjects s = r.sketch();
        assertEquals(13, s.rectangles.size(), "12 obstacles, then 13");
        S08_ManyObjects.Rectangle added = s.rectangles.get(12);
        assertEquals(520, added.x + added.rectWidth / 2, "centred on the mouse across");
        assertEquals(40, added.y + added.rectHeight / 2, "and down");
        SketchPixels.assertColour(r.lastFrame(), 520, 40, Palette.OBSTACLE, "the new obstacle is drawn");
    }

    @Test
    void clickOnTheBox_isRefused() {
        // The box starts at (150, 150), 30 x 30, and moves (3.3, 2.7) a frame.
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(5).click(2, 170, 170)).run();
        assertEquals(12, r.sketch().rectangles.size(), "no obstacle on top of the box");
        assertTrue(r.sketch().message.startsWith("not added"), "and it says so: " + r.sketch().message);
    }

    @Test
    void hitboxLoop_tenThousandFrames_withAddedObstacles_neverOverlapsAny() {
        // Clicks that squeeze gaps narrower than one move next to the blocks.
        Script script = new Script().frames(10_000).key(1, 'l').key(1, 's')
                .click(300, 130, 135).click(1300, 330, 95).click(2300, 160, 285).click(3300, 440, 160)
                .click(4300, 540, 345).click(5300, 215, 180);
        Set<Integer> lit = new HashSet<>();
        int[] moves = new int[1];
        float[] last = new float[2];
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects()).script(script).everyFrame(s -> {
            assertEquals(-1, inside(s), "the box at (" + s.bouncingRectX + ", " + s.bouncingRectY + ") overlaps an obstacle");
            assertEquals(Set.of(), Edges.crossed(new Rect(s.bouncingRectX, s.bouncingRectY, s.bouncingRectWidth, s.bouncingRectHeight), s.width, s.height), "inside the window");
            for (int i = 0; i < s.rectangles.size(); i++) {
                if (s.rectangles.get(i).lit()) {
                    lit.add(i);
                }
            }
            if (s.bouncingRectX != last[0] || s.bouncingRectY != last[1]) {
                moves[0]++;
            }
            last[0] = s.bouncingRectX;
            last[1] = s.bouncingRectY;
        }).run();
        assertTrue(r.sketch().rectangles.size() > 12, "the clicks added obstacles");
        assertTrue(moves[0] > 9000, "it kept moving: " + moves[0] + " frames of 10,000");
        assertTrue(lit.size() >= 12, "it bounced off many different obstacles: " + lit);
    }

    @Test
    void hitboxLoop_inTheSlot_waitsAcrossAndSlidesOut() {
        List<float[]> at = new ArrayList<>();
        SketchRun.of(new S08_ManyObjects()).script(new Script().frames(120).key(1, 'l').key(1, 's')).everyFrame(s -> {
            assertEquals(-1, inside(s), "the box at (" + s.bouncingRectX + ", " + s.bouncingRectY + ") overlaps an obstacle");
            if (s.frameCount < 2) {
                return;
            }
            at.add(new float[] {s.bouncingRectX, s.bouncingRectY});
        }).run();
        // While it is between the pillars (y + 30 < 240), it never moves across, only down.
        int slid = 0;
        for (int i = 1; i < at.size() && at.get(i)[1] + 30 < 240; i++) {
            assertEquals(271, at.get(i)[0], "frame " + (i + 1) + ": waits across in the slot");
            assertTrue(at.get(i)[1] > at.get(i - 1)[1], "frame " + (i + 1) + ": and slides down");
            slid++;
        }
        assertTrue(slid > 40, "it slid down the slot for " + slid + " frames");
        assertTrue(at.get(at.size() - 1)[0] != 271, "and left it");
    }

    @Test
    void squeezedByTwoClickedObstacles_waitsInsteadOfBouncingIntoTheOther() {
        // Where the box is after frame 300; then the same run with two obstacles clicked in
        // beside it, each 2 to 3 px away: less than one move (3.3 px), so reversing off
        // one points it straight into the other.
        S08_ManyObjects before = SketchRun.of(new S08_ManyObjects()).script(new Script().frames(300).key(1, 'l').key(1, 's'))
                .run().sketch();
        int cy = Math.round(before.bouncingRectY + before.bouncingRectHeight / 2);
        int left = (int) Math.floor(before.bouncingRectX) - 32;                 // right edge 2 to 3 px left of the box
        int right = (int) Math.ceil(before.bouncingRectX + before.bouncingRectWidth) + 32;      // left edge 2 to 3 px right of it
        int[] waited = new int[1];
        float[] last = new float[2];
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(500).key(1, 'l').key(1, 's').click(300, left, cy).click(300, right, cy))
                .everyFrame(s -> {
                    assertEquals(-1, inside(s), "the box at (" + s.bouncingRectX + ", " + s.bouncingRectY + ") overlaps an obstacle");
                    if (s.frameCount > 301 && s.bouncingRectX == last[0] && s.bouncingRectY != last[1]) {
                        waited[0]++;
                    }
                    last[0] = s.bouncingRectX;
                    last[1] = s.bouncingRectY;
                }).run();
        assertEquals(14, r.sketch().rectangles.size(), "both clicks added an obstacle");
        assertTrue(waited[0] > 0, "it waited across (moving only down) while squeezed");
    }

    @Test
    void tutorialLoop_flipsTwiceInTheSlot_andTheBoxMovesIntoAPillar_andStaysThere() {
        // s after frame 1: the box in the slot; the tutorial's loop (the default) moves it.
        float[][] at = new float[62][];
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(61).key(1, 's'))
                .capture(2)
                .everyFrame(s -> at[s.frameCount] = new float[] {s.bouncingRectX, s.bouncingRectY, s.bouncingRectSpeedX, inside(s)})
                .run();
        S08_ManyObjects s = r.sketch();
        assertFalse(s.hitboxDecides);
        // Frame 2 starts at (271, 70) going left: pillar 5 flips vx, pillar 6 flips it back.
        assertEquals(-3.3f, at[2][2], 1e-6, "vx flipped twice: as it was");
        assertEquals(5, (int) at[2][3], "so the box moved into pillar 5, at x = " + at[2][0]);
        int insideFrames = 0;
        for (int f = 2; f <= 61; f++) {
            insideFrames += at[f][3] >= 0 ? 1 : 0;
            assertTrue(Math.abs(at[f][0] - 271) < 4 && Math.abs(at[f][1] - 70) < 4,
                    "frame " + f + ": stuck in the slot, flickering, at (" + at[f][0] + ", " + at[f][1] + ")");
        }
        assertEquals(30, insideFrames, "inside pillar 5 every other frame");
        // Drawn as a learner sees it: frame 2 shows the box inside, ringed red.
        PImage frame = r.frame(2);
        SketchPixels.assertColour(frame, Math.round(at[2][0]) + 15, Math.round(at[2][1]), Palette.HIT,
                "the red ring on the box's top edge");
    }

    @Test
    void tutorialPreview_saysWhereTheBoxWillLand() {
        // The maths overlay's text is the tutorial's loop run ahead on copies of the speeds:
        // "it lands inside" exactly when the next frame finds the box inside an obstacle.
        boolean[] predicted = new boolean[1];
        int[] checked = new int[2];
        SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(200).key(1, 's'))
                .everyFrame(s -> {
                    if (s.frameCount >= 3) {
                        assertEquals(predicted[0], inside(s) >= 0, "frame " + s.frameCount + ": the preview said "
                                + (predicted[0] ? "inside" : "not inside"));
                        checked[predicted[0] ? 1 : 0]++;
                    }
                    predicted[0] = s.tutorialPreview().contains("lands inside");
                }).run();
        assertTrue(checked[0] > 0 && checked[1] > 0, "both answers were checked: " + checked[0] + " and " + checked[1]);
    }

    @Test
    void hitboxLoop_theBlockingObstaclesLightUp() {
        // Frame 2, in the slot: pillar 5 blocks the move across, and pillar 6 the move back.
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(3).key(1, 'l').key(1, 's')).run();
        S08_ManyObjects s = r.sketch();
        assertTrue(s.rectangles.get(5).lit() && s.rectangles.get(6).lit(), "both pillars lit");
        SketchPixels.assertColour(r.lastFrame(), 250, 200, Palette.HIT, "pillar 5 is red");
        SketchPixels.assertColour(r.lastFrame(), 322, 200, Palette.HIT, "pillar 6 is red");
        SketchPixels.assertColour(r.lastFrame(), 475, 95, Palette.OBSTACLE, "obstacle 7 is not");
    }

    @Test
    void overlay_drawsNextPositionBoxes_andPressingAgainHidesIt() {
        SketchRun.Result<S08_ManyObjects> r = SketchRun.of(new S08_ManyObjects())
                .script(new Script().frames(26).key(10, 'p').key(15, 'd').key(20, 'd'))
                .capture(14).capture(18).run();
        PImage off = r.frame(14);
        PImage on = r.frame(18);
        assertTrue(SketchPixels.differing(off, on) > 1000, "the overlay changes what is drawn");
        assertEquals(0, SketchPixels.count(off, Overlay.MISS), "no green without the overlay");
        assertTrue(SketchPixels.count(on, Overlay.MISS) > 40, "the free next-position box is green");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "d again hides it (paused: nothing else changed)");
    }
}
