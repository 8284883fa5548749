package hitbox;

/**
 * The one table behind {@link Shape#overlaps}: every pair of shape kinds, in either order,
 * routed to the {@link Collide} method for that pair.
 *
 * <p>The kinds are taken in a fixed order (ellipse, capsule, circle, rectangle, segment, polygon): the pair is
 * handed to the method of its earlier kind, with the arguments swapped if they came the
 * other way round, so each unordered pair has exactly one line of code and
 * {@code a.overlaps(b) == b.overlaps(a)} holds by construction.
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
final class Overlaps {
    private Overlaps() {
    }

    static boolean test(Shape a, Shape b) {
        // Two of a kind first, the commonest pairs in a game: one check each way instead of a
        // walk down the order below (which would route them to the same line).
        if (a instanceof Rect r && b instanceof Rect) {
            return rectWith(r, b);
        }
        if (a instanceof Circle c && b instanceof Circle) {
            return circleWith(c, b);
        }
        if (a instanceof Polygon p && b instanceof Polygon q) {
            return Polygons.overlap(p, q);
        }
        if (a instanceof Ellipse e) {
            return ellipseWith(e, b);
        }
        if (b instanceof Ellipse e) {
            return ellipseWith(e, a);
        }
        if (a instanceof Capsule k) {
            return capsuleWith(k, b);
        }
        if (b instanceof Capsule k) {
            return capsuleWith(k, a);
        }
        if (a instanceof Circle c) {
            return circleWith(c, b);
        }
        if (b instanceof Circle c) {
            return circleWith(c, a);
        }
        if (a instanceof Rect r) {
            return rectWith(r, b);
        }
        if (b instanceof Rect r) {
            return rectWith(r, a);
        }
        if (a instanceof Segment s) {
            return segmentWith(s, b);
        }
        if (b instanceof Segment s) {
            return segmentWith(s, a);
        }
        return Polygons.overlap((Polygon) a, (Polygon) b);
    }

    /** An ellipse with anything. */
    private static boolean ellipseWith(Ellipse e, Shape other) {
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
        return Collide.polygonEllipse(((Polygon) other).raw(), x, y, a, b);
    }

    /** A capsule with anything but an ellipse. */
    private static boolean capsuleWith(Capsule k, Shape other) {
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
        return Collide.polygonCapsule(((Polygon) other).raw(), x1, y1, x2, y2, r);
    }

    private static boolean circleWith(Circle c, Shape other) {
        if (other instanceof Circle d) {
            return Collide.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
        }
        if (other instanceof Rect r) {
            return Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        }
        if (other instanceof Segment s) {
            return Collide.lineCircle(s.x1(), s.y1(), s.x2(), s.y2(), c.x(), c.y(), c.r());
        }
        return Collide.polygonCircle(((Polygon) other).raw(), c.x(), c.y(), c.r());
    }

    /** A rectangle with anything but a circle. */
    private static boolean rectWith(Rect r, Shape other) {
        if (other instanceof Rect s) {
            return Collide.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h());
        }
        if (other instanceof Segment s) {
            return Collide.lineRect(s.x1(), s.y1(), s.x2(), s.y2(), r.x(), r.y(), r.w(), r.h());
        }
        return Collide.polygonRect(((Polygon) other).raw(), r.x(), r.y(), r.w(), r.h());
    }

    /** A segment with a segment or a polygon. */
    private static boolean segmentWith(Segment s, Shape other) {
        if (other instanceof Segment t) {
            return Collide.lineLine(s.x1(), s.y1(), s.x2(), s.y2(), t.x1(), t.y1(), t.x2(), t.y2());
        }
        return Collide.polygonLine(((Polygon) other).raw(), s.x1(), s.y1(), s.x2(), s.y2());
    }
}
