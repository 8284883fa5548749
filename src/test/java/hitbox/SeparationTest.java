package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@link Separation}: tables of pairs with known distances and closest points, in both orders,
 * exact on whole numbers where the distance is; touching (0, not null), overlapping (null),
 * zero-size, coincident and huge shapes; the raw-float forms against the shape form.
 */
class SeparationTest {

    /** A shape written as a kind and its numbers: circle x y r, rect x y w h, segment, capsule, ellipse x y rx ry [angle], polygon xy... */
    static Shape shape(String text) {
        String[] p = text.trim().split("\\s+");
        float[] v = new float[p.length - 1];
        for (int i = 1; i < p.length; i++) {
            v[i - 1] = Float.parseFloat(p[i]);
        }
        return switch (p[0]) {
            case "circle" -> new Circle(v[0], v[1], v[2]);
            case "rect" -> new Rect(v[0], v[1], v[2], v[3]);
            case "segment" -> new Segment(v[0], v[1], v[2], v[3]);
            case "capsule" -> new Capsule(v[0], v[1], v[2], v[3], v[4]);
            case "ellipse" -> v.length > 4 ? new Ellipse(v[0], v[1], v[2], v[3], v[4]) : new Ellipse(v[0], v[1], v[2], v[3]);
            case "polygon" -> Polygon.of(v);
            default -> throw new IllegalArgumentException(p[0]);
        };
    }

    /** Checks a separation both ways round: the distance, exactly or within tol, and the points swapped. */
    private static void check(Shape a, Shape b, float distance, double tol, float ax, float ay, float bx, float by) {
        Separation s = Separation.between(a, b);
        assertNotNull(s, a + " and " + b);
        Separation back = Separation.between(b, a);
        assertNotNull(back, b + " and " + a);
        if (tol == 0) {
            assertEquals(distance, s.distance(), a + " and " + b);
            assertEquals(distance, back.distance(), b + " and " + a);
        } else {
            assertEquals(distance, s.distance(), tol, a + " and " + b);
            assertEquals(distance, back.distance(), tol, b + " and " + a);
        }
        if (!Float.isNaN(ax)) {
            double ptol = Math.max(tol, 1e-5);
            assertEquals(ax, s.ax(), ptol, "ax " + s);
            assertEquals(ay, s.ay(), ptol, "ay " + s);
            assertEquals(bx, s.bx(), ptol, "bx " + s);
            assertEquals(by, s.by(), ptol, "by " + s);
            assertEquals(bx, back.ax(), ptol, "swapped " + back);
            assertEquals(by, back.ay(), ptol, "swapped " + back);
            assertEquals(ax, back.bx(), ptol, "swapped " + back);
            assertEquals(ay, back.by(), ptol, "swapped " + back);
        }
    }

    // a; b; distance; tolerance (0: exact); closest point on a (x, y) and on b (NaN: not checked).
    // Where many pairs are equally close (parallel edges), the one with the least midpoint.
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', textBlock = """
            circles345;              circle 0 0 1;        circle 6 8 2;                  7;   0;     0.6; 0.8; 4.8; 6.4
            circlesAlongX;           circle 0 0 1;        circle 5 0 1;                  3;   0;     1; 0; 4; 0
            rectsCornerToCorner;     rect 0 0 10 10;      rect 13 14 5 5;                5;   0;     10; 10; 13; 14
            rectsSideGap;            rect 0 0 10 10;      rect 12 3 5 2;                 2;   0;     10; 3; 12; 3
            rectsBelowGap;           rect 0 0 10 10;      rect -20 17 100 2;             7;   0;     0; 10; 0; 17
            circleRectSide;          circle -5 5 3;       rect 0 0 10 10;                2;   0;     -2; 5; 0; 5
            circleRectCorner;        circle 16 18 5;      rect 0 0 10 10;                5;   0;     13; 14; 10; 10
            circleHypotenuse;        circle 7 7 4;        polygon 0 0 8 0 0 6;           1;   0;     4.6; 3.8; 4; 3
            segmentPoint;            segment 0 0 10 0;    circle 4 -3 0;                 3;   0;     4; 0; 4; -3
            segmentsParallel;        segment 0 0 10 0;    segment 2 4 6 4;               4;   0;     2; 0; 2; 4
            segmentsSkew;            segment 0 0 10 0;    segment 13 4 20 9;             5;   0;     10; 0; 13; 4
            capsulesSideBySide;      capsule 0 0 10 0 2;  capsule 0 9 10 9 3;            4;   0;     0; 2; 0; 6
            capsuleEndToCircle;      capsule 0 0 10 0 1;  circle 16 8 5;                 4;   0;     10.6; 0.8; 13; 4
            capsuleRect;             capsule 0 0 10 0 2;  rect -5 5 20 5;                3;   0;     NaN; 0; 0; 0
            polygonsEdgeToVertex;    polygon 0 0 10 0 10 10 0 10; polygon 15 5 20 0 20 10; 5; 0;  10; 5; 15; 5
            concaveNotch;            polygon 0 0 4 0 4 8 6 8 6 0 10 0 10 12 0 12; circle 5 1 0.5; 0.5; 0; NaN; 0; 0; 0
            rectPolygonRotated;      rect 0 0 10 10;      polygon 13 14 17 11 20 15 16 18; 5; 0;  10; 10; 13; 14
            ellipseCircleOnAxis;     ellipse 0 0 10 5;    circle 20 0 2;                 8;   1e-5;  10; 0; 18; 0
            ellipseRectBelow;        ellipse 0 0 10 5;    rect -20 8 40 3;               3;   1e-5;  0; 5; 0; 8
            ellipseTurnedQuarter;    ellipse 0 0 10 5 1.5707964; circle 0 20 2;          8;   1e-5;  0; 10; 0; 18
            ellipsesOnAxis;          ellipse 0 0 10 5;    ellipse 30 0 8 3;              12;  1e-5;  10; 0; 22; 0
            ellipseSegmentAbove;     ellipse 0 0 10 5;    segment -20 -9 20 -9;          4;   1e-5;  0; -5; 0; -9
            ellipseCapsule;          ellipse 0 0 10 5;    capsule 15 -10 15 10 2;        3;   1e-5;  10; 0; 13; 0
            flatEllipseAsSegment;    ellipse 0 0 10 0;    circle 5 7 3;                  4;   0;     5; 0; 5; 4
            roundEllipseAsCircle;    ellipse 0 0 5 5 0.3; circle 12 16 5;                10;  0;     3; 4; 9; 12
            """)
    void between_knownDistances_bothOrders(String name, String a, String b, float distance, double tol,
                                            float ax, float ay, float bx, float by) {
        check(shape(a), shape(b), distance, tol, ax, ay, bx, by);
    }

    // a; b: shapes that touch and do not overlap: distance exactly 0, one point for both
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', textBlock = """
            circles345;            circle 0 0 2;          circle 3 4 3
            rectsSideBySide;       rect 0 0 10 10;        rect 10 2 5 5
            rectsCorner;           rect 0 0 10 10;        rect 10 10 5 5
            circleRectCorner;      circle 13 14 5;        rect 0 0 10 10
            circleHypotenuse;      circle 7 7 5;          polygon 0 0 8 0 0 6
            polygonsSharingEdge;   polygon 0 0 10 0 10 10; polygon 0 0 10 10 0 10
            segmentAlongRectEdge;  segment 2 0 8 0;       rect 0 0 10 10
            segmentEndOnCircle;    segment 5 0 9 0;       circle 0 0 5
            zeroCircleOnSegment;   circle 4 0 0;          segment 0 0 10 0
            zeroCirclesCoincident; circle 4 4 0;          circle 4 4 0
            flatRectCrossingSegment; rect 0 5 10 0;       segment 5 0 5 10
            zeroCapsuleCrossingSegment; capsule 0 0 10 10 0; segment 0 10 10 0
            capsulesEndToEnd;      capsule 0 0 10 0 2;    capsule 14 0 20 0 2
            ellipseRectTangent;    ellipse 0 0 10 5;      rect 10 -5 4 10
            ellipseOnTopOfRect;    ellipse 0 0 10 5;      rect -3 5 6 1
            concaveCupAroundCircle; polygon 0 0 4 0 4 8 6 8 6 0 10 0 10 12 0 12; circle 5 4 1
            """)
    void between_touching_isZeroNotNull(String name, String a, String b) {
        Shape p = shape(a), q = shape(b);
        assertTrue(!p.overlaps(q), "the case must touch, not overlap");
        for (Separation s : new Separation[] {Separation.between(p, q), Separation.between(q, p)}) {
            assertNotNull(s, name);
            assertEquals(0f, s.distance(), name + " " + s);
            assertEquals(s.ax(), s.bx(), 1e-5, name + " " + s);
            assertEquals(s.ay(), s.by(), 1e-5, name + " " + s);
            assertEquals(0f, s.nx());
            assertEquals(0f, s.ny());
        }
    }

    // a; b: shapes that overlap: null both ways
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', textBlock = """
            circles;               circle 0 0 2;          circle 3 0 2
            circleInsideCircle;    circle 0 0 10;         circle 1 1 2
            equalCircles;          circle 5 5 3;          circle 5 5 3
            rectInsideRect;        rect 0 0 10 10;        rect 2 2 3 3
            segmentsCrossing;      segment 0 0 10 10;     segment 0 10 10 0
            segmentsMeetingAtEnd;  segment 0 0 10 0;      segment 10 0 10 10
            equalSegments;         segment 0 0 10 0;      segment 0 0 10 0
            pointInPolygon;        circle 2 2 0;          polygon 0 0 10 0 0 10
            polygonInsideConcave;  polygon 0 0 10 0 10 10 0 10; polygon 2 2 3 2 3 3
            ellipseAroundRect;     ellipse 0 0 10 5;      rect -1 -1 2 2
            capsuleThroughPolygon; capsule -5 5 15 5 0;   polygon 0 0 10 0 10 10 0 10
            turnedEllipses;        ellipse 0 0 10 2 0.5;  ellipse 0 0 10 2 -0.5
            """)
    void between_overlapping_isNull(String name, String a, String b) {
        Shape p = shape(a), q = shape(b);
        assertTrue(p.overlaps(q), "the case must overlap");
        assertNull(Separation.between(p, q));
        assertNull(Separation.between(q, p));
        assertNull(Separation.between(p, q));
    }

    @Test
    void between_crossingFlatShapes_meetAtTheCrossing() {
        Separation s = Separation.between(new Rect(0, 5, 10, 0), new Segment(5, 0, 5, 10));
        assertEquals(new Separation(0, 5, 5, 5, 5), s);
    }

    @Test
    void between_hugeCoordinates_stayFinite() {
        Separation s = Separation.between(new Circle(-1e30f, 0, 1), new Circle(1e30f, 0, 1));
        assertEquals(2e30f, s.distance(), 1e24f);
        s = Separation.between(new Circle(-Float.MAX_VALUE, 0, 0), new Circle(Float.MAX_VALUE, 0, 0));
        assertEquals(Float.MAX_VALUE, s.distance(), "past the float range: held at MAX_VALUE");
        float far = 1e20f + 3e13f;
        s = Separation.between(new Rect(1e20f, 1e20f, 1e10f, 1e10f), new Rect(far, 1e20f, 1e10f, 1e10f));
        assertEquals((float) ((double) far - (1e20f + (double) 1e10f)), s.distance(), "an axis-aligned gap, exact");
        s = Separation.between(new Ellipse(1e7f, 1e7f, 100, 50), new Circle(1e7f + 200, 1e7f, 10));
        assertEquals(90, s.distance(), 1e-3);
        assertEquals(Separation.circleCircle(-Float.MAX_VALUE, 0, 0, Float.MAX_VALUE, 0, 0), Float.MAX_VALUE);
    }

    @Test
    void direction_pointsFromAToB() {
        Separation s = Separation.between(new Circle(0, 0, 1), new Circle(6, 8, 2));
        assertEquals(0.6f, s.nx(), 1e-6);
        assertEquals(0.8f, s.ny(), 1e-6);
        Separation f = s.flipped();
        assertEquals(-0.6f, f.nx(), 1e-6);
        assertEquals(s.distance(), f.distance());
        assertEquals(s, f.flipped());
    }

    @Test
    void constructor_checksItsValues() {
        assertThrows(IllegalArgumentException.class, () -> new Separation(-1, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new Separation(Float.NaN, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new Separation(1, 0, Float.POSITIVE_INFINITY, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Separation.between(null, new Circle(0, 0, 1)));
        assertThrows(IllegalArgumentException.class, () -> Separation.between(new Circle(0, 0, 1), null));
        assertEquals(new Separation(0, 1, 1, 1, 1), new Separation(-0f, 1, 1, 1, 1));
    }

    // ---------------------------------------------------------------- raw floats

    @Test
    void rawForms_agreeWithTheShapes_andGiveZeroForOverlap() {
        assertEquals(7f, Separation.circleCircle(0, 0, 1, 6, 8, 2));
        assertEquals(0f, Separation.circleCircle(0, 0, 5, 1, 1, 1), "overlapping: 0");
        assertEquals(0f, Separation.circleCircle(0, 0, 2, 3, 4, 3), "touching: 0");
        assertEquals(5f, Raw.separationCirclePoint(0, 0, 5, 6, 8));
        assertEquals(0f, Raw.separationCirclePoint(0, 0, 5, 1, 1));
        assertEquals(5f, Raw.separationRectPoint(0, 0, 10, 10, 13, 14));
        assertEquals(0f, Raw.separationRectPoint(0, 0, 10, 10, 5, 5), "inside: 0");
        assertEquals(3f, Raw.separationRectPoint(0, 0, 10, 10, 5, -3));
        assertEquals(5f, Raw.separationRectRect(0, 0, 10, 10, 13, 14, 5, 5));
        assertEquals(0f, Raw.separationRectRect(0, 0, 10, 10, 2, 2, 3, 3), "inside: 0");
        assertEquals(0f, Raw.separationRectRect(0, 0, 10, 10, 10, 0, 3, 3), "touching: 0");
        assertEquals(5f, Raw.separationCircleRect(16, 18, 5, 0, 0, 10, 10));
        assertEquals(3f, Raw.separationLinePoint(0, 0, 10, 0, 4, -3));
        assertEquals(2f, Raw.separationLineCircle(0, 0, 10, 0, 4, -3, 1));
        assertEquals(5f, Raw.separationLineLine(0, 0, 10, 0, 13, 4, 20, 9));
        assertEquals(0f, Raw.separationLineLine(0, 0, 10, 10, 0, 10, 10, 0));
        assertEquals(2f, Raw.separationLineRect(-5, 12, 20, 12, 0, 0, 10, 10));
        assertEquals(0f, Raw.separationLineRect(2, 2, 3, 3, 0, 0, 10, 10), "inside: 0");
        float[] square = {0, 0, 10, 0, 10, 10, 0, 10};
        float[] triangle = {15, 5, 20, 0, 20, 10};
        assertEquals(5f, Raw.separationPolygonPolygon(square, triangle));
        assertEquals(0f, Raw.separationPolygonPolygon(square, new float[] {2, 2, 3, 2, 3, 3}));
        assertEquals(5f, Raw.separationPolygonPoint(square, 13, 14));
        assertEquals(0f, Raw.separationPolygonPoint(square, 3, 3));
        assertEquals(1f, Raw.separationPolygonCircle(TestShapes.TRIANGLE_345, 7, 7, 4));
        assertEquals(5f, Raw.separationPolygonRect(triangle, -5, 0, 15, 10));
        assertEquals(4f, Raw.separationPolygonLine(square, 0, 14, 10, 20));
        assertEquals(Separation.between(Polygon.of(square), Polygon.of(triangle)).distance(),
                Raw.separationPolygonPolygon(square, triangle));
    }

    @Test
    void badInput_rawCircleCircleAnswersInfinity_theShapesRefuseIt() {
        // The one raw form left keeps its rule; the others went, and the shapes refuse such values.
        float inf = Float.POSITIVE_INFINITY;
        assertEquals(inf, Separation.circleCircle(Float.NaN, 0, 1, 5, 0, 1));
        assertEquals(inf, Separation.circleCircle(0, 0, -1, 5, 0, 1), "negative radius");
        assertThrows(IllegalArgumentException.class, () -> Raw.separationRectRect(0, 0, 10, 10, inf, 0, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> Raw.separationRectPoint(0, 0, -1, 10, 20, 20));
        assertThrows(IllegalArgumentException.class, () -> Raw.separationPolygonPoint(new float[] {0, 0, 10, 0}, 5, 5), "fewer than 3 vertices");
        assertThrows(IllegalArgumentException.class, () -> Raw.separationPolygonPoint(new float[] {0, 0, 10, Float.NaN, 0, 10}, 50, 5));
        assertThrows(IllegalArgumentException.class, () -> Raw.separationPolygonPoint(null, 0, 0));
    }
}
