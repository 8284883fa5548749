package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Body;
import hitbox.Collision;
import hitbox.Reaction;
import hitbox.Shape;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * The platformer on the world: the player never ends a frame inside a tile or a window side,
 * runs along the floor of tiles without catching on a seam, jumps up through the one-way
 * platforms and stands on them, is carried by the moving platform, and passes through the
 * coins (sensors), which the enter events collect. The demo plays the level until a key.
 */
class B02_PlatformerTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The solid bodies: the tiles and the window's sides (everything not one-way, not a sensor, not the lift). */
    private static boolean solid(B02_Platformer s, Body b) {
        return b != s.player && b != s.lift && !b.isSensor() && !s.platforms.contains(b);
    }

    private static void assertInNothingSolid(B02_Platformer s) {
        for (Body b : s.world.overlapping(s.player)) {
            assertFalse(solid(s, b), "frame " + s.frameCount + ": the player " + s.player.shape() + " is inside " + b.shape());
        }
    }

    @Test
    void demo_playsTheLevel_everyCoinCollected_andANewRound() {
        int[] mostCoins = {0};
        boolean[] newRound = {false};
        SketchRun.of(new B02_Platformer()).frames(900).everyFrame(s -> {
            assertTrue(s.demo, "no key: the demo plays");
            assertInNothingSolid(s);
            for (Collision c : s.met) {
                if (c.other().isSensor()) {
                    assertEquals(Reaction.CROSS, c.reaction(), "a coin is a sensor: crossed, never blocking");
                }
            }
            if (s.collected >= 6 && s.coins.size() >= 5) {
                newRound[0] = true;
            }
            mostCoins[0] = Math.max(mostCoins[0], s.collected);
        }).run();
        assertTrue(mostCoins[0] >= 6, "the demo collects every coin: " + mostCoins[0]);
        assertTrue(newRound[0], "and the coins come back for a new round");
    }

    @Test
    void coins_areCollectedOnTheirEnterEvent_andLeaveTheWorld() {
        Set<Body> seen = new HashSet<>();
        int[] before = {0};
        SketchRun.of(new B02_Platformer()).frames(500).everyFrame(s -> {
            seen.addAll(s.coins);
            for (Body coin : seen) {
                if (!s.coins.contains(coin)) {
                    assertFalse(s.world.contains(coin), "a collected coin is removed from the world");
                }
            }
            if (s.collected > before[0]) {
                // The coin went this frame: the player's shape reaches where it was.
                assertEquals(before[0] + 1, s.collected, "one coin at a time here");
            }
            before[0] = s.collected;
        }).run();
        assertTrue(before[0] >= 3, "coins collected: " + before[0]);
    }

    @Test
    void oneWayPlatform_jumpedThroughFromBelow_thenStoodOn() {
        int[] through = {-1};
        int[] stood = {-1};
        SketchRun.of(new B02_Platformer()).frames(80).everyFrame(s -> {
            Body low = s.platforms.get(0);
            if (through[0] < 0 && s.player.shape().overlaps(low.shape())) {
                through[0] = s.frameCount;
                assertTrue(s.vy < 0, "it is inside the platform on the way up");
            }
            if (through[0] > 0 && stood[0] < 0 && s.onGround && s.player.shape().maxY() == low.shape().minY()) {
                stood[0] = s.frameCount;
            }
        }).run();
        assertTrue(through[0] > 0, "the player passed up through the low platform");
        assertTrue(stood[0] > through[0], "and then stood on it: frames " + through[0] + ", " + stood[0]);
    }

    @Test
    void movingPlatform_carriesThePlayerStandingOnIt() {
        int[] carried = {0};
        float[] last = new float[3];   // player x, lift x, stood on it
        SketchRun.of(new B02_Platformer()).frames(400).everyFrame(s -> {
            boolean onLift = s.onGround && s.player.shape().maxY() == s.lift.shape().minY()
                    && s.player.shape().maxX() > s.lift.shape().minX() && s.player.shape().minX() < s.lift.shape().maxX();
            if (onLift && last[2] == 1 && !s.left && !s.right) {
                assertEquals(s.lift.x() - last[1], s.player.x() - last[0], 1e-3f,
                        "frame " + s.frameCount + ": standing still on it, the player moves as the platform does");
                carried[0]++;
            }
            last[0] = s.player.x();
            last[1] = s.lift.x();
            last[2] = onLift ? 1 : 0;
        }).run();
        assertTrue(carried[0] > 40, "frames carried: " + carried[0]);
    }

    @Test
    void tileFloor_runningRight_neverCatchesOnASeam() {
        // The first key hands the player over; it lands, then runs along the tiles to the step.
        Script script = new Script().frames(190).hold(1, "RIGHT", 189);
        float[] last = {Float.NaN};
        int[] steps = {0};
        SketchRun.of(new B02_Platformer()).script(script).everyFrame(s -> {
            assertInNothingSolid(s);
            if (s.frameCount < 3) {
                return;
            }
            assertFalse(s.demo, "an arrow key ends the demo");
            Shape p = s.player.shape();
            boolean onFloor = p.maxY() == 360;
            if (onFloor && !Float.isNaN(last[0]) && p.maxX() < 520) {
                assertEquals(3, s.player.x() - last[0], 1e-3f, "frame " + s.frameCount + " at x " + p.minX()
                        + ": three pixels every frame, no stop at a seam");
                steps[0]++;
            }
            last[0] = onFloor ? s.player.x() : Float.NaN;
        }).run();
        assertTrue(steps[0] > 120, "frames run along the floor: " + steps[0]);
    }

    @Test
    void overlayKey_drawsWhatTheWorldSees_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).key(3, 'd').key(8, 'd');
        SketchRun.Result<B02_Platformer> r = SketchRun.of(new B02_Platformer()).script(script).capture(2).capture(6).run();
        assertTrue(SketchPixels.differing(r.frame(2), r.frame(6)) > 1000, "boxes, cells, the contact and its text");
        SketchRun.Result<B02_Platformer> plain = SketchRun.of(new B02_Platformer()).frames(12).run();
        assertEquals(0, SketchPixels.differing(plain.lastFrame(), r.lastFrame()), "pressing d again hides it");
        PImage f = r.frame(6);
        assertTrue(f.width == 600 && f.height == 400);
    }
}
