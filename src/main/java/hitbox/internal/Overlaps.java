package hitbox.internal;

import hitbox.*;

/**
 * The one table behind {@link Shape#overlaps}: every pair of shape kinds, in either order,
 * routed to the {@link Collide} method for that pair.
 *
 * <p>The kinds are taken in a fixed order (ellipse, capsule, circle, rectangle, segment, polygon): the pair is
 * handed to the method of its earlier kind, with the arguments swapped if they came the
 * other way round, so each unordered pair has exactly one line of code and
 * {@code a.overlaps(b) == b.overlaps(a)} holds by construction.
 *
 * <p>Each kind has its own small method ({@link #circleWith}, say), which its class's
 * {@code overlaps} calls directly: it answers the pairs whose earlier kind it is, and hands
 * the pair swapped straight to an earlier kind's method. Small is the point: one big dispatch
 * on both shapes was too large for the JIT to inline into a caller's loop (once compiled on
 * its own it is "already compiled into a big method"), which cost a call on every test even
 * where the raw {@code Collide} call inlines whole, up to 1.6x its time; a per-kind method of
 * a few type checks inlines, and the compiler then keeps only the branch the loop takes. For
 * the same reason a swap never goes back through {@link #test}. At worst, when a kind's
 * {@code overlaps} is compiled on its own first with the {@code Collide} method inside it,
 * the loop makes the one call it would make to a {@code Collide} method compiled on its own.
 *
 * <table>
 *   <caption>Which Collide method answers each pair</caption>
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
        // The commonest kinds in a game first; the order here decides nothing, each kind's
        // method does.
        if (a instanceof Rect r) {
            return rectWith(r, b);
        }
        if (a instanceof Circle c) {
            return circleWith(c, b);
        }
        if (a instanceof Polygon p) {
            return polygonWith(p, b);
        }
        if (a instanceof Segment s) {
            return segmentWith(s, b);
        }
        if (a instanceof Ellipse e) {
            return ellipseWith(e, b);
        }
        return capsuleWith((Capsule) a, b);
    }

    /** An ellipse with anything: the first kind, so it answers every pair it is in. */
    public static boolean ellipseWith(Ellipse e, Shape other) {
        if (!TurnedEllipses.aligned(e) || other instanceof Ellipse f && !TurnedEllipses.aligned(f)) {
            return TurnedEllipses.turned(e, other); // a turned ellipse: the other shape in its frame
        }
        float x = e.x(), y = e.y(), a = e.rx(), b = e.ry();
        if (other instanceof Ellipse f) {
            return Collide.ellipseEllipse(x, y, a, b, f.x(), f.y(), f.rx(), f.ry());
        }
        if (other instanceof Capsule k) {
            return Collide.ellipseCapsule(x, y, a, b, k.x1(), k.y1(), k.x2(), k.y2(), k.r());
        }
        if (other instanceof Circle c) {
            return Collide.ellipseCircle(x, y, a, b, c.x(), c.y(), c.r());
        }
        if (other instanceof Rect r) {
            return Collide.ellipseRect(x, y, a, b, r.x(), r.y(), r.w(), r.h());
        }
        if (other instanceof Segment s) {
            return Collide.ellipseLine(x, y, a, b, s.x1(), s.y1(), s.x2(), s.y2());
        }
        return Collide.polygonEllipse(HiddenParts.raw((Polygon) other), x, y, a, b);
    }

    /** A capsule with anything: an ellipse, the one earlier kind, takes the pair swapped. */
    public static boolean capsuleWith(Capsule k, Shape other) {
        if (other instanceof Ellipse e) {
            return ellipseWith(e, k);
        }
        float x1 = k.x1(), y1 = k.y1(), x2 = k.x2(), y2 = k.y2(), r = k.r();
        if (other instanceof Capsule o) {
            return Collide.capsuleCapsule(x1, y1, x2, y2, r, o.x1(), o.y1(), o.x2(), o.y2(), o.r());
        }
        if (other instanceof Circle c) {
            return Collide.capsuleCircle(x1, y1, x2, y2, r, c.x(), c.y(), c.r());
        }
        if (other instanceof Rect q) {
            return Collide.capsuleRect(x1, y1, x2, y2, r, q.x(), q.y(), q.w(), q.h());
        }
        if (other instanceof Segment s) {
            return Collide.capsuleLine(x1, y1, x2, y2, r, s.x1(), s.y1(), s.x2(), s.y2());
        }
        return Collide.polygonCapsule(HiddenParts.raw((Polygon) other), x1, y1, x2, y2, r);
    }

    /** A circle with anything: a capsule or an ellipse, the earlier kinds, takes the pair swapped. */
    public static boolean circleWith(Circle c, Shape other) {
        if (other instanceof Circle d) {
            return Collide.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
        }
        if (other instanceof Rect r) {
            return Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        }
        if (other instanceof Segment s) {
            return Collide.lineCircle(s.x1(), s.y1(), s.x2(), s.y2(), c.x(), c.y(), c.r());
        }
        if (other instanceof Polygon p) {
            return Collide.polygonCircle(HiddenParts.raw(p), c.x(), c.y(), c.r());
        }
        if (other instanceof Capsule k) {
            return capsuleWith(k, c);
        }
        return ellipseWith((Ellipse) other, c);
    }

    /** A rectangle with anything: a circle, a capsule or an ellipse takes the pair swapped. */
    public static boolean rectWith(Rect r, Shape other) {
        if (other instanceof Rect s) {
            return Collide.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h());
        }
        if (other instanceof Segment s) {
            return Collide.lineRect(s.x1(), s.y1(), s.x2(), s.y2(), r.x(), r.y(), r.w(), r.h());
        }
        if (other instanceof Polygon p) {
            return Collide.polygonRect(HiddenParts.raw(p), r.x(), r.y(), r.w(), r.h());
        }
        if (other instanceof Circle c) {
            return circleWith(c, r);
        }
        if (other instanceof Capsule k) {
            return capsuleWith(k, r);
        }
        return ellipseWith((Ellipse) other, r);
    }

    /** A segment with anything: every kind but a polygon comes earlier and takes the pair swapped. */
    public static boolean segmentWith(Segment s, Shape other) {
        if (other instanceof Segment t) {
            return Collide.lineLine(s.x1(), s.y1(), s.x2(), s.y2(), t.x1(), t.y1(), t.x2(), t.y2());
        }
        if (other instanceof Polygon p) {
            return Collide.polygonLine(HiddenParts.raw(p), s.x1(), s.y1(), s.x2(), s.y2());
        }
        if (other instanceof Rect r) {
            return rectWith(r, s);
        }
        if (other instanceof Circle c) {
            return circleWith(c, s);
        }
        if (other instanceof Capsule k) {
            return capsuleWith(k, s);
        }
        return ellipseWith((Ellipse) other, s);
    }

    /** A polygon with anything: the last kind, so every other kind takes the pair swapped. */
    public static boolean polygonWith(Polygon p, Shape other) {
        if (other instanceof Polygon q) {
            return Polygons.overlap(p, q);
        }
        if (other instanceof Rect r) {
            return rectWith(r, p);
        }
        if (other instanceof Circle c) {
            return circleWith(c, p);
        }
        if (other instanceof Segment s) {
            return segmentWith(s, p);
        }
        if (other instanceof Capsule k) {
            return capsuleWith(k, p);
        }
        return ellipseWith((Ellipse) other, p);
    }
}
