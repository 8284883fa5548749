package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;

/**
 * {@link Contact#manifold} of two turned boxes against an oracle that does not share the
 * kernel's clipping: the manifold's documented rule (the reference face is the face of either
 * box most nearly along the normal, the incident edge the other box's face most nearly
 * against it, clipped to the reference box and its face's side lines; the ends behind the
 * face are the points) worked out with JTS, which clips the incident edge to the reference
 * box stretched far out beyond its face (so that an end in front of the face stays, and is
 * then dropped as in front).
 *
 * <p>The pinned cases are those of the narrow-phase table's "manifoldBoxes" question (seed
 * 97) where Hitbox gave one point and JBox2D and dyn4j two, the second inside both boxes:
 * the incident edge's end clipped onto the reference box's side line lies on that side to
 * rounding, and the ray along the face normal that measures its depth runs along that side,
 * so the rounding divided by the side's tiny cosine to the ray put the end outside the box,
 * at depth 0, and it was dropped. And case 127, where the two boxes' faces were taken as
 * equally along the normal (their cosines 7e-7 apart, their angles 0.0012 radians) and the
 * tie rule chose the face that leaves no incident edge inside.
 */
class ManifoldBoxClipTest {

    private static final GeometryFactory GF = new GeometryFactory();

    /** A point the oracle keeps must be this deep (relative to the scale); shallower ones are not checked. */
    private static final double CLEAR = 1e-5;

    /**
     * How far apart (in radians) the two shapes' faces' angles to the normal must be for the
     * oracle to call the reference face clear: far above the rounding of float corners.
     */
    private static final double CLEAR_ANGLE = 1e-4;

    // Case 35 of manifoldBoxes (seed 97): the second point (104.62, 28.83) at depth 0.694.
    private static final Polygon CASE35_A = Polygon.of(178.56967f, -4.502619f, 164.0625f, 46.473278f, 104.43032f, 29.502619f, 118.9375f, -21.473276f);
    private static final Polygon CASE35_B = Polygon.of(129.08075f, 23.886436f, 139.9861f, 77.79445f, 93.91925f, 87.11356f, 83.0139f, 33.205555f);

    /** The other five such cases of seed 97 (62, 144, 167, 363, 560), a and b. */
    private static final Polygon[][] OTHERS = {
        {Polygon.of(81.17091f, 88.21564f, 46.539646f, 116.9502f, 24.829086f, 90.78436f, 59.460354f, 62.049793f),
         Polygon.of(92.57045f, 52.908646f, 72.8173f, 97.75074f, 55.42955f, 90.091354f, 75.1827f, 45.249264f)},
        {Polygon.of(178.8965f, 27.445065f, 172.86494f, 85.13059f, 129.1035f, 80.55493f, 135.13506f, 22.869406f),
         Polygon.of(159.94261f, 1.9244456f, 192.65907f, 51.02265f, 146.05739f, 82.075554f, 113.340935f, 32.97735f)},
        {Polygon.of(46.734425f, 46.215755f, 27.161604f, 109.246735f, -38.734425f, 88.78425f, -19.161604f, 25.753262f),
         Polygon.of(47.79221f, 15.097043f, 44.008656f, 62.947693f, -19.79221f, 57.902958f, -16.008657f, 10.052306f)},
        {Polygon.of(66.20911f, 111.18102f, 76.79089f, 136.02103f, 53.790897f, 145.81898f, 43.209103f, 120.97898f),
         Polygon.of(59.9165f, 125.69297f, 59.08116f, 193.68784f, 28.083502f, 193.30702f, 28.918839f, 125.31216f)},
        {Polygon.of(-23.0f, -21.0f, 34.0f, -21.0f, 34.0f, 29.0f, -23.0f, 29.0f),
         Polygon.of(30.83312f, 23.491045f, 61.771397f, 31.665577f, 45.16688f, 94.50896f, 14.228602f, 86.33442f)},
    };

    @Test
    void case35_twoPoints_theSecondOnTheReferenceBoxsSideAtDepth0_69() {
        for (boolean swap : new boolean[] {false, true}) {
            Polygon a = swap ? CASE35_B : CASE35_A, b = swap ? CASE35_A : CASE35_B;
            Manifold m = Contact.manifold(a, b);
            assertNotNull(m);
            assertEquals(2, m.pointCount(), "both points of " + m);
            // By JBox2D's and dyn4j's clipping and the oracle: the corner (129.08, 23.89) at the
            // contact's depth, and the end clipped to the side, (104.620, 28.835), 0.6945 deep.
            int side = m.x(0) < m.x(1) ? 0 : 1;
            assertEquals(104.62042, m.x(side), 1e-3);
            assertEquals(28.834653, m.y(side), 1e-3);
            assertEquals(0.694489, m.depth(side), 1e-4);
            assertEquals(129.08075f, m.x(1 - side));
            assertEquals(23.886436f, m.y(1 - side));
            assertEquals(m.contact().depth(), m.depth(1 - side));
            assertAsTheOracle(a, b, true);
        }
    }

    @Test
    void aBoxTurned0_07DegreesInsideAnUprightOne_theUprightFaceIsTheReference_twoPoints() {
        // Case 127 of manifoldBoxes (seed 97): a 36 x 43 box turned 0.068 degrees from upright,
        // wholly inside an upright box. The upright box's bottom face is along the normal (0, 1)
        // exactly, the turned box's top face 0.0012 radians off it: not a tie (the cosines differ
        // by only 7e-7, which a cosine slack of 1e-6 took for one). The turned box's top edge is
        // the incident edge, both its corners inside: two points, as dyn4j's, 0.043 apart in depth.
        Polygon a = Polygon.of(192.47443f, -15.021379f, 192.52554f, 27.97859f, 156.52557f, 28.02138f, 156.47446f, -14.97859f);
        Polygon b = Polygon.of(138.5f, -22.0f, 208.5f, -22.0f, 208.5f, 45.0f, 138.5f, 45.0f);
        Manifold m = Contact.manifold(a, b);
        assertEquals(new Manifold(new Contact(0, 1, 50.021378f), 2, 156.52557f, 28.02138f, 50.021378f, 192.52554f, 27.97859f, 49.978592f), m);
        assertEquals(m.flipped(), Contact.manifold(b, a));
        assertAsTheOracle(a, b, true);
        assertAsTheOracle(b, a, true);
    }

    @Test
    void theOtherTableCases_twoPointsAsTheOracle_bothOrders() {
        for (Polygon[] pair : OTHERS) {
            assertAsTheOracle(pair[0], pair[1], true);
            assertAsTheOracle(pair[1], pair[0], true);
        }
    }

    @Test
    void randomTurnedBoxes_asTheOracle_bothOrders() {
        // Boxes as the table's generator makes them (whole or half-pixel centres, 10 to 70 a
        // side, square to the axes in 1 case of 4, else turned by a random angle), and 1 in 4
        // turned a little off square, whose faces are nearly but not quite along an upright one's.
        Random rnd = new Random(23);
        int checked = 0, two = 0;
        for (int k = 0; k < 20000; k++) {
            Polygon a = box(rnd), b = box(rnd);
            if (!a.overlaps(b)) {
                continue;
            }
            int n = assertAsTheOracle(a, b, false);
            if (n > 0) {
                assertAsTheOracle(b, a, false);
                checked++;
                two += n == 2 ? 1 : 0;
            }
        }
        // Enough checked (most pairs of boxes this close overlap, and most have a clear reference face).
        assertTrue(checked > 1500, "pairs checked " + checked);
        assertTrue(two > 500, "two-point pairs checked " + two);
    }

    /** A box as the table's, or 1 in 4 turned a little (up to 0.2 degrees) off a right angle. */
    private static Polygon box(Random r) {
        int kind = r.nextInt(4);
        float angle = kind == 0 ? 0 : kind == 1 ? (float) (r.nextInt(4) * Math.PI / 2 + (r.nextDouble() - 0.5) * 0.007)
                : (float) (r.nextDouble() * Math.PI);
        float cx = 20 + r.nextInt(120) / 2f, cy = 20 + r.nextInt(120) / 2f;
        return Polygon.of(Rect.centered(cx, cy, 10 + r.nextInt(61), 10 + r.nextInt(61))).rotated(angle, cx, cy);
    }

    /**
     * Checks the manifold of a and b against the oracle where the oracle's answer is clear (a
     * clear reference face and incident edge, each kept end clearly behind the face or in front
     * of it, at least one kept); returns the oracle's count, 0 where it did not check. With
     * {@code mustCheck} an unclear case fails. The reference shape must be a box (its face's
     * side lines are its neighbouring faces); the incident one may be any convex polygon.
     */
    static int assertAsTheOracle(Polygon a, Polygon b, boolean mustCheck) {
        Manifold m = Contact.manifold(a, b);
        assertNotNull(m, a + " and " + b);
        double nx = m.contact().nx(), ny = m.contact().ny();
        double scale = scale(a, b);
        // The reference face: of a's faces the one most along n, of b's the one most against it.
        double[] fa = faces(a), fb = faces(b);
        int ia = best(fa, nx, ny), ib = best(fb, -nx, -ny);
        // By their angles to the normal (near it the cosines differ by the angles' squares).
        double ta = Math.atan2(Math.abs(fa[6 * ia] * ny - fa[6 * ia + 1] * nx), along(fa, ia, nx, ny));
        double tb = Math.atan2(Math.abs(fb[6 * ib] * ny - fb[6 * ib + 1] * nx), along(fb, ib, -nx, -ny));
        if (Math.abs(ta - tb) < CLEAR_ANGLE) {
            assertTrue(!mustCheck, "no clear reference face for " + a + " and " + b);
            return 0;
        }
        boolean refA = ta < tb;
        Polygon ref = refA ? a : b, inc = refA ? b : a;
        double[] fr = refA ? fa : fb, fi = refA ? fb : fa;
        int f = refA ? ia : ib;
        double ux = fr[6 * f], uy = fr[6 * f + 1];
        // The stretched slab below is the face's side lines only when the reference is a box.
        assertEquals(4, ref.size(), "the oracle's reference must be a box: " + ref);
        for (int k = 0; k < 4; k++) {
            assertTrue(Math.abs(along(fr, k, fr[6 * ((k + 1) % 4)], fr[6 * ((k + 1) % 4) + 1])) < 1e-6,
                    "the oracle's reference must be a box: " + ref);
        }
        // The incident edge: inc's face most against u, clearly, by their angles to -u (near
        // -u the cosines differ by the angles' squares).
        int g = best(fi, -ux, -uy);
        for (int k = 0; k < fi.length / 6; k++) {
            if (k != g && angle(fi, k, -ux, -uy) - angle(fi, g, -ux, -uy) < CLEAR_ANGLE) {
                assertTrue(!mustCheck, "no clear incident edge for " + a + " and " + b);
                return 0;
            }
        }
        // The reference box stretched far out beyond its face: JTS clips the incident edge to it.
        double far = 10 * scale;
        List<Coordinate> ring = new ArrayList<>();
        int n = ref.size();
        for (int i = 0; i < n; i++) {
            boolean onFace = i == f || i == (f + 1) % n;
            ring.add(new Coordinate(ref.x(i) + (onFace ? far * ux : 0), ref.y(i) + (onFace ? far * uy : 0)));
        }
        ring.add(ring.get(0));
        Geometry slab = GF.createPolygon(ring.toArray(new Coordinate[0]));
        Geometry edge = GF.createLineString(new Coordinate[] {
            new Coordinate(fi[6 * g + 2], fi[6 * g + 3]), new Coordinate(fi[6 * g + 4], fi[6 * g + 5])});
        Coordinate[] clipped = slab.intersection(edge).getCoordinates();
        if (clipped.length == 0) {
            assertTrue(!mustCheck, "the incident edge misses the reference box: " + a + " and " + b);
            return 0;
        }
        Coordinate[] ends = {clipped[0], clipped[clipped.length - 1]};
        double faceC = ux * fr[6 * f + 2] + uy * fr[6 * f + 3];
        List<double[]> want = new ArrayList<>();
        for (Coordinate e : ends) {
            double depth = faceC - (ux * e.x + uy * e.y);
            if (Math.abs(depth) < CLEAR * scale) {
                assertTrue(!mustCheck, "an end on the face: " + a + " and " + b);
                return 0;
            }
            if (depth > 0 && (want.isEmpty() || Math.hypot(e.x - want.get(0)[0], e.y - want.get(0)[1]) > CLEAR * scale)) {
                want.add(new double[] {e.x, e.y, depth});
            }
        }
        if (want.isEmpty()) {
            assertTrue(!mustCheck, "no end behind the face: " + a + " and " + b);
            return 0;
        }
        String what = a + " and " + b + ": " + m + ", the oracle's points (x, y, depth) "
                + want.stream().map(java.util.Arrays::toString).toList();
        assertEquals(want.size(), m.pointCount(), "the count, " + what);
        double tol = Manifold.TOLERANCE * scale;
        for (double[] w : want) {
            boolean found = false;
            for (int i = 0; i < m.pointCount(); i++) {
                found |= Math.abs(m.x(i) - w[0]) <= tol && Math.abs(m.y(i) - w[1]) <= tol && Math.abs(m.depth(i) - w[2]) <= tol;
            }
            assertTrue(found, "the point " + java.util.Arrays.toString(w) + " of " + what);
        }
        return want.size();
    }

    /** The polygon's faces, wound either way: outward unit normal and the two ends, six numbers each. */
    private static double[] faces(Polygon p) {
        int n = p.size();
        double area = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            area += (double) p.x(i) * p.y(j) - (double) p.x(j) * p.y(i);
        }
        double sign = area > 0 ? 1 : -1;
        double[] out = new double[6 * n];
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = (double) p.x(j) - p.x(i), ey = (double) p.y(j) - p.y(i), len = Math.hypot(ex, ey);
            out[6 * i] = sign * ey / len;
            out[6 * i + 1] = -sign * ex / len;
            out[6 * i + 2] = p.x(i);
            out[6 * i + 3] = p.y(i);
            out[6 * i + 4] = p.x(j);
            out[6 * i + 5] = p.y(j);
        }
        return out;
    }

    private static int best(double[] faces, double ux, double uy) {
        int best = 0;
        for (int k = 1; k < faces.length / 6; k++) {
            best = along(faces, k, ux, uy) > along(faces, best, ux, uy) ? k : best;
        }
        return best;
    }

    /** The angle, in [0, pi], between face k's normal and unit (ux, uy). */
    private static double angle(double[] faces, int k, double ux, double uy) {
        return Math.atan2(Math.abs(faces[6 * k] * uy - faces[6 * k + 1] * ux), along(faces, k, ux, uy));
    }

    private static double along(double[] faces, int k, double ux, double uy) {
        return faces[6 * k] * ux + faces[6 * k + 1] * uy;
    }

    private static double scale(Shape a, Shape b) {
        double s = 1;
        for (Shape t : new Shape[] {a, b}) {
            s = Math.max(s, Math.max(Math.max(Math.abs(Extents.minX(t)), Math.abs(Extents.maxX(t))), Math.max(Math.abs(Extents.minY(t)), Math.abs(Extents.maxY(t)))));
            s = Math.max(s, Math.max(Extents.maxX(t) - Extents.minX(t), Extents.maxY(t) - Extents.minY(t)));
        }
        return s;
    }
}
