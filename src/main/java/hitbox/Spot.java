package hitbox;

import hitbox.internal.*;

/**
 * Where a moving body is at one point of its move's walk: a box or a circle kept as numbers,
 * so that a walk's legs, stops and probes make no shape (a game's movers are mostly boxes and
 * circles), any other shape as the shape itself. Each question the walk asks of it (its
 * extents, its overlap with an obstacle, its sweep into one) goes to the same kernel the
 * shape's own method goes to, on the numbers: {@code SpotTest} holds the two together.
 *
 * <p>Mutable, owned by the world's {@link Mover} and by a character's walk, and set by
 * copying ({@link #set(Spot)}), never shared: one spot per place the walk keeps.
 */
final class Spot {
    /** {@link ShapeKind#RECT} or {@link ShapeKind#CIRCLE}: the numbers are the shape; null: {@link #shape} is. */
    private ShapeKind kind;
    /** A box's x, y, w and h; a circle's x, y and its radius in w. */
    private float x, y, w, h;
    /** The shape: always for other kinds; for numbers, made when first asked (else null). */
    private Shape shape;

    /** Takes a shape: a box's or a circle's numbers, anything else as itself. */
    Spot set(Shape s) {
        shape = s;
        if (s instanceof Rect r) {
            kind = ShapeKind.RECT;
            x = r.x();
            y = r.y();
            w = r.w();
            h = r.h();
        } else if (s instanceof Circle c) {
            kind = ShapeKind.CIRCLE;
            x = c.x();
            y = c.y();
            w = c.r();
            h = 0;
        } else {
            kind = null;
        }
        return this;
    }

    /** Takes a box's numbers, no shape made. */
    Spot setBox(float x, float y, float w, float h) {
        kind = ShapeKind.RECT;
        this.x = x;
        this.y = y;
        this.w = w;
        this.h = h;
        shape = null;
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
        kind = p.kind();
        x = p.a();
        y = p.b();
        w = p.c();
        h = kind == ShapeKind.RECT ? p.d() : 0;
        shape = b.shape;  // if made
        return this;
    }

    /** Takes another spot's place. */
    Spot set(Spot o) {
        kind = o.kind;
        x = o.x;
        y = o.y;
        w = o.w;
        h = o.h;
        shape = o.shape;
        return this;
    }

    /**
     * Moves by (dx, dy), as {@link Shape#translated} moves the shape: each coordinate plus the
     * motion in float, refused alike.
     *
     * @throws IllegalArgumentException if dx or dy is NaN or infinite, or a coordinate leaves
     *                                  the float range
     */
    Spot translate(float dx, float dy) {
        if (kind == null) {
            shape = shape.translated(dx, dy);
            return this;
        }
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        x = Check.finite("x + dx", x + dx);
        y = Check.finite("y + dy", y + dy);
        shape = null;
        return this;
    }

    /** @return the shape, made from the numbers when first asked */
    Shape shape() {
        if (shape == null) {
            shape = kind == ShapeKind.RECT ? new Rect(x, y, w, h) : new Circle(x, y, w);
        }
        return shape;
    }

    /** @return is it a box or a circle kept as numbers (then {@link #placeInto} makes no shape)? */
    boolean numbers() {
        return kind != null;
    }

    /**
     * Places a body here: the translation, and the numbers (no shape made) or the shape.
     * The spot's kind is the body's own, as a walk of that body leaves it.
     */
    void placeInto(Body b, double tx, double ty) {
        if (kind == null || shape != null) {
            b.placed(tx, ty, shape());
        } else if (kind == ShapeKind.RECT) {
            b.placedBox(tx, ty, x, y, w, h);
        } else {
            b.placedCircle(tx, ty, x, y, w);
        }
    }

    /** @return {@link Poses#refX}: the x a pose's translation is measured by */
    double refX() {
        return kind == null ? Poses.refX(shape) : x;
    }

    /** @return {@link Poses#refY} */
    double refY() {
        return kind == null ? Poses.refY(shape) : y;
    }

    /** @return {@link Extents#minX} */
    double minX() {
        return kind == null ? Extents.minX(shape) : kind == ShapeKind.RECT ? x : (double) x - w;
    }

    /** @return {@link Extents#minY} */
    double minY() {
        return kind == null ? Extents.minY(shape) : kind == ShapeKind.RECT ? y : (double) y - w;
    }

    /** @return {@link Extents#maxX} */
    double maxX() {
        return kind == null ? Extents.maxX(shape) : (double) x + w;
    }

    /** @return {@link Extents#maxY} */
    double maxY() {
        return kind == null ? Extents.maxY(shape) : kind == ShapeKind.RECT ? (double) y + h : (double) y + w;
    }

    /** @return {@link Extents#reach} */
    double reach() {
        return kind == null ? Extents.reach(shape)
                : kind == ShapeKind.RECT ? Extents.boxReach(x, y, w, h) : Extents.circleReach(x, y, w);
    }

    /** @return {@link Shape#overlaps}: does it overlap the other shape? */
    boolean overlaps(Shape other) {
        if (kind == null) {
            return shape.overlaps(other);
        }
        return kind == ShapeKind.RECT ? Overlaps.rectWith(x, y, w, h, other) : Overlaps.circleWith(x, y, w, other);
    }

    /**
     * {@link Sweep#timeOfImpact(Shape, float, float, Shape)} as numbers, no {@code Hit} made
     * (see {@code Sweep}'s package form).
     *
     * @param out given the hit's t, nx and ny (untouched for no hit)
     * @return the side met ({@link Side#NONE} if overlapping at the start), or null for no
     *         hit within the motion
     */
    Side sweep(float vx, float vy, Shape obstacle, float[] out) {
        if (kind == null || !Float.isFinite(vx) || !Float.isFinite(vy)) {
            return Sweep.timeOfImpact(shape(), vx, vy, obstacle, out);  // which refuses a motion out of range
        }
        boolean recording = SweptPairs.recording(true);
        Hit hit;
        try {
            hit = kind == ShapeKind.RECT ? Sweep.rectInto((Rect) shape, x, y, w, h, vx, vy, obstacle)
                    : Sweep.circleInto((Circle) shape, x, y, w, vx, vy, obstacle);
        } finally {
            SweptPairs.recording(recording);
        }
        return SweptPairs.recorded(hit, out);
    }

    /** @return the shape, for printing */
    @Override
    public String toString() {
        return String.valueOf(shape());
    }
}
