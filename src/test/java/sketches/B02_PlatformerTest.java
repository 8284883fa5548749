package sketches;

import hitbox.internal.Extents;

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
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * The platformer on the world: the player (a character body) never ends a frame inside a tile
 * or a window side, runs along the floor of tiles without catching on a seam, stands still on
 * the slope and walks up and down it, climbs the stairs without jumping, jumps up through the one-way
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
        return b != s.player.body() && b != s.lift && !b.isSensor() && !s.platforms.contains(b);
    }

    private static void assertInNothingSolid(B02_Platformer s) {
        for (Body b : s.world.overlapping(s.player.body())) {
            assertFalse(solid(s, b), "frame " + s.frameCount + ": the player " + s.player.body().shape() + " is inside " + b.shape());
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
                    assertFalse(coin.alive(), "a collected coin is removed from the world");
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
            if (through[0] < 0 && s.player.body().shape().overlaps(low.shape())) {
                through[0] = s.frameCount;
                assertTrue(s.vy < 0, "it is inside the platform on the way up");
            }
            if (through[0] > 0 && stood[0] < 0 && s.player.onGround() && Extents.maxY(s.player.body().shape()) == Extents.minY(low.shape())) {
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
            boolean onLift = s.player.onGround() && Extents.maxY(s.player.body().shape()) == Extents.minY(s.lift.shape())
                    && Extents.maxX(s.player.body().shape()) > Extents.minX(s.lift.shape()) && Extents.minX(s.player.body().shape()) < Extents.maxX(s.lift.shape());
            if (onLift && last[2] == 1 && !s.left && !s.right) {
                assertEquals(s.lift.pivotX() - last[1], s.player.body().pivotX() - last[0], 1e-3f,
                        "frame " + s.frameCount + ": standing still on it, the player moves as the platform does");
                carried[0]++;
            }
            last[0] = s.player.body().pivotX();
            last[1] = s.lift.pivotX();
            last[2] = onLift ? 1 : 0;
        }).run();
        assertTrue(carried[0] > 40, "frames carried: " + carried[0]);
    }

    @Test
    void tileFloor_runningRight_neverCatchesOnASeam() {
        // The first key hands the player over; it lands on the slope, then runs down it, along
        // the tiles and up the stairs: three pixels sideways every frame it is on the ground.
        Script script = new Script().frames(190).hold(1, "RIGHT", 189);
        float[] last = {Float.NaN};
        int[] steps = {0};
        int[] onFloor = {0};
        SketchRun.of(new B02_Platformer()).script(script).everyFrame(s -> {
            assertInNothingSolid(s);
            if (s.frameCount < 3) {
                return;
            }
            assertFalse(s.demo, "an arrow key ends the demo");
            Shape p = s.player.body().shape();
            boolean grounded = s.player.onGround() && Extents.maxX(p) < 598;
            if (grounded && !Float.isNaN(last[0])) {
                assertEquals(3, s.player.body().pivotX() - last[0], 1e-3f, "frame " + s.frameCount + " at x " + Extents.minX(p)
                        + ": three pixels every frame, no stop at a seam, a slope or a step");
                steps[0]++;
                onFloor[0] += Extents.maxY(p) == 360 ? 1 : 0;
            }
            last[0] = grounded ? s.player.body().pivotX() : Float.NaN;
        }).run();
        assertTrue(steps[0] > 160, "frames run on the ground: " + steps[0]);
        assertTrue(onFloor[0] > 90, "of them along the floor of tiles: " + onFloor[0]);
    }

    /** The slope's top at x: from (0, 310) down to (130, 360). */
    private static double slopeY(double x) {
        return 310 + 50 * x / 130;
    }

    @Test
    void slope_thePlayerLandsOnIt_andStandsStill_withNoDrift() {
        // DOWN hands the player over and does nothing else: it falls onto the slope and stands.
        Script script = new Script().frames(120).hold(1, "DOWN", 1);
        float[] last = {Float.NaN, Float.NaN};
        int[] still = {0};
        SketchRun.Result<B02_Platformer> r = SketchRun.of(new B02_Platformer()).script(script).capture(40).everyFrame(s -> {
            Shape p = s.player.body().shape();
            if (s.player.onGround()) {
                assertEquals(s.slope, s.player.ground(), "frame " + s.frameCount + ": it stands on the slope");
                // Its lower left corner rests on the slope's line, within a skin.
                assertEquals(slopeY(Extents.minX(p)), Extents.maxY(p), 0.1, "frame " + s.frameCount + ": the corner on the slope");
                if (!Float.isNaN(last[0])) {
                    assertEquals(last[0], s.player.body().pivotX(), "frame " + s.frameCount + ": no drift sideways");
                    assertEquals(last[1], s.player.body().pivotY(), "frame " + s.frameCount + ": nor down the slope");
                    still[0]++;
                }
                last[0] = s.player.body().pivotX();
                last[1] = s.player.body().pivotY();
            }
        }).run();
        assertTrue(still[0] > 90, "frames standing still on the slope: " + still[0]);
        // And what is drawn: the player in the same pixels at frame 40 and at the end, over the slope.
        Shape p = r.sketch().player.body().shape();
        assertEquals(0, SketchPixels.differing(r.frame(40), r.lastFrame(), (int) Extents.minX(p) - 2, (int) Extents.minY(p) - 2,
                (int) Extents.maxX(p) + 2, (int) Extents.maxY(p) + 2), "the player drawn in the same place");
        SketchPixels.assertColour(r.lastFrame(), (int) Extents.minX(p) + 9, (int) Extents.minY(p) + 13, Palette.PLAYER, "the player");
        SketchPixels.assertColour(r.lastFrame(), (int) Extents.minX(p) + 2, (int) Extents.maxY(p) + 3, Palette.OBSTACLE, "the slope under it");
    }

    @Test
    void slope_thePlayerWalksDownAndUpIt_atItsRunningSpeed_onTheGround() {
        // It lands on the slope, runs right down it, then left back up it.
        Script script = new Script().frames(115).hold(1, "DOWN", 1).hold(30, "RIGHT", 30).hold(75, "LEFT", 35);
        float[] last = {Float.NaN, Float.NaN, 0};   // x, y, and the key held: the next frame runs with it
        int[] down = {0};
        int[] up = {0};
        SketchRun.Result<B02_Platformer> r = SketchRun.of(new B02_Platformer()).script(script).everyFrame(s -> {
            Shape p = s.player.body().shape();
            boolean onSlope = s.player.onGround() && s.player.ground() == s.slope && Extents.minX(p) > 1;
            if (onSlope && !Float.isNaN(last[0]) && last[2] != 0) {
                float dx = s.player.body().pivotX() - last[0];
                float dy = s.player.body().pivotY() - last[1];
                assertEquals(3 * last[2], dx, 1e-3f, "frame " + s.frameCount + ": three pixels sideways");
                assertEquals(dx * 50 / 130, dy, 0.05f, "frame " + s.frameCount + ": along the slope");
                assertEquals(slopeY(Extents.minX(p)), Extents.maxY(p), 0.1, "frame " + s.frameCount + ": the corner on the slope");
                down[0] += last[2] > 0 ? 1 : 0;
                up[0] += last[2] < 0 ? 1 : 0;
            }
            last[0] = onSlope ? s.player.body().pivotX() : Float.NaN;
            last[1] = s.player.body().pivotY();
            last[2] = s.right ? 1 : s.left ? -1 : 0;
        }).run();
        assertTrue(down[0] > 20 && up[0] > 25, "frames walking down the slope: " + down[0] + ", up it: " + up[0]);
        B02_Platformer s = r.sketch();
        Shape p = s.player.body().shape();
        assertTrue(Extents.maxY(p) < 330, "up the slope, well above the floor: " + Extents.maxY(p));
        SketchPixels.assertColour(r.lastFrame(), (int) Extents.minX(p) + 9, (int) Extents.minY(p) + 13, Palette.PLAYER, "the player");
        SketchPixels.assertColour(r.lastFrame(), (int) Extents.minX(p) + 2, (int) Extents.maxY(p) + 3, Palette.OBSTACLE, "the slope under it");
    }

    @Test
    void stairs_thePlayerClimbsThem_withoutJumping_andStandsOnTheTop() {
        // It runs right from the slope to the stairs and up them: never a jump, never rising
        // off the ground, yet it ends 40 pixels above the floor on the top step.
        Script script = new Script().frames(200).hold(1, "RIGHT", 199);
        Set<Double> heights = new HashSet<>();
        SketchRun.Result<B02_Platformer> r = SketchRun.of(new B02_Platformer()).script(script).everyFrame(s -> {
            assertFalse(s.jump, "no jump key");
            if (s.frameCount > 20) {
                assertTrue(s.player.onGround(), "frame " + s.frameCount + ": on the ground all the way");
            }
            int step = s.tiles.indexOf(s.player.ground()) - s.tiles.indexOf(s.slope);
            if (step >= 1) {
                assertEquals(360 - 10 * step, Extents.maxY(s.player.body().shape()), 1e-3f, "frame " + s.frameCount + ": on step " + step);
                heights.add((double) Math.round(Extents.maxY(s.player.body().shape())));
            }
        }).run();
        assertEquals(Set.of(350.0, 340.0, 330.0, 320.0), heights, "it stood on every step");
        Shape p = r.sketch().player.body().shape();
        assertEquals(320, Extents.maxY(p), 1e-3f, "on the top step");
        SketchPixels.assertColour(r.lastFrame(), (int) Extents.minX(p) + 9, (int) Extents.minY(p) + 13, Palette.PLAYER, "the player");
        SketchPixels.assertColour(r.lastFrame(), (int) Extents.minX(p) + 9, (int) Extents.maxY(p) + 3, Palette.OBSTACLE, "the top step under it");
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
