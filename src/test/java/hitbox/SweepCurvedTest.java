package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@link Sweep#timeOfImpact(Shape, float, float, Shape)} with an ellipse (aligned or turned)
 * or a capsule as the mover or the obstacle, against every kind of shape: the Hit contract
 * (the largest float t at which the mover, moved in float as a sketch moves it, does not
 * overlap, the next float up overlapping), never passing through anything a dense sample of
 * the motion finds, both orders of the roles, and small fast shapes against thin walls.
 */
class SweepCurvedTest {

    private static final int SAMPLES = 512;

    private static Shape curved(Random rnd) {
        switch (rnd.nextInt(3)) {
            case 0:
                return Sampled.ellipse(rnd);
            case 1:
                return Sampled.turnedEllipse(rnd);
            default:
                return Sampled.capsule(rnd);
        }
    }

    private static Shape moved(Shape s, float t, float vx, float vy) {
        return s.translated(t * vx, t * vy);
    }

    /** The contract on one pair; returns whether it hit (not counting already overlapping). */
    private static boolean checkContract(Shape mover, float vx, float vy, Shape obstacle) {
        Hit hit = Sweep.timeOfImpact(mover, vx, vy, obstacle);
        String where = mover + " by (" + vx + ", " + vy + ") into " + obstacle + ": " + hit;
        assertEquals(mover.overlaps(obstacle), hit != null && hit.alreadyOverlapping(), where);
        if (hit != null && hit.alreadyOverlapping()) {
            return false;
        }
        float t = hit == null ? Float.POSITIVE_INFINITY : hit.t();
        // Never through: no sampled position before t overlaps (nor the end, when there is no hit).
        for (int k = 0; k <= SAMPLES; k++) {
            float s = (float) k / SAMPLES;
            if (s < t) {
                assertFalse(moved(mover, s, vx, vy).overlaps(obstacle), "overlaps at " + s + " before the hit, " + where);
            }
        }
        if (hit == null) {
            return false;
        }
        assertTrue(t >= 0 && t <= 1, where);
        assertFalse(moved(mover, t, vx, vy).overlaps(obstacle), "overlaps at the hit, " + where);
        if (t == 0) {
            // Touching at the start and moving in (Hit's promise: t = 0): the mover overlaps
            // once it has moved by a float step of its largest coordinate.
            float m = (float) Math.max(Math.max(Math.abs(Extents.minX(mover)), Math.abs(Extents.maxX(mover))), Math.max(Math.abs(Extents.minY(mover)), Math.abs(Extents.maxY(mover))));
            float step = 2 * Math.ulp(m) / Math.max(Math.abs(vx), Math.abs(vy));
            assertTrue(moved(mover, step, vx, vy).overlaps(obstacle), "t = 0, but not touching and moving in, " + where);
        } else {
            assertTrue(t < 1 && moved(mover, Math.nextUp(t), vx, vy).overlaps(obstacle), "clear just after the hit, " + where);
        }
        assertTrue(hit.nx() * vx + hit.ny() * vy > 0, "the normal points along the motion into the obstacle, " + where);
        assertEquals(1, Math.hypot(hit.nx(), hit.ny()), 1e-5, where);
        return true;
    }

    private static void randomPairs(long seed, int count, Function<Random, Shape> movers, Function<Random, Shape> obstacles) {
        Random rnd = new Random(seed);
        int hits = 0, misses = 0;
        for (int i = 0; i < count; i++) {
            Shape mover = movers.apply(rnd), obstacle = obstacles.apply(rnd);
            float vx = rnd.nextInt(241) - 120 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            float vy = rnd.nextInt(241) - 120 + (rnd.nextBoolean() ? rnd.nextFloat() : 0);
            if (checkContract(mover, vx, vy, obstacle)) {
                hits++;
            } else if (!mover.overlaps(obstacle)) {
                misses++;
            }
            // The roles swapped (the obstacle moving back): a hit either way, at about the same time.
            Hit there = Sweep.timeOfImpact(mover, vx, vy, obstacle);
            Hit back = Sweep.timeOfImpact(obstacle, -vx, -vy, mover);
            assertEquals(there == null, back == null, mover + " " + obstacle + " " + there + " " + back);
            if (there != null) {
                assertEquals(there.t(), back.t(), 1e-3, mover + " " + obstacle);
            }
        }
        assertTrue(hits > count / 10 && misses > count / 10, hits + " hits, " + misses + " misses");
    }

    @Test
    void curvedMover_everyObstacle() {
        randomPairs(14L, 600, SweepCurvedTest::curved, Sampled::any);
    }

    @Test
    void everyMover_curvedObstacle() {
        randomPairs(15L, 600, Sampled::any, SweepCurvedTest::curved);
    }

    /** Every pair, polygons and two segments included: the pairs with no exact swept test go by convex pieces. */
    @Test
    void anyMover_anyObstacle() {
        randomPairs(19L, 600, Sampled::any, Sampled::any);
    }

    @Test
    void turnedEllipses_againstEachOther() {
        randomPairs(16L, 300, Sampled::turnedEllipse, Sampled::turnedEllipse);
    }

    /** Degenerate curved shapes: flat ellipses, capsules of radius 0 or with a point segment. */
    @Test
    void degenerateShapes_keepTheContract() {
        Random rnd = new Random(17);
        for (int i = 0; i < 400; i++) {
            Shape mover = switch (rnd.nextInt(4)) {
                case 0 -> new Ellipse(Sampled.coord(rnd), Sampled.coord(rnd), 10, 0);
                case 1 -> new Ellipse(Sampled.coord(rnd), Sampled.coord(rnd), 0, 8, 0.7f);
                case 2 -> new Capsule(Sampled.coord(rnd), Sampled.coord(rnd), Sampled.coord(rnd), Sampled.coord(rnd), 0);
                default -> {
                    float x = Sampled.coord(rnd), y = Sampled.coord(rnd);
                    yield new Capsule(x, y, x, y, 5);
                }
            };
            float vx = rnd.nextInt(241) - 120, vy = rnd.nextInt(241) - 120;
            checkContract(mover, vx, vy, Sampled.any(rnd));
        }
    }

    /** A capsule of radius r with a point segment is a circle: it hits when the circle does, at the same float t. */
    @Test
    void pointCapsule_hitsWhenTheCircleDoes() {
        Random rnd = new Random(18);
        for (int i = 0; i < 300; i++) {
            float x = Sampled.coord(rnd), y = Sampled.coord(rnd), r = 1 + rnd.nextInt(20);
            Rect wall = new Rect(Sampled.coord(rnd), Sampled.coord(rnd), 1 + rnd.nextInt(40), 1 + rnd.nextInt(40));
            float vx = rnd.nextInt(241) - 120, vy = rnd.nextInt(241) - 120;
            Hit circle = Sweep.timeOfImpact(new Circle(x, y, r), vx, vy, wall);
            Hit capsule = Sweep.timeOfImpact(new Capsule(x, y, x, y, r), vx, vy, wall);
            assertEquals(circle == null, capsule == null, x + "," + y + " r " + r + " " + wall);
            if (circle != null) {
                assertEquals(circle.t(), capsule.t(), 0f, "the same float t: " + x + "," + y + " r " + r + " " + wall);
                assertEquals(circle.nx(), capsule.nx(), 1e-4);
                assertEquals(circle.ny(), capsule.ny(), 1e-4);
            }
        }
    }

    /** Sliding along a wall it touches is no hit; moving away from a touching shape neither. */
    @Test
    void touchingAndSliding_isNoHit() {
        Rect floor = new Rect(0, 10, 100, 10);
        assertNull(Sweep.timeOfImpact(new Ellipse(20, 5, 8, 5), 50, 0, floor));
        assertNull(Sweep.timeOfImpact(new Capsule(10, 5, 30, 5, 5), 50, 0, floor));
        assertNull(Sweep.timeOfImpact(new Ellipse(20, 5, 8, 5), 0, -20, floor));
        Hit landing = Sweep.timeOfImpact(new Ellipse(20, 0, 8, 5), 0, 20, floor);
        assertNotNull(landing);
        assertEquals(0.25f, landing.t(), 1e-6f);
        assertEquals(Side.TOP, landing.side());
        assertEquals(1, landing.ny(), 1e-6);
    }

    /** Small fast curved shapes never pass through a thin wall, at any angle. */
    @ParameterizedTest(name = "speed {0}, wall {1} thick")
    @CsvSource({"10, 1", "100, 0.5", "1000, 1", "10000, 0.5"})
    void fastSmallCurvedShapes_alwaysHitAThinWall(float speed, float thickness) {
        Shape[] movers = {new Ellipse(0, 0, 1, 0.5f), new Ellipse(0, 0, 1.5f, 0.5f, 0.7f), new Capsule(-1, 0, 1, 0, 0.5f)};
        for (int degrees = 0; degrees < 360; degrees += 5) {
            double a = Math.toRadians(degrees + 0.3);
            float vx = (float) (speed * Math.cos(a)), vy = (float) (speed * Math.sin(a));
            boolean upright = Math.abs(vx) >= Math.abs(vy);
            float half = speed / 2;
            Rect wall = upright
                    ? new Rect(Math.signum(vx) * half, -2 * speed, thickness, 4 * speed)
                    : new Rect(-2 * speed, Math.signum(vy) * half, 4 * speed, thickness);
            Shape thinEllipse = upright
                    ? new Ellipse(Math.signum(vx) * half, 0, thickness / 2, 2 * speed)
                    : new Ellipse(0, Math.signum(vy) * half, 2 * speed, thickness / 2);
            for (Shape m : movers) {
                for (Shape w : new Shape[] {wall, thinEllipse}) {
                    Hit hit = Sweep.timeOfImpact(m, vx, vy, w);
                    assertNotNull(hit, m + " missed " + w + " at " + degrees);
                    assertTrue(upright ? Math.abs(hit.t() * vx) < half : Math.abs(hit.t() * vy) < half, "stopped before the wall: " + m + " " + w + " " + hit);
                    assertFalse(moved(m, hit.t(), vx, vy).overlaps(w), m + " " + w + " " + hit);
                    assertEquals(upright, (hit.side() == Side.LEFT || hit.side() == Side.RIGHT), m + " " + w + " " + hit + " at " + degrees);
                }
            }
        }
    }
}
