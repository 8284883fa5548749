package hitbox.internal;

import hitbox.*;

/**
 * Bounding boxes: each shape's extent in {@code double}, read through {@link ShapeKind} from
 * the shape's own {@code minX()}, {@code minY()}, {@code maxX()} and {@code maxY()} (exact:
 * the sums of two floats that make a circle's or a rectangle's far edges are exact in double;
 * a turned ellipse's widened past its rounding), or a polygon's cached
 * {@link Polygon#bounds() box}; and the float {@link Rect} that holds an extent, rounded
 * outwards. {@link Shape#bounds()} and {@link Hybrid} both read the same extents, so the two
 * never disagree.
 */
public final class Bounds {
    private Bounds() {
    }

    /** The shape's smallest x. */
    static double left(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> ((Ellipse) s).minX();
            case CAPSULE -> ((Capsule) s).minX();
            case CIRCLE -> ((Circle) s).minX();
            case RECT -> ((Rect) s).minX();
            case SEGMENT -> ((Segment) s).minX();
            case POLYGON -> ((Polygon) s).bounds().x(); // its cached box
        };
    }

    /** The shape's smallest y. */
    static double top(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> ((Ellipse) s).minY();
            case CAPSULE -> ((Capsule) s).minY();
            case CIRCLE -> ((Circle) s).minY();
            case RECT -> ((Rect) s).minY();
            case SEGMENT -> ((Segment) s).minY();
            case POLYGON -> ((Polygon) s).bounds().y(); // its cached box
        };
    }

    /** The shape's largest x (for a polygon a hair beyond: its cached box's edge). */
    static double right(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> ((Ellipse) s).maxX();
            case CAPSULE -> ((Capsule) s).maxX();
            case CIRCLE -> ((Circle) s).maxX();
            case RECT -> ((Rect) s).maxX();
            case SEGMENT -> ((Segment) s).maxX();
            case POLYGON -> (double) ((Polygon) s).bounds().x() + ((Polygon) s).bounds().w(); // its cached box
        };
    }

    /** The shape's largest y (for a polygon a hair beyond). */
    static double bottom(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> ((Ellipse) s).maxY();
            case CAPSULE -> ((Capsule) s).maxY();
            case CIRCLE -> ((Circle) s).maxY();
            case RECT -> ((Rect) s).maxY();
            case SEGMENT -> ((Segment) s).maxY();
            case POLYGON -> (double) ((Polygon) s).bounds().y() + ((Polygon) s).bounds().h(); // its cached box
        };
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
