package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.statistics.Statistics;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Shape.overlaps for all 16 ordered pairs of Circle, Rect, Segment and Polygon: the same answer
 * both ways round, the same as the Collide method for the pair, and the touching rule.
 */
class OverlapsTableTest {

    /** A shape written out: {@code "circle 0 0 5"}, {@code "rect 0 0 10 10"}, {@code "segment 0 0 5 5"}, {@code "polygon ..."}. */
    static Shape shape(String spec) {
        String[] parts = spec.trim().split("\\s+");
        float[] v = new float[parts.length - 1];
        for (int i = 1; i < parts.length; i++) {
            v[i - 1] = Float.parseFloat(parts[i]);
        }
        return switch (parts[0]) {
            case "circle" -> new Circle(v[0], v[1], v[2]);
            case "rect" -> new Rect(v[0], v[1], v[2], v[3]);
            case "segment" -> new Segment(v[0], v[1], v[2], v[3]);
            case "polygon" -> Polygon.of(v);
            default -> throw new IllegalArgumentException("unknown shape " + parts[0]);
        };
    }

    /**
     * The Collide method for the pair, called directly: the table the brief asks for, written
     * out again here independently of Overlaps.
     */
    static boolean collide(Shape a, Shape b) {
        if (a instanceof Circle c && b instanceof Circle d) {
            return Collide.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
        } else if (a instanceof Circle c && b instanceof Rect r) {
            return Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        } else if (a instanceof Circle c && b instanceof Segment s) {
            return Collide.lineCircle(s.x1(), s.y1(), s.x2(), s.y2(), c.x(), c.y(), c.r());
        } else if (a instanceof Circle c && b instanceof Polygon p) {
            return Collide.polygonCircle(p.coordinates(), c.x(), c.y(), c.r());
        } else if (a instanceof Rect r && b instanceof Rect q) {
            return Collide.rectRect(r.x(), r.y(), r.w(), r.h(), q.x(), q.y(), q.w(), q.h());
        } else if (a instanceof Rect r && b instanceof Segment s) {
            return Collide.lineRect(s.x1(), s.y1(), s.x2(), s.y2(), r.x(), r.y(), r.w(), r.h());
        } else if (a instanceof Rect r && b instanceof Polygon p) {
            return Collide.polygonRect(p.coordinates(), r.x(), r.y(), r.w(), r.h());
        } else if (a instanceof Segment s && b instanceof Segment t) {
            return Collide.lineLine(s.x1(), s.y1(), s.x2(), s.y2(), t.x1(), t.y1(), t.x2(), t.y2());
        } else if (a instanceof Segment s && b instanceof Polygon p) {
            return Collide.polygonLine(p.coordinates(), s.x1(), s.y1(), s.x2(), s.y2());
        } else if (a instanceof Polygon p && b instanceof Polygon q) {
            return Collide.polygonPolygon(p.coordinates(), q.coordinates());
        }
        return collide(b, a);
    }

    /** The slow exact answer for any pair, from ExactReference, by the touching rule. */
    static boolean reference(Shape a, Shape b) {
        if (a instanceof Circle c && b instanceof Circle d) {
            ExactReference.Q dx = ExactReference.Q.of(d.x()).minus(ExactReference.Q.of(c.x()));
            ExactReference.Q dy = ExactReference.Q.of(d.y()).minus(ExactReference.Q.of(c.y()));
            ExactReference.Q reach = ExactReference.Q.of(c.r()).plus(ExactReference.Q.of(d.r()));
            return dx.times(dx).plus(dy.times(dy)).compareTo(reach.times(reach)) < 0;
        } else if (a instanceof Circle c && b instanceof Rect r) {
            return hasArea(r) ? ExactReference.polygonCircle(corners(r), c.x(), c.y(), c.r())
                    : ExactReference.segmentCircle(r.x(), r.y(), r.right(), r.bottom(), c.x(), c.y(), c.r());
        } else if (a instanceof Circle c && b instanceof Segment s) {
            return ExactReference.segmentCircle(s.x1(), s.y1(), s.x2(), s.y2(), c.x(), c.y(), c.r());
        } else if (a instanceof Circle c && b instanceof Polygon p) {
            return ExactReference.polygonCircle(p.coordinates(), c.x(), c.y(), c.r());
        } else if (a instanceof Rect r && b instanceof Rect q) {
            if (!hasArea(r) && !hasArea(q)) {
                // Neither has an inside: the tutorial's comparisons, axis by axis, exactly.
                return openRangesMeet(r.x(), r.w(), q.x(), q.w()) && openRangesMeet(r.y(), r.h(), q.y(), q.h());
            }
            if (hasArea(r) && hasArea(q)) {
                return ExactReference.polygonsMeet(corners(r), corners(q));
            }
            return hasArea(r) ? ExactReference.segmentPolygon(corners(r), q.x(), q.y(), q.right(), q.bottom())
                    : hasArea(q) && ExactReference.segmentPolygon(corners(q), r.x(), r.y(), r.right(), r.bottom());
        } else if (a instanceof Rect r && b instanceof Segment s) {
            return hasArea(r) && ExactReference.segmentPolygon(corners(r), s.x1(), s.y1(), s.x2(), s.y2());
        } else if (a instanceof Rect r && b instanceof Polygon p) {
            return hasArea(r) ? ExactReference.polygonsMeet(p.coordinates(), corners(r))
                    : ExactReference.segmentPolygon(p.coordinates(), r.x(), r.y(), r.right(), r.bottom());
        } else if (a instanceof Segment s && b instanceof Segment t) {
            return ExactReference.segmentsMeet(s.x1(), s.y1(), s.x2(), s.y2(), t.x1(), t.y1(), t.x2(), t.y2());
        } else if (a instanceof Segment s && b instanceof Polygon p) {
            return ExactReference.segmentPolygon(p.coordinates(), s.x1(), s.y1(), s.x2(), s.y2());
        } else if (a instanceof Polygon p && b instanceof Polygon q) {
            return ExactReference.polygonsMeet(p.coordinates(), q.coordinates());
        }
        return reference(b, a);
    }

    private static boolean hasArea(Rect r) {
        return r.w() > 0 && r.h() > 0;
    }

    private static float[] corners(Rect r) {
        return ExactReference.rectPolygon(r.x(), r.y(), r.w(), r.h());
    }

    static void assertOverlaps(boolean expected, Shape a, Shape b) {
        assertEquals(expected, a.overlaps(b), "a.overlaps(b)");
        assertEquals(expected, b.overlaps(a), "b.overlaps(a)");
        assertEquals(expected, collide(a, b), "the Collide method for the pair");
        assertEquals(expected, reference(a, b), "the reference");
        Shape fa = a.translated(1_000_000, -1_000_000);
        Shape fb = b.translated(1_000_000, -1_000_000);
        assertEquals(expected, fa.overlaps(fb), "moved by a million");
        assertEquals(expected, fb.overlaps(fa), "moved by a million, swapped");
    }

    /** Each of the ten kinds of pair, asked both ways: one case that touches, one that overlaps. */
    @ParameterizedTest(name = "{0}  vs  {1}")
    @CsvSource({
            "circle 0 0 5,                  circle 10 0 5,                          false",
            "circle 0 0 5,                  circle 9 0 5,                           true",
            "circle 15 5 5,                 rect 0 0 10 10,                         false",
            "circle 14 5 5,                 rect 0 0 10 10,                         true",
            "circle 0 0 5,                  segment -10 5 10 5,                     false",
            "circle 0 0 5,                  segment -10 4 10 4,                     true",
            "circle 15 5 5,                 polygon 0 0 10 0 10 10 0 10,            false",
            "circle 14 5 5,                 polygon 0 0 10 0 10 10 0 10,            true",
            "rect 0 0 10 10,                rect 10 0 5 5,                          false",
            "rect 0 0 10 10,                rect 9 0 5 5,                           true",
            "rect 0 0 10 10,                segment -5 0 15 0,                      false",
            "rect 0 0 10 10,                segment -5 1 15 1,                      true",
            "rect 0 0 10 10,                segment 2 2 8 8,                        true",
            "rect 10 0 5 10,                polygon 0 0 10 0 10 10 0 10,            false",
            "rect 9 0 5 10,                 polygon 0 0 10 0 10 10 0 10,            true",
            "segment 0 0 10 0,              segment 0 1 10 1,                       false",
            "segment 0 0 10 0,              segment 10 0 10 10,                     true",
            "segment -5 0 15 0,             polygon 0 0 10 0 10 10 0 10,            false",
            "segment -5 1 15 1,             polygon 0 0 10 0 10 10 0 10,            true",
            "polygon 0 0 10 0 10 10 0 10,   polygon 10 0 20 0 20 10 10 10,          false",
            "polygon 0 0 10 0 10 10 0 10,   polygon 9 0 19 0 19 10 9 10,            true",
            "polygon 0 0 10 0 10 10 0 10,   polygon 2 2 4 2 4 4 2 4,                true",
    })
    void overlaps_everyPairBothWays(String a, String b, boolean expected) {
        assertOverlaps(expected, shape(a), shape(b));
    }

    /** Zero-size shapes have no inside; a segment is closed but has no inside either. */
    @ParameterizedTest(name = "{0}  vs  {1}")
    @CsvSource({
            "circle 0 0 0,                  segment -5 0 5 0,                       false",
            "circle 0 0 0,                  circle 0 0 0,                           false",
            "circle 0 0 0,                  rect -5 0 10 0,                         false",
            "rect 0 0 0 10,                 segment -5 5 5 5,                       false",
            "rect 0 0 0 0,                  rect 0 0 0 0,                           false",
            "circle 5 5 0,                  polygon 0 0 10 0 10 10 0 10,            true",
            "circle 0 5 0,                  polygon 0 0 10 0 10 10 0 10,            false",
            "rect 2 2 0 5,                  polygon 0 0 10 0 10 10 0 10,            true",
            "rect 0 0 0 10,                 polygon 0 0 10 0 10 10 0 10,            false",
            "rect 5 5 0 0,                  rect 0 0 10 10,                         true",
            "rect 5 5 0 0,                  circle 5 5 1,                           true",
            "segment 5 0 5 0,               segment 0 0 10 0,                       true",
            "segment 5 5 5 5,               polygon 0 0 10 0 10 10 0 10,            true",
            "segment 5 5 5 5,               circle 5 5 1,                           true",
            "segment 5 5 5 5,               rect 0 0 10 10,                         true",
    })
    void overlaps_zeroSizeShapes(String a, String b, boolean expected) {
        assertOverlaps(expected, shape(a), shape(b));
    }

    /**
     * Two zero-size rectangles follow the tutorial's four comparisons (see the touching rule
     * in package-info): flat rectangles crossing like a plus sign collide; lying along each
     * other, meeting at an end, or a point, they do not.
     */
    @ParameterizedTest
    @CsvSource({
            "rect 1 0 0 2,    rect 0 1 2 0,    true",   // plus sign
            "rect 1 0 0 2,    rect 1 1 0 4,    false",  // along each other
            "rect 1 0 0 2,    rect 1 2 2 0,    false",  // an L: meet at an end
            "rect 1 0 0 2,    rect 0 2 2 0,    false",  // a T: one ends on the other
            "rect 1 1 0 0,    rect 0 1 2 0,    false",  // a point on a flat rect
            "rect 1 1 0 0,    rect 1 1 0 0,    false",  // a point on a point
    })
    void overlaps_twoZeroSizeRects_followTheTutorialsComparisons(String a, String b, boolean expected) {
        assertOverlaps(expected, shape(a), shape(b));
    }

    /** start1 < start2 + size2 and start2 < start1 + size1, in exact arithmetic. */
    private static boolean openRangesMeet(float start1, float size1, float start2, float size2) {
        ExactReference.Q a = ExactReference.Q.of(start1);
        ExactReference.Q b = ExactReference.Q.of(start2);
        return a.compareTo(b.plus(ExactReference.Q.of(size2))) < 0
                && b.compareTo(a.plus(ExactReference.Q.of(size1))) < 0;
    }

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Integer> c = Arbitraries.integers().between(0, 6);
        Arbitrary<Integer> size = Arbitraries.integers().between(0, 4);
        Arbitrary<Shape> circles = Combinators.combine(c, c, Arbitraries.integers().between(0, 3)).as((x, y, r) -> new Circle(x, y, r));
        Arbitrary<Shape> rects = Combinators.combine(c, c, size, size).as((x, y, w, h) -> new Rect(x, y, w, h));
        Arbitrary<Shape> segments = Combinators.combine(c, c, c, c).as((x1, y1, x2, y2) -> new Segment(x1, y1, x2, y2));
        Arbitrary<Shape> polygons = TestShapes.simplePolygons(6, 5).map(Polygon::of);
        return Arbitraries.oneOf(circles, rects, segments, polygons);
    }

    @StatisticsReport(onFailureOnly = true)
    @Property(tries = 3000)
    void overlaps_symmetricRoutedAndExact(@ForAll("shapes") Shape a, @ForAll("shapes") Shape b) {
        boolean ab = a.overlaps(b);
        Statistics.label("pair").collect(a.getClass().getSimpleName() + "-" + b.getClass().getSimpleName());
        assertEquals(ab, b.overlaps(a), "symmetric");
        assertEquals(ab, collide(a, b), "routed to the pair's Collide method");
        assertEquals(ab, reference(a, b), "exact reference");
    }

    @Property(tries = 1000)
    void overlaps_translationInvariant(@ForAll("shapes") Shape a, @ForAll("shapes") Shape b,
                                       @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                       @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        assertEquals(a.overlaps(b), a.translated(dx, dy).overlaps(b.translated(dx, dy)),
                () -> a + " and " + b + " moved by " + Arrays.toString(new int[] {dx, dy}));
    }
}
