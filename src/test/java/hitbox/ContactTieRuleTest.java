package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.internal.Supports;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.PropertyDefaults;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import org.junit.jupiter.api.Test;

/**
 * Issue 23, item 5: the tie rule of {@link Contact} decided by the rule, not by the rounding of
 * the computed normals; and the exact fit whose push {@link Response#separate} overshot.
 */
@PropertyDefaults(shrinking = ShrinkingMode.OFF)
class ContactTieRuleTest {

    private static final float S = (float) Math.sqrt(0.5);

    /** A regular polygon of n corners, radius r, centre (cx, cy), first corner at angle 0, mirrored in y if asked. */
    private static Polygon regular(int n, double r, double cx, double cy, boolean mirrorY) {
        float[] xy = new float[2 * n];
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n;
            xy[2 * i] = (float) (cx + r * Math.cos(a));
            xy[2 * i + 1] = (float) (cy + (mirrorY ? -1 : 1) * r * Math.sin(a));
        }
        return Polygon.of(xy);
    }

    private static void assertNormal(float nx, float ny, Contact c, String what) {
        assertNotNull(c, what);
        assertEquals(nx, c.nx(), 1e-6f, () -> what + ": " + c);
        assertEquals(ny, c.ny(), 1e-6f, () -> what + ": " + c);
    }

    @Test
    void pentagonAgainstHexagon_mirrored_bothGoToThePositiveDiagonal() {
        // Before: (0.866, -0.5) one way and (0.866, 0.5) mirrored; the |ny| differed by an ulp.
        float c30 = (float) Math.cos(Math.PI / 6);
        for (boolean mirror : new boolean[] {false, true}) {
            Contact c = (regular(5, 1, -1, 0, mirror)).contact(regular(6, 0.5, 0, 0, mirror));
            assertNormal(c30, 0.5f, c, "mirrored " + mirror);
        }
    }

    @Test
    void circleAndEllipse_concentric_upAndDownTie_theRuleSaysUp() {
        // Before: (1.6e-8, -1), the search's stopping place deciding.
        assertEquals(new Contact(0, 1, 1.5f), new Circle(0, 0, 1).contact(new Ellipse(0, 0, 1, 0.5f)));
        assertEquals(new Contact(0, 1, 1.5f), new Ellipse(0, 0, 1, 0.5f).contact(new Circle(0, 0, 1)));
        assertEquals(new Contact(0, 1, 1.5f), Raw.contactEllipseCircle(0, 0, 1, 0.5f, 0, 0, 1));
    }

    @Test
    void ellipseAndVerticalCapsule_concentric_upAndDownTie_theRuleSaysUp() {
        // Up and down: 0.5 + 0.25 + 0.25 = 1; sideways 1 + 0.25.
        Ellipse e = new Ellipse(0, 0, 1, 0.5f);
        Capsule k = new Capsule(0, -0.25f, 0, 0.25f, 0.25f);
        assertEquals(new Contact(0, 1, 1), e.contact(k));
        assertEquals(new Contact(0, 1, 1), k.contact(e));
        // A taller capsule: the vertical ones are the longer way, left and right tie.
        Capsule tall = new Capsule(0, -1, 0, 1, 0.5f);
        assertEquals(new Contact(1, 0, 1.5f), e.contact(tall));
        assertEquals(new Contact(1, 0, 1.5f), tall.contact(e));
    }

    @Test
    void twoDiagonalPushes_equallyShort_goToPositiveNxTimesNy() {
        // Edges (3, 3) and (-2, 2) long: the two unit normals' |ny| differ by an ulp; before,
        // (-0.707, 0.707) won.
        assertNormal(S, S, (Polygon.of(0, 0, 3, 3, 1, 5, -2, 2)).contact(Polygon.of(1, 4, 2, 5, -3, 10, -4, 9)), "small");
        assertNormal(S, S, (Polygon.of(0, 0, 3, 3, -2, 8, -5, 5)).contact(Polygon.of(-2, 4, 3, 9, -2, 14, -7, 9)), "large");
    }

    @Test
    void concavePolygonAgainstEllipse_upAndADiagonalEquallyShort_theRuleSaysUp_mirroredToo() {
        // The ellipse leaves the concave polygon up, (0, -1), or along (-0.6, 0.8), both by
        // exactly 4 (dense sampling of the push over 3600 directions finds no other least
        // value at 4; down is 4.6); the rule prefers the larger |ny|, so up, and mirrored in x
        // the same. Before: (0, -1) one way and (0.6, 0.8) mirrored, the search's first found
        // of the equally short pushes winning.
        Polygon p = Polygon.of(1, 1, 1, 2, -3, -1, -2, -3, 2, -2, 3, 2);
        Ellipse e = new Ellipse(-2, -1, 5, 2);
        Polygon pm = Polygon.of(-1, 1, -1, 2, 3, -1, 2, -3, -2, -2, -3, 2);
        Ellipse em = new Ellipse(2, -1, 5, 2);
        // Both pushes of 4 clear, and neither 3.999.
        for (float d : new float[] {3.999f, 4}) {
            assertEquals(d < 4, new Ellipse(-2, -1 - d, 5, 2).overlaps(p));
            assertEquals(d < 4, new Ellipse(-2 - 0.6f * d, -1 + 0.8f * d, 5, 2).overlaps(p));
            assertEquals(d < 4, new Ellipse(2, -1 - d, 5, 2).overlaps(pm));
            assertEquals(d < 4, new Ellipse(2 + 0.6f * d, -1 + 0.8f * d, 5, 2).overlaps(pm));
        }
        // And no push is shorter: 3.999 along any of 3600 directions still overlaps.
        assertEveryPushOverlaps(e, p, 3.999);
        assertEquals(new Contact(0, -1, 4), p.contact(e));
        assertEquals(new Contact(0, 1, 4), e.contact(p));
        assertEquals(new Contact(0, -1, 4), pm.contact(em));
        assertEquals(new Contact(0, 1, 4), em.contact(pm));
    }

    @Test
    void concavePolygonAgainstCapsule_aConeOfEqualPushes_theRuleTakesItsMostVerticalEnd_mirroredToo() {
        // The capsule's end (-1, -1) is a corner of the polygon: every push of 2.5 (its
        // radius) in a cone from about 90.8 to 206.5 degrees clears, and the rule takes the
        // end with the larger |ny|. That end is no edge normal: the capsule's end, pushed by
        // 2.5, reaches 2.5 from the edge (1, 0)-(0, -1), the line x - y = 1, where
        // sin(t - 45 deg) = 1 - 0.4 / sqrt 2. Before: directions inside the cone where the
        // search happened to stop, (-0.851, 0.526) one way and (-0.960, 0.282) mirrored in y.
        Polygon p = Polygon.of(-1, -1, 0, -3, 1, -2, 1, 0, 0, -1);
        Capsule k = new Capsule(-1, -1, -3, -1, 2.5f);
        double t = Math.PI / 4 + Math.asin(1 - 0.4 / Math.sqrt(2));
        float ex = (float) Math.cos(t), ey = (float) Math.sin(t);
        assertEveryPushOverlaps(k, p, 2.499);
        for (boolean mirror : new boolean[] {false, true}) {
            Polygon q = mirror ? (Polygon) mirrored(p, false) : p;
            Capsule m = mirror ? (Capsule) mirrored(k, false) : k;
            float sy = mirror ? -1 : 1;
            Contact c = q.contact(m);
            assertNormal(ex, sy * ey, c, "mirrored " + mirror);
            assertEquals(2.5f, c.depth(), 1e-6f);
            assertNormal(-ex, -sy * ey, m.contact(q), "swapped, mirrored " + mirror);
            // The push clears, and the cone's end is sharp: 1e-3 radians past it does not.
            assertFalse(m.translated(c.nx() * 2.5f, c.ny() * 2.5f).overlaps(q));
            double past = t + 1e-3;
            assertTrue(m.translated((float) (2.5 * Math.cos(past)), (float) (sy * 2.5 * Math.sin(past))).overlaps(q));
        }
    }

    @Test
    void concavePolygonAgainstEllipse_aCornerAtTheCentreOfCurvature_theAxisBothWays() {
        // The polygon's corner (0, -3) is the centre of curvature of the ellipse's left end
        // (-1, -3) (radius ry^2 / rx = 1): the push out along (1, 0), 1 deep, is the least
        // but flat to the fourth order, so that directions 1e-4 off are as short to a
        // double's resolution. Before, the search's stopping place decided: (1, -1.7e-8) one
        // way and (1, 4.3e-4) mirrored in y.
        Polygon p = Polygon.of(0, -2, 0, -3, -2, -3, -1, 1, 0, 1, 1, 2);
        Ellipse e = new Ellipse(3, -3, 4, 2);
        assertEveryPushOverlaps(e, p, 0.999);
        assertFalse(e.translated(1, 0).overlaps(p));
        for (boolean mirror : new boolean[] {false, true}) {
            Shape q = mirror ? mirrored(p, false) : p, m = mirror ? mirrored(e, false) : e;
            assertEquals(new Contact(1, 0, 1), q.contact(m), "mirrored " + mirror);
            assertEquals(new Contact(-1, 0, 1), m.contact(q), "swapped, mirrored " + mirror);
        }
    }

    @Test
    void ellipseAgainstCapsule_flatToTheFourthOrder_theAxisBothWays_mirroredToo() {
        // The capsule's end (-3, 0), radius 2, and the ellipse's left end (-4, 0), where the
        // ellipse's radius of curvature is ry^2 / rx = 1: along (-cos t, sin t) the push is
        // 3 + t^4 * 3 / 32 for small t > 0 (the segment's other end takes over for t < 0),
        // so the least, 3 along (-1, 0), is flat to about 1e-15 over 2e-4 radians. Before,
        // the search's stopping place decided: (-1, 2.4e-5) one way and (1, 2.4e-4) mirrored
        // in x.
        Ellipse e = new Ellipse(0, 0, 4, 2);
        Capsule k = new Capsule(-3, 0, -3, 2, 2);
        assertEveryPushOverlaps(k, e, 2.999);
        assertFalse(k.translated(-3, 0).overlaps(e));
        for (int mirror = 0; mirror < 3; mirror++) {
            Shape me = mirror == 0 ? e : mirrored(e, mirror == 1), mk = mirror == 0 ? k : mirrored(k, mirror == 1);
            float sx = mirror == 1 ? -1 : 1;
            String what = "mirrored " + (mirror == 0 ? "not" : mirror == 1 ? "in x" : "in y");
            assertEquals(new Contact(-sx, 0, 3), me.contact(mk), what);
            assertEquals(new Contact(sx, 0, 3), mk.contact(me), "swapped, " + what);
        }
    }

    @Test
    void heptagonAgainstCapsule_fourEdgeNormalsEquallyShort_theRuleTakesTheMostVertical_mirroredToo() {
        // The capsule's end is the heptagon's centre (1, -1), so every edge normal n with
        // (4, -1) . n <= 0 (the capsule's other end not farther along -n) pushes 3 + cos(pi/7),
        // the capsule's radius and the heptagon's apothem: those at 77, 129, 180 and 231
        // degrees. The float corners make their depths differ by about 1.4e-8; the rule takes
        // the largest |ny|, 77 degrees. Before: which of them won depended on the order they
        // were offered in, (-0.623, 0.782) one way and the mirror of (0.223, 0.975) mirrored.
        Polygon h = regular(7, 1, 1, -1, false);
        Capsule k = new Capsule(1, -1, -3, 0, 3);
        double depth = 3 + Math.cos(Math.PI / 7), t = 3 * Math.PI / 7;
        float ex = (float) Math.cos(t), ey = (float) Math.sin(t);
        assertEveryPushOverlaps(k, h, depth - 1e-3);
        for (int mirror = 0; mirror < 3; mirror++) {
            Shape mh = mirror == 0 ? h : mirrored(h, mirror == 1), mk = mirror == 0 ? k : mirrored(k, mirror == 1);
            float sx = mirror == 1 ? -1 : 1, sy = mirror == 2 ? -1 : 1;
            String what = "mirrored " + (mirror == 0 ? "not" : mirror == 1 ? "in x" : "in y");
            Contact c = mh.contact(mk);
            assertNormal(sx * ex, sy * ey, c, what);
            assertEquals(depth, c.depth(), 1e-6, what);
            assertFalse(mk.translated(c.nx() * (c.depth() + 1e-4f), c.ny() * (c.depth() + 1e-4f)).overlaps(mh), what);
            Contact s = mk.contact(mh);
            assertNormal(-sx * ex, -sy * ey, s, "swapped, " + what);
            assertEquals(depth, s.depth(), 1e-6, "swapped, " + what);
        }
    }

    /** Moved by {@code d} along each of 3600 directions, the shape still overlaps the other. */
    private static void assertEveryPushOverlaps(Shape moving, Shape other, double d) {
        for (int i = 0; i < 3600; i++) {
            double a = 2 * Math.PI * i / 3600;
            Shape moved = moving.translated((float) (d * Math.cos(a)), (float) (d * Math.sin(a)));
            assertTrue(moved.overlaps(other), () -> "clears at " + a + ": " + moved);
        }
    }

    @Test
    void separate_concaveExactFit_movesByTheDepthAlongTheNormal() {
        // Before: the contact's normal was (-1, -3.15e-8), a corner of the clearance search
        // found on an edge moved in by its tolerance and preferred by the tie rule for its
        // larger |ny|; moving along it never cleared, and separate doubled its way to 6.33.
        Polygon a = Polygon.of(0, 5, 0, -1, -6, 0, -2, -2, 1, -8, 6, -8, 3, -3);
        Polygon b = Polygon.of(-1, 7, 2, 12, -10, 8, 1, -1, -1, 2, 1, 1);
        Contact c = a.contact(b);
        assertEquals(new Contact(-1, 0, 1), c);
        Polygon moved = Response.separate(a, b);
        assertEquals(a.translated(1, 0), moved);
        assertFalse(moved.overlaps(b));
        assertTrue(a.translated(0.999f, 0).overlaps(b));
    }

    // ---------------------------------------------------------------- symmetric placements

    /** Small shapes on a coarse grid near the origin, so that equal pushes are common. */
    @Provide
    Arbitrary<Shape> smallShapes() {
        Arbitrary<Integer> c = Arbitraries.integers().between(-3, 3);
        Arbitrary<Integer> size = Arbitraries.integers().between(1, 6);
        Arbitrary<Shape> circles = Combinators.combine(c, c, size).as((x, y, r) -> new Circle(x, y, r));
        Arbitrary<Shape> rects = Combinators.combine(c, c, size, size).as((x, y, w, h) -> new Rect(x, y, w, h));
        Arbitrary<Shape> ellipses = Combinators.combine(c, c, size, size).as((x, y, w, h) -> new Ellipse(x, y, w, h / 2f));
        Arbitrary<Shape> capsules = Combinators.combine(c, c, c, c, size).as((x1, y1, x2, y2, r) -> new Capsule(x1, y1, x2, y2, r / 2f));
        Arbitrary<Shape> polygons = TestShapes.simplePolygons(6, 6).map(xy -> {
            float[] moved = xy.clone();
            for (int i = 0; i < moved.length; i++) {
                moved[i] -= 3;
            }
            return Polygon.of(moved);
        });
        Arbitrary<Shape> regular = Combinators.combine(Arbitraries.integers().between(3, 8), size, c, c)
                .as((n, r, x, y) -> regular(n, r, x, y, false));
        return Arbitraries.oneOf(circles, rects, ellipses, capsules, polygons, regular);
    }

    /** The shape mirrored in x (x to -x) or in y. */
    private static Shape mirrored(Shape s, boolean inX) {
        float fx = inX ? -1 : 1, fy = inX ? 1 : -1;
        if (s instanceof Circle c) {
            return new Circle(fx * c.x(), fy * c.y(), c.r());
        }
        if (s instanceof Rect r) {
            return new Rect(inX ? -r.x() - r.w() : r.x(), inX ? r.y() : -r.y() - r.h(), r.w(), r.h());
        }
        if (s instanceof Ellipse e) {
            return new Ellipse(fx * e.x(), fy * e.y(), e.rx(), e.ry(), -e.angle());
        }
        if (s instanceof Capsule k) {
            return new Capsule(fx * k.x1(), fy * k.y1(), fx * k.x2(), fy * k.y2(), k.r());
        }
        float[] xy = ((Polygon) s).coordinates();
        for (int i = 0; i < xy.length; i += 2) {
            xy[i] *= fx;
            xy[i + 1] *= fy;
        }
        return Polygon.of(xy);
    }

    /** The tie rule on float normals, keys equal within 1e-4: is n preferred to o? */
    private static boolean rulePrefers(float nx, float ny, float ox, float oy) {
        float[][] keys = {{Math.abs(ny), Math.abs(oy)}, {nx * ny, ox * oy}, {ny, oy}, {nx, ox}};
        for (float[] k : keys) {
            if (Math.abs(k[0] - k[1]) > 1e-4f) {
                return k[0] > k[1];
            }
        }
        return false;
    }

    private static boolean near(float ax, float ay, float bx, float by) {
        return Math.abs(ax - bx) <= 1e-4f && Math.abs(ay - by) <= 1e-4f;
    }

    private static boolean convex(Shape s) {
        return !(s instanceof Polygon p) || p.isConvex();
    }

    /**
     * Mirroring a pair mirrors its contact: the same depth, and the normal mirrored, unless
     * several directions are equally short and the rule picks among them. Then the mirrored
     * pair's normal m must beat the mirror of the first answer c by the rule, c must beat the
     * mirror of m likewise, and (for convex shapes, by their support functions) m must be as
     * short as c's mirror: each answer is the rule's pick from the same set of shortest
     * directions, mirrored.
     */
    @Property(tries = 1500)
    void mirroredPair_mirroredNormal_followingTheRule(@ForAll("smallShapes") Shape a, @ForAll("smallShapes") Shape b,
                                                      @ForAll boolean inX) {
        Contact c = a.contact(b);
        Shape ma = mirrored(a, inX), mb = mirrored(b, inX);
        Contact m = ma.contact(mb);
        String what = a + " " + b + " mirrored in " + (inX ? "x" : "y") + ": " + c + " then " + m;
        if (c == null) {
            assertNull(m, what);
            return;
        }
        assertNotNull(m, what);
        assertEquals(c.depth(), m.depth(), 1e-5f * Math.max(1, c.depth()), what);
        float cx = inX ? -c.nx() : c.nx(), cy = inX ? c.ny() : -c.ny();
        if (near(m.nx(), m.ny(), cx, cy)) {
            return;
        }
        float mx = inX ? -m.nx() : m.nx(), my = inX ? m.ny() : -m.ny();
        assertTrue(rulePrefers(m.nx(), m.ny(), cx, cy), () -> "the rule prefers the mirror of the first: " + what);
        assertTrue(rulePrefers(c.nx(), c.ny(), mx, my), () -> "the rule prefers the mirror of the second: " + what);
        if (convex(a) && convex(b)) {
            double along = Supports.support(ma, m.nx(), m.ny()) + Supports.support(mb, -m.nx(), -m.ny());
            assertEquals(c.depth(), along, 1e-5 * Math.max(1, along), () -> "not equally short: " + what);
        }
    }
}
