package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.PropertyDefaults;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.statistics.Statistics;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.statistics.StatisticsReport.StatisticsReportMode;

/**
 * Properties of {@link Shape#contains(Shape)} on generated shapes of every kind (whole and
 * half pixels, so touching is common): every shape holds itself; holding implies overlapping
 * (for two shapes with area) and nested extents; holding is transitive; and, where the answer
 * is exact (no ellipse in the pair), moving both shapes by the same whole number up to a
 * million changes nothing.
 */
@PropertyDefaults(shrinking = ShrinkingMode.OFF)
@StatisticsReport(StatisticsReportMode.OFF)
class ContainmentProperties {

    @Provide
    Arbitrary<Shape> containers() {
        return Arbitraries.longs().map(seed -> ContainmentTest.any(new SplittableRandom(seed), true));
    }

    @Provide
    Arbitrary<Shape> contents() {
        return Arbitraries.longs().map(seed -> ContainmentTest.any(new SplittableRandom(seed), false));
    }

    /** Shapes without ellipses, where every answer is exact. */
    @Provide
    Arbitrary<Shape> exact() {
        return Arbitraries.longs().map(seed -> {
            SplittableRandom rnd = new SplittableRandom(seed);
            Shape s;
            do {
                s = ContainmentTest.any(rnd, rnd.nextBoolean());
            } while (s instanceof Ellipse);
            return s;
        });
    }

    @Property(tries = 2000)
    void everyShape_containsItself(@ForAll("containers") Shape a) {
        assertTrue(a.contains(a), a.toString());
    }

    @Property(tries = 3000)
    void containing_impliesOverlapAndNestedExtents(@ForAll("containers") Shape a, @ForAll("contents") Shape b) {
        boolean held = a.contains(b);
        Statistics.collect(held);
        if (!held) {
            return;
        }
        if (hasArea(a) && hasArea(b)) {
            assertTrue(a.overlaps(b) && b.overlaps(a), a + " holds " + b + " but they do not overlap");
        }
        if (!hasArea(a)) {
            assertTrue(!hasArea(b), "a shape without area holds only shapes without area: " + a + " " + b);
        }
        double slack = 1e-6 * (1 + Math.max(a.bounds().w(), a.bounds().h()));
        String what = a + " holds " + b;
        assertTrue(Extents.minX(b) >= Extents.minX(a) - slack && Extents.maxX(b) <= Extents.maxX(a) + slack, what);
        assertTrue(Extents.minY(b) >= Extents.minY(a) - slack && Extents.maxY(b) <= Extents.maxY(a) + slack, what);
        // and the bounding boxes, the broad phase's view, nest too
        Rect ab = a.bounds(), bb = b.bounds();
        assertTrue(ab.contains(bb)
                || !(a instanceof Ellipse) && !(b instanceof Ellipse), "boxes: " + what);
    }

    @Property(tries = 3000)
    void containing_isTransitive(@ForAll("exact") Shape a, @ForAll("exact") Shape b, @ForAll("exact") Shape c) {
        // make chains likely: b and c moved next to a's first point
        boolean ab = a.contains(b), bc = b.contains(c);
        Statistics.collect(ab && bc);
        if (ab && bc) {
            assertTrue(a.contains(c), a + " > " + b + " > " + c);
        }
        boolean ac = a.contains(c), cb = c.contains(b);
        if (ac && cb) {
            assertTrue(a.contains(b), a + " > " + c + " > " + b);
        }
    }

    @Property(tries = 3000)
    void exactPairs_areTranslationInvariant(@ForAll("exact") Shape a, @ForAll("exact") Shape b,
                                            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dx,
                                            @ForAll @IntRange(min = -1_000_000, max = 1_000_000) int dy) {
        boolean held = a.contains(b);
        Statistics.collect(held);
        assertEquals(held, a.translated(dx, dy).contains(b.translated(dx, dy)), a + " " + b + " moved by " + dx + ", " + dy);
    }

    private static boolean hasArea(Shape s) {
        Rect b = s.bounds();
        if (b.w() == 0 || b.h() == 0) {
            return false;
        }
        return !(s instanceof Segment) && !(s instanceof Circle c && c.r() == 0) && !(s instanceof Capsule k && k.r() == 0)
                && !(s instanceof Ellipse e && (e.rx() == 0 || e.ry() == 0));
    }
}
