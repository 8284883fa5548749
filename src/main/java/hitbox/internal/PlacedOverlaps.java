package hitbox.internal;

/**
 * Do two bodies' {@link Placement}s overlap? {@link Overlaps}' answer for the shapes the
 * numbers stand for, routed to the same kernels ({@link RawTests}, {@link Polygons},
 * {@link TurnedEllipses}' plain-number cases) with the numbers a body keeps, so that a world's
 * pair test makes no shape. The pairs go by {@link ShapeKind}'s order, as in
 * {@link Overlaps}: each unordered pair is answered by its earlier kind's method, the other
 * handed over swapped. {@code PlacementTest} holds this table to {@link Overlaps} on
 * every pair of kinds, in both orders.
 *
 * <p>Each switch names every kind, so a new kind does not compile until it has a case here.
 */
public final class PlacedOverlaps {
    private PlacedOverlaps() {
    }

    /**
     * @param p a placement whose kind is set
     * @param q another
     * @return whether the shapes they stand for overlap, as {@code Shape.overlaps} answers
     */
    public static boolean test(Placement p, Placement q) {
        return switch (p.kind) {
            case ELLIPSE -> ellipseWith(p, q);
            case CIRCLE -> circleWith(p, q);
            case RECT -> rectWith(p, q);
            case SEGMENT -> segmentWith(p, q);
            case POLYGON -> polygonWith(p, q);
            case CAPSULE -> capsuleWith(p, q);
        };
    }

    private static boolean aligned(Placement e) {
        return e.e == 0 || e.c == e.d;  // TurnedEllipses.aligned
    }

    /** A real ellipse (x a, y b, radii c and d, angle e) with anything: the first kind. */
    private static boolean ellipseWith(Placement e, Placement o) {
        float x = e.a, y = e.b, rx = e.c, ry = e.d, angle = e.e;
        if (!aligned(e)) {
            return switch (o.kind) {
                case ELLIPSE -> TurnedEllipses.realPair(x, y, rx, ry, angle, o.a, o.b, o.c, o.d, o.e);
                case CAPSULE -> TurnedEllipses.capsule(x, y, rx, ry, angle, o.a, o.b, o.c, o.d, o.e);
                case CIRCLE -> TurnedEllipses.circle(x, y, rx, ry, angle, o.a, o.b, o.c);
                case RECT -> TurnedEllipses.rect(x, y, rx, ry, angle, o.a, o.b, o.c, o.d);
                case SEGMENT -> TurnedEllipses.segment(x, y, rx, ry, angle, o.a, o.b, o.c, o.d);
                case POLYGON -> TurnedEllipses.polygon(x, y, rx, ry, angle, o.xy);
            };
        }
        return switch (o.kind) {
            case ELLIPSE -> aligned(o) ? RawTests.ellipseEllipse(x, y, rx, ry, o.a, o.b, o.c, o.d)
                    : TurnedEllipses.realPair(x, y, rx, ry, angle, o.a, o.b, o.c, o.d, o.e);
            case CAPSULE -> RawTests.ellipseCapsule(x, y, rx, ry, o.a, o.b, o.c, o.d, o.e);
            case CIRCLE -> RawTests.ellipseCircle(x, y, rx, ry, o.a, o.b, o.c);
            case RECT -> RawTests.ellipseRect(x, y, rx, ry, o.a, o.b, o.c, o.d);
            case SEGMENT -> RawTests.ellipseLine(x, y, rx, ry, o.a, o.b, o.c, o.d);
            case POLYGON -> RawTests.polygonEllipse(o.xy, x, y, rx, ry);
        };
    }

    /** A capsule (ends (a, b) and (c, d), radius e) with anything: an ellipse takes the pair swapped. */
    private static boolean capsuleWith(Placement k, Placement o) {
        float x1 = k.a, y1 = k.b, x2 = k.c, y2 = k.d, r = k.e;
        return switch (o.kind) {
            case ELLIPSE -> ellipseWith(o, k);
            case CAPSULE -> RawTests.capsuleCapsule(x1, y1, x2, y2, r, o.a, o.b, o.c, o.d, o.e);
            case CIRCLE -> RawTests.capsuleCircle(x1, y1, x2, y2, r, o.a, o.b, o.c);
            case RECT -> RawTests.capsuleRect(x1, y1, x2, y2, r, o.a, o.b, o.c, o.d);
            case SEGMENT -> RawTests.capsuleLine(x1, y1, x2, y2, r, o.a, o.b, o.c, o.d);
            case POLYGON -> RawTests.polygonCapsule(o.xy, x1, y1, x2, y2, r);
        };
    }

    /** A circle (x a, y b, radius c) with anything: an ellipse or a capsule takes the pair swapped. */
    private static boolean circleWith(Placement c, Placement o) {
        return switch (o.kind) {
            case ELLIPSE -> ellipseWith(o, c);
            case CAPSULE -> capsuleWith(o, c);
            case CIRCLE -> RawTests.circleCircle(c.a, c.b, c.c, o.a, o.b, o.c);
            case RECT -> RawTests.circleRect(c.a, c.b, c.c, o.a, o.b, o.c, o.d);
            case SEGMENT -> RawTests.lineCircle(o.a, o.b, o.c, o.d, c.a, c.b, c.c);
            case POLYGON -> RawTests.polygonCircleChecked(o.xy, c.a, c.b, c.c);
        };
    }

    /** A rectangle (x a, y b, w c, h d) with anything: an ellipse, a capsule or a circle takes the pair swapped. */
    private static boolean rectWith(Placement r, Placement o) {
        return switch (o.kind) {
            case ELLIPSE -> ellipseWith(o, r);
            case CAPSULE -> capsuleWith(o, r);
            case CIRCLE -> circleWith(o, r);
            case RECT -> RawTests.rectRect(r.a, r.b, r.c, r.d, o.a, o.b, o.c, o.d);
            case SEGMENT -> RawTests.lineRect(o.a, o.b, o.c, o.d, r.a, r.b, r.c, r.d);
            case POLYGON -> Overlaps.rectPolygon(r.a, r.b, r.c, r.d, o.xy, o.winding);
        };
    }

    /** A segment (x1 a, y1 b, x2 c, y2 d) with anything: only a polygon comes later. */
    private static boolean segmentWith(Placement s, Placement o) {
        return switch (o.kind) {
            case ELLIPSE -> ellipseWith(o, s);
            case CAPSULE -> capsuleWith(o, s);
            case CIRCLE -> circleWith(o, s);
            case RECT -> rectWith(o, s);
            case SEGMENT -> RawTests.lineLine(s.a, s.b, s.c, s.d, o.a, o.b, o.c, o.d);
            case POLYGON -> RawTests.polygonLine(o.xy, s.a, s.b, s.c, s.d);
        };
    }

    /** A convex polygon with anything: the last kind, so every other kind takes the pair swapped. */
    private static boolean polygonWith(Placement p, Placement o) {
        return switch (o.kind) {
            case ELLIPSE -> ellipseWith(o, p);
            case CAPSULE -> capsuleWith(o, p);
            case CIRCLE -> circleWith(o, p);
            case RECT -> rectWith(o, p);
            case SEGMENT -> segmentWith(o, p);
            case POLYGON -> Polygons.convexOverlap(p.xy, p.winding, o.xy, o.winding);
        };
    }
}
