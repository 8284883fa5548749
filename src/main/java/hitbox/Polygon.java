package hitbox;

import java.util.Arrays;

/**
 * A simple polygon, convex or concave, in either winding: its vertices in order.
 *
 * <p>Open, like every shape with area: a point on an edge is not in it.
 */
public final class Polygon implements Shape {
    private final float[] xy;
    private final Rect bounds;

    private Polygon(float[] xy) {
        this.xy = xy;
        this.bounds = Polygons.bounds(xy);
    }

    /**
     * Makes a polygon from its vertices, {@code x0, y0, x1, y1, ...}, in either winding.
     *
     * @param xy the vertices' coordinates, in pairs
     * @return the polygon
     * @throws IllegalArgumentException if there are fewer than 3 vertices, an odd number of
     *                                  coordinates, a NaN or infinite value, or the polygon
     *                                  has no area or crosses itself
     */
    public static Polygon of(float... xy) {
        Check.notNull("xy", xy);
        float[] copy = xy.clone();
        Polygons.validate(copy);
        return new Polygon(copy);
    }

    /** @return how many vertices the polygon has */
    public int size() {
        return xy.length / 2;
    }

    /**
     * @param i the vertex index, from 0 to {@code size() - 1}
     * @return vertex i's x
     */
    public float x(int i) {
        return xy[2 * i];
    }

    /**
     * @param i the vertex index, from 0 to {@code size() - 1}
     * @return vertex i's y
     */
    public float y(int i) {
        return xy[2 * i + 1];
    }

    /** @return a copy of the coordinates, {@code x0, y0, x1, y1, ...} */
    public float[] coordinates() {
        return xy.clone();
    }

    /** The coordinates without a copy, for the library's own loops; never handed out. */
    float[] raw() {
        return xy;
    }

    /** {@inheritDoc} Same as {@link Collide#polygonPoint}. */
    @Override
    public boolean contains(float px, float py) {
        return Collide.polygonPoint(xy, px, py);
    }

    /** {@inheritDoc} */
    @Override
    public Rect bounds() {
        return bounds;
    }

    /** {@inheritDoc} */
    @Override
    public Polygon translated(float dx, float dy) {
        float[] moved = xy.clone();
        for (int i = 0; i < moved.length; i += 2) {
            moved[i] += dx;
            moved[i + 1] += dy;
        }
        return of(moved);
    }

    /** Two polygons are equal when they have the same vertices in the same order. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Polygon p && Arrays.equals(xy, p.xy);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(xy);
    }

    @Override
    public String toString() {
        return "Polygon" + Arrays.toString(xy);
    }
}
