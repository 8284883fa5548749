package hitbox;

/**
 * The one table behind {@link Shape#overlaps}: every pair of shape kinds, in either order,
 * routed to the {@link Collide} method for that pair.
 */
final class Overlaps {
    private Overlaps() {
    }

    static boolean test(Shape a, Shape b) {
        if (a instanceof Circle c) {
            return circleWith(c, b);
        }
        if (b instanceof Circle c) {
            return circleWith(c, a);
        }
        if (a instanceof Rect r && b instanceof Rect s) {
            return Collide.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h());
        }
        throw new IllegalStateException("no overlap test yet for " + a.getClass().getSimpleName()
                + " and " + b.getClass().getSimpleName());
    }

    private static boolean circleWith(Circle c, Shape other) {
        if (other instanceof Circle d) {
            return Collide.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
        }
        if (other instanceof Rect r) {
            return Collide.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
        }
        throw new IllegalStateException("no overlap test yet for Circle and " + other.getClass().getSimpleName());
    }
}
