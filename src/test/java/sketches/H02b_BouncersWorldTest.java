package sketches;

import java.util.Set;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Body;
import hitbox.Collision;
import hitbox.Edges;
import hitbox.Hits;
import hitbox.Rect;
import hitbox.Shape;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * Homework 2 on the world: 100 bouncers among 100 obstacles, moved by world.move with a
 * bounce reaction; never inside an obstacle, never out of the window, a new colour exactly
 * when a move met an obstacle, the speed turned round along the normals met; bouncers pass
 * through each other by their layers until b.
 */
class H02b_BouncersWorldTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private static Rect box(H02b_BouncersWorld.Bouncer b) {
        return (Rect) b.body.shape();
    }

    private static List<Rect> obstacleRects(H02b_BouncersWorld s) {
        List<Rect> out = new ArrayList<>();
        for (Body o : s.obstacles) {
            out.add((Rect) o.shape());
        }
        return out;
    }

    @Test
    void aHundredOfEach_theSameAsTheTutorialsHomeworkSketch() {
        H02b_BouncersWorld s = SketchRun.of(new H02b_BouncersWorld()).frames(1).run().sketch();
        H02_Bouncers h = SketchRun.of(new H02_Bouncers()).frames(1).run().sketch();
        assertEquals(100, s.obstacles.size());
        assertEquals(100, s.bouncers.size());
        assertEquals(204, s.world.size(), "the obstacles, the bouncers and four walls are bodies");
        assertEquals(h.obstacles, obstacleRects(s), "the same obstacles as H02_Bouncers, from the same seed");
    }

    @Test
    void threeThousandFrames_noBouncerInsideAnObstacle_orOutsideTheWindow() {
        int[] moving = new int[1];
        SketchRun.of(new H02b_BouncersWorld()).frames(3000).everyFrame(s -> {
            List<Rect> obstacles = obstacleRects(s);
            for (int i = 0; i < s.bouncers.size(); i++) {
                Rect r = box(s.bouncers.get(i));
                int inside = Hits.first(new Rect(r.x(), r.y(), r.w(), r.h()), obstacles);
                assertEquals(-1, inside, "frame " + s.frameCount + ": bouncer " + i + " at " + r + " is inside obstacle " + inside);
                assertEquals(Set.of(), Edges.crossed(new Rect(r.x(), r.y(), r.w(), r.h()), s.width, s.height),
                        "frame " + s.frameCount + ": bouncer " + i + " left the window at " + r);
            }
            if (s.frameCount == 3000) {
                for (H02b_BouncersWorld.Bouncer b : s.bouncers) {
                    moving[0] += b.vx != 0 && b.vy != 0 ? 1 : 0;
                }
            }
        }).run();
        assertEquals(100, moving[0], "every bouncer still has a speed on both axes");
    }

    @Test
    void colour_changesExactlyWhenAMoveMetAnObstacle_andTheSpeedTurnsAlongTheNormal() {
        int[] colours = new int[100];
        float[][] speeds = new float[100][];
        int[] changes = new int[1];
        SketchRun.of(new H02b_BouncersWorld()).frames(1000).everyFrame(s -> {
            int counted = 0;
            for (int i = 0; i < 100; i++) {
                H02b_BouncersWorld.Bouncer b = s.bouncers.get(i);
                boolean hitObstacle = false;
                for (Collision c : b.met) {
                    assertEquals(b.body, c.mover());
                    assertTrue(s.obstacles.contains(c.other()) || c.other().category() == s.WALL,
                            "frame " + s.frameCount + ": bouncers pass through each other: " + c);
                    hitObstacle |= s.obstacles.contains(c.other());
                }
                if (speeds[i] != null) {
                    assertEquals(hitObstacle, b.colour != colours[i], "frame " + s.frameCount + ", bouncer " + i
                            + ": a new colour if and only if its move met an obstacle");
                    changes[0] += hitObstacle ? 1 : 0;
                    counted += hitObstacle ? 1 : 0;
                    // The speed: turned round along each normal met (axis normals for boxes).
                    float vx = speeds[i][0], vy = speeds[i][1];
                    for (Collision c : b.met) {
                        if (c.nx() * vx > 0) {
                            vx = -vx;
                        }
                        if (c.ny() * vy > 0) {
                            vy = -vy;
                        }
                    }
                    assertEquals(vx, b.vx, "frame " + s.frameCount + ", bouncer " + i + " vx");
                    assertEquals(vy, b.vy, "frame " + s.frameCount + ", bouncer " + i + " vy");
                }
                speeds[i] = new float[] {b.vx, b.vy};
                colours[i] = b.colour;
            }
            if (s.frameCount > 1) {
                assertEquals(counted, s.hitsThisFrame, "frame " + s.frameCount + ": hits this frame");
            }
        }).run();
        assertTrue(changes[0] > 1000, "colours changed on many hits: " + changes[0]);
    }

    @Test
    void bKey_bouncersMeetEachOtherToo() {
        int[] between = new int[1];
        SketchRun.of(new H02b_BouncersWorld()).script(new Script().frames(800).key(1, 'b')).everyFrame(s -> {
            if (s.frameCount < 3) {
                return;
            }
            assertTrue(s.bounceOffEachOther);
            for (H02b_BouncersWorld.Bouncer b : s.bouncers) {
                for (Collision c : b.met) {
                    if (c.other().category() == s.BOUNCER && !c.hit().alreadyOverlapping()) {
                        between[0]++;
                    }
                }
            }
        }).run();
        assertTrue(between[0] > 20, "bouncers bounce off each other: " + between[0]);
    }

    @Test
    void sameSeed_sameRun() {
        H02b_BouncersWorld a = SketchRun.of(new H02b_BouncersWorld()).frames(200).run().sketch();
        H02b_BouncersWorld b = SketchRun.of(new H02b_BouncersWorld()).frames(200).run().sketch();
        for (int i = 0; i < 100; i++) {
            assertEquals(box(a.bouncers.get(i)), box(b.bouncers.get(i)), "bouncer " + i);
            assertEquals(a.bouncers.get(i).colour, b.bouncers.get(i).colour, "bouncer " + i + " colour");
        }
        assertEquals(a.totalHits, b.totalHits, "the same hits");
    }

    @Test
    void overlay_drawsWhatTheWorldSees_andPressingAgainHidesIt() {
        SketchRun.Result<H02b_BouncersWorld> off = SketchRun.of(new H02b_BouncersWorld()).frames(158).run();
        SketchRun.Result<H02b_BouncersWorld> on = SketchRun.of(new H02b_BouncersWorld())
                .script(new Script().frames(158).key(2, 'd')).run();
        PImage a = off.lastFrame();
        PImage b = on.lastFrame();
        assertTrue(SketchPixels.differing(a, b) > 2000, "cells, boxes and contacts are drawn");
        assertTrue(SketchPixels.differing(a, b, 8, 8, 200, 40) > 200, "the counts are written top left");
        assertTrue(!on.sketch().world.collisions().isEmpty(), "the frame had contacts to draw");
        SketchRun.Result<H02b_BouncersWorld> onOff = SketchRun.of(new H02b_BouncersWorld())
                .script(new Script().frames(158).key(2, 'd').key(100, 'd')).run();
        assertEquals(0, SketchPixels.differing(a, onOff.lastFrame(), 0, 0, 599, 380), "d again hides it");
    }
}
