package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;

/**
 * Ellipses and capsules on a small whole-number grid, zero radii and point segments included,
 * where touching is the common case: every pair answers the same in both orders and moved by
 * up to a million pixels (the decisions work on differences, exactly).
 */
class EllipseCapsuleGridTest {

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Integer> c = Arbitraries.integers().between(0, 6);
        Arbitrary<Integer> r = Arbitraries.integers().between(0, 3);
        Arbitrary<Shape> ellipses = Combinators.combine(c, c, r, r).as((x, y, a, b) -> new Ellipse(x, y, a, b));
        Arbitrary<Shape> capsules = Combinators.combine(c, c, c, c, r).as((x1, y1, x2, y2, k) -> new Capsule(x1, y1, x2, y2, k));
        Arbitrary<Shape> circles = Combinators.combine(c, c, r).as((x, y, k) -> new Circle(x, y, k));
        Arbitrary<Shape> rects = Combinators.combine(c, c, r, r).as((x, y, w, h) -> new Rect(x, y, w, h));
        Arbitrary<Shape> segments = Combinators.combine(c, c, c, c).as((x1, y1, x2, y2) -> new Segment(x1, y1, x2, y2));
        Arbitrary<Shape> triangles = Combinators.combine(c, c).as((x, y) -> Polygon.of(x, y, x + 3, y, x, y + 2));
        return Arbitraries.oneOf(ellipses, capsules, ellipses, capsules, circles, rects, segments, triangles);
    }

    @Property(tries = 3000)
    void symmetricAndTranslationInvariant(@ForAll("shapes") Shape a, @ForAll("shapes") Shape b,
                                          @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                          @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean ab = a.overlaps(b);
        assertEquals(ab, b.overlaps(a), () -> "symmetric: " + a + " and " + b);
        assertEquals(ab, a.translated(dx, dy).overlaps(b.translated(dx, dy)), () -> a + " and " + b + " moved by " + dx + ", " + dy);
    }
}
