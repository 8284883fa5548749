package hitbox;

import hitbox.internal.*;

/**
 * An axis-aligned rectangle: its top-left corner and its size, Processing's {@code CORNER}
 * mode ({@code rect(x, y, w, h)}).
 *
 * <p>Open: a point on an edge is not in it, and rectangles side by side do not overlap. A
 * rectangle of width or height 0 behaves as a segment (or a point). A rectangle is its own
 * {@link #bounds()}.
 *
 * <p><b>Transformed</b> ({@link #transformed}, {@link #rotated}): a rect stays a rect when the
 * transform keeps the axes (exactly {@code m01 = m10 = 0} or {@code m00 = m11 = 0}: a move, a scale or mirror along the
 * axes, a whole number of quarter turns), each edge the transformed edge rounded to float; a
 * scale by 0 gives a rect of width or height 0. Otherwise it becomes the {@link Polygon} of
 * its four corners, transformed, in the order top-left, top-right, bottom-right, bottom-left
 * of the rect. Refused when a corner goes beyond the float range, when the transform turns
 * or shears a rect of width or height 0 (a segment without its ends, which no kind is), or
 * when it is singular and does not keep the axes (no area for a polygon).
 *
 * @param x the left edge
 * @param y the top edge
 * @param w the width, 0 or more
 * @param h the height, 0 or more
 */
public record Rect(float x, float y, float w, float h) implements Shape {

    /**
     * Makes a rectangle, checking its values.
     *
     * @param x the left edge
     * @param y the top edge
     * @param w the width, 0 or more
     * @param h the height, 0 or more
     *
     * @throws IllegalArgumentException if a value is NaN or infinite, or a size is negative
     */
    public Rect {
        Check.finite("x", x);
        Check.finite("y", y);
        Check.size("width w", w);
        Check.size("height h", h);
    }

    /**
     * A rectangle from its centre and size, Processing's {@code CENTER} mode.
     *
     * @param cx the centre's x
     * @param cy the centre's y
     * @param w  the width, 0 or more
     * @param h  the height, 0 or more
     * @return the rectangle, never null
     * @throws IllegalArgumentException if a value is NaN or infinite, or a size is negative
     */
    public static Rect centered(float cx, float cy, float w, float h) {
        // Checked here, not left to the constructor, so the message names the centre the
        // caller passed rather than the corner computed from it.
        Check.finite("cx", cx);
        Check.finite("cy", cy);
        Check.size("width w", w);
        Check.size("height h", h);
        return new Rect(Check.finite("cx - w / 2", cx - w / 2), Check.finite("cy - h / 2", cy - h / 2), w, h);
    }

    /** @return the right edge, {@code x + w} */
    public float right() {
        return x + w;
    }

    /** @return the bottom edge, {@code y + h} */
    public float bottom() {
        return y + h;
    }

    /** @return the centre's x */
    public float centerX() {
        return x + w / 2;
    }

    /** @return the centre's y */
    public float centerY() {
        return y + h / 2;
    }

    /**
     * The region inside both rectangles: what a platformer draws as "the overlap", and the
     * sizes {@link Snap#pushOut} compares.
     *
     * @param other the other rectangle
     * @return the overlap, or null when they do not overlap ({@link Collide#rectRect} is
     *         false; rectangles that only touch have no overlap)
     * @throws IllegalArgumentException if {@code other} is null
     */
    public Rect intersection(Rect other) {
        Check.notNull("other", other);
        if (!Collide.rectRect(x, y, w, h, other.x, other.y, other.w, other.h)) {
            return null;
        }
        float left = Math.max(x, other.x);
        float top = Math.max(y, other.y);
        return new Rect(left, top, Math.min(right(), other.right()) - left, Math.min(bottom(), other.bottom()) - top);
    }

    /** {@inheritDoc} */
    @Override
    public Rect translated(float dx, float dy) {
        Check.finite("dx", dx);
        Check.finite("dy", dy);
        return new Rect(Check.finite("x + dx", x + dx), Check.finite("y + dy", y + dy), w, h);
    }

    /**
     * This rectangle with its top-left corner moved to (x, y), the size kept.
     *
     * @param newX the new left edge
     * @param newY the new top edge
     * @return the moved rectangle, never null
     * @throws IllegalArgumentException if a value is NaN or infinite
     */
    public Rect at(float newX, float newY) {
        return new Rect(Check.finite("newX", newX), Check.finite("newY", newY), w, h);
    }
}
