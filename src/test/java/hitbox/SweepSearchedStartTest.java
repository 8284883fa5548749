package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Hit's t = 0 promise for the pairs answered by a search (conservative advancement: an
 * ellipse, a capsule or a polygon against a curved shape): a mover that touches at the start,
 * at a place that is not axis-aligned (so the touching is exact only to the float rounding
 * of its position), and moves in gets t = 0; one a clear gap away does not.
 */
class SweepSearchedStartTest {

    /** A circle of radius r touching the ellipse (a, b at the origin) at parameter angle deg, outside. */
    private static Circle touchingCircle(float a, float b, float r, double deg, double gap) {
        double th = Math.toRadians(deg);
        double px = a * Math.cos(th), py = b * Math.sin(th);
        double nx = Math.cos(th) / a, ny = Math.sin(th) / b, len = Math.hypot(nx, ny);
        return new Circle((float) (px + (r + gap) * nx / len), (float) (py + (r + gap) * ny / len), r);
    }

    /** The unit outward normal of that ellipse at parameter angle deg. */
    private static double[] normal(float a, float b, double deg) {
        double th = Math.toRadians(deg);
        double nx = Math.cos(th) / a, ny = Math.sin(th) / b, len = Math.hypot(nx, ny);
        return new double[] {nx / len, ny / len};
    }

    @Test
    void circleTouchingAnEllipseAtAnAngle_movingIn_isZero() {
        Ellipse e = new Ellipse(0, 0, 20, 10);
        for (int deg = 5; deg < 360; deg += 25) {
            Circle c = touchingCircle(20, 10, 4, deg, 0);
            double[] n = normal(20, 10, deg);
            // Into the ellipse along its normal, and slanting in at 45 degrees off it.
            for (double turn : new double[] {0, Math.PI / 4, -Math.PI / 4}) {
                float vx = (float) (-8 * (n[0] * Math.cos(turn) - n[1] * Math.sin(turn)));
                float vy = (float) (-8 * (n[0] * Math.sin(turn) + n[1] * Math.cos(turn)));
                String what = c + " at " + deg + " degrees, moving " + vx + ", " + vy;
                Hit h = Sweep.timeOfImpact(c, vx, vy, e);
                assertNotNull(h, what);
                assertEquals(0f, h.t(), what + ": " + h);
                Hit back = Sweep.timeOfImpact(e, -vx, -vy, c);
                assertNotNull(back, what);
                assertEquals(0f, back.t(), what + ", the ellipse moving: " + back);
            }
        }
    }

    @Test
    void capsuleAndPolygonTouchingAtAnAngle_movingIn_areZero() {
        Ellipse e = new Ellipse(0, 0, 20, 10);
        for (int deg = 10; deg < 360; deg += 40) {
            Circle c = touchingCircle(20, 10, 3, deg, 0);
            double[] n = normal(20, 10, deg);
            float vx = (float) (-6 * n[0]), vy = (float) (-6 * n[1]);
            // A capsule whose end circle is that circle, lying along the normal, away from the ellipse.
            Capsule cap = new Capsule(c.x(), c.y(), (float) (c.x() + 10 * n[0]), (float) (c.y() + 10 * n[1]), 3);
            Hit h = Sweep.timeOfImpact(cap, vx, vy, e);
            assertNotNull(h, cap + " at " + deg);
            assertEquals(0f, h.t(), cap + " at " + deg + ": " + h);
            // A square whose corner is the touching point of the circle... placed on the
            // ellipse's tangent: its side along the tangent, touching at the middle.
            double px = c.x() - 3 * n[0], py = c.y() - 3 * n[1], tx = -n[1], ty = n[0];
            Polygon sq = Polygon.of((float) (px - 2 * tx), (float) (py - 2 * ty), (float) (px + 2 * tx), (float) (py + 2 * ty),
                    (float) (px + 2 * tx + 4 * n[0]), (float) (py + 2 * ty + 4 * n[1]),
                    (float) (px - 2 * tx + 4 * n[0]), (float) (py - 2 * ty + 4 * n[1]));
            Hit hp = Sweep.timeOfImpact(sq, vx, vy, e);
            assertNotNull(hp, sq + " at " + deg);
            assertEquals(0f, hp.t(), sq + " at " + deg + ": " + hp);
        }
    }

    @Test
    void aClearGapAtTheStart_isNotZero() {
        Ellipse e = new Ellipse(0, 0, 20, 10);
        for (int deg = 5; deg < 360; deg += 25) {
            Circle c = touchingCircle(20, 10, 4, deg, 0.01);
            double[] n = normal(20, 10, deg);
            Hit h = Sweep.timeOfImpact(c, (float) (-8 * n[0]), (float) (-8 * n[1]), e);
            assertNotNull(h);
            // 0.01 px at 8 px a frame: about t = 0.00125, never 0.
            assertTrue(h.t() > 0.001f && h.t() < 0.0015f, deg + ": " + h);
        }
    }

    @Test
    void turningSquareTouchingAnEllipseAtAnAngle_movingIn_isZero() {
        Ellipse e = new Ellipse(0, 0, 20, 10);
        for (int deg = 10; deg < 360; deg += 40) {
            double[] n = normal(20, 10, deg);
            double th = Math.toRadians(deg);
            double px = 20 * Math.cos(th), py = 10 * Math.sin(th), tx = -n[1], ty = n[0];
            for (double gap : new double[] {0, 0.05}) {
                double qx = px + gap * n[0], qy = py + gap * n[1];
                Polygon sq = Polygon.of((float) (qx - 2 * tx), (float) (qy - 2 * ty), (float) (qx + 2 * tx),
                        (float) (qy + 2 * ty), (float) (qx + 2 * tx + 4 * n[0]), (float) (qy + 2 * ty + 4 * n[1]),
                        (float) (qx - 2 * tx + 4 * n[0]), (float) (qy - 2 * ty + 4 * n[1]));
                // Turning a little about its far side's middle while moving in along the normal.
                float pivotX = (float) (qx + 4 * n[0]), pivotY = (float) (qy + 4 * n[1]);
                Hit h = Sweep.turningTimeOfImpact(sq, pivotX, pivotY, (float) (-6 * n[0]), (float) (-6 * n[1]), 0.01f, e);
                assertNotNull(h, deg + " gap " + gap);
                if (gap == 0) {
                    assertEquals(0f, h.t(), deg + ": " + h);
                } else {
                    assertTrue(h.t() > 0.005f && h.t() < 0.01f, deg + " gap " + gap + ": " + h);
                }
            }
        }
    }
}
