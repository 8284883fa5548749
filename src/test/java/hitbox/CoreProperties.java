package hitbox;

import java.math.BigDecimal;
import java.util.List;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Assume;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.PropertyDefaults;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import net.jqwik.api.Tuple;
import net.jqwik.api.statistics.Statistics;
import net.jqwik.api.statistics.StatisticsReport;
import net.jqwik.api.statistics.StatisticsReport.StatisticsReportMode;

/**
 * Properties of the five core tests (circle-point, circle-circle, rect-point, rect-rect,
 * circle-rect), checked on generated shapes.
 *
 * <ul>
 *   <li><b>Symmetry</b>: each pair gives the same answer in either order, through
 *       {@link Collide} and {@link Shape#overlaps}; a point gives the same answer as a circle of
 *       radius 0 and a rectangle of size 0, in either order.</li>
 *   <li><b>Translation invariance</b>: moving both shapes by the same whole-number offset, up
 *       to 1e6 each way, changes no answer, touching cases included.</li>
 *   <li><b>Agreement with {@link ExactReference}</b>, the exact slow version: on whole numbers
 *       always (the library promises exactness there), and on fractional floats whenever the
 *       case is not within rounding distance of touching.</li>
 *   <li><b>Bounds are a safe first test</b>: when a circle overlaps something, so does its
 *       bounding rectangle.</li>
 * </ul>
 *
 * <p>Small whole numbers make touching common, and the generators also build touching cases
 * on purpose (3-4-5 and other Pythagorean distances, nudged by -1, 0 or +1); each such
 * property checks that at least a few percent of its cases touch, so it cannot quietly stop
 * testing the boundary.
 */
// Shrinking is off: the case generators combine several alternatives, and jqwik's shrinking of
// such combinations ran for over ten minutes on a failing property. Every assertion message
// prints the whole case, which is small, so the first failing sample is readable as it is.
@PropertyDefaults(shrinking = ShrinkingMode.OFF)
@StatisticsReport(StatisticsReportMode.OFF)
class CoreProperties {

    // ---------------------------------------------------------------- symmetry

    @Property
    void circleCircle_isSymmetric(@ForAll("anyCircles") Circle a, @ForAll("anyCircles") Circle b) {
        boolean ab = Collide.circleCircle(a.x(), a.y(), a.r(), b.x(), b.y(), b.r());
        assertSame(ab, Collide.circleCircle(b.x(), b.y(), b.r(), a.x(), a.y(), a.r()), "Collide(b, a)");
        assertSame(ab, a.overlaps(b), "a.overlaps(b)");
        assertSame(ab, b.overlaps(a), "b.overlaps(a)");
    }

    @Property
    void rectRect_isSymmetric(@ForAll("anyRects") Rect a, @ForAll("anyRects") Rect b) {
        boolean ab = Collide.rectRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h());
        assertSame(ab, Collide.rectRect(b.x(), b.y(), b.w(), b.h(), a.x(), a.y(), a.w(), a.h()), "Collide(b, a)");
        assertSame(ab, a.overlaps(b), "a.overlaps(b)");
        assertSame(ab, b.overlaps(a), "b.overlaps(a)");
    }

    @Property
    void circleRect_agreesWithOverlapsBothWays(@ForAll("anyCircles") Circle c, @ForAll("anyRects") Rect r) {
        boolean collide = circleRect(c, r);
        assertSame(collide, c.overlaps(r), "circle.overlaps(rect)");
        assertSame(collide, r.overlaps(c), "rect.overlaps(circle)");
    }

    @Property
    void circlePoint_isACircleOfRadiusZeroEitherWay(@ForAll("anyCircles") Circle c, @ForAll("anyPoints") Vec p) {
        boolean inside = Collide.circlePoint(c.x(), c.y(), c.r(), p.x(), p.y());
        assertSame(inside, c.contains(p.x(), p.y()), "Circle.contains");
        assertSame(inside, Collide.circleCircle(c.x(), c.y(), c.r(), p.x(), p.y(), 0), "circleCircle(c, p)");
        assertSame(inside, Collide.circleCircle(p.x(), p.y(), 0, c.x(), c.y(), c.r()), "circleCircle(p, c)");
        assertSame(inside, Collide.circleRect(c.x(), c.y(), c.r(), p.x(), p.y(), 0, 0), "circleRect(c, 0x0)");
    }

    @Property
    void rectPoint_isARectOfSizeZeroEitherWay(@ForAll("anyRects") Rect r, @ForAll("anyPoints") Vec p) {
        boolean inside = Collide.rectPoint(r.x(), r.y(), r.w(), r.h(), p.x(), p.y());
        assertSame(inside, r.contains(p.x(), p.y()), "Rect.contains");
        assertSame(inside, Collide.rectRect(r.x(), r.y(), r.w(), r.h(), p.x(), p.y(), 0, 0), "rectRect(r, 0x0)");
        assertSame(inside, Collide.rectRect(p.x(), p.y(), 0, 0, r.x(), r.y(), r.w(), r.h()), "rectRect(0x0, r)");
        assertSame(inside, Collide.circleRect(p.x(), p.y(), 0, r.x(), r.y(), r.w(), r.h()), "circleRect(radius 0, r)");
    }

    // ---------------------------------------------------- translation invariance

    @Property
    void circlePoint_sameAnswerMovedByWholeOffsets(@ForAll("circlePointCases") CirclePoint k,
                                                   @ForAll("wholeOffsets") int dx,
                                                   @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        CirclePoint moved = k.moved(dx, dy);
        assertSame(k.collide(), moved.collide(), "moved by (" + dx + ", " + dy + "): " + moved);
        checkTouchingCoverage();
    }

    @Property
    void circleCircle_sameAnswerMovedByWholeOffsets(@ForAll("circleCircleCases") CircleCircle k,
                                                    @ForAll("wholeOffsets") int dx,
                                                    @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        CircleCircle moved = k.moved(dx, dy);
        assertSame(k.collide(), moved.collide(), "moved by (" + dx + ", " + dy + "): " + moved);
        checkTouchingCoverage();
    }

    @Property
    void rectPoint_sameAnswerMovedByWholeOffsets(@ForAll("rectPointCases") RectPoint k,
                                                 @ForAll("wholeOffsets") int dx,
                                                 @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        RectPoint moved = k.moved(dx, dy);
        assertSame(k.collide(), moved.collide(), "moved by (" + dx + ", " + dy + "): " + moved);
        checkTouchingCoverage();
    }

    @Property
    void rectRect_sameAnswerMovedByWholeOffsets(@ForAll("rectRectCases") RectRect k,
                                                @ForAll("wholeOffsets") int dx,
                                                @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        RectRect moved = k.moved(dx, dy);
        assertSame(k.collide(), moved.collide(), "moved by (" + dx + ", " + dy + "): " + moved);
        checkTouchingCoverage();
    }

    @Property
    void circleRect_sameAnswerMovedByWholeOffsets(@ForAll("circleRectCases") CircleRect k,
                                                  @ForAll("wholeOffsets") int dx,
                                                  @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        CircleRect moved = k.moved(dx, dy);
        assertSame(k.collide(), moved.collide(), "moved by (" + dx + ", " + dy + "): " + moved);
        checkTouchingCoverage();
    }

    // ------------------------------------- exact agreement on whole numbers

    @Property
    void circlePoint_agreesExactlyWithReferenceOnWholeNumbers(@ForAll("circlePointCases") CirclePoint k,
            @ForAll("wholeOffsets") int dx, @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        CirclePoint m = k.moved(dx, dy);
        assertSame(m.reference(), m.collide(), "Reference vs Collide: " + m);
        checkTouchingCoverage();
    }

    @Property
    void circleCircle_agreesExactlyWithReferenceOnWholeNumbers(@ForAll("circleCircleCases") CircleCircle k,
            @ForAll("wholeOffsets") int dx, @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        CircleCircle m = k.moved(dx, dy);
        assertSame(m.reference(), m.collide(), "Reference vs Collide: " + m);
        checkTouchingCoverage();
    }

    @Property
    void rectPoint_agreesExactlyWithReferenceOnWholeNumbers(@ForAll("rectPointCases") RectPoint k,
            @ForAll("wholeOffsets") int dx, @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        RectPoint m = k.moved(dx, dy);
        assertSame(m.reference(), m.collide(), "Reference vs Collide: " + m);
        checkTouchingCoverage();
    }

    @Property
    void rectRect_agreesExactlyWithReferenceOnWholeNumbers(@ForAll("rectRectCases") RectRect k,
            @ForAll("wholeOffsets") int dx, @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        RectRect m = k.moved(dx, dy);
        assertSame(m.reference(), m.collide(), "Reference vs Collide: " + m);
        checkTouchingCoverage();
    }

    @Property
    void circleRect_agreesExactlyWithReferenceOnWholeNumbers(@ForAll("circleRectCases") CircleRect k,
            @ForAll("wholeOffsets") int dx, @ForAll("wholeOffsets") int dy) {
        label(k.touching());
        CircleRect m = k.moved(dx, dy);
        assertSame(m.reference(), m.collide(), "Reference vs Collide: " + m);
        checkTouchingCoverage();
    }

    @Property
    void all_agreeExactlyWithReferenceOnLargeWholeNumbers(@ForAll("largeWholeCircles") Circle c,
                                                          @ForAll("largeWholeCircles") Circle d,
                                                          @ForAll("largeWholeRects") Rect r,
                                                          @ForAll("largeWholeRects") Rect s) {
        // Whole numbers up to 2^20 each way, sizes too: far apart, far inside, and every
        // difference and square still exact in a double.
        CirclePoint circlePoint = new CirclePoint(c, new Vec(d.x(), d.y()));
        CircleCircle circleCircle = new CircleCircle(c, d);
        RectPoint rectPoint = new RectPoint(r, new Vec(c.x(), c.y()));
        RectRect rectRect = new RectRect(r, s);
        CircleRect circleRect = new CircleRect(c, r);
        assertSame(circlePoint.reference(), circlePoint.collide(), "Reference vs Collide: " + circlePoint);
        assertSame(circleCircle.reference(), circleCircle.collide(), "Reference vs Collide: " + circleCircle);
        assertSame(rectPoint.reference(), rectPoint.collide(), "Reference vs Collide: " + rectPoint);
        assertSame(rectRect.reference(), rectRect.collide(), "Reference vs Collide: " + rectRect);
        assertSame(circleRect.reference(), circleRect.collide(), "Reference vs Collide: " + circleRect);
    }

    // ------------------------- agreement on fractional floats, away from touching

    @Property
    void circlePoint_agreesWithReferenceAwayFromTheOutline(@ForAll("fractionalCircles") Circle c,
                                                           @ForAll("fractionalPoints") Vec p) {
        CirclePoint k = new CirclePoint(c, p);
        Assume.that(farFrom(k.margin(), 2, c.x(), c.y(), c.r(), p.x(), p.y()));
        assertSame(k.reference(), k.collide(), "Reference vs Collide: " + k);
    }

    @Property
    void circleCircle_agreesWithReferenceAwayFromTouching(@ForAll("fractionalCircles") Circle a,
                                                          @ForAll("fractionalCircles") Circle b) {
        CircleCircle k = new CircleCircle(a, b);
        Assume.that(farFrom(k.margin(), 2, a.x(), a.y(), a.r(), b.x(), b.y(), b.r()));
        assertSame(k.reference(), k.collide(), "Reference vs Collide: " + k);
    }

    @Property
    void rectPoint_agreesWithReferenceAwayFromTheEdges(@ForAll("fractionalRects") Rect r,
                                                       @ForAll("fractionalPoints") Vec p) {
        RectPoint k = new RectPoint(r, p);
        Assume.that(allFarFrom(k.margins(), r.x(), r.y(), r.w(), r.h(), p.x(), p.y()));
        assertSame(k.reference(), k.collide(), "Reference vs Collide: " + k);
    }

    @Property
    void rectRect_agreesWithReferenceAwayFromTouching(@ForAll("fractionalRects") Rect a,
                                                      @ForAll("fractionalRects") Rect b) {
        RectRect k = new RectRect(a, b);
        Assume.that(allFarFrom(k.margins(), a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h()));
        assertSame(k.reference(), k.collide(), "Reference vs Collide: " + k);
    }

    @Property
    void circleRect_agreesWithReferenceAwayFromTouching(@ForAll("fractionalCircles") Circle c,
                                                        @ForAll("fractionalRects") Rect r) {
        CircleRect k = new CircleRect(c, r);
        Assume.that(c.r() > 0
                ? farFrom(k.margin(), 2, c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h())
                : allFarFrom(new RectPoint(r, new Vec(c.x(), c.y())).margins(),
                        c.x(), c.y(), r.x(), r.y(), r.w(), r.h()));
        assertSame(k.reference(), k.collide(), "Reference vs Collide: " + k);
    }

    // --------------------------------------------- bounds are a safe first test

    @Property
    void circleBounds_overlapWheneverTheCircleDoes(@ForAll("circleRectCases") CircleRect k) {
        label(k.touching());
        Rect bounds = k.c().bounds();
        if (k.collide()) {
            assertSame(true, new RectRect(bounds, k.r()).collide(), "bounds " + bounds + " miss " + k);
        }
        checkTouchingCoverage();
    }

    @Property
    void circleBounds_overlapWheneverTwoCirclesDo(@ForAll("circleCircleCases") CircleCircle k) {
        label(k.touching());
        if (k.collide()) {
            assertSame(true, new RectRect(k.a().bounds(), k.b().bounds()).collide(), "bounds miss " + k);
        }
        checkTouchingCoverage();
    }

    @Property
    void circleBounds_containWhatTheCircleContains(@ForAll("circlePointCases") CirclePoint k) {
        label(k.touching());
        if (k.collide()) {
            assertSame(true, k.c().bounds().contains(k.p().x(), k.p().y()), "bounds miss " + k);
        }
        checkTouchingCoverage();
    }

    // ------------------------------------------------------------------ cases

    /** A circle and a point, with the library's and the reference's answers. */
    record CirclePoint(Circle c, Vec p) {
        CirclePoint moved(float dx, float dy) {
            return new CirclePoint(c.translated(dx, dy), new Vec(p.x() + dx, p.y() + dy));
        }

        boolean collide() {
            return Collide.circlePoint(c.x(), c.y(), c.r(), p.x(), p.y());
        }

        boolean reference() {
            return ExactReference.circlePoint(c.x(), c.y(), c.r(), p.x(), p.y());
        }

        /** r^2 - d^2: positive inside, 0 on the outline. */
        BigDecimal margin() {
            return ExactReference.circleCircleMargin(c.x(), c.y(), c.r(), p.x(), p.y(), 0);
        }

        boolean touching() {
            return margin().signum() == 0;
        }
    }

    /** Two circles, with the library's and the reference's answers. */
    record CircleCircle(Circle a, Circle b) {
        CircleCircle moved(float dx, float dy) {
            return new CircleCircle(a.translated(dx, dy), b.translated(dx, dy));
        }

        boolean collide() {
            return Collide.circleCircle(a.x(), a.y(), a.r(), b.x(), b.y(), b.r());
        }

        boolean reference() {
            return ExactReference.circleCircle(a.x(), a.y(), a.r(), b.x(), b.y(), b.r());
        }

        /** (r1 + r2)^2 - d^2: positive when overlapping, 0 when touching. */
        BigDecimal margin() {
            return ExactReference.circleCircleMargin(a.x(), a.y(), a.r(), b.x(), b.y(), b.r());
        }

        boolean touching() {
            return margin().signum() == 0;
        }
    }

    /** A rectangle and a point, with the library's and the reference's answers. */
    record RectPoint(Rect r, Vec p) {
        RectPoint moved(float dx, float dy) {
            return new RectPoint(r.translated(dx, dy), new Vec(p.x() + dx, p.y() + dy));
        }

        boolean collide() {
            return Collide.rectPoint(r.x(), r.y(), r.w(), r.h(), p.x(), p.y());
        }

        boolean reference() {
            return ExactReference.rectPoint(r.x(), r.y(), r.w(), r.h(), p.x(), p.y());
        }

        /** How far the point is inside each edge (left, right, top, bottom); 0 is on it. */
        List<BigDecimal> margins() {
            return List.of(diff(p.x(), r.x()), diff(r.x(), r.w(), p.x()),
                    diff(p.y(), r.y()), diff(r.y(), r.h(), p.y()));
        }

        boolean touching() {
            return !reference() && new RectRect(r, new Rect(p.x(), p.y(), 0, 0)).closedBoxesMeet();
        }
    }

    /** Two rectangles, with the library's and the reference's answers. */
    record RectRect(Rect a, Rect b) {
        RectRect moved(float dx, float dy) {
            return new RectRect(a.translated(dx, dy), b.translated(dx, dy));
        }

        boolean collide() {
            return Collide.rectRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h());
        }

        boolean reference() {
            return ExactReference.rectRect(a.x(), a.y(), a.w(), a.h(), b.x(), b.y(), b.w(), b.h());
        }

        /** The four edge comparisons' margins, positive when that comparison says "overlap". */
        List<BigDecimal> margins() {
            return List.of(diff(a.x(), a.w(), b.x()), diff(b.x(), b.w(), a.x()),
                    diff(a.y(), a.h(), b.y()), diff(b.y(), b.h(), a.y()));
        }

        boolean closedBoxesMeet() {
            return margins().stream().allMatch(m -> m.signum() >= 0);
        }

        /** The closed rectangles meet but the shapes do not collide: they only touch. */
        boolean touching() {
            return closedBoxesMeet() && !reference();
        }
    }

    /** A circle and a rectangle, with the library's and the reference's answers. */
    record CircleRect(Circle c, Rect r) {
        CircleRect moved(float dx, float dy) {
            return new CircleRect(c.translated(dx, dy), r.translated(dx, dy));
        }

        boolean collide() {
            return circleRect(c, r);
        }

        boolean reference() {
            return ExactReference.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        }

        /** r^2 minus the squared distance from the centre to the closed rectangle. */
        BigDecimal margin() {
            return ExactReference.circleRectMargin(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        }

        /** The circle's outline reaches the rectangle but the shapes do not collide. */
        boolean touching() {
            return margin().signum() >= 0 && !reference();
        }
    }

    // ------------------------------------------------------------- generators

    /** Pythagorean directions (a, b, a^2 + b^2 = c^2) with their length c, for exact touching. */
    private static final int[][] PYTHAGOREAN = {
            {0, 1, 1}, {1, 0, 1}, {3, 4, 5}, {4, 3, 5}, {5, 12, 13}, {12, 5, 13}, {8, 15, 17}, {15, 8, 17}};

    @Provide
    Arbitrary<Integer> wholeOffsets() {
        return Arbitraries.integers().between(-1_000_000, 1_000_000)
                .edgeCases(e -> e.includeOnly(0, -1_000_000, 1_000_000));
    }

    private static Arbitrary<Integer> smallCoordinates() {
        return Arbitraries.integers().between(-20, 20);
    }

    private static Arbitrary<Integer> smallSizes() {
        return Arbitraries.integers().between(0, 12);
    }

    private static Arbitrary<Circle> smallCircles() {
        return Combinators.combine(smallCoordinates(), smallCoordinates(), smallSizes())
                .as((x, y, r) -> new Circle(x, y, r));
    }

    private static Arbitrary<Rect> smallRects() {
        return Combinators.combine(smallCoordinates(), smallCoordinates(), smallSizes(), smallSizes())
                .as((x, y, w, h) -> new Rect(x, y, w, h));
    }

    private static Arbitrary<Vec> smallPoints() {
        return Combinators.combine(smallCoordinates(), smallCoordinates()).as((x, y) -> new Vec(x, y));
    }

    /** A Pythagorean offset {dx, dy, length} with random signs, scaled by 1 or 2. */
    private static Arbitrary<int[]> pythagoreanOffsets() {
        return Combinators.combine(Arbitraries.of(PYTHAGOREAN), Arbitraries.of(-1, 1), Arbitraries.of(-1, 1),
                        Arbitraries.integers().between(1, 2))
                .as((t, sx, sy, k) -> new int[] {sx * k * t[0], sy * k * t[1], k * t[2]});
    }

    /** -1, 0 or +1, mostly 0: a touching case, or its nearest neighbours either side. */
    private static Arbitrary<Integer> nudges() {
        return Arbitraries.frequency(Tuple.of(2, 0), Tuple.of(1, -1), Tuple.of(1, 1));
    }

    @Provide
    Arbitrary<CirclePoint> circlePointCases() {
        Arbitrary<CirclePoint> onOutline = Combinators.combine(smallPoints(), pythagoreanOffsets(), nudges())
                .as((c, d, n) -> new CirclePoint(new Circle(c.x(), c.y(), Math.max(0, d[2] + n)),
                        new Vec(c.x() + d[0], c.y() + d[1])));
        Arbitrary<CirclePoint> random = Combinators.combine(smallCircles(), smallPoints()).as(CirclePoint::new);
        return either(random, onOutline);
    }

    @Provide
    Arbitrary<CircleCircle> circleCircleCases() {
        Arbitrary<CircleCircle> touching = Combinators.combine(smallPoints(), pythagoreanOffsets(),
                        Arbitraries.integers().between(0, 34), nudges())
                .as((c, d, share, n) -> {
                    int r1 = Math.min(share, d[2]);
                    int r2 = Math.max(0, d[2] - r1 + n);
                    return new CircleCircle(new Circle(c.x(), c.y(), r1), new Circle(c.x() + d[0], c.y() + d[1], r2));
                });
        Arbitrary<CircleCircle> random = Combinators.combine(smallCircles(), smallCircles()).as(CircleCircle::new);
        return either(random, touching);
    }

    @Provide
    Arbitrary<RectPoint> rectPointCases() {
        // A point on an edge or a corner, or one step inside or outside it.
        Arbitrary<RectPoint> onEdge = Combinators.combine(smallRects(), Arbitraries.integers().between(0, 3),
                        Arbitraries.integers().between(0, 12), nudges())
                .as((r, side, along, n) -> {
                    float px = switch (side) {
                        case 0 -> r.x() + n;
                        case 1 -> r.right() + n;
                        default -> r.x() + Math.min(along, r.w());
                    };
                    float py = switch (side) {
                        case 2 -> r.y() + n;
                        case 3 -> r.bottom() + n;
                        default -> r.y() + Math.min(along, r.h());
                    };
                    return new RectPoint(r, new Vec(px, py));
                });
        Arbitrary<RectPoint> random = Combinators.combine(smallRects(), smallPoints()).as(RectPoint::new);
        return either(random, onEdge);
    }

    @Provide
    Arbitrary<RectRect> rectRectCases() {
        // The second rectangle put against one side of the first (side by side, stacked, or
        // corner to corner), slid along it, then nudged one step apart, or one step in.
        Arbitrary<RectRect> against = Combinators.combine(smallRects(), smallSizes(), smallSizes(),
                        Arbitraries.integers().between(0, 3), Arbitraries.integers().between(-14, 14), nudges())
                .as((a, w, h, side, along, n) -> {
                    float x = switch (side) {
                        case 0 -> a.x() - w - n;
                        case 1 -> a.right() + n;
                        default -> a.x() + along;
                    };
                    float y = switch (side) {
                        case 2 -> a.y() - h - n;
                        case 3 -> a.bottom() + n;
                        default -> a.y() + along;
                    };
                    return new RectRect(a, new Rect(x, y, w, h));
                });
        // A zero-width and a zero-height rectangle near each other, often crossing like a plus
        // sign (which collides) or meeting at an end (which does not).
        Arbitrary<Integer> near = Arbitraries.integers().between(-6, 6);
        Arbitrary<RectRect> segments = Combinators.combine(near, near, smallSizes(), near, near, smallSizes())
                .as((x1, y1, h, x2, y2, w) -> new RectRect(new Rect(x1, y1, 0, h), new Rect(x2, y2, w, 0)));
        Arbitrary<RectRect> random = Combinators.combine(smallRects(), smallRects()).as(RectRect::new);
        return either(random, against, segments);
    }

    @Provide
    Arbitrary<CircleRect> circleRectCases() {
        // A circle whose outline passes through a corner, from outside the rectangle.
        Arbitrary<CircleRect> atCorner = Combinators.combine(smallRects(), Arbitraries.of(0, 1),
                        Arbitraries.of(0, 1), pythagoreanOffsets(), nudges())
                .as((r, right, bottom, d, n) -> {
                    float cornerX = right == 1 ? r.right() : r.x();
                    float cornerY = bottom == 1 ? r.bottom() : r.y();
                    float cx = cornerX + (right == 1 ? 1 : -1) * Math.abs(d[0]);
                    float cy = cornerY + (bottom == 1 ? 1 : -1) * Math.abs(d[1]);
                    return new CircleRect(new Circle(cx, cy, Math.max(0, d[2] + n)), r);
                });
        // A circle beside an edge, its outline reaching the edge at any point along it.
        Arbitrary<CircleRect> atEdge = Combinators.combine(smallRects(), Arbitraries.integers().between(0, 3),
                        Arbitraries.integers().between(0, 12), Arbitraries.integers().between(0, 12), nudges())
                .as((r, side, along, gap, n) -> {
                    float cx = switch (side) {
                        case 0 -> r.x() - gap;
                        case 1 -> r.right() + gap;
                        default -> r.x() + Math.min(along, r.w());
                    };
                    float cy = switch (side) {
                        case 2 -> r.y() - gap;
                        case 3 -> r.bottom() + gap;
                        default -> r.y() + Math.min(along, r.h());
                    };
                    return new CircleRect(new Circle(cx, cy, Math.max(0, gap + n)), r);
                });
        Arbitrary<CircleRect> random = Combinators.combine(smallCircles(), smallRects()).as(CircleRect::new);
        return either(random, atCorner, atEdge);
    }

    /** Whole numbers up to 2^20 each way: every sum, difference and square exact in a double. */
    private static Arbitrary<Integer> largeWhole() {
        return Arbitraries.integers().between(-(1 << 20), 1 << 20);
    }

    @Provide
    Arbitrary<Circle> largeWholeCircles() {
        return Combinators.combine(largeWhole(), largeWhole(), largeWhole().map(Math::abs))
                .as((x, y, r) -> new Circle(x, y, r));
    }

    @Provide
    Arbitrary<Rect> largeWholeRects() {
        return Combinators.combine(largeWhole(), largeWhole(), largeWhole().map(Math::abs), largeWhole().map(Math::abs))
                .as((x, y, w, h) -> new Rect(x, y, w, h));
    }

    private static Arbitrary<Float> fractionalCoordinates() {
        return Arbitraries.floats().between(-1000, 1000).ofScale(5);
    }

    private static Arbitrary<Float> fractionalSizes() {
        return Arbitraries.floats().between(0, 600).ofScale(5);
    }

    @Provide
    Arbitrary<Circle> fractionalCircles() {
        return Combinators.combine(fractionalCoordinates(), fractionalCoordinates(), fractionalSizes())
                .as(Circle::new);
    }

    @Provide
    Arbitrary<Rect> fractionalRects() {
        return Combinators.combine(fractionalCoordinates(), fractionalCoordinates(),
                        fractionalSizes(), fractionalSizes())
                .as(Rect::new);
    }

    @Provide
    Arbitrary<Vec> fractionalPoints() {
        return Combinators.combine(fractionalCoordinates(), fractionalCoordinates()).as(Vec::new);
    }

    /** Small whole, fractional and very large values mixed: symmetry must hold for all of them. */
    private static Arbitrary<Float> anyCoordinates() {
        return either(smallCoordinates().map(Integer::floatValue), fractionalCoordinates(),
                Arbitraries.floats().between(-1e30f, 1e30f));
    }

    private static Arbitrary<Float> anySizes() {
        return either(smallSizes().map(Integer::floatValue), fractionalSizes(),
                Arbitraries.floats().between(0, 1e30f));
    }

    @Provide
    Arbitrary<Circle> anyCircles() {
        return Combinators.combine(anyCoordinates(), anyCoordinates(), anySizes()).as(Circle::new);
    }

    @Provide
    Arbitrary<Rect> anyRects() {
        return Combinators.combine(anyCoordinates(), anyCoordinates(), anySizes(), anySizes()).as(Rect::new);
    }

    @Provide
    Arbitrary<Vec> anyPoints() {
        return Combinators.combine(anyCoordinates(), anyCoordinates()).as(Vec::new);
    }

    // ---------------------------------------------------------------- helpers

    /**
     * One of the choices, picked by a generated index. Arbitraries.oneOf would do, but it is
     * built on flatMap, which jqwik is slowest of all to shrink or to replay from its database.
     */
    private static <T> Arbitrary<T> either(Arbitrary<T> first, Arbitrary<T> second) {
        return Combinators.combine(Arbitraries.integers().between(0, 1), first, second)
                .as((i, a, b) -> i == 0 ? a : b);
    }

    private static <T> Arbitrary<T> either(Arbitrary<T> first, Arbitrary<T> second, Arbitrary<T> third) {
        return Combinators.combine(Arbitraries.integers().between(0, 2), first, second, third)
                .as((i, a, b, c) -> i == 0 ? a : i == 1 ? b : c);
    }

    private static boolean circleRect(Circle c, Rect r) {
        return Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
    }

    private static BigDecimal sum(float a, float b) {
        return ExactReference.exact(a).add(ExactReference.exact(b));
    }

    /** a - b, exactly. */
    private static BigDecimal diff(float a, float b) {
        return ExactReference.exact(a).subtract(ExactReference.exact(b));
    }

    /** (start + length) - v, exactly. */
    private static BigDecimal diff(float start, float length, float v) {
        return sum(start, length).subtract(ExactReference.exact(v));
    }

    /**
     * Is the margin clear of 0 by more than rounding could bridge? The library rounds once or
     * twice per operation in double (relative error near 1e-16); this asks for 1e-9 of the
     * inputs' size, raised to the margin's degree (1 for edges, 2 for squared distances).
     */
    private static boolean farFrom(BigDecimal margin, int degree, float... inputs) {
        BigDecimal size = BigDecimal.ONE;
        for (float v : inputs) {
            size = size.add(ExactReference.exact(v).abs());
        }
        return margin.abs().compareTo(size.pow(degree).multiply(new BigDecimal("1e-9"))) > 0;
    }

    private static boolean allFarFrom(List<BigDecimal> margins, float... inputs) {
        return margins.stream().allMatch(m -> farFrom(m, 1, inputs));
    }

    private static void assertSame(boolean expected, boolean actual, String what) {
        if (expected != actual) {
            throw new AssertionError(what + ": expected " + expected + " but was " + actual);
        }
    }

    private static void label(boolean touching) {
        Statistics.label("touching").collect(touching);
    }

    /** Fails the property if fewer than 3% of its cases touched: the boundary must be tested. */
    private static void checkTouchingCoverage() {
        Statistics.label("touching").coverage(c -> c.check(true).percentage(p -> p >= 3));
    }
}
