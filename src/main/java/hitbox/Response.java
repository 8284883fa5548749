package hitbox;

import hitbox.internal.*;

/**
 * What to do after a hit, given its {@link Contact}: push the shapes apart, bounce, or slide.
 *
 * <p>One call per question: {@link #pushOut} moves a shape by a contact, {@link #separate}
 * moves one shape clear of another, {@link #bounce} and {@link #slide} give a new velocity. Velocities belong to the sketch's own objects, so the
 * velocity methods take plain floats and a normal and hand back the new value as a
 * {@link Vec}; nothing is changed in place. The contact's normal points from a to b, so "a"
 * and "b" below are the first and second shape given to {@link Shape#contact a.contact(b)}.
 *
 * <p>One normal convention, the package's: a {@link Contact}'s normal points from a to b, a
 * {@link Hit}'s and a {@link RayHit}'s from the mover into what it hit, and the velocity
 * methods take that normal as it comes: {@code Response.bounce(vx, vy, c.nx(), c.ny(), 1)}.
 * One rule per kind of value: a velocity or normal that is NaN or infinite gives the velocity
 * back unchanged (the values a sketch computes); a restitution or a share (numbers a sketch
 * chooses) that is NaN, infinite or outside [0, 1] is refused with an
 * {@link IllegalArgumentException}, in every method that takes one; a null shape or contact
 * is refused.
 *
 * <p>Velocity responses act only when a is moving into b (its velocity has a part along the
 * normal). A velocity that already moves a away from b is returned unchanged: reflecting it
 * would turn it back into b, and an object that is still overlapping after its first bounce
 * (because it went deep in one frame) would then bounce again every frame, trembling inside
 * the other instead of leaving it.
 *
 * <p>Which push-out to call (the package documentation says the same): {@link #separate}
 * when a shape must end up clear of another, exactly ({@code overlaps} false afterwards),
 * whatever the shapes; {@link #pushOut} when you already have the
 * {@link Contact} and want to move by its depth, or share the push between the two with
 * {@code share}; {@link Snap#pushOut} for a box against a box, along one axis, with the
 * {@link Side} it was pushed to (a platformer's tiles).
 */
public final class Response {
    private Response() {
    }

    /**
     * A shape pushed out of the other by its share of the contact's depth: moved against the
     * contact's normal by {@code share * depth}. The contact is the one between this shape and
     * the other ({@code shape.contact(other)}); for the other shape, pass
     * {@code contact.flipped()}. Shares that add up to 1 leave the two just touching:
     * {@code pushOut(a, c, 1)} moves a alone; {@code pushOut(a, c, 0.5f)} and
     * {@code pushOut(b, c.flipped(), 0.5f)} move each half way; a light object can take more
     * than a heavy one. Which push-out: this one moves by a contact you already have;
     * {@link #separate} when the shape must end up clear, exactly; {@link Snap#pushOut} for
     * two boxes, with the side.
     * <p>A NaN {@code share} throws, naming it
     * (the <a href="package-summary.html#bad-input">NaN rule</a>).
     *
     * @param <S>     the kind of shape
     * @param shape   the shape to push, the first of the contact, not null
     * @param contact the contact from this shape to the other (its normal points from this
     *                shape into the other), not null
     * @param share   how much of the depth the shape moves, from 0 to 1
     * @return the shape, moved, never null
     * @throws IllegalArgumentException if the shape or the contact is null, share is outside
     *                                  [0, 1], or the move gives a coordinate too large for a
     *                                  float
     */
    public static <S extends Shape> S pushOut(S shape, Contact contact, float share) {
        return translated(Check.notNull("shape", shape), contact, -share, share);
    }

    /**
     * The bounce on plain floats: velocity (vx, vy) against a surface whose normal (nx, ny)
     * points from the mover into what it hits, the package's one convention: pass a
     * {@link Contact}'s, a {@link Hit}'s or a {@link RayHit}'s normal as it is,
     * {@code Response.bounce(vx, vy, hit.nx(), hit.ny(), 1)}. The normal need not have length
     * 1 (it is scaled to 1), so {@code (bx - ax, by - ay)} between two centres will do.
     *
     * <p>A NaN or infinite velocity or normal, or a normal of (0, 0), gives no bounce, the
     * velocity back unchanged (the <a href="package-summary.html#bad-input">NaN rule</a>, for
     * the values a sketch computes). The restitution is a number the sketch chooses, and has
     * one rule wherever the library takes one: NaN, infinite or outside [0, 1] is refused.
     *
     * @param vx          the mover's velocity x
     * @param vy          the mover's velocity y
     * @param nx          the normal's x, pointing from the mover into the obstacle
     * @param ny          the normal's y
     * @param restitution from 0 (stop) to 1 (perfect bounce)
     * @return the new velocity; unchanged if the mover is not moving into the obstacle, never null
     * @throws IllegalArgumentException if {@code restitution} is NaN, infinite or outside [0, 1]
     */
    public static Vec bounce(float vx, float vy, float nx, float ny, float restitution) {
        checkRestitution(restitution);
        if (Check.notFinite(vx, vy, nx, ny, 0)) {
            return new Vec(vx, vy);
        }
        double e = restitution;
        double len = Math.hypot(nx, ny);
        if (len == 0) {
            return new Vec(vx, vy);
        }
        double ux = nx / len, uy = ny / len;
        double into = vx * ux + vy * uy;
        if (!(into > 0)) {
            return new Vec(vx, vy);
        }
        double k = (1 + e) * into;
        return new Vec((float) (vx - k * ux), (float) (vy - k * uy));
    }

    /**
     * The slide on plain floats: velocity (vx, vy) against a surface whose normal (nx, ny)
     * points from the mover into the obstacle (a contact's, hit's or ray hit's normal as it
     * is), any length. Never throws: NaN, infinite or a (0, 0) normal gives the velocity back
     * unchanged.
     *
     * @param vx the mover's velocity x
     * @param vy the mover's velocity y
     * @param nx the normal's x, pointing from the mover into the obstacle
     * @param ny the normal's y
     * @return the new velocity; unchanged if the mover is not moving into the obstacle, never null
     */
    public static Vec slide(float vx, float vy, float nx, float ny) {
        return bounce(vx, vy, nx, ny, 0);
    }

    /** (x, y) moved along the normal by {@code signedShare * depth}, after checking the share. */
    /**
     * Shape a moved the shortest way out of b, so that afterwards {@code a.overlaps(b)} is
     * false, exactly, and the two touch to within float rounding. Shapes that do not overlap
     * come back unchanged. Which push-out: this one when a must end up clear of b, any pair
     * with area; {@link #pushOut(Shape, Contact, float)} to move by a contact you already have;
     * {@link Snap#pushOut} for two boxes, with the side.
     *
     * <p>Why more than {@link #pushOut(Shape, Contact, float)}: a contact's normal and depth are
     * floats, so moving by them can leave the shapes overlapping by a rounding error (a few
     * millionths of a pixel), and a game loop that pushes out until {@code overlaps} is false
     * would never finish. This moves along the same normal, by the depth and then by the
     * smallest float steps more (doubling each time), until the exact test agrees.
     *
     * @param <S> the kind of shape
     * @param a   the shape to move, with area (any shape but a segment), not null
     * @param b   the shape it must leave, with area, not null
     * @return a, moved out of b (or a itself if they do not overlap), never null
     * @throws IllegalArgumentException if a shape is null or a segment (see
     *                                  {@link Shape#contact})
     */
    @SuppressWarnings("unchecked")
    public static <S extends Shape> S separate(S a, Shape b) {
        Contact contact = Check.notNull("a", a).contact(Check.notNull("b", b));
        if (contact == null) {
            return a;
        }
        // Along the normal, by the depth and then by more: doubling from the smallest step
        // that can move a coordinate until a is clear, then halving back to the shortest clear
        // move found, so a is left touching b (to within float rounding), never beyond it.
        double depth = contact.depth();
        double extra = Math.ulp(depth);
        S clear = null;
        for (int i = 0; i < 200 && clear == null; i++) {
            S moved = movedBy(a, contact, depth + extra);
            if (!moved.overlaps(b)) {
                clear = moved;
            } else {
                extra *= 2;
            }
        }
        if (clear == null) {
            return movedBy(a, contact, depth + extra);
        }
        double lo = extra / 2, hi = extra;
        for (int i = 0; i < 64 && lo < hi; i++) {
            double mid = (lo + hi) / 2;
            if (mid == lo || mid == hi) {
                break;
            }
            S moved = movedBy(a, contact, depth + mid);
            if (moved.overlaps(b)) {
                lo = mid;
            } else {
                hi = mid;
                clear = moved;
            }
        }
        // No extra at all may already be clear (a depth rounded up).
        S exact = movedBy(a, contact, depth);
        return exact.overlaps(b) ? clear : exact;
    }

    /** a moved against the contact normal by d. */
    @SuppressWarnings("unchecked")
    private static <S extends Shape> S movedBy(S a, Contact contact, double d) {
        return (S) a.translated((float) (-d * contact.nx()), (float) (-d * contact.ny()));
    }

    /** The shape moved along the normal by {@code signedShare * depth}, after checking the share. */
    // Every Shape.translated returns a shape of its own kind (the sealed family's contract,
    // and each record narrows the return type), so the cast back to S is safe.
    @SuppressWarnings("unchecked")
    private static <S extends Shape> S translated(S s, Contact contact, float signedShare, float share) {
        Check.notNull("contact", contact);
        checkShare(share);
        double d = (double) signedShare * contact.depth();
        return (S) s.translated((float) (d * contact.nx()), (float) (d * contact.ny()));
    }

    private static void checkRestitution(float restitution) {
        Check.finite("restitution", restitution);
        if (restitution < 0 || restitution > 1) {
            throw new IllegalArgumentException("restitution must be between 0 and 1, was " + restitution);
        }
    }

    private static void checkShare(float share) {
        Check.finite("share", share);
        if (share < 0 || share > 1) {
            throw new IllegalArgumentException("share must be between 0 and 1, was " + share);
        }
    }
}
