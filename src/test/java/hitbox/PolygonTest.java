package hitbox;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.Provide;
import net.jqwik.api.statistics.Statistics;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Polygon: what it accepts, what it refuses (and says), its factories and its queries. */
class PolygonTest {

    private static String refusal(float... xy) {
        return assertThrows(IllegalArgumentException.class, () -> Polygon.of(xy)).getMessage();
    }

    // ---- what Polygon.of refuses, and what it says ----

    @Test
    void of_refusesTooFewVertices() {
        assertEquals("a polygon needs at least 3 vertices, got 2", refusal(0, 0, 10, 0));
        assertEquals("a polygon needs at least 3 vertices, got 0", refusal());
    }

    @Test
    void of_refusesAnOddNumberOfCoordinates() {
        assertEquals("a polygon needs x, y pairs, but got an odd number of coordinates (7)", refusal(0, 0, 10, 0, 10, 10, 5));
    }

    @Test
    void of_refusesNull() {
        assertEquals("xy must not be null",
                assertThrows(IllegalArgumentException.class, () -> Polygon.of((float[]) null)).getMessage());
    }

    @ParameterizedTest(name = "{0} at {1}")
    @CsvSource({
            "NaN, 5, 'y2 must be a finite number, was NaN'",
            "Infinity, 0, 'x0 must be a finite number, was Infinity'",
            "-Infinity, 3, 'y1 must be a finite number, was -Infinity'",
    })
    void of_refusesNonFiniteValuesNamingTheCoordinate(float bad, int slot, String message) {
        float[] xy = {0, 0, 10, 0, 10, 10};
        xy[slot] = bad;
        assertEquals(message, refusal(xy));
    }

    @Test
    void of_refusesZeroArea() {
        assertEquals("the polygon has no area: all its vertices lie on one line", refusal(0, 0, 5, 0, 10, 0));
        assertEquals("the polygon has no area: all its vertices lie on one line", refusal(0, 0, 5, 5, 10, 10, 3, 3));
    }

    @Test
    void of_refusesTheFirstVertexRepeatedAtTheEnd() {
        assertEquals("vertices 3 and 0 are the same point (0.0, 0.0): a polygon closes itself, so do not repeat the first"
                + " vertex at the end", refusal(0, 0, 10, 0, 10, 10, 0, 0));
    }

    @Test
    void of_refusesConsecutiveDuplicates() {
        assertEquals("vertices 1 and 2 are the same point (10.0, 0.0): remove the repeated vertex",
                refusal(0, 0, 10, 0, 10, 0, 10, 10));
    }

    @Test
    void of_refusesCrossingEdges() {
        // a bow tie: edge 0 (0,0)-(10,10) crosses edge 2 (10,0)-(0,10)
        assertEquals("edges 0 and 2 cross: a polygon's edges may only meet at the corner they share"
                + " (edge i runs from vertex i to vertex i + 1)", refusal(0, 0, 10, 10, 10, 0, 0, 10));
    }

    @Test
    void of_refusesEdgesThatTouch() {
        // vertex 4 (5, 0) sits on edge 0
        assertEquals("edges 0 and 3 touch: a polygon's edges may only meet at the corner they share"
                + " (edge i runs from vertex i to vertex i + 1)", refusal(0, 0, 10, 0, 10, 10, 6, 10, 5, 0, 4, 10, 0, 10));
        // a figure eight pinched at one point: vertices 0 and 3 are the same place, where edge 2 ends
        assertEquals("edges 0 and 2 touch: a polygon's edges may only meet at the corner they share"
                + " (edge i runs from vertex i to vertex i + 1)", refusal(5, 5, 0, 0, 10, 0, 5, 5, 10, 10, 0, 10));
    }

    @Test
    void of_refusesAnOutlineThatFoldsBack() {
        assertEquals("edges 0 and 1 overlap (the outline folds back on itself at vertex 1): a polygon's edges may only"
                + " meet at the corner they share", refusal(0, 0, 10, 0, 5, 0, 5, 5));
    }

    @Test
    void of_acceptsEitherWindingConcaveAndStraightCorners() {
        for (float[] xy : TestShapes.NAMED.values()) {
            assertEquals(xy.length / 2, Polygon.of(xy).size());
            assertEquals(xy.length / 2, Polygon.of(ExactReference.reversed(xy)).size());
        }
    }

    @Test
    void of_copiesItsInput() {
        float[] xy = TestShapes.get("square");
        Polygon p = Polygon.of(xy);
        xy[0] = 99;
        assertEquals(0, p.x(0));
        p.coordinates()[0] = 99;
        assertEquals(0, p.x(0));
    }

    /** Random vertex lists, in random order: accepted exactly when they form a simple polygon. */
    @Provide
    Arbitrary<float[]> vertexLists() {
        return Arbitraries.integers().between(0, 4).list().ofMinSize(6).ofMaxSize(12)
                .filter(l -> l.size() % 2 == 0)
                .map(PolygonTest::toFloats);
    }

    private static float[] toFloats(List<Integer> l) {
        float[] xy = new float[l.size()];
        for (int i = 0; i < xy.length; i++) {
            xy[i] = l.get(i);
        }
        return xy;
    }

    @StatisticsReport(onFailureOnly = true)
    @Property(tries = 3000)
    void of_acceptsExactlySimplePolygons(@ForAll("vertexLists") float[] xy) {
        boolean simple = ExactReference.isSimple(xy);
        boolean accepted;
        try {
            Polygon.of(xy);
            accepted = true;
        } catch (IllegalArgumentException e) {
            accepted = false;
        }
        assertEquals(simple, accepted);
        Statistics.collect(simple);
        Statistics.coverage(c -> {
            c.check(true).percentage(p -> p > 5);
            c.check(false).percentage(p -> p > 5);
        });
    }

    // ---- factories ----

    @Test
    void ofRect_givesTheFourCornersClockwiseOnScreen() {
        assertArrayEquals(new float[] {1, 2, 4, 2, 4, 6, 1, 6}, Polygon.of(new Rect(1, 2, 3, 4)).coordinates());
        assertEquals("a polygon needs area, but the rectangle's width and height are 0.0 and 4.0 (both must be > 0)",
                assertThrows(IllegalArgumentException.class, () -> Polygon.of(new Rect(1, 2, 0, 4))).getMessage());
        assertThrows(IllegalArgumentException.class, () -> Polygon.of((Rect) null));
    }

    @Test
    void of_threeCorners_isATriangle() {
        Polygon t = Polygon.of(0, 0, 10, 0, 0, 10);
        assertEquals(3, t.size());
        assertEquals(50, t.area());
        assertArrayEquals(new float[] {0, 0, 10, 0, 0, 10}, t.coordinates());
        assertThrows(IllegalArgumentException.class, () -> Polygon.of(0, 0, 5, 5, 10, 10));
    }

    @Test
    void turnedRect_atAngleZeroIsTheCentredRect() {
        assertArrayEquals(new float[] {0, 3, 10, 3, 10, 7, 0, 7}, Polygon.of(Rect.centered(5, 5, 10, 4)).rotated(0, 5, 5).coordinates());
    }

    @Test
    void turnedRect_turnsClockwiseOnScreenLikeProcessing() {
        // a quarter turn takes the top-left corner (-5, -2) from the centre to (2, -5)
        Polygon p = Polygon.of(Rect.centered(0, 0, 10, 4)).rotated((float) (Math.PI / 2), 0, 0);
        assertEquals(2, p.x(0), 1e-5);
        assertEquals(-5, p.y(0), 1e-5);
        assertEquals(40, p.area(), 1e-3);
        assertTrue(p.contains(0, 4));
        assertFalse(p.contains(4, 0));
    }

    @Test
    void turnedRect_refusesBadSizes() {
        assertEquals("a polygon needs area, but the rectangle's width and height are 0.0 and 4.0 (both must be > 0)",
                assertThrows(IllegalArgumentException.class, () -> Polygon.of(Rect.centered(0, 0, 0, 4)).rotated(1, 0, 0)).getMessage());
        assertEquals("height h must be >= 0, was -1.0",
                assertThrows(IllegalArgumentException.class, () -> Polygon.of(Rect.centered(0, 0, 4, -1)).rotated(1, 0, 0)).getMessage());
        assertEquals("angle must be a finite number, was NaN",
                assertThrows(IllegalArgumentException.class, () -> Polygon.of(Rect.centered(0, 0, 4, 4)).rotated(Float.NaN, 0, 0)).getMessage());
    }

    @Test
    void regular_putsTheFirstCornerToTheRight() {
        Polygon square = Polygon.regular(0, 0, 10, 4, 0);
        assertEquals(4, square.size());
        assertEquals(10, square.x(0), 1e-5);
        assertEquals(0, square.y(0), 1e-5);
        assertEquals(0, square.x(1), 1e-5);
        assertEquals(10, square.y(1), 1e-5); // a quarter turn clockwise on screen: down
        assertEquals(200, square.area(), 1e-3);
        assertTrue(square.isConvex());
        Polygon turned = Polygon.regular(0, 0, 10, 4, (float) (Math.PI / 4));
        assertEquals(10 * Math.cos(Math.PI / 4), turned.x(0), 1e-5);
        assertEquals(10 * Math.sin(Math.PI / 4), turned.y(0), 1e-5);
        assertEquals(64, Polygon.regular(100, 100, 50, 64, 0).size());
    }

    @Test
    void regular_refusesBadArguments() {
        assertEquals("sides must be from 3 to 4096, was 2",
                assertThrows(IllegalArgumentException.class, () -> Polygon.regular(0, 0, 10, 2, 0)).getMessage());
        assertEquals("radius must be > 0, was 0.0",
                assertThrows(IllegalArgumentException.class, () -> Polygon.regular(0, 0, 0, 5, 0)).getMessage());
        assertEquals("cx must be a finite number, was NaN",
                assertThrows(IllegalArgumentException.class, () -> Polygon.regular(Float.NaN, 0, 10, 5, 0)).getMessage());
    }

    // ---- queries ----

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "square, 100, 5, 5, true",
            "squareWithMidpoint, 100, 5, 5, true",
            "triangle, 50, 3.3333333, 3.3333333, true",
            "diamond, 50, 5, 5, true",
            "ell, 75, 4.1666667, 4.1666667, false",
            "cup, 104, 5, 6.3076923, false",
            "crown, 75, 5, 6.1111111, false",
    })
    void areaCentroidAndConvexity(String shape, float area, float cx, float cy, boolean convex) {
        for (float[] xy : new float[][] {TestShapes.get(shape), ExactReference.reversed(TestShapes.get(shape))}) {
            Polygon p = Polygon.of(xy);
            assertEquals(area, p.area(), 1e-4);
            assertEquals(cx, p.centroid().x(), 1e-5);
            assertEquals(cy, p.centroid().y(), 1e-5);
            assertEquals(convex, p.isConvex());
        }
    }

    @Test
    void area_staysExactFarFromTheOrigin() {
        Polygon far = Polygon.of(ExactReference.translated(TestShapes.ELL, 1_000_000, -1_000_000));
        assertEquals(75, far.area());
        assertEquals(1_000_004.1666667, far.centroid().x(), 0.07);
    }

    @Test
    void edgesAndVertices() {
        Polygon p = Polygon.of(TestShapes.SQUARE);
        assertEquals(4, p.size());
        assertEquals(new Segment(0, 0, 10, 0), p.edge(0));
        assertEquals(new Segment(0, 10, 0, 0), p.edge(3));
        assertEquals(10, p.x(2));
        assertEquals(10, p.y(2));
        assertEquals("edge index i must be 0 to 3, was 4",
                assertThrows(IllegalArgumentException.class, () -> p.edge(4)).getMessage());
        assertEquals("vertex index i must be 0 to 3, was -1",
                assertThrows(IllegalArgumentException.class, () -> p.x(-1)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> p.y(4));
    }

    @Test
    void bounds_holdTheVertices() {
        assertEquals(new Rect(0, 0, 10, 12), Polygon.of(TestShapes.CUP).bounds());
        assertEquals(new Rect(0, 0, 8, 6), Polygon.of(TestShapes.TRIANGLE_345).bounds());
    }

    @Test
    void contains_isCollidePolygonPoint() {
        Polygon crown = Polygon.of(TestShapes.CROWN);
        assertTrue(crown.contains(5, 6));
        assertFalse(crown.contains(5, 5));
        assertFalse(crown.contains(5, 4));
    }

    @Test
    void translated_movesEveryVertex() {
        Polygon moved = Polygon.of(TestShapes.SQUARE).translated(3, -4);
        assertEquals(Polygon.of(3, -4, 13, -4, 13, 6, 3, 6), moved);
        assertEquals(new Rect(3, -4, 10, 10), moved.bounds());
        Polygon rounded = Polygon.of(TestShapes.SQUARE).translated(0.1f, 0.2f);
        assertEquals(0.1f, rounded.x(0));
        assertEquals(10.2f, rounded.y(2));
        assertEquals("x0 + dx must be a finite number, was Infinity", assertThrows(IllegalArgumentException.class,
                () -> Polygon.of(3e38f, 0, 3.1e38f, 0, 3e38f, 1).translated(3e38f, 0)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> Polygon.of(TestShapes.SQUARE).translated(Float.NaN, 0));
    }

    @Test
    void equalsHashCodeAndToString() {
        Polygon a = Polygon.of(TestShapes.SQUARE);
        assertEquals(a, Polygon.of(TestShapes.SQUARE));
        assertEquals(a.hashCode(), Polygon.of(TestShapes.SQUARE).hashCode());
        assertNotEquals(a, Polygon.of(ExactReference.rotated(TestShapes.SQUARE, 1)));
        assertEquals("Polygon[0.0, 0.0, 10.0, 0.0, 0.0, 10.0]", Polygon.of(TestShapes.TRIANGLE).toString());
    }
}
