package hitbox;

import hitbox.internal.Extents;
import hitbox.internal.Transforms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * {@link Transform} and {@link Shape#transformed} / {@link Shape#rotated}, against a
 * sampling oracle that shares no maths with the kernel: a point p is in t(shape) exactly when
 * t<sup>-1</sup>(p) is in the shape. Checked on a dense grid of points over the image's box,
 * for every kind, under turns, mirrors, scales, shears and moves, at modest and at huge
 * coordinates, except at points within a small margin of the outline (where rounding may go
 * either way): those are skipped, and the test counts that most points were decided.
 */
class TransformTest {

    // ---------------------------------------------------------------- the oracle

    /** The shapes of every kind that the oracle runs on: plain and awkward ones. */
    static List<Shape> shapes(float ox, float oy) {
        return List.of(
                new Circle(ox + 10, oy - 5, 30),
                new Rect(ox - 20, oy - 10, 40, 20),
                new Segment(ox - 30, oy - 5, ox + 25, oy + 15),
                Polygon.of(ox - 30, oy - 30, ox + 30, oy - 30, ox + 30, oy + 30, ox - 30, oy + 30).translated(0, 0),
                // concave: a notch in the top
                Polygon.of(ox - 30, oy - 30, ox - 10, oy - 30, ox, oy - 5, ox + 10, oy - 30, ox + 30, oy - 30,
                        ox + 30, oy + 30, ox - 30, oy + 30),
                new Ellipse(ox, oy, 40, 15),
                new Ellipse(ox + 5, oy, 40, 15, 0.6f),
                new Capsule(ox - 20, oy - 10, ox + 25, oy + 5, 12));
    }

    /** Transforms of every sort: turns (about the origin and a pivot), mirrors, scales, shears, moves. */
    static List<Transform> transforms(float px, float py) {
        return List.of(
                Transform.IDENTITY,
                Transform.translation(13.25f, -7.5f),
                Transform.rotation(0.3f),
                Transform.rotation(-2.2f, px, py),
                Transform.rotation((float) Math.PI / 2, px, py),
                Transform.rotation((float) Math.PI),
                Transform.scaling(-1, 1),
                Transform.scaling(1, -1).then(Transform.rotation(0.9f, px, py)),
                Transform.scaling(2.5f, 2.5f),
                Transform.scaling(3, 0.5f),
                Transform.rotation(0.5f).then(Transform.scaling(2, 0.7f)).then(Transform.translation(40, -12)),
                Transform.of(1, 0.8f, 5, 0.3f, 1.2f, -9),
                Transform.of(-0.5f, 1.5f, 0, 2, 0.25f, 100));
    }

    /** How many points were decided and checked, and how many skipped as too near the outline. */
    private record Tally(int checked, int skipped) {
    }

    /**
     * Checks the image of {@code s} under {@code t} against the oracle on a grid of points
     * over the image's box; returns the tally.
     */
    static Tally oracle(Shape s, Transform t, Shape image, int steps) {
        Transform back = t.inverse();
        Rect box = image.bounds();
        double size = Math.max(Extents.maxX(s) - Extents.minX(s), Extents.maxY(s) - Extents.minY(s));
        double big = Math.max(Math.max(Math.abs(Extents.minX(image)), Math.abs(Extents.maxX(image))),
                Math.max(Math.abs(Extents.minY(image)), Math.abs(Extents.maxY(image))));
        double bigS = Math.max(Math.max(Math.abs(Extents.minX(s)), Math.abs(Extents.maxX(s))), Math.max(Math.abs(Extents.minY(s)), Math.abs(Extents.maxY(s))));
        double stretch = Math.max(Math.hypot(back.m00(), back.m10()), Math.hypot(back.m01(), back.m11()));
        // the margin in the shape's frame: a thousandth of its size, and the rounding of the
        // image's floats and of the way back, with room to spare
        double eps = 1e-3 * size + 3 * (Math.ulp((float) big) * stretch + Math.ulp((float) bigS));
        int checked = 0, skipped = 0;
        double w = Math.max(box.w(), 1e-3), h = Math.max(box.h(), 1e-3);
        for (int i = 0; i <= steps; i++) {
            for (int j = 0; j <= steps; j++) {
                float px = (float) (box.x() - 0.05 * w + 1.1 * w * i / steps);
                float py = (float) (box.y() - 0.05 * h + 1.1 * h * j / steps);
                // the way back in double, from the inverse's entries
                double qx = (double) back.m00() * px + (double) back.m01() * py + back.m02();
                double qy = (double) back.m10() * px + (double) back.m11() * py + back.m12();
                Boolean sure = sureAnswer(s, qx, qy, eps);
                if (sure == null) {
                    skipped++;
                    continue;
                }
                checked++;
                if (image.contains(px, py) != sure) {
                    throw new AssertionError("(" + px + ", " + py + ") goes back to (" + qx + ", " + qy + "), which is "
                            + (sure ? "in " : "not in ") + s + ", but the image " + image + " under " + t
                            + (sure ? " does not contain it" : " contains it"));
                }
            }
        }
        return new Tally(checked, skipped);
    }

    /** The shape's answer at (x, y) when the 8 points eps around it agree; null near the outline. */
    private static Boolean sureAnswer(Shape s, double x, double y, double eps) {
        if (!ShapeKindOracle.hasArea(s)) {
            // a segment: a point off its line is surely out; nothing on it is decided here
            return s.contains((float) x, (float) y) || near(s, x, y, eps) ? null : Boolean.FALSE;
        }
        boolean in = s.contains((float) x, (float) y);
        for (int k = 0; k < 8; k++) {
            double a = Math.PI / 4 * k;
            if (s.contains((float) (x + eps * Math.cos(a)), (float) (y + eps * Math.sin(a))) != in) {
                return null;
            }
        }
        return in;
    }

    private static boolean near(Shape s, double x, double y, double eps) {
        Segment g = (Segment) s;
        double ex = g.x2() - g.x1(), ey = g.y2() - g.y1();
        double len2 = ex * ex + ey * ey;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - g.x1()) * ex + (y - g.y1()) * ey) / len2));
        return Math.hypot(x - g.x1() - t * ex, y - g.y1() - t * ey) <= eps;
    }

    /** What the oracle needs of a shape's kind, without the library's dispatch. */
    private static final class ShapeKindOracle {
        static boolean hasArea(Shape s) {
            return !(s instanceof Segment);
        }
    }

    @TestFactory
    List<DynamicTest> everyKind_everyTransform_agreesWithTheInverseOracle() {
        List<DynamicTest> tests = new ArrayList<>();
        float[][] places = {{0, 0}, {317.5f, -120.25f}};
        for (float[] at : places) {
            for (Shape s : shapes(at[0], at[1])) {
                for (Transform t : transforms(at[0] + 7, at[1] - 3)) {
                    String name = s + " under " + t;
                    tests.add(DynamicTest.dynamicTest(name, () -> {
                        Shape image;
                        try {
                            image = s.transformed(t);
                        } catch (IllegalArgumentException e) {
                            // only a capsule stretched one way may be refused here
                            assertInstanceOf(Capsule.class, s, e.getMessage());
                            assertTrue(e.getMessage().contains("capsule"), e.getMessage());
                            double[] sv = singularValues(t);
                            assertTrue(sv[0] / sv[1] > 1 + 1e-6, "refused a similarity: " + e.getMessage());
                            return;
                        }
                        Tally tally = oracle(s, t, image, 80);
                        if (!(s instanceof Segment)) {
                            assertTrue(tally.checked() > 5 * tally.skipped(), name + ": too few points decided " + tally);
                        }
                    }));
                }
            }
        }
        return tests;
    }

    @TestFactory
    List<DynamicTest> hugeCoordinates_agreeWithTheOracle() {
        List<DynamicTest> tests = new ArrayList<>();
        float ox = 3.5e6f, oy = -2.25e6f;
        for (Shape s : shapes(ox, oy)) {
            for (Transform t : List.of(Transform.rotation(0.7f, ox, oy), Transform.rotation(-1.1f, ox + 40, oy - 20),
                    Transform.translation(0.3f, 1e5f + 0.7f), Transform.scaling(-1, 1).then(Transform.translation(2 * ox, 0)))) {
                tests.add(DynamicTest.dynamicTest(s + " under " + t, () -> {
                    Shape image = s.transformed(t);
                    Tally tally = oracle(s, t, image, 60);
                    if (!(s instanceof Segment)) {
                        // a float step is 0.25 to 0.5 here: the band about the outline is wide
                        assertTrue(tally.checked() > tally.skipped(), "too few decided " + tally);
                    }
                }));
            }
        }
        return tests;
    }

    /** The singular values of the transform's linear part, largest first, from its entries. */
    static double[] singularValues(Transform t) {
        double a = t.m00(), b = t.m01(), c = t.m10(), d = t.m11();
        double s = a * a + b * b + c * c + d * d;
        double det = a * d - b * c;
        double root = Math.sqrt(Math.max(0, s * s / 4 - det * det));
        return new double[] {Math.sqrt(s / 2 + root), Math.sqrt(Math.max(0, s / 2 - root))};
    }

    // ---------------------------------------------------------------- Transform itself

    @Test
    void pointsGoWhereTheFormulaSays() {
        Transform t = Transform.of(2, 3, 5, 7, 11, 13);
        assertEquals(2 * 1 + 3 * 2 + 5, t.applyX(1, 2));
        assertEquals(7 * 1 + 11 * 2 + 13, t.applyY(1, 2));
        assertEquals(2f, t.m00());
        assertEquals(13f, t.m12());
        assertEquals(2 * 11 - 3 * 7, Transforms.affine(t).det(), "the kernels' determinant");
    }

    @Test
    void then_appliesThisFirst_asProcessingReadsTranslateThenRotate() {
        // translate(100, 50); rotate(HALF_PI); rect(-20, -10, 40, 20): the corner (-20, -10)
        // turned a quarter clockwise is (10, -20), then moved: (110, 30)
        Transform drawn = Transform.rotation((float) Math.PI / 2).then(Transform.translation(100, 50));
        assertEquals(110f, drawn.applyX(-20, -10));
        assertEquals(30f, drawn.applyY(-20, -10));
        assertEquals(new Rect(90, 30, 20, 40), new Rect(-20, -10, 40, 20).transformed(drawn));
    }

    @Test
    void rotation_positiveAngle_turnsClockwiseOnScreen() {
        Transform r = Transform.rotation(0.25f);
        // (1, 0) goes down-right: y grows
        assertTrue(r.applyY(1, 0) > 0);
        assertEquals(Math.cos(0.25f), r.applyX(1, 0), 1e-7);
    }

    @Test
    void quarterTurns_areExact() {
        float halfPi = (float) Math.PI / 2;
        float[] quarters = {halfPi, (float) Math.PI, 3 * halfPi, -halfPi, 2 * (float) Math.PI, 0, 4 * (float) Math.PI};
        int[][] expected = {{0, 1}, {-1, 0}, {0, -1}, {0, -1}, {1, 0}, {1, 0}, {1, 0}};
        for (int i = 0; i < quarters.length; i++) {
            Transform r = Transform.rotation(quarters[i]);
            assertEquals(expected[i][0], r.m00(), "cos of " + quarters[i]);
            assertEquals(expected[i][1], r.m10(), "sin of " + quarters[i]);
            assertTrue(Transforms.affine(r).keepsAxes() && Transforms.affine(r).isSimilarity());
        }
        // a rect stays a rect, exactly, about any pivot with whole coordinates
        assertEquals(new Rect(1, 3, 2, 4), new Rect(3, 1, 4, 2).rotated(halfPi, 2, 2));
        assertEquals(new Rect(-7, -3, 4, 2), new Rect(3, 1, 4, 2).rotated((float) Math.PI, 0, 0));
        // a polygon's vertices land exactly
        Polygon p = Polygon.of(1, 0, 5, 0, 5, 3, 1, 3);
        assertEquals(Polygon.of(0, 1, 0, 5, -3, 5, -3, 1), p.rotated(halfPi, 0, 0));
        assertEquals(p, p.rotated(2 * (float) Math.PI, 100, -40));
        // an aligned ellipse turned a quarter is aligned with its radii swapped
        assertEquals(new Ellipse(-2, 10, 3, 8), new Ellipse(10, 2, 8, 3).transformed(Transform.rotation(halfPi)));
        // a segment's ends
        assertEquals(new Segment(-2, 1, -4, 3), new Segment(1, 2, 3, 4).rotated(halfPi, 0, 0));
    }

    @Test
    void aTurnAboutAPivot_keepsThePivot_andBothPivotsAgreeAfterAMove() {
        Circle atPivot = new Circle(250, -75, 9);
        assertEquals(atPivot, atPivot.rotated(1.234f, 250, -75));
        // turning about (px, py) = moving the pivot to the origin, turning, moving back
        Shape s = Polygon.of(200, -80, 260, -90, 270, -40, 215, -30);
        Transform viaOrigin = Transform.translation(-250, 75).then(Transform.rotation(0.8f))
                .then(Transform.translation(250, -75));
        Polygon a = (Polygon) s.rotated(0.8f, 250, -75);
        Polygon b = (Polygon) s.transformed(viaOrigin);
        for (int i = 0; i < a.size(); i++) {
            assertEquals(b.x(i), a.x(i), 1e-4);
            assertEquals(b.y(i), a.y(i), 1e-4);
        }
    }

    @Test
    void inverse_undoes_andASingularTransformIsRefusedClearly() {
        Transform t = Transform.rotation(0.6f, 30, 40).then(Transform.scaling(2, -3)).then(Transform.translation(5, 6));
        Transform back = t.then(t.inverse());
        assertEquals(17.5, back.applyX(17.5f, -3.25f), 1e-4);
        assertEquals(-3.25, back.applyY(17.5f, -3.25f), 1e-4);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Transform.scaling(0, 5).inverse());
        assertTrue(e.getMessage().contains("singular"), e.getMessage());
        assertEquals(0, Transforms.affine(Transform.scaling(0, 5)).det(), "singular");
        assertTrue(Transforms.affine(Transform.scaling(-1, 1)).det() < 0, "a reflection");
        assertTrue(Transforms.affine(Transform.rotation(2)).det() > 0, "a turn is no reflection");
    }

    @Test
    void equalsHashCodeAndToString() {
        assertEquals(Transform.translation(3, 4), Transform.of(1, 0, 3, 0, 1, 4));
        assertEquals(Transform.translation(3, 4).hashCode(), Transform.of(1, 0, 3, 0, 1, 4).hashCode());
        assertEquals(Transform.IDENTITY, Transform.rotation(0));
        assertEquals(Transform.IDENTITY.hashCode(), Transform.rotation(0).hashCode(), "-0 in a turn's entries hashes as 0");
        assertEquals(Transform.rotation((float) Math.PI).hashCode(), Transform.scaling(-1, -1).hashCode());
        assertNotEquals(Transform.translation(3, 4), Transform.translation(4, 3));
        assertEquals("Transform[1.0, 0.0, 3.0; 0.0, 1.0, 4.0]", Transform.translation(3, 4).toString());
        assertEquals(Transform.scaling(0, 0), Transform.scaling(-0f, -0f), "-0 is 0");
    }

    @Test
    void badInput_namesTheParameter() {
        assertNames("m01", () -> Transform.of(1, Float.NaN, 0, 0, 1, 0));
        assertNames("m12", () -> Transform.of(1, 0, 0, 0, 1, Float.POSITIVE_INFINITY));
        assertNames("dy", () -> Transform.translation(0, Float.NaN));
        assertNames("angle", () -> Transform.rotation(Float.NaN));
        assertNames("pivotY", () -> Transform.rotation(1, 0, Float.NEGATIVE_INFINITY));
        assertNames("sx", () -> Transform.scaling(Float.NaN, 1));
        assertNames("next", () -> Transform.IDENTITY.then(null));
        assertNames("t", () -> new Circle(0, 0, 1).transformed(null));
        assertNames("t", () -> Polygon.of(0, 0, 1, 0, 0, 1).transformed(null));
        assertNames("angle", () -> new Rect(0, 0, 1, 1).rotated(Float.NaN, 0, 0));
        assertNames("pivotX", () -> new Segment(0, 0, 1, 1).rotated(1, Float.NaN, 0));
        // beyond the float range: the product, and a point carried past it
        assertThrows(IllegalArgumentException.class,
                () -> Transform.scaling(Float.MAX_VALUE, Float.MAX_VALUE).then(Transform.scaling(4, 4)));
        IllegalArgumentException far = assertThrows(IllegalArgumentException.class,
                () -> new Circle(Float.MAX_VALUE, 0, 1).transformed(Transform.scaling(4, 4)));
        assertTrue(far.getMessage().contains("float range"), far.getMessage());
        IllegalArgumentException turned = assertThrows(IllegalArgumentException.class,
                () -> new Circle(Float.MAX_VALUE, 0, 1).rotated(2, -Float.MAX_VALUE, 0));
        assertTrue(turned.getMessage().contains("pivotX"), turned.getMessage());
    }

    private static void assertNames(String name, org.junit.jupiter.api.function.Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().matches("(?s).*\\b" + name + "\\b.*"), "should name " + name + ": " + e.getMessage());
    }

    // ---------------------------------------------------------------- what each kind becomes

    @Test
    void circle_staysACircleUnderASimilarity_elseBecomesAnEllipse() {
        Circle c = new Circle(10, 20, 5);
        assertEquals(new Circle(20, 40, 10), c.transformed(Transform.scaling(2, 2)));
        assertInstanceOf(Circle.class, c.transformed(Transform.rotation(0.3f, 4, 4).then(Transform.scaling(-3, 3))));
        assertEquals(new Ellipse(20, 20, 10, 5), c.transformed(Transform.scaling(2, 1)));
        Shape sheared = c.transformed(Transform.of(1, 1, 0, 0, 1, 0));
        Ellipse e = assertInstanceOf(Ellipse.class, sheared);
        // the shear's singular values are the golden ratio and its inverse
        assertEquals(5 * 1.618034, e.rx(), 1e-4);
        assertEquals(5 / 1.618034, e.ry(), 1e-4);
        // singular: a flat ellipse, answering as its flat box
        Ellipse flat = assertInstanceOf(Ellipse.class, c.transformed(Transform.scaling(0, 1)));
        assertEquals(0, flat.rx());
        assertEquals(5, flat.ry());
        assertEquals(new Circle(0, 0, 0), c.transformed(Transform.scaling(0, 0)));
    }

    @Test
    void rect_staysARectWhenTheAxesAreKept_elseBecomesAPolygon() {
        Rect r = new Rect(10, 20, 40, 30);
        assertEquals(new Rect(-50, 20, 40, 30), r.transformed(Transform.scaling(-1, 1)));
        assertEquals(new Rect(20, -100, 80, 60), r.transformed(Transform.scaling(2, -2)));
        assertEquals(new Rect(10, 20, 0, 30), r.transformed(Transform.scaling(0, 1).then(Transform.translation(10, 0))),
                "a scale by 0 keeps the axes: a rect of width 0");
        Polygon turned = assertInstanceOf(Polygon.class, r.rotated(0.5f, 30, 35));
        assertEquals(4, turned.size());
        assertEquals(1200, turned.area(), 1e-2);
        assertTrue(turned.isConvex());
        IllegalArgumentException flat = assertThrows(IllegalArgumentException.class,
                () -> new Rect(0, 0, 10, 0).rotated(0.5f, 0, 0));
        assertTrue(flat.getMessage().contains("Segment"), flat.getMessage());
        IllegalArgumentException singular = assertThrows(IllegalArgumentException.class,
                () -> r.transformed(Transform.of(1, 2, 0, 2, 4, 0)));
        assertTrue(singular.getMessage().contains("singular"), singular.getMessage());
    }

    @Test
    void polygon_mirrored_isValid_reversesItsWinding_andAConcaveOneStaysConcave() {
        Polygon notch = Polygon.of(0, 0, 10, 0, 10, 10, 5, 3, 0, 10);
        assertFalse(notch.isConvex());
        Polygon mirrored = notch.transformed(Transform.scaling(-1, 1));
        assertFalse(mirrored.isConvex());
        assertEquals(Polygon.of(0, 0, -10, 0, -10, 10, -5, 3, 0, 10), mirrored);
        assertEquals(notch.area(), mirrored.area());
        assertTrue(mirrored.contains(-5, 1) && !mirrored.contains(-5, 5));
        // the convex fast paths read the winding: a mirrored convex polygon still overlaps right
        Polygon tri = Polygon.of(0, 0, 10, 0, 0, 10).transformed(Transform.scaling(1, -1));
        assertTrue(tri.overlaps(Polygon.of(1, -1, 3, -1, 1, -3)));
        assertFalse(tri.overlaps(Polygon.of(6, -6, 9, -6, 9, -9)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> notch.transformed(Transform.scaling(0, 1)));
        assertTrue(e.getMessage().contains("singular"), e.getMessage());
    }

    @Test
    void ellipse_staysAnEllipse_exactWhereItCanBe() {
        Ellipse e = new Ellipse(0, 0, 10, 4, 0.5f);
        Ellipse turned = e.rotated(0.25f, 0, 0);
        assertEquals(10, turned.rx());
        assertEquals(4, turned.ry());
        assertEquals(0.75f, turned.angle());
        Ellipse mirrored = e.transformed(Transform.scaling(-1, 1));
        assertEquals(10, mirrored.rx());
        assertEquals(Math.PI - 0.5, mirrored.angle(), 1e-6);
        assertEquals(new Ellipse(6, 0, 20, 12), new Ellipse(3, 0, 10, 4).transformed(Transform.scaling(2, 3)));
        // a turned ellipse scaled back to a circle: equal radii
        Ellipse round = new Ellipse(0, 0, 4, 2).transformed(Transform.scaling(1, 2));
        assertEquals(round.rx(), round.ry());
    }

    @Test
    void capsule_staysACapsuleUnderASimilarity_elseIsRefusedSayingWhatToDo() {
        Capsule c = new Capsule(0, 0, 10, 0, 2);
        assertEquals(new Capsule(0, 0, 0, 10, 2), c.rotated((float) Math.PI / 2, 0, 0));
        assertEquals(new Capsule(0, 0, -30, 0, 6), c.transformed(Transform.scaling(-3, 3)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> c.transformed(Transform.scaling(2, 1)));
        assertTrue(e.getMessage().contains("no exact result") && e.getMessage().contains("segment()"), e.getMessage());
        // a capsule of radius 0 is its segment: any transform
        assertEquals(new Capsule(0, 0, 20, 0, 0), new Capsule(0, 0, 10, 0, 0).transformed(Transform.scaling(2, 1)));
    }

    @Test
    void segment_staysASegment_evenUnderASingularTransform() {
        assertEquals(new Segment(0, 2, 0, 4), new Segment(1, 2, 3, 4).transformed(Transform.scaling(0, 1)));
    }

    // ---------------------------------------------------------------- polygons move cheaply

    @Test
    void translated_fractionalMoves_keepAConcavePolygonValid_withoutThrowing() {
        // a comb of 200 teeth: concave, and quadratic to check
        Polygon comb = comb(200);
        Polygon p = comb;
        for (int i = 0; i < 2000; i++) {
            p = p.translated(0.1f, -0.37f);
        }
        assertFalse(p.isConvex());
        assertEquals(comb.area(), p.area(), comb.area() * 1e-4);
        // every move above was checked only by the margin rule, yet the result is valid
        assertEquals(p, Polygon.of(p.coordinates()));
        // and turning it every frame
        Polygon q = comb;
        for (int i = 0; i < 200; i++) {
            q = q.rotated(0.031f, 500, 20);
        }
        assertEquals(q, Polygon.of(q.coordinates()));
    }

    @Test
    void translated_stillRefusesAnOutlineThatRoundingReallyBreaks() {
        // two vertices a float step apart near 1, moved to 1e8 where a float step is 8
        Polygon tiny = Polygon.of(1, 0, 1.0000001f, 0.5f, 1, 1, 0, 0.5f);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> tiny.translated(1e8f + 0.5f, 0));
        assertTrue(e.getMessage().startsWith("moving by dx = "), e.getMessage());
    }

    /** A comb: a bar with n teeth hanging down, 2 + 4n vertices. */
    static Polygon comb(int n) {
        float[] xy = new float[2 * (2 + 4 * n)];
        int k = 0;
        xy[k++] = 0;
        xy[k++] = 0;
        xy[k++] = 10 * n;
        xy[k++] = 0;
        for (int i = n - 1; i >= 0; i--) {
            float x = 10 * i;
            xy[k++] = x + 7.5f;
            xy[k++] = 5;
            xy[k++] = x + 7.5f;
            xy[k++] = 40;
            xy[k++] = x + 2.5f;
            xy[k++] = 40;
            xy[k++] = x + 2.5f;
            xy[k++] = 5;
        }
        return Polygon.of(xy);
    }
}
