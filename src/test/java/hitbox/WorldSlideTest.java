package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.FloatRange;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 28's slide, judged by where the body ends, against geometry: the part of a move along
 * a free surface is kept at any angle for every kind, a body gets round a convex obstacle met
 * away from its extreme point, settles in a V and stays still, bouncing balls never freeze,
 * and a box walks up the issue's ramp. Distances come from JTS, not from the library.
 */
class WorldSlideTest {

    static final String[] KINDS = {"rect", "circle", "capsule", "octagon", "triangle"};

    /** A mover of each kind, around (0, 0). */
    static Shape mover(String kind) {
        return switch (kind) {
            case "rect" -> new Rect(-10, -15, 20, 30);
            case "circle" -> new Circle(0, 0, 12);
            case "capsule" -> new Capsule(0, -10, 0, 10, 8);
            case "octagon" -> Polygon.regular(0, 0, 12, 8, 0).rotated(0.3f, 0, 0);
            case "triangle" -> Polygon.of(-12, 10, 12, 10, 0, -12);
            default -> throw new IllegalArgumentException(kind);
        };
    }

    /** How far apart two shapes are (JTS), a mover's radius taken off. */
    static double gap(Shape mover, Shape straightObstacle) {
        return JtsShapes.core(mover).distance(JtsShapes.straight(straightObstacle)) - JtsShapes.radius(mover);
    }

    // ---------------------------------------------------------------- along a slanted face

    @Property(tries = 150)
    void slideAlongATurnedSlab_keepsTheMotionAlongItsFace(@ForAll @IntRange(min = 0, max = 4) int kind,
                                                          @ForAll @FloatRange(min = -57, max = 57) float degrees,
                                                          @ForAll boolean forwards) {
        String k = KINDS[kind];
        World w = new World();
        float angle = (float) Math.toRadians(degrees);
        Body slab = w.add(new Rect(-400, 0, 800, 20), 400, 300, angle);
        double nx = Math.sin(angle), ny = -Math.cos(angle);  // out of the slab's top face
        Body b = w.add(mover(k), (float) (400 + nx * 40), (float) (300 + ny * 40), 0);
        for (int i = 0; i < 30; i++) {
            w.move(b, (float) (-nx * 2), (float) (-ny * 2));  // land on it
        }
        double tx = Math.cos(angle) * (forwards ? 1 : -1), ty = Math.sin(angle) * (forwards ? 1 : -1);
        String what = k + " on a slab at " + degrees + " degrees, " + (forwards ? "forwards" : "backwards");
        for (int f = 0; f < 60; f++) {
            float px = b.pivotX(), py = b.pivotY();
            Collisions got = w.move(b, (float) (tx * 2 - nx * 0.2), (float) (ty * 2 - ny * 0.2));  // along, pressing in
            double along = (b.pivotX() - px) * tx + (b.pivotY() - py) * ty;
            assertTrue(along >= 0.99 * 2 && along <= 2 + 1e-3, what + ": frame " + f + " went " + along + " along the face");
            assertTrue(got.finished(), what + ": frame " + f + " gave up: " + got);
            assertFalse(b.shape().overlaps(slab.shape()), what + ": inside at frame " + f);
            double gap = gap(b.shape(), slab.shape());
            assertTrue(gap >= 0 && gap <= 0.1, what + ": " + gap + " px off the face at frame " + f);
        }
    }

    // ---------------------------------------------------------------- round a convex obstacle

    /**
     * Every kind pushed right into a diamond or a hexagon, at heights where what meets first
     * is one of its slanted faces (not its left corner square on): it gets round.
     */
    @ParameterizedTest
    @ValueSource(strings = {"rect", "circle", "capsule", "octagon", "triangle"})
    void pushedIntoAConvexObstacleAwayFromItsExtremePoint_getsRound(String kind) {
        Shape probe = mover(kind);
        float half = (float) (Extents.maxY(probe) - Extents.minY(probe)) / 2;
        int cases = 0;
        for (int sides : new int[] {4, 6}) {
            for (float off = -36; off <= 36; off += 3) {
                boolean flatFront = kind.equals("rect") || kind.equals("capsule");
                if (Math.abs(off) < 2 || flatFront && Math.abs(off) <= half) {
                    continue;  // a flat face square on the corner: a head-on stop is right
                }
                World w = new World();
                Body obstacle = w.add(Polygon.regular(300, 200, 40, sides, 0));
                Body b = w.add(mover(kind), 150, 200 + off, 0);
                for (int f = 0; f < 200 && Extents.minX(b.shape()) < 345; f++) {
                    w.move(b, 2, 0);
                    assertFalse(b.shape().overlaps(obstacle.shape()));
                }
                assertTrue(Extents.minX(b.shape()) >= 340, kind + " at " + off + " px off the centre of a " + sides
                        + "-gon stopped at " + b.shape());
                cases++;
            }
        }
        assertTrue(cases > 20, "only " + cases);
    }

    // ---------------------------------------------------------------- a V

    @ParameterizedTest
    @ValueSource(strings = {"rect", "circle", "capsule", "octagon", "triangle"})
    void pushedDownIntoAV_comesToRestAtItsBottomAndStaysStill(String kind) {
        for (int s = 0; s < 5; s++) {
            World w = new World();
            Body left = w.add(new Rect(-200, 0, 200, 20), 300, 300, (float) Math.toRadians(25 + 6 * s));
            Body right = w.add(new Rect(0, 0, 200, 20), 300, 300, (float) Math.toRadians(-30 - 4 * s));
            Body b = w.add(mover(kind), 250 + 20 * s, 120, 0);
            for (int f = 0; f < 150; f++) {
                w.move(b, 0, 3);
            }
            Shape rest = b.shape();
            String what = kind + " in V " + s;
            assertTrue(gap(rest, left.shape()) <= 0.1 && gap(rest, right.shape()) <= 0.1,
                    what + ": not at the bottom, " + gap(rest, left.shape()) + " and " + gap(rest, right.shape()) + " px off");
            for (int f = 0; f < 40; f++) {
                Collisions got = w.move(b, 0, 3);
                assertEquals(rest, b.shape(), what + ": moved at frame " + f);
                assertTrue(got.finished(), what + ": " + got);
            }
        }
    }

    // ---------------------------------------------------------------- bouncing

    @Test
    void bouncingBallsAmongTurnedObstacles_neverFreeze() {
        SplittableRandom rnd = new SplittableRandom(28);
        World w = new World();
        w.add(new Rect(0, -20, 600, 20));
        w.add(new Rect(0, 600, 600, 20));
        w.add(new Rect(-20, 0, 20, 600));
        w.add(new Rect(600, 0, 20, 600));
        for (int i = 0; i < 24; i++) {
            float x = 40 + (float) rnd.nextDouble() * 520, y = 40 + (float) rnd.nextDouble() * 520;
            Shape s = i % 2 == 0 ? new Rect(-15, -15, 30, 30) : Polygon.of(-20, 15, 20, 15, 0, -20);
            w.add(s, x, y, (float) rnd.nextDouble() * 6);
        }
        List<Body> balls = new ArrayList<>();
        List<float[]> velocities = new ArrayList<>();
        while (balls.size() < 150) {
            Circle c = new Circle(15 + (float) rnd.nextDouble() * 570, 15 + (float) rnd.nextDouble() * 570, 3 + (float) rnd.nextDouble() * 4);
            if (!w.queryShape(c).isEmpty()) {
                continue;
            }
            Body b = w.add(c).layers(2, 1);  // balls pass each other, bounce off the rest
            balls.add(b);
            double a = rnd.nextDouble() * 2 * Math.PI;
            velocities.add(new float[] {(float) (4 * Math.cos(a)), (float) (4 * Math.sin(a))});
        }
        for (int f = 0; f < 400; f++) {
            for (int i = 0; i < balls.size(); i++) {
                Body b = balls.get(i);
                float[] v = velocities.get(i);
                Shape before = b.shape();
                Collisions got = w.move(b, v[0], v[1], (m, o) -> Reaction.BOUNCE);
                assertTrue(got.finished(), "ball " + i + " frame " + f + ": " + got);
                for (Collision c : got) {
                    float d = v[0] * c.nx() + v[1] * c.ny();
                    if (d > 0) {
                        v[0] -= 2 * d * c.nx();
                        v[1] -= 2 * d * c.ny();
                    }
                }
                assertNotEquals(before, b.shape(), "ball " + i + " froze at frame " + f + ": " + got);
            }
        }
    }

    @Test
    void bounceOffASlantedSurface_reflectsAboutItsNormal() {
        World w = new World();
        w.add(new Rect(-200, 0, 400, 20), 300, 300, (float) Math.toRadians(30));
        Body b = w.add(new Circle(0, 0, 5), 250, 200, 0);
        float dx = 0, dy = 100;
        Collisions got = w.move(b, dx, dy, (m, o) -> Reaction.BOUNCE);
        assertEquals(1, got.size(), got.toString());
        Collision c = got.get(0);
        // Mirror the path after the hit about the face: the end is the hit point plus the rest
        // of the motion, reflected (within the skin the body keeps from the face).
        double nx = -Math.sin(Math.toRadians(30)), ny = Math.cos(Math.toRadians(30));
        double rest = (1 - c.hit().t()) * dy;
        double rx = 0 - 2 * (rest * ny) * nx, ry = rest - 2 * (rest * ny) * ny;
        assertEquals(c.x() + rx, b.pivotX(), 0.05);
        assertEquals(c.y() + ry, b.pivotY(), 0.05);
        assertEquals(nx, c.nx(), 1e-6);
        assertEquals(ny, c.ny(), 1e-6);
    }

    // ---------------------------------------------------------------- the issue's ramp

    @Test
    void aBoxWalksUpTheIssuesRamp() {
        World world = new World();
        Body ramp = world.add(Polygon.of(0, 300, 400, 300, 400, 70));
        Body player = world.add(new Rect(20, 230, 20, 30));
        float vy = 0;
        for (int f = 0; f < 100; f++) {
            vy += 0.5f;
            float x = player.pivotX();
            Collisions got = world.move(player, 2, vy);
            for (Collision c : got) {
                if (c.ny() > 0.5f) {
                    vy = 0;
                }
            }
            assertTrue(got.finished(), "frame " + f + ": " + got);
            assertTrue(player.pivotX() > x, "frame " + f + ": no progress at " + player.shape());
            assertFalse(player.shape().overlaps(ramp.shape()));
        }
        // Gravity's part along the slope is kept for a plain body, so it climbs slower than 2 a frame.
        assertTrue(player.pivotX() > 150, "only reached " + player.shape());
        assertTrue(Extents.maxY(player.shape()) < 300 - 0.575 * 150 + 1, "not on the ramp: " + player.shape());
    }

    @Test
    void aMoveNeverRepeatsItsLastCollision() {
        World w = new World();
        w.add(new Rect(-200, 0, 400, 20), 300, 300, (float) Math.toRadians(20));
        w.add(new Rect(-200, 0, 400, 20), 300, 300, (float) Math.toRadians(-20));
        Body b = w.add(new Circle(0, 0, 10), 300, 250, 0);
        for (int f = 0; f < 50; f++) {
            Collisions got = w.move(b, 1, 5);
            for (int i = 1; i < got.size(); i++) {
                Collision p = got.get(i - 1), c = got.get(i);
                assertFalse(p.other() == c.other() && p.x() == c.x() && p.y() == c.y() && p.nx() == c.nx(),
                        "frame " + f + " repeats " + c);
            }
        }
    }
}
