package hitbox.internal;

import hitbox.*;

/**
 * The one table behind {@link Shape#overlaps}: every pair of shape kinds, in either order,
 * routed to the {@link RawTests} method for that pair (the body of {@link Collide}'s method of
 * the same name, for the tutorial's pairs).
 *
 * <p>The kinds are taken in {@link ShapeKind}'s order (ellipse, capsule, circle, rectangle, segment, polygon): the pair is
 * handed to the method of its earlier kind, with the arguments swapped if they came the
 * other way round, so each unordered pair has exactly one line of code and
 * {@code a.overlaps(b) == b.overlaps(a)} holds by construction.
 *
 * <p>Each kind has its own small method ({@link #circleWith}, say), which
 * {@link Shape#overlaps} reaches through {@link #test}'s one switch on the receiver's kind
 * (for a receiver of one kind the JIT keeps only that case): it answers the pairs whose
 * earlier kind it is, and hands the pair swapped straight to an earlier kind's method. Small is the point: one big dispatch
 * on both shapes was too large for the JIT to inline into a caller's loop (once compiled on
 * its own it is "already compiled into a big method"), which cost a call on every test even
 * where the raw {@code Collide} call inlines whole, up to 1.6x its time; a per-kind method of
 * a few type checks inlines, and the compiler then keeps only the branch the loop takes. For
 * the same reason a swap never goes back through {@link #test}. At worst, when a kind's
 * {@code overlaps} is compiled on its own first with the {@code Collide} method inside it,
 * the loop makes the one call it would make to a {@code Collide} method compiled on its own.
 * Each method is a switch expression over {@link ShapeKind#of} (its type checks), so a new
 * kind does not compile until every kind's method has its case.
 *
 * <table>
 *   <caption>Which RawTests method answers each pair</caption>
 *   <tr><th></th><th>Circle</th><th>Rect</th><th>Segment</th><th>Polygon</th><th>Ellipse</th><th>Capsule</th></tr>
 *   <tr><th>Circle</th><td>circleCircle</td><td>circleRect</td><td>lineCircle</td><td>polygonCircle</td><td></td><td></td></tr>
 *   <tr><th>Rect</th><td></td><td>rectRect</td><td>lineRect</td><td>polygonRect</td><td></td><td></td></tr>
 *   <tr><th>Segment</th><td></td><td></td><td>lineLine</td><td>polygonLine</td><td></td><td></td></tr>
 *   <tr><th>Polygon</th><td></td><td></td><td></td><td>polygonPolygon</td><td></td><td></td></tr>
 *   <tr><th>Ellipse</th><td>ellipseCircle</td><td>ellipseRect</td><td>ellipseLine</td><td>polygonEllipse</td><td>ellipseEllipse</td><td>ellipseCapsule</td></tr>
 *   <tr><th>Capsule</th><td>capsuleCircle</td><td>capsuleRect</td><td>capsuleLine</td><td>polygonCapsule</td><td></td><td>capsuleCapsule</td></tr>
 * </table>
 */
public final class Overlaps {
    private Overlaps() {
    }

    /**
     * Any two shapes: routed on the first shape's kind only, to that kind's method, which
     * routes the second (and swaps the pair to the second's method if that kind comes
     * earlier). For the library's own callers, which hold two shapes of unknown kinds.
     */
    public static boolean test(Shape a, Shape b) {
        return switch (ShapeKind.of(a)) {
            case ELLIPSE -> ellipseWith((Ellipse) a, b);
            case CAPSULE -> capsuleWith((Capsule) a, b);
            case CIRCLE -> circleWith((Circle) a, b);
            case RECT -> rectWith((Rect) a, b);
            case SEGMENT -> segmentWith((Segment) a, b);
            case POLYGON -> polygonWith((Polygon) a, b);
        };
    }

    /** An ellipse with anything: the first kind, so it answers every pair it is in. */
    public static boolean ellipseWith(Ellipse e, Shape other) {
        ShapeKind k = ShapeKind.of(other);
        if (!TurnedEllipses.aligned(e) || k == ShapeKind.ELLIPSE && !TurnedEllipses.aligned((Ellipse) other)) {
            return TurnedEllipses.turned(e, other); // a turned ellipse: the other shape in its frame
        }
        float x = e.x(), y = e.y(), a = e.rx(), b = e.ry();
        return switch (k) {
            case ELLIPSE -> {
                Ellipse f = (Ellipse) other;
                yield RawTests.ellipseEllipse(x, y, a, b, f.x(), f.y(), f.rx(), f.ry());
            }
            case CAPSULE -> {
                Capsule c = (Capsule) other;
                yield RawTests.ellipseCapsule(x, y, a, b, c.x1(), c.y1(), c.x2(), c.y2(), c.r());
            }
            case CIRCLE -> {
                Circle c = (Circle) other;
                yield RawTests.ellipseCircle(x, y, a, b, c.x(), c.y(), c.r());
            }
            case RECT -> {
                Rect r = (Rect) other;
                yield RawTests.ellipseRect(x, y, a, b, r.x(), r.y(), r.w(), r.h());
            }
            case SEGMENT -> {
                Segment s = (Segment) other;
                yield RawTests.ellipseLine(x, y, a, b, s.x1(), s.y1(), s.x2(), s.y2());
            }
            case POLYGON -> RawTests.polygonEllipse(HiddenParts.raw((Polygon) other), x, y, a, b);
        };
    }

    /** A capsule with anything: an ellipse, the one earlier kind, takes the pair swapped. */
    public static boolean capsuleWith(Capsule k, Shape other) {
        float x1 = k.x1(), y1 = k.y1(), x2 = k.x2(), y2 = k.y2(), r = k.r();
        return switch (ShapeKind.of(other)) {
            case ELLIPSE -> ellipseWith((Ellipse) other, k);
            case CAPSULE -> {
                Capsule o = (Capsule) other;
                yield RawTests.capsuleCapsule(x1, y1, x2, y2, r, o.x1(), o.y1(), o.x2(), o.y2(), o.r());
            }
            case CIRCLE -> {
                Circle c = (Circle) other;
                yield RawTests.capsuleCircle(x1, y1, x2, y2, r, c.x(), c.y(), c.r());
            }
            case RECT -> {
                Rect q = (Rect) other;
                yield RawTests.capsuleRect(x1, y1, x2, y2, r, q.x(), q.y(), q.w(), q.h());
            }
            case SEGMENT -> {
                Segment s = (Segment) other;
                yield RawTests.capsuleLine(x1, y1, x2, y2, r, s.x1(), s.y1(), s.x2(), s.y2());
            }
            case POLYGON -> RawTests.polygonCapsule(HiddenParts.raw((Polygon) other), x1, y1, x2, y2, r);
        };
    }

    /**
     * A circle with anything: a capsule or an ellipse, the earlier kinds, takes the pair swapped.
     *
     * <p>The two commonest pairs, circle with circle (the tutorial's) and circle with rectangle
     * (which the tutorial leaves out), are asked before the switch: a documented fast path (docs/architecture.md). The narrow-phase table
     * measured {@code Circle.overlaps} about 1 ns (20 to 25%) slower through the switch alone,
     * which reads the kind's case from a table javac makes for an enum switch; the other kinds'
     * {@code overlaps} showed no such loss. The switch keeps both cases, so the dispatch stays
     * complete without the fast path.
     */
    public static boolean circleWith(Circle c, Shape other) {
        if (other instanceof Circle d) {
            return circleCircle(c, d);
        }
        if (other instanceof Rect r) {
            return circleRect(c, r);
        }
        return switch (ShapeKind.of(other)) {
            case ELLIPSE -> ellipseWith((Ellipse) other, c);
            case CAPSULE -> capsuleWith((Capsule) other, c);
            case CIRCLE, RECT, SEGMENT, POLYGON -> circleWith(c.x(), c.y(), c.r(), other);
        };
    }

    /**
     * {@link #circleWith(Circle, Shape)} for the circle at (x, y) of radius r: a
     * {@code Circle} is made only for an ellipse or a capsule, which take the pair swapped. A
     * world's walk tests a moved circle many times a move, and needs no circle made for each.
     */
    public static boolean circleWith(float x, float y, float r, Shape other) {
        return switch (ShapeKind.of(other)) {
            case ELLIPSE, CAPSULE -> circleWith(new Circle(x, y, r), other);
            case CIRCLE -> {
                Circle d = (Circle) other;
                yield RawTests.circleCircle(x, y, r, d.x(), d.y(), d.r());
            }
            case RECT -> {
                Rect q = (Rect) other;
                yield RawTests.circleRect(x, y, r, q.x(), q.y(), q.w(), q.h());
            }
            case SEGMENT -> {
                Segment s = (Segment) other;
                yield RawTests.lineCircle(s.x1(), s.y1(), s.x2(), s.y2(), x, y, r);
            }
            case POLYGON -> RawTests.polygonCircleChecked(HiddenParts.raw((Polygon) other), x, y, r);
        };
    }

    private static boolean circleCircle(Circle c, Circle d) {
        return RawTests.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
    }

    private static boolean circleRect(Circle c, Rect r) {
        return RawTests.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
    }

    /** A rectangle with anything: a circle, a capsule or an ellipse takes the pair swapped. */
    public static boolean rectWith(Rect r, Shape other) {
        return switch (ShapeKind.of(other)) {
            case ELLIPSE -> ellipseWith((Ellipse) other, r);
            case CAPSULE -> capsuleWith((Capsule) other, r);
            case CIRCLE, RECT, SEGMENT, POLYGON -> rectWith(r.x(), r.y(), r.w(), r.h(), other);
        };
    }

    /**
     * {@link #rectWith(Rect, Shape)} for the rectangle of (x, y, w, h), w and h at least 0:
     * a {@code Rect} is made only for an ellipse or a capsule, which take the pair swapped. A
     * sweep tests a moved rectangle many times a call, and needs no rectangle made for each.
     */
    public static boolean rectWith(float x, float y, float w, float h, Shape other) {
        return switch (ShapeKind.of(other)) {
            case ELLIPSE, CAPSULE -> rectWith(new Rect(x, y, w, h), other);
            case CIRCLE -> {
                Circle c = (Circle) other;
                yield RawTests.circleRect(c.x(), c.y(), c.r(), x, y, w, h);
            }
            case RECT -> {
                Rect s = (Rect) other;
                yield RawTests.rectRect(x, y, w, h, s.x(), s.y(), s.w(), s.h());
            }
            case SEGMENT -> {
                Segment s = (Segment) other;
                yield RawTests.lineRect(s.x1(), s.y1(), s.x2(), s.y2(), x, y, w, h);
            }
            case POLYGON -> rectPolygon(x, y, w, h, HiddenParts.raw((Polygon) other),
                    HiddenParts.convexWinding((Polygon) other));  // the winding kept if convex
        };
    }

    /**
     * The rectangle (x, y, w, h), w and h at least 0, with the polygon of the vertices xy,
     * given its convex winding (0 if it is not convex): the one home of this pair's routing,
     * for shapes here and for a world's placed numbers ({@link PlacedOverlaps}).
     */
    public static boolean rectPolygon(float x, float y, float w, float h, float[] xy, int winding) {
        if (w == 0 || h == 0) {
            return RawTests.polygonRect(xy, x, y, w, h);  // a flat rectangle: a segment
        }
        return winding != 0 ? Polygons.convexRectOverlap(xy, winding, x, y, w, h)
                : RawTests.polygonRectWound(xy, Polygons.winding(xy), x, y, w, h);
    }

    /** A segment with anything: every kind but a polygon comes earlier and takes the pair swapped. */
    public static boolean segmentWith(Segment s, Shape other) {
        return switch (ShapeKind.of(other)) {
            case ELLIPSE -> ellipseWith((Ellipse) other, s);
            case CAPSULE -> capsuleWith((Capsule) other, s);
            case CIRCLE -> circleWith((Circle) other, s);
            case RECT -> rectWith((Rect) other, s);
            case SEGMENT -> {
                Segment t = (Segment) other;
                yield RawTests.lineLine(s.x1(), s.y1(), s.x2(), s.y2(), t.x1(), t.y1(), t.x2(), t.y2());
            }
            case POLYGON -> RawTests.polygonLine(HiddenParts.raw((Polygon) other), s.x1(), s.y1(), s.x2(), s.y2());
        };
    }

    /** A polygon with anything: the last kind, so every other kind takes the pair swapped. */
    public static boolean polygonWith(Polygon p, Shape other) {
        return switch (ShapeKind.of(other)) {
            case ELLIPSE -> ellipseWith((Ellipse) other, p);
            case CAPSULE -> capsuleWith((Capsule) other, p);
            case CIRCLE -> circleWith((Circle) other, p);
            case RECT -> rectWith((Rect) other, p);
            case SEGMENT -> segmentWith((Segment) other, p);
            case POLYGON -> Polygons.overlap(p, (Polygon) other);
        };
    }
}
