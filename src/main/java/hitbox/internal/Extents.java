package hitbox.internal;

import hitbox.*;

/**
 * A shape's exact extents in {@code double}: its smallest and largest x and y. Exact for
 * circles, rectangles, segments and capsules (a sum of two floats is exact in double), a hair
 * outside for a turned ellipse (widened past the rounding of its cos and sin) and a polygon
 * (its kept bounding box's edge). {@link Shape#bounds()} is these four rounded outwards to
 * floats ({@link Bounds#of}); the library's own code reads the extents where a float box's
 * rounding would show: a body's place at a world's edge ({@code Edges}), the cells and boxes
 * a move gathers, {@code Hybrid}'s stages.
 *
 * <p>Internal: a user asks {@link Shape#bounds()}, which is exact for a rectangle (its own
 * bounds) and for every shape whose edges are floats. Each extent is a switch expression
 * over {@link ShapeKind} with no {@code default}, so a new kind does not compile until it has
 * its four cases.
 */
public final class Extents {
    private Extents() {
    }

    /**
     * @param s the shape, not null
     * @return its smallest x, at or below every point of the shape
     */
    public static double minX(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                yield (double) e.x() - TurnedEllipses.halfWidth(e);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.min(k.x1(), k.x2()) - (double) k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield (double) c.x() - c.r();
            }
            case RECT -> ((Rect) s).x();
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.min(g.x1(), g.x2());
            }
            case POLYGON -> HiddenParts.bounds((Polygon) s).x();
        };
    }

    /**
     * @param s the shape, not null
     * @return its smallest y, at or below every point of the shape
     */
    public static double minY(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                yield (double) e.y() - TurnedEllipses.halfHeight(e);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.min(k.y1(), k.y2()) - (double) k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield (double) c.y() - c.r();
            }
            case RECT -> ((Rect) s).y();
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.min(g.y1(), g.y2());
            }
            case POLYGON -> HiddenParts.bounds((Polygon) s).y();
        };
    }

    /**
     * @param s the shape, not null
     * @return its largest x, at or above every point of the shape
     */
    public static double maxX(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                yield (double) e.x() + TurnedEllipses.halfWidth(e);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.max(k.x1(), k.x2()) + (double) k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield (double) c.x() + c.r();
            }
            case RECT -> {
                Rect r = (Rect) s;
                yield (double) r.x() + r.w();
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.max(g.x1(), g.x2());
            }
            case POLYGON -> {
                Rect b = HiddenParts.bounds((Polygon) s);
                yield (double) b.x() + b.w();
            }
        };
    }

    /**
     * @param s the shape, not null
     * @return its largest y, at or above every point of the shape
     */
    public static double maxY(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                yield (double) e.y() + TurnedEllipses.halfHeight(e);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.max(k.y1(), k.y2()) + (double) k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield (double) c.y() + c.r();
            }
            case RECT -> {
                Rect r = (Rect) s;
                yield (double) r.y() + r.h();
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.max(g.y1(), g.y2());
            }
            case POLYGON -> {
                Rect b = HiddenParts.bounds((Polygon) s);
                yield (double) b.y() + b.h();
            }
        };
    }

    /**
     * How far the shape reaches from the origin along either axis: the largest of its four
     * extents by size, {@code max(|minX|, |maxX|, |minY|, |maxY|)}, the scale of a kernel's
     * rounding. One switch, not four: the kernels ask it in loops the JIT inlines whole.
     *
     * @param s the shape, not null
     * @return the largest size of an extent, 0 or more
     */
    public static double reach(Shape s) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> {
                Ellipse e = (Ellipse) s;
                yield Math.max(Math.abs((double) e.x()) + TurnedEllipses.halfWidth(e), Math.abs((double) e.y()) + TurnedEllipses.halfHeight(e));
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                yield Math.max(Math.max(Math.abs(k.x1()), Math.abs(k.x2())), Math.max(Math.abs(k.y1()), Math.abs(k.y2()))) + (double) k.r();
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                yield circleReach(c.x(), c.y(), c.r());
            }
            case RECT -> {
                Rect r = (Rect) s;
                yield boxReach(r.x(), r.y(), r.w(), r.h());
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                yield Math.max(Math.max(Math.abs(g.x1()), Math.abs(g.x2())), Math.max(Math.abs(g.y1()), Math.abs(g.y2())));
            }
            case POLYGON -> {
                Rect r = HiddenParts.bounds((Polygon) s);
                yield boxReach(r.x(), r.y(), r.w(), r.h());
            }
        };
    }

    /** {@link #reach} of the box (x, y, w, h): its four edges by size, the far ones added in double. */
    public static double boxReach(float x, float y, float w, float h) {
        return Math.max(Math.max(Math.abs(x), Math.abs((double) x + w)), Math.max(Math.abs(y), Math.abs((double) y + h)));
    }

    /** {@link #reach} of the circle at (x, y) of radius r. */
    public static double circleReach(float x, float y, float r) {
        return Math.max(Math.abs(x), Math.abs(y)) + (double) r;
    }
}
