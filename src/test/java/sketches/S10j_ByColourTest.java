package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.Random;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Polygon;
import hitbox.Rect;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10j_ByColour: a car on a track that is only a picture. It reads the canvas colour under
 * its wheels (where they would be after the move) with get(): grass lowers its top speed,
 * wall colour stops it.
 */
class S10j_ByColourTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private static int round(float v) {
        return Math.round(v);
    }

    /** The checks every frame of every run: what was read is the track, and no wheel is on the wall. */
    private static void readsTheTrack_andKeepsOffTheWall(S10j_ByColour s) {
        PImage track = s.track;
        String at = "frame " + s.frameCount + ", car at (" + s.x + ", " + s.y + ")";
        for (int i = 0; i < 4; i++) {
            int px = round(s.wheels.x(i));
            int py = round(s.wheels.y(i));
            // The track's own colour there: get() read the canvas before the car was drawn.
            assertEquals(Integer.toHexString(track.get(px, py)), Integer.toHexString(s.under[i]),
                    at + ": wheel " + i + " read the track at (" + px + ", " + py + ")");
        }
        Polygon car = Polygon.of(Rect.centered(s.x, s.y, s.carLength, s.carWidth)).rotated(s.angle, s.x, s.y);
        for (int i = 0; i < 4; i++) {
            int colour = track.get(round(car.x(i)), round(car.y(i)));
            assertTrue(colour != s.WALL, at + ": wheel " + i + " is on the wall");
        }
        assertTrue(s.x > 0 && s.x < s.width && s.y > 0 && s.y < s.height, at + ": in the window");
    }

    @Test
    void track_isExactColours_andTheCarStartsOnTheRoad() {
        SketchRun.Result<S10j_ByColour> r = SketchRun.of(new S10j_ByColour()).frames(3).run();
        S10j_ByColour s = r.sketch();
        PImage frame = r.lastFrame();
        // The canvas shows the track picture pixel for pixel (away from the car and labels).
        assertEquals(0, SketchPixels.differing(frame, s.track, 0, 40, 599, 280), "the canvas is the track");
        assertEquals(s.GRASS, frame.get(300, 250), "grass in the middle");
        assertEquals(s.ROAD, frame.get(400, 320), "road on the bottom straight");
        assertEquals(s.WALL, frame.get(4, 200), "the wall at the edge");
        for (int i = 0; i < 4; i++) {
            assertEquals(s.ROAD, s.under[i], "wheel " + i + " starts on the road");
        }
        assertEquals(4, s.topSpeed, 0, "full top speed");
        readsTheTrack_andKeepsOffTheWall(s);
    }

    @Test
    void onTheRoad_itReachesTopSpeed_4() {
        SketchRun.Result<S10j_ByColour> r = SketchRun.of(new S10j_ByColour())
                .script(new Script().frames(45).hold(1, "UP", 44))
                .everyFrame(S10j_ByColourTest::readsTheTrack_andKeepsOffTheWall).run();
        S10j_ByColour s = r.sketch();
        assertEquals(0, s.wheelsOnGrass);
        assertEquals(4, s.speed, 1e-4, "top speed on the road");
        assertEquals(320, s.y, 1e-3, "straight along the bottom straight");
        assertTrue(s.x > 280, "it went along it, to x = " + s.x);
    }

    @Test
    void offTheRoad_theGrassSlowsIt_andTheWallStopsIt() {
        // Full throttle along the bottom straight, then a turn to the right, down onto the
        // grass and on into the wall.
        float[] slowest = {99};
        int[] onGrass = {0};
        int[] stopped = {0};
        SketchRun.of(new S10j_ByColour())
                .script(new Script().frames(120).hold(1, "UP", 119).hold(28, "RIGHT", 8))
                .everyFrame(s -> {
                    readsTheTrack_andKeepsOffTheWall(s);
                    if (s.wheelsOnGrass >= 2 && !s.hitWall) {
                        onGrass[0]++;
                        assertTrue(s.topSpeed <= 2.5f, "two wheels on grass: top speed " + s.topSpeed);
                        slowest[0] = Math.min(slowest[0], s.speed);
                    }
                    if (s.hitWall) {
                        stopped[0]++;
                        assertEquals(0, s.speed, 0, "a wheel would be on the wall: stopped");
                    }
                }).run();
        assertTrue(onGrass[0] > 5, "it drove on the grass for " + onGrass[0] + " frames");
        assertTrue(slowest[0] <= 2.5f, "and slowed down there, to " + slowest[0]);
        assertTrue(stopped[0] > 20, "then the wall stopped it, and kept it stopped: " + stopped[0] + " frames");
    }

    @Test
    void randomDriving_neverPutsAWheelOnTheWall() {
        Random random = new Random(5);
        Script script = new Script().frames(2400);
        String[] keys = {"UP", "UP", "UP", "DOWN", "LEFT", "RIGHT"};
        for (int f = 1; f < 2360; f += 20) {
            script.hold(f, keys[random.nextInt(keys.length)], 10 + random.nextInt(30));
        }
        int[] walls = {0};
        int[] grass = {0};
        SketchRun.of(new S10j_ByColour()).script(script).everyFrame(s -> {
            readsTheTrack_andKeepsOffTheWall(s);
            walls[0] += s.hitWall ? 1 : 0;
            grass[0] += s.wheelsOnGrass > 0 ? 1 : 0;
        }).run();
        assertTrue(walls[0] > 0 && grass[0] > 0, "it met the wall (" + walls[0] + " frames) and the grass (" + grass[0] + ")");
    }

    @Test
    void r_putsTheCarBackAtTheStart() {
        S10j_ByColour s = SketchRun.of(new S10j_ByColour())
                .script(new Script().frames(40).hold(1, "UP", 30).key(35, 'r')).run().sketch();
        assertEquals(200, s.x, 0);
        assertEquals(320, s.y, 0);
        assertEquals(0, s.speed, 0);
    }

    @Test
    void overlay_showsThePointsReadAndTheirColours_andPressingAgainHidesIt() {
        SketchRun.Result<S10j_ByColour> r = SketchRun.of(new S10j_ByColour())
                .script(new Script().frames(8).key(3, 'd').key(6, 'd')).capture(2).capture(5).run();
        PImage off = r.frame(2);
        PImage on = r.frame(5);
        assertTrue(SketchPixels.differing(off, on) > 2000, "the overlay draws the points and the panel");
        // A ring round the front left wheel's point, (214, 312).
        assertTrue(SketchPixels.differing(off, on, 208, 306, 220, 318) > 10, "the front left point is ringed");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "d again hides it");
    }
}
