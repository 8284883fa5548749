package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.statistics.Statistics;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The reason swept tests exist: small, fast objects never pass through thin walls. A 2x2 box
 * and a circle of radius 1 fly at up to 10,000 pixels a frame, in every direction, at walls
 * one or half a pixel thick; moving then testing where they land would miss almost all of
 * these.
 */
class NoTunnellingTest {

    @ParameterizedTest(name = "speed {0}, wall {1} thick")
    @CsvSource({
            "10, 1", "10, 0.5", "100, 1", "100, 0.5", "1000, 1", "1000, 0.5",
            "5000, 0.5", "10000, 1", "10000, 0.5",
    })
    void fastSmallObjects_alwaysHitAThinWall(float speed, float thickness) {
        for (int degrees = 0; degrees < 360; degrees += 5) {
            double a = Math.toRadians(degrees + 0.3);  // never exactly along an axis
            float vx = (float) (speed * Math.cos(a)), vy = (float) (speed * Math.sin(a));
            // A wall across the motion, halfway along it, long enough to catch any angle.
            boolean upright = Math.abs(vx) >= Math.abs(vy);
            float half = speed / 2;
            Rect wall = upright
                    ? new Rect(Math.signum(vx) * half, -2 * speed, thickness, 4 * speed)
                    : new Rect(-2 * speed, Math.signum(vy) * half, 4 * speed, thickness);
            String where = "at " + degrees + " degrees, wall " + wall;

            Rect box = new Rect(-1, -1, 2, 2);
            float t = Sweep.rectRect(box.x(), box.y(), 2, 2, vx, vy, wall.x(), wall.y(), wall.w(), wall.h());
            assertTrue(t < 1, "box missed " + where);
            Hit boxHit = Sweep.timeOfImpact(box, vx, vy, wall);
            assertNotNull(boxHit, "box missed " + where);
            assertEquals(upright, (boxHit.side() == Side.LEFT || boxHit.side() == Side.RIGHT), where);
            // Stopped at the impact, it touches the wall and is not inside it.
            assertFalse(Collide.rectRect(box.x() + boxHit.t() * vx * 0.999999f, box.y() + boxHit.t() * vy * 0.999999f, 2, 2,
                    wall.x(), wall.y(), wall.w(), wall.h()), where);

            Sweep.Move move = Sweep.move(box, vx, vy, List.of(wall));
            assertTrue(move.hitAnything(), "move went through " + where);
            assertFalse(Collide.rectRect(move.x(), move.y(), 2, 2, wall.x(), wall.y(), wall.w(), wall.h()), where);
            assertTrue(upright ? Math.abs(move.x()) < half : Math.abs(move.y()) < half, "move ended beyond " + where);

            Circle ball = new Circle(0, 0, 1);
            Hit ballHit = Sweep.timeOfImpact(ball, vx, vy, wall);
            assertNotNull(ballHit, "ball missed " + where);
            assertEquals(boxHit.side(), ballHit.side(), where);

            // The wall's near face as a segment, and the ball against it.
            Segment face = upright
                    ? new Segment(wall.x() + (vx > 0 ? 0 : thickness), wall.y(), wall.x() + (vx > 0 ? 0 : thickness), wall.bottom())
                    : new Segment(wall.x(), wall.y() + (vy > 0 ? 0 : thickness), wall.right(), wall.y() + (vy > 0 ? 0 : thickness));
            assertNotNull(Sweep.timeOfImpact(ball, vx, vy, face), "ball missed " + face);
            assertNotNull(Sweep.timeOfImpact(box, vx, vy, face), "box missed " + face);
            assertEquals(boxHit.t(), Sweep.timeOfImpact(box, vx, vy, face).t(), 1e-6f, "the face is where the wall starts");
        }
    }

    @ParameterizedTest(name = "speed {0}")
    @CsvSource({"10", "1000", "10000"})
    void fastSmallCircles_alwaysHitASmallCircle(float speed) {
        for (int degrees = 0; degrees < 360; degrees += 5) {
            double a = Math.toRadians(degrees + 0.3);
            float vx = (float) (speed * Math.cos(a)), vy = (float) (speed * Math.sin(a));
            float t = Raw.sweepCircleCircle(0, 0, 1, vx, vy, vx / 2, vy / 2, 0.5f);
            assertTrue(t < 1, "missed at " + degrees);
            assertEquals((speed / 2 - 1.5f) / speed, t, 1e-5f);
        }
    }

    /**
     * No swept test misses a wall its straight path crosses, and none reports a hit it should
     * not. The truth comes from exact interval arithmetic (SweepReference) and from sampling
     * the path densely enough (steps shorter than the wall is thick) that no crossing can
     * fall between two samples.
     */
    @StatisticsReport(onFailureOnly = true)
    @Property(tries = 1500)
    void sweptTests_neverMissAWallThePathCrosses(
            @ForAll @IntRange(min = -200, max = 200) int sx, @ForAll @IntRange(min = -200, max = 200) int sy,
            @ForAll @IntRange(min = -400, max = 400) int wallX, @ForAll @IntRange(min = -400, max = 400) int wallY,
            @ForAll @IntRange(min = 0, max = 1) int thin, @ForAll @IntRange(min = 1, max = 200) int length,
            @ForAll @IntRange(min = 0, max = 1) int upright,
            @ForAll @IntRange(min = 0, max = 200) int aimAt, @ForAll @IntRange(min = 100, max = 4000) int overshoot,
            @ForAll @IntRange(min = -3, max = 3) int jitter) {
        float thickness = thin == 1 ? 0.5f : 1f;
        Rect wall = upright == 1
                ? new Rect(wallX, wallY, thickness, length)
                : new Rect(wallX, wallY, length, thickness);
        // Aim at a point along the wall (mostly crossing it), and fly past it by up to 40x
        // the distance: speeds up to tens of thousands of pixels a frame.
        float ax = upright == 1 ? wallX + thickness / 2 : wallX + length * aimAt / 200f;
        float ay = upright == 1 ? wallY + length * aimAt / 200f : wallY + thickness / 2;
        float vx = (ax - sx) * overshoot / 100f + jitter, vy = (ay - sy) * overshoot / 100f - jitter;

        // The 2x2 box.
        float t = Sweep.rectRect(sx - 1, sy - 1, 2, 2, vx, vy, wall.x(), wall.y(), wall.w(), wall.h());
        SweepReference.Q exact = SweepReference.rectRect(sx - 1, sy - 1, 2, 2, vx, vy, wall.x(), wall.y(), wall.w(), wall.h());
        assertEquals(exact != null, t <= 1, "box: t = " + t);
        boolean sampled = sampledCrossing(vx, vy, thickness, s -> Collide.rectRect(
                (float) (sx - 1 + s * vx), (float) (sy - 1 + s * vy), 2, 2, wall.x(), wall.y(), wall.w(), wall.h()));
        assertTrue(!sampled || t <= 1, "box went through the wall between samples");

        // The circle of radius 1.
        Hit ball = Raw.sweepCircleRectHit(sx, sy, 1, vx, vy, wall.x(), wall.y(), wall.w(), wall.h());
        assertEquals(SweepReference.circleRectHits(sx, sy, 1, vx, vy, wall.x(), wall.y(), wall.w(), wall.h()), ball != null);
        boolean sampledBall = sampledCrossing(vx, vy, thickness, s -> Collide.circleRect(
                (float) (sx + s * vx), (float) (sy + s * vy), 1, wall.x(), wall.y(), wall.w(), wall.h()));
        assertTrue(!sampledBall || ball != null, "ball went through the wall between samples");
        Statistics.label("box").collect(t <= 1 ? "hits" : "misses");
        double speed = Math.hypot(vx, vy);
        Statistics.label("speed").collect(speed > 10_000 ? "over 10000 px/frame" : speed > 1000 ? "1000 to 10000 px/frame" : "up to 1000 px/frame");
    }

    /** Does any sample along the motion, spaced less than half the wall's thickness apart, overlap? */
    private static boolean sampledCrossing(float vx, float vy, float thickness, java.util.function.DoublePredicate overlapsAt) {
        double length = Math.hypot(vx, vy);
        int n = (int) Math.ceil(length / (thickness / 2)) + 1;
        for (int k = 0; k <= n; k++) {
            if (overlapsAt.test((double) k / n)) {
                return true;
            }
        }
        return false;
    }
}
