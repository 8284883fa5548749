package hitbox.internal;

import hitbox.*;

/**
 * Bounding boxes: the float {@link Rect} that holds a shape's extent in {@code double}
 * ({@link Extents}), rounded outwards. {@link Shape#bounds()} and {@link Hybrid} both read
 * those extents, so the two never disagree.
 */
public final class Bounds {
    private Bounds() {
    }

    /**
     * The box behind {@link Shape#bounds()}, by the shape's kind: a rectangle is its own box,
     * a polygon keeps its box (made once, with the polygon), every other kind has its four
     * {@link Extents} rounded outwards.
     *
     * @param s the shape, not null
     * @return its bounding box, never null
     */
    public static Rect of(Shape s) {
        return switch (ShapeKind.of(s)) {
            case RECT -> (Rect) s;
            case POLYGON -> HiddenParts.bounds((Polygon) s);
            case ELLIPSE, CAPSULE, CIRCLE, SEGMENT ->
                    enclosing(Extents.minX(s), Extents.minY(s), Extents.maxX(s), Extents.maxY(s));
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
