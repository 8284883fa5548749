package hitbox;

import hitbox.internal.*;

/**
 * Where a body is at one point of a move's walk, the mover or an obstacle: a box or a circle
 * kept as numbers, so that a walk's legs, stops and probes make no shape (a game's movers are
 * mostly boxes and circles, and a grid's cells are boxes), any other shape as the shape
 * itself. Each question the walk asks (extents, an overlap, a sweep) goes to the same kernel
 * the shapes' own methods go to, on the numbers: {@code SpotTest} holds the two together.
 *
 * <p>Mutable, owned by the world's {@link Mover} and by a character's walk, and set by
 * copying ({@link #set(Spot)}), never shared: one spot per place the walk keeps.
 */
final class Spot {
    /** The numbers, a box's or a circle's ({@link Placement}'s), when {@link #numbers}. */
    private final Placement at = new Placement();
    /** Is it a box or a circle kept as numbers ({@link #at})? Else {@link #shape} is it. */
    private boolean numbers;
    /** The shape: always for other kinds; for numbers, made when first asked (else null). */
    private Shape shape;
    /**
     * The body whose place this is, untouched since, when kept as numbers: its shape, made
     * when first asked, is kept by the body, so a standing obstacle's shape is made once, not
     * at every leg that meets it. Null otherwise.
     */
    private Body source;

    /** Takes a shape: a box's or a circle's numbers, anything else as itself. */
    Spot set(Shape s) {
        shape = s;
        source = null;
        switch (ShapeKind.of(s)) {
            case RECT -> {
                Rect r = (Rect) s;
                at.rect(r.x(), r.y(), r.w(), r.h());
                numbers = true;
            }
            case CIRCLE -> {
                Circle c = (Circle) s;
                at.circle(c.x(), c.y(), c.r());
                numbers = true;
            }
            default -> numbers = false;
        }
        return this;
    }

    /** Takes a box's numbers, no shape made. */
    Spot setBox(float x, float y, float w, float h) {
        numbers = true;
        at.rect(x, y, w, h);
        shape = null;
        source = null;
        return this;
    }

    /**
     * Takes where a body stands: from its numbers where it is a box or a circle (no shape
     * made), else its shape.
     */
    Spot set(Body b) {
        Placement p = b.placement();
        if (p == null || p.kind() != ShapeKind.RECT && p.kind() != ShapeKind.CIRCLE) {
            return set(b.shape());
        }
        take(p);
        shape = b.shape;  // if made
        source = b;
        return this;
    }

    /** Takes another spot's place. */
    Spot set(Spot o) {
        if (o.numbers) {
            take(o.at);
        } else {
            numbers = false;
        }
        shape = o.shape;
        source = o.source;
        return this;
    }

    /** Takes a box's or a circle's numbers. */
    private void take(Placement p) {
        numbers = true;
        if (p.kind() == ShapeKind.RECT) {
            at.rect(p.a(), p.b(), p.c(), p.d());
        } else {
            at.circle(p.a(), p.b(), p.c());
        }
    }

    /**
     * Moves by (dx, dy), as {@link Shape#translated} moves the shape: each coordinate plus the
     * motion in float, refused alike.
     *
     * @throws IllegalArgumentException if dx or dy is NaN or infinite, or a coordinate leaves
     *                                  the float range
     */
    Spot translate(float dx, float dy) {
        if (!numbers) {
            shape = shape.translated(dx, dy);
            return this;
        }
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        float x = Check.finite("x + dx", at.a() + dx), y = Check.finite("y + dy", at.b() + dy);
        if (box()) {
            at.rect(x, y, at.c(), at.d());
        } else {
            at.circle(x, y, at.c());
        }
        shape = null;
        source = null;
        return this;
    }

    /** @return the shape, made from the numbers when first asked */
    Shape shape() {
        if (shape == null) {
            shape = source != null ? source.shape() : at.shape();
        }
        return shape;
    }

    /** @return is it a box kept as numbers (then {@link #x()} to {@link #h()} are the box)? */
    boolean box() {
        return numbers && at.kind() == ShapeKind.RECT;
    }

    /** @return a box's x, or a circle's */
    float x() {
        return at.a();
    }

    /** @return a box's y, or a circle's */
    float y() {
        return at.b();
    }

    /** @return a box's width */
    float w() {
        return at.c();
    }

    /** @return a box's height */
    float h() {
        return at.d();
    }

    /**
     * Places a body here: the translation, and the numbers (no shape made) or the shape.
     * The spot's kind is the body's own, as a walk of that body leaves it.
     */
    void placeInto(Body b, double tx, double ty) {
        if (!numbers || shape != null) {
            b.placed(tx, ty, shape());
        } else if (box()) {
            b.placedBox(tx, ty, at.a(), at.b(), at.c(), at.d());
        } else {
            b.placedCircle(tx, ty, at.a(), at.b(), at.c());
        }
    }

    /** @return {@link Poses#refX}: the x a pose's translation is measured by */
    double refX() {
        return numbers ? at.a() : Poses.refX(shape);
    }

    /** @return {@link Poses#refY} */
    double refY() {
        return numbers ? at.b() : Poses.refY(shape);
    }

    /** @return {@link Extents#minX} */
    double minX() {
        return !numbers ? Extents.minX(shape) : box() ? at.a() : (double) at.a() - at.c();
    }

    /** @return {@link Extents#minY} */
    double minY() {
        return !numbers ? Extents.minY(shape) : box() ? at.b() : (double) at.b() - at.c();
    }

    /** @return {@link Extents#maxX} */
    double maxX() {
        return !numbers ? Extents.maxX(shape) : (double) at.a() + at.c();
    }

    /** @return {@link Extents#maxY} */
    double maxY() {
        return !numbers ? Extents.maxY(shape) : box() ? (double) at.b() + at.d() : (double) at.b() + at.c();
    }

    /** @return {@link Extents#reach} */
    double reach() {
        return !numbers ? Extents.reach(shape)
                : box() ? Extents.boxReach(at.a(), at.b(), at.c(), at.d()) : Extents.circleReach(at.a(), at.b(), at.c());
    }

    /** @return {@link Shape#overlaps}: does it overlap the other shape? */
    boolean overlaps(Shape other) {
        if (!numbers) {
            return shape.overlaps(other);
        }
        return box() ? Overlaps.rectWith(at.a(), at.b(), at.c(), at.d(), other) : Overlaps.circleWith(at.a(), at.b(), at.c(), other);
    }

    /** @return {@link Shape#overlaps}: do the two overlap? Two kept as numbers by their numbers' table. */
    boolean overlaps(Spot other) {
        if (numbers && other.numbers) {
            return PlacedOverlaps.test(at, other.at);
        }
        if (!other.numbers || other.shape != null || other.source != null) {
            return overlaps(other.shape());  // made already, or kept by its body
        }
        // Overlapping is symmetric: a box or a circle kept as numbers is asked by its numbers.
        return other.overlaps(shape);
    }

    /**
     * {@link Sweep#timeOfImpact(Shape, float, float, Shape)} into another spot, as numbers:
     * no {@code Hit} made (see {@code Sweep}'s package form), and no shape made where both are
     * kept as numbers.
     *
     * @param out given the hit's t, nx and ny (untouched for no hit)
     * @return the side met ({@link Side#NONE} if overlapping at the start), or null for no
     *         hit within the motion
     */
    Side sweep(float vx, float vy, Spot obstacle, float[] out) {
        if (!numbers || !Float.isFinite(vx) || !Float.isFinite(vy)) {
            // Refused alike: the shape's sweep throws for a motion out of the float range.
            return Sweep.timeOfImpact(shape(), vx, vy, obstacle.shape(), out);
        }
        boolean recording = SweptPairs.recording(true);
        Hit hit;
        try {
            Placement o = obstacle.at;
            if (!obstacle.numbers) {
                hit = box() ? Sweep.rectInto((Rect) shape, at.a(), at.b(), at.c(), at.d(), vx, vy, obstacle.shape)
                        : Sweep.circleInto((Circle) shape, at.a(), at.b(), at.c(), vx, vy, obstacle.shape);
            } else if (box()) {
                hit = Sweep.rectInto(at.a(), at.b(), at.c(), at.d(), vx, vy, o.kind(), o.a(), o.b(), o.c(), o.d());
            } else {
                hit = Sweep.circleInto(at.a(), at.b(), at.c(), vx, vy, o.kind(), o.a(), o.b(), o.c(), o.d());
            }
        } finally {
            SweptPairs.recording(recording);
        }
        return SweptPairs.recorded(hit, out);
    }

    /** The spots, grown to n: the old ones kept, each new one its own. */
    static Spot[] grown(Spot[] old, int n) {
        Spot[] grown = java.util.Arrays.copyOf(old, n);
        for (int i = old.length; i < n; i++) {
            grown[i] = new Spot();
        }
        return grown;
    }

    /** @return the shape, for printing */
    @Override
    public String toString() {
        return String.valueOf(shape());
    }
}
