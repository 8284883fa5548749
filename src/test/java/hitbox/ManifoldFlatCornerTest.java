package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@link Contact#manifold} where the incident shape meets the reference face with a very flat
 * corner (179.91 to 179.99 degrees): its two faces there are both within 0.08 degrees of
 * straight against the face, one of them more nearly so. The rule takes that one as the
 * incident edge (as Box2D and dyn4j do); the faces are neither in line (their union would
 * skip the corner) nor equally against the face (the corner alone would drop the edge's other
 * end). Checked with {@link ManifoldBoxClipTest}'s oracle, which picks the faces from the
 * coordinates by their angles and clips with JTS, in both orders.
 */
class ManifoldFlatCornerTest {

    /** A wide box with its top at y = top. */
    private static Polygon floor(float top) {
        return Polygon.of(-100, -50, 100, -50, 100, top, -100, top);
    }

    /** A polygon whose bottom is the corner (0, 0) with its ends (-50, left) and (50, right) above it. */
    private static Polygon flatBottom(float left, float right) {
        return Polygon.of(-50, left, 0, 0, 50, right, 50, 30, -50, 30);
    }

    @Test
    void aCornerOf179_93Degrees_theLeftFaceIsIncident_itsTwoEnds() {
        // The faces turn 0.0003 and 0.0009 radians off level (their cosines 3.6e-7 apart, and
        // 7.2e-7 apart from each other): the left face is the incident edge, both its ends
        // inside, (-50, 0.015) 0.985 deep and the corner (0, 0) 1 deep; not the right face's
        // far end (50, 0.045).
        Polygon a = floor(1), b = flatBottom(0.015f, 0.045f);
        Manifold m = Contact.manifold(a, b);
        assertEquals(2, m.pointCount(), m.toString());
        int left = m.x(0) < m.x(1) ? 0 : 1;
        assertEquals(-50, m.x(left), 1e-4);
        assertEquals(0.985, m.depth(left), 1e-4);
        assertEquals(0, m.x(1 - left), 1e-4);
        assertEquals(0, m.y(1 - left), 1e-4);
        assertEquals(1, m.depth(1 - left), 1e-4);
        assertEquals(m.flipped(), Contact.manifold(b, a));
        assertEquals(2, ManifoldBoxClipTest.assertAsTheOracle(a, b, true));
        assertEquals(2, ManifoldBoxClipTest.assertAsTheOracle(b, a, true));
    }

    @Test
    void aCornerOf179_93DegreesJustIn_twoPointsNotOne() {
        // The same corner 0.03 into the floor: the left face lies wholly behind the floor's top,
        // two points; the union of the two faces ends at (50, 0.045), in front of it, one.
        Polygon a = floor(0.03f), b = flatBottom(0.015f, 0.045f);
        assertEquals(2, ManifoldBoxClipTest.assertAsTheOracle(a, b, true));
        assertEquals(2, ManifoldBoxClipTest.assertAsTheOracle(b, a, true));
    }

    @Test
    void aCornerOf179_91Degrees_notTheCornerAlone() {
        // Faces 0.0003 and 0.0013 radians off level: not in line even by cosines (1.3e-6 apart),
        // but equally against the floor by them (8e-7 apart), and the corner alone was kept.
        Polygon a = floor(1), b = flatBottom(0.015f, 0.065f);
        assertEquals(2, ManifoldBoxClipTest.assertAsTheOracle(a, b, true));
        assertEquals(2, ManifoldBoxClipTest.assertAsTheOracle(b, a, true));
    }

    @Test
    void flatCornersTurnedAndPlaced_asTheOracle_bothOrders() {
        // Corners of 179.92 to 179.99 degrees (faces 0.0001 to 0.0013 radians off level, on
        // either side), at depths from 0.01 to 2, the pair turned about the origin and moved.
        java.util.Random rnd = new java.util.Random(5);
        int checked = 0;
        for (int k = 0; k < 400; k++) {
            double tl = 1e-4 + rnd.nextDouble() * 1.2e-3, tr = 1e-4 + rnd.nextDouble() * 1.2e-3;
            if (Math.abs(tl - tr) < 2e-4) {
                continue;
            }
            float top = (float) (0.01 + rnd.nextDouble() * 2);
            float angle = (float) (rnd.nextDouble() * 2 * Math.PI);
            float dx = rnd.nextInt(200) - 100, dy = rnd.nextInt(200) - 100;
            Polygon a = floor(top).rotated(angle, 0, 0).translated(dx, dy);
            Polygon b = flatBottom((float) (50 * Math.tan(tl)), (float) (50 * Math.tan(tr))).rotated(angle, 0, 0).translated(dx, dy);
            int n = ManifoldBoxClipTest.assertAsTheOracle(a, b, false);
            if (n > 0) {
                ManifoldBoxClipTest.assertAsTheOracle(b, a, false);
                checked++;
            }
        }
        assertTrue(checked > 200, "pairs checked " + checked);
    }
}
