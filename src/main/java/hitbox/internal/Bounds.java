package hitbox.internal;

import hitbox.*;

/**
 * Bounding boxes, in one place: each shape's extent in {@code double} (exact: the sums of
 * two floats that make a circle's or a rectangle's far edges are exact in double), and the
 * float {@link Rect} that holds it, rounded outwards. {@link Shape#bounds()} and
 * {@link Hybrid} both read them here, so the two never disagree.
 */
public final class Bounds {
    private Bounds() {
    }

    /** The shape's smallest x, exactly. */
    public static double left(Shape s) {
        if (s instanceof Circle c) {
            return (double) c.x() - c.r();
        }
        if (s instanceof Rect r) {
            return r.x();
        }
        if (s instanceof Segment g) {
            return Math.min(g.x1(), g.x2());
        }
        if (s instanceof Ellipse e) {
            return (double) e.x() - TurnedEllipses.halfWidth(e);
        }
        if (s instanceof Capsule k) {
            return Math.min(k.x1(), k.x2()) - (double) k.r();
        }
        return ((Polygon) s).bounds().x();
    }

    /** The shape's smallest y, exactly. */
    public static double top(Shape s) {
        if (s instanceof Circle c) {
            return (double) c.y() - c.r();
        }
        if (s instanceof Rect r) {
            return r.y();
        }
        if (s instanceof Segment g) {
            return Math.min(g.y1(), g.y2());
        }
        if (s instanceof Ellipse e) {
            return (double) e.y() - TurnedEllipses.halfHeight(e);
        }
        if (s instanceof Capsule k) {
            return Math.min(k.y1(), k.y2()) - (double) k.r();
        }
        return ((Polygon) s).bounds().y();
    }

    /** The shape's largest x: exact, or for a polygon a hair beyond (its cached box's edge). */
    public static double right(Shape s) {
        if (s instanceof Circle c) {
            return (double) c.x() + c.r();
        }
        if (s instanceof Rect r) {
            return (double) r.x() + r.w();
        }
        if (s instanceof Segment g) {
            return Math.max(g.x1(), g.x2());
        }
        if (s instanceof Ellipse e) {
            return (double) e.x() + TurnedEllipses.halfWidth(e);
        }
        if (s instanceof Capsule k) {
            return Math.max(k.x1(), k.x2()) + (double) k.r();
        }
        Rect b = ((Polygon) s).bounds();
        return (double) b.x() + b.w();
    }

    /** The shape's largest y: exact, or for a polygon a hair beyond. */
    public static double bottom(Shape s) {
        if (s instanceof Circle c) {
            return (double) c.y() + c.r();
        }
        if (s instanceof Rect r) {
            return (double) r.y() + r.h();
        }
        if (s instanceof Segment g) {
            return Math.max(g.y1(), g.y2());
        }
        if (s instanceof Ellipse e) {
            return (double) e.y() + TurnedEllipses.halfHeight(e);
        }
        if (s instanceof Capsule k) {
            return Math.max(k.y1(), k.y2()) + (double) k.r();
        }
        Rect b = ((Polygon) s).bounds();
        return (double) b.y() + b.h();
    }

    /**
     * The float rectangle that holds [left, right] x [top, bottom], rounded outwards: its
     * corner at or before (left, top), and its far edges, {@code x + w} and {@code y + h}
     * added in double as {@link Collide} adds them, at or beyond (right, bottom). Values past
     * the float range are held back at {@code -Float.MAX_VALUE} and a size of at most
     * {@code Float.MAX_VALUE}: the only case where the box can fall short of the extent.
     */
    public static Rect enclosing(double left, double top, double right, double bottom) {
        float x = down(left);
        float y = down(top);
        return new Rect(x, y, size(x, right), size(y, bottom));
    }

    /** The largest finite float at or below v. */
    private static float down(double v) {
        float f = (float) v;
        if (f > v) {
            f = Math.nextDown(f);
        }
        return Math.max(Math.min(f, Float.MAX_VALUE), -Float.MAX_VALUE);
    }

    /** The smallest float size s with {@code start + s >= end} (in double), at most MAX_VALUE. */
    private static float size(float start, double end) {
        double need = end - start;
        if (!(need > 0)) {
            return 0;
        }
        float s = (float) Math.min(need, Float.MAX_VALUE);
        while ((double) start + s < end && s < Float.MAX_VALUE) {
            s = Math.nextUp(s);
        }
        return s;
    }
}
