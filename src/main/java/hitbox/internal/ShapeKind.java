package hitbox.internal;

import hitbox.*;

/**
 * The kinds of {@link Shape}, and the one place that tells them apart. Internal, like the
 * rest of this package: public so that the API and {@code hitbox.processing}'s drawing go
 * through the same dispatch as the kernels.
 *
 * <p>{@link #of} is the only {@code instanceof} over the shape kinds in the library. Every
 * operation that needs a kind's own code (overlaps, contact, containment, rays, sweeps, bounding boxes,
 * support functions and convex pieces, drawing) switches on the kind with a switch
 * <em>expression</em> that names every constant and has no {@code default}: javac refuses a
 * switch expression that misses a constant, so a new kind of shape does not compile until
 * every operation has a case for it. {@link Shape}'s own questions ({@code overlaps},
 * {@code contains}, {@code bounds}, {@code transformed}) are its {@code default} methods,
 * each one switch here to its kind's case in a kernel ({@link Overlaps}, {@link Containment},
 * {@link Bounds}, {@link Transforms}); only {@code translated}, and {@code transformed} and
 * {@code rotated} where a kind keeps its kind, stay in the shape's own class, to answer with
 * its own type.
 *
 * <p>The constants' order is the order in which the pair operations are written: a pair is
 * answered by the code of its earlier kind (the later one handed over, swapped if it came
 * first), so each unordered pair has one piece of code and both orders give the same
 * answer.
 */
public enum ShapeKind {
    /** {@link Ellipse}, aligned or turned. */
    ELLIPSE,
    /** {@link Capsule}. */
    CAPSULE,
    /** {@link Circle}. */
    CIRCLE,
    /** {@link Rect}. */
    RECT,
    /** {@link Segment}. */
    SEGMENT,
    /** {@link Polygon}, convex or concave. */
    POLYGON;

    /**
     * Has this shape an inside (area), in the package's touching rule? Its kind's
     * {@link #hasArea()}, and a size in every direction: a circle, rectangle, ellipse or
     * capsule of size 0 has none.
     *
     * @param shape the shape, not null
     * @return true if it has an inside
     */
    public static boolean hasInside(Shape shape) {
        return switch (of(shape)) {
            case ELLIPSE -> ((Ellipse) shape).rx() > 0 && ((Ellipse) shape).ry() > 0;
            case CAPSULE -> ((Capsule) shape).r() > 0;
            case CIRCLE -> ((Circle) shape).r() > 0;
            case RECT -> ((Rect) shape).w() > 0 && ((Rect) shape).h() > 0;
            case SEGMENT -> false;
            case POLYGON -> true;
        };
    }

    /**
     * The shape's kind.
     *
     * @param shape the shape, not null
     * @return its kind, never null
     * @throws IllegalArgumentException if {@code shape} is null
     * @throws IllegalStateException if the shape's class has no kind here (a new kind added to
     *                               {@link Shape}'s permitted classes, but not here)
     */
    public static ShapeKind of(Shape shape) {
        // The commonest kinds in a game first. Each test is one class compare (every kind is
        // final), and a caller's loop that only ever sees one kind keeps only its test.
        if (shape instanceof Rect) {
            return RECT;
        }
        if (shape instanceof Circle) {
            return CIRCLE;
        }
        if (shape instanceof Polygon) {
            return POLYGON;
        }
        if (shape instanceof Segment) {
            return SEGMENT;
        }
        if (shape instanceof Ellipse) {
            return ELLIPSE;
        }
        if (shape instanceof Capsule) {
            return CAPSULE;
        }
        Check.notNull("shape", shape);
        throw new IllegalStateException("no ShapeKind for " + shape.getClass().getName()
                + ": a new kind of Shape needs its constant in ShapeKind, and a case in every switch over it");
    }

    /**
     * Has a shape of this kind an inside, as a rule? False only for {@link #SEGMENT}; a shape
     * of a kind with area may still have none (a circle of radius 0).
     *
     * @return true for every kind but a segment
     */
    public boolean hasArea() {
        return switch (this) {
            case ELLIPSE, CAPSULE, CIRCLE, RECT, POLYGON -> true;
            case SEGMENT -> false;
        };
    }
}
