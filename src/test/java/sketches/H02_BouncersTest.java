package sketches;

import hitbox.Rect;
import java.util.Set;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Edges;
import hitbox.Hits;
import hitbox.Motion;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * 100 bouncers among 100 obstacles, the same run every time. By default section 8's loop (a
 * flip inside the loop) moves them, a new colour on every flip, and lets some into obstacles,
 * as the header says it can. With l, Hitbox's loop: never inside one, a new colour on every hit.
 */
class H02_BouncersTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The sketch with Hitbox's loop on from the first frame, as l gives it. */
    private static H02_Bouncers hitboxLoop() {
        H02_Bouncers s = new H02_Bouncers();
        s.hitboxDecides = true;
        return s;
    }

    @Test
    void aHundredOfEach_startingInFreeSpots() {
        H02_Bouncers s = SketchRun.of(new H02_Bouncers()).frames(1).run().sketch();
        assertEquals(100, s.obstacles.size());
        assertEquals(100, s.bouncers.size());
    }

    @Test
    void hitboxLoop_threeThousandFrames_noBouncerEndsAFrameInsideAnObstacle_orOutsideTheWindow() {
        int[] moving = new int[1];
        SketchRun.of(hitboxLoop()).frames(3000).everyFrame(s -> {
            for (int i = 0; i < s.bouncers.size(); i++) {
                H02_Bouncers.Bouncer b = s.bouncers.get(i);
                int inside = Hits.first(new Rect(b.x, b.y, s.size, s.size), s.obstacles);
                assertEquals(-1, inside, "bouncer " + i + " at (" + b.x + ", " + b.y + ") is inside obstacle " + inside);
                assertEquals(Set.of(), Edges.crossed(new Rect(b.x, b.y, s.size, s.size), s.width, s.height),
                        "bouncer " + i + " left the window at (" + b.x + ", " + b.y + ")");
            }
            if (s.frameCount == 3000) {
                for (H02_Bouncers.Bouncer b : s.bouncers) {
                    moving[0] += b.vx != 0 && b.vy != 0 ? 1 : 0;
                }
            }
        }).run();
        assertEquals(100, moving[0], "every bouncer still has a speed on both axes");
    }

    @Test
    void hitboxLoop_colour_changesExactlyOnHits() {
        // A hit is what Motion says about the bouncer's next move from where it was: asked
        // here afresh, from the previous frame's positions and speeds.
        float[][] before = new float[100][];
        int[] colours = new int[100];
        int[] changes = new int[1];
        SketchRun.of(hitboxLoop()).frames(1000).everyFrame(s -> {
            int counted = 0;
            for (int i = 0; i < s.bouncers.size(); i++) {
                H02_Bouncers.Bouncer b = s.bouncers.get(i);
                if (before[i] != null) {
                    float[] p = before[i];
                    boolean hit = !Motion.blocked(new Rect(p[0], p[1], s.size, s.size), p[2], p[3], s.obstacles).isEmpty();
                    boolean changed = b.colour != colours[i];
                    assertEquals(hit, changed, "frame " + s.frameCount + ", bouncer " + i
                            + ": a new colour if and only if it hit an obstacle");
                    changes[0] += changed ? 1 : 0;
                    counted += hit ? 1 : 0;
                }
                before[i] = new float[] {b.x, b.y, b.vx, b.vy};
                colours[i] = b.colour;
            }
            if (s.frameCount > 1) {
                assertEquals(counted, s.hitsThisFrame, "hits this frame");
            }
        }).run();
        assertTrue(changes[0] > 1000, "colours changed on many hits: " + changes[0]);
    }

    @Test
    void lKey_hitboxLoop_movesEachBouncerAsMotionBounceDoes() {
        // Hitbox's loop (ask every obstacle, combine, reverse once, window edges, move where
        // free) is Motion.bounce's frame, written out: check it bouncer by bouncer from frame 2,
        // the first after l.
        float[][] before = new float[100][];
        int[] compared = new int[1];
        SketchRun.of(new H02_Bouncers()).script(new Script().frames(600).key(1, 'l')).everyFrame(s -> {
            for (int i = 0; i < s.bouncers.size(); i++) {
                H02_Bouncers.Bouncer b = s.bouncers.get(i);
                if (before[i] != null) {
                    assertTrue(s.hitboxDecides);
                    float[] p = before[i];
                    Motion.Step step = Motion.bounce(new Rect(p[0], p[1], s.size, s.size), p[2], p[3], s.obstacles, s.width, s.height);
                    String what = "frame " + s.frameCount + ", bouncer " + i;
                    assertEquals(step.x(), b.x, what + " x");
                    assertEquals(step.y(), b.y, what + " y");
                    assertEquals(step.vx(), b.vx, what + " vx");
                    assertEquals(step.vy(), b.vy, what + " vy");
                    compared[0]++;
                }
                before[i] = new float[] {b.x, b.y, b.vx, b.vy};
            }
        }).run();
        assertEquals(599 * 100, compared[0]);
    }

    @Test
    void sameSeed_sameRun() {
        H02_Bouncers a = SketchRun.of(new H02_Bouncers()).frames(200).run().sketch();
        H02_Bouncers b = SketchRun.of(new H02_Bouncers()).frames(200).run().sketch();
        assertEquals(a.obstacles, b.obstacles, "the same obstacles");
        for (int i = 0; i < 100; i++) {
            assertEquals(a.bouncers.get(i).x, b.bouncers.get(i).x, "bouncer " + i + " x");
            assertEquals(a.bouncers.get(i).y, b.bouncers.get(i).y, "bouncer " + i + " y");
            assertEquals(a.bouncers.get(i).colour, b.bouncers.get(i).colour, "bouncer " + i + " colour");
        }
        assertEquals(a.totalHits, b.totalHits, "the same hits");
    }

    @Test
    void overlay_showsCountsAndBouncerZerosBoxes() {
        SketchRun.Result<H02_Bouncers> off = SketchRun.of(new H02_Bouncers()).frames(158).run();
        SketchRun.Result<H02_Bouncers> on = SketchRun.of(new H02_Bouncers()).script(new Script().frames(158).key(2, 'd')).run();
        PImage a = off.lastFrame();
        PImage b = on.lastFrame();
        assertTrue(SketchPixels.differing(a, b) > 1000, "the overlay changes what is drawn");
        // The counts label sits in the top-left corner, drawn over whatever is there.
        assertTrue(SketchPixels.differing(a, b, 8, 8, 200, 40) > 200, "the counts are written top left");
        H02_Bouncers.Bouncer zero = on.sketch().bouncers.get(0);
        int cx = (int) (zero.x + on.sketch().size / 2);
        int cy = (int) (zero.y + on.sketch().size / 2);
        assertTrue(SketchPixels.differing(a, b, cx - 20, cy - 20, cx + 20, cy + 20) > 50, "bouncer 0 is ringed");
        assertFalse(on.sketch().bouncers.get(0).x != off.sketch().bouncers.get(0).x, "the overlay does not change the run");
        SketchRun.Result<H02_Bouncers> onOff = SketchRun.of(new H02_Bouncers())
                .script(new Script().frames(158).key(2, 'd').key(100, 'd')).run();
        // Above the key hint, whose text Processing may draw a little differently once labels
        // have used another text size.
        assertEquals(0, SketchPixels.differing(a, onOff.lastFrame(), 0, 0, 599, 380), "d again hides it");
    }

    @Test
    void byDefault_sectionEightsLoop_flipByFlip_aColourPerHit_andSomeBouncersEndUpInsideObstacles() {
        // Each frame, section 8's loop (and section 6's window edges) run here on every bouncer
        // as it was: the sketch must match it exactly, speeds, positions and colours.
        int[] caughtFrames = new int[1];
        int[] hits = new int[1];
        float[][] before = new float[100][];
        int[] colours = new int[100];
        SketchRun.of(new H02_Bouncers()).frames(1500).everyFrame(s -> {
            assertFalse(s.hitboxDecides);
            int counted = 0;
            for (int i = 0; i < 100; i++) {
                H02_Bouncers.Bouncer b = s.bouncers.get(i);
                if (before[i] != null) {
                    float x = before[i][0], y = before[i][1], vx = before[i][2], vy = before[i][3];
                    float size = s.size;
                    boolean hit = false;
                    for (hitbox.Rect o : s.obstacles) {
                        if (x + size + vx > o.x() && x + vx < o.x() + o.w() && y + size > o.y() && y < o.y() + o.h()) {
                            vx *= -1;
                            hit = true;
                        }
                        if (x + size > o.x() && x < o.x() + o.w() && y + size + vy > o.y() && y + vy < o.y() + o.h()) {
                            vy *= -1;
                            hit = true;
                        }
                    }
                    if (x < 0 || x + size > s.width) {
                        vx *= -1;
                    }
                    if (y < 0 || y + size > s.height) {
                        vy *= -1;
                    }
                    String what = "frame " + s.frameCount + ", bouncer " + i;
                    assertEquals(vx, b.vx, what + " vx");
                    assertEquals(vy, b.vy, what + " vy");
                    assertEquals(x + vx, b.x, what + " x");
                    assertEquals(y + vy, b.y, what + " y");
                    assertEquals(hit, b.colour != colours[i], what + ": a new colour exactly when an obstacle flipped it");
                    counted += hit ? 1 : 0;
                }
                before[i] = new float[] {b.x, b.y, b.vx, b.vy};
                colours[i] = b.colour;
            }
            if (s.frameCount > 1) {
                assertEquals(counted, s.hitsThisFrame, "hits this frame");
                hits[0] += counted;
            }
            boolean anyInside = false;
            for (H02_Bouncers.Bouncer b : s.bouncers) {
                anyInside |= Hits.any(new Rect(b.x, b.y, s.size, s.size), s.obstacles);
            }
            caughtFrames[0] += anyInside ? 1 : 0;
        }).run();
        assertTrue(hits[0] > 100, "the bouncers bounce off obstacles: " + hits[0] + " hits");
        assertTrue(caughtFrames[0] > 0, "some frame ends with a bouncer inside an obstacle: " + caughtFrames[0]);
    }
}
