package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The scene of sketch S10e_FastObjects, headless: a ball of radius 12 shot along a lane at a
 * wall 6 px thick (x 420 to 426, y 70 to 306) in a 600 px window, at the sketch's speeds, from
 * thousands of starts, moved frame by frame as the sketch moves it.
 *
 * <p>Moved by {@link Sweep#circleRectHit} (t of the step on a hit, the whole step otherwise),
 * the ball always stops touching the wall and never passes it. Moved, then tested with
 * {@link Collide#circleRect} where it landed (the naive ball), it goes through never while a
 * step is shorter than ball and wall together (30 px), sometimes above that, and always once
 * its first step lands past the window. The display test only checks a few frames of this.
 */
class SweepNoTunnelSketchCaseTest {

    private static final float WALL_X = 420;
    private static final float WALL_Y = 70;
    private static final float WALL_H = 236;
    private static final float R = 12;
    private static final float LANE = 254;
    private static final float WIDTH = 600;
    private static final int STARTS = 2000;

    /** Where the sketch starts a shot: 40 px in, plus up to one step or 80 px. */
    private static float start(int i, float speed) {
        return 40 + (float) i / STARTS * Math.min(speed, 80);
    }

    @ParameterizedTest(name = "{0} px/frame, wall {1} px: the naive ball goes through {2}")
    @CsvSource({
            // px/frame, wall thickness, how often the naive ball goes through
            "2,    6,   never",
            "5,    6,   never",
            "10,   6,   never",
            "20,   6,   never",       // a step shorter than 30 px always lands in the wall
            "40,   6,   sometimes",
            "80,   6,   sometimes",
            "150,  6,   sometimes",
            "300,  6,   sometimes",
            "600,  6,   always",      // the first step already lands past the window
            "1200, 6,   always",
            "2500, 6,   always",
            "5000, 6,   always",
            "28,   6,   never",       // 28 < 24 + 6...
            "28,   1,   sometimes",   // ...but 28 > 24 + 1: the sketch's "try this", a 1 px wall
            "80,   1,   sometimes",
            "5000, 1,   always",
            "80,   0.5, sometimes",
    })
    void sketchScene_theSweptBallNeverGoesThrough_theNaiveOneWhenFast(float speed, float wallW, String naive) {
        int naiveThrough = 0;
        for (int i = 0; i < STARTS; i++) {
            float x0 = start(i, speed);
            String where = "start x = " + x0;

            // The swept ball: ask about the whole step, move t of it on a hit.
            float x = x0;
            boolean stopped = false;
            while (!stopped) {
                Hit hit = Raw.sweepCircleRectHit(x, LANE, R, speed, 0, WALL_X, WALL_Y, wallW, WALL_H);
                if (hit != null && !hit.alreadyOverlapping()) {
                    assertTrue(hit.t() >= 0 && hit.t() <= 1, where + ": t in [0, 1], was " + hit.t());
                    x += hit.t() * speed;
                    stopped = true;
                } else {
                    x += speed;
                    assertTrue(x < WALL_X, where + ": the swept ball went past the wall to x = " + x);
                }
            }
            assertEquals(WALL_X - R, x, 1e-3f, where + ": stopped touching the wall");
            assertFalse(Collide.circleRect(x - 1e-3f, LANE, R, WALL_X, WALL_Y, wallW, WALL_H),
                    where + ": not inside it");

            // The naive ball: move, then test where it landed; the shot ends on a hit or
            // past the window, as in the sketch.
            float nx = x0;
            boolean caught = false;
            boolean through = false;
            while (!caught && nx <= WIDTH + R) {
                nx += speed;
                caught = Collide.circleRect(nx, LANE, R, WALL_X, WALL_Y, wallW, WALL_H);
                through |= !caught && nx > WALL_X + wallW;
            }
            naiveThrough += through ? 1 : 0;
        }
        switch (naive) {
            case "never" -> assertEquals(0, naiveThrough, "the naive ball went through " + naiveThrough + " of " + STARTS);
            case "always" -> assertEquals(STARTS, naiveThrough, "the naive ball went through every shot");
            default -> assertTrue(naiveThrough > 0 && naiveThrough < STARTS,
                    "the naive ball went through some shots, not all: " + naiveThrough + " of " + STARTS);
        }
    }

    @ParameterizedTest(name = "{0} px/frame at {1} degrees")
    @CsvSource({
            "20, -30", "20, 10", "80, -10", "80, 30", "300, -30", "300, 10", "5000, -10", "5000, 30",
    })
    void sketchScene_shotAtAnAngle_theSweptBallStillStopsAtTheWall(float speed, float degrees) {
        // The sketch's other "try this": give the balls a vy. Each shot is aimed at the wall's
        // middle (y 188), so its path meets the wall's face.
        double a = Math.toRadians(degrees);
        float vx = (float) (speed * Math.cos(a));
        float vy = (float) (speed * Math.sin(a));
        for (int i = 0; i < STARTS; i++) {
            float x = start(i, vx);
            float y = (float) (188 - Math.tan(a) * (WALL_X - R - x));
            String where = "start (" + x + ", " + y + ")";
            Hit hit = null;
            for (int frame = 0; frame < 1000 && hit == null; frame++) {
                hit = Raw.sweepCircleRectHit(x, y, R, vx, vy, WALL_X, WALL_Y, 6, WALL_H);
                if (hit == null) {
                    x += vx;
                    y += vy;
                    assertTrue(x < WALL_X, where + ": went past the wall to x = " + x);
                }
            }
            assertNotNull(hit, where + ": never reached the wall");
            assertFalse(hit.alreadyOverlapping(), where);
            float hx = x + hit.t() * vx;
            float hy = y + hit.t() * vy;
            assertEquals(WALL_X - R, hx, 1e-3f, where + ": stopped touching the wall's face, at y = " + hy);
            assertFalse(Collide.circleRect(hx - 1e-3f, hy, R, WALL_X, WALL_Y, 6, WALL_H), where + ": not inside it");
        }
    }
}
