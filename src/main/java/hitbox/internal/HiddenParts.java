package hitbox.internal;

import hitbox.Grid;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Transform;
import java.util.function.Supplier;

/**
 * What the kernels read of a {@link Polygon} and a {@link Grid} that the API does not hand
 * out: a polygon's coordinates and corners without a copy, its convex winding, first
 * concave vertex and kept bounding box, and a grid's cells. The API classes grant the
 * access once, from their static initialisers (the JDK's {@code SharedSecrets} pattern), so the kernels can live
 * apart from the API without those members becoming public.
 *
 * <p>The granted access is read through a static final field, which the JIT treats as a
 * constant: a call here costs what the package-private accessor it replaces cost.
 */
public final class HiddenParts {
    private HiddenParts() {
    }

    /** A polygon's kept parts, granted by {@link Polygon}. */
    public interface PolygonAccess {
        /**
         * @param p the polygon
         * @return its coordinates {@code x0, y0, x1, y1, ...} without a copy: never written
         */
        float[] raw(Polygon p);

        /**
         * @param p the polygon
         * @return its vertices widened to double, without a copy: never written
         */
        double[] corners(Polygon p);

        /**
         * @param p the polygon
         * @return its winding (+1 or -1) if it is convex, 0 if it is concave
         */
        int convexWinding(Polygon p);

        /**
         * @param p the polygon
         * @return its first vertex where the outline bends inwards, or -1 if convex
         */
        int concaveVertex(Polygon p);

        /**
         * @param p the polygon
         * @return its bounding box, made when first asked and kept
         */
        Rect bounds(Polygon p);

        /**
         * @param p        the polygon
         * @param xy       its vertices' images under an affine map, rounded to float (taken, not copied)
         * @param scaleMin the map's smallest stretch (its smaller singular value), or less
         * @param delta    how far rounding may have moved a vertex from its exact image, or more
         * @param verb     what was done, for a message ("moving by dx = 1.5, dy = 0"), made only when needed
         * @return the polygon of {@code xy}, checked only as far as the rounding could have changed it
         * @throws IllegalArgumentException if the rounded outline is not a valid polygon
         */
        Polygon image(Polygon p, float[] xy, double scaleMin, double delta, Supplier<String> verb);

        /**
         * @param xy the vertices {@code x0, y0, x1, y1, ...} (taken, not copied: the caller made
         *           them and keeps no reference)
         * @return the polygon, checked in full as {@link Polygon#of(float...)} checks it
         * @throws IllegalArgumentException as {@link Polygon#of(float...)} does
         */
        Polygon taken(float[] xy);

        /**
         * @param xy the image of a convex outline (a turned rectangle's corners, say), finite
         *           and rounded to float (taken, not copied)
         * @return the polygon: at once if the image is still convex with no repeated vertex
         *         (then it is simple, as for {@link #image}), else checked in full as
         *         {@link #taken} checks it
         * @throws IllegalArgumentException as {@link Polygon#of(float...)} does
         */
        Polygon convexImage(float[] xy);
    }

    /** A transform's entries in double, granted by {@link Transform}. */
    public interface TransformAccess {
        /**
         * @param t the transform
         * @return its entries in double, as kept
         */
        Affine affine(Transform t);
    }

    /** A grid's cells, granted by {@link Grid}. */
    public interface GridAccess {
        /**
         * @param g the grid
         * @return its cells' terrains, row by row, without a copy (written by the map readers)
         */
        int[] cells(Grid g);
    }

    private static PolygonAccess polygons;
    private static GridAccess grids;
    private static TransformAccess transforms;

    /**
     * Called once, by {@link Polygon}'s static initialiser.
     *
     * @param access the access, not null
     * @throws IllegalStateException if it was granted already
     */
    public static synchronized void grant(PolygonAccess access) {
        if (polygons != null) {
            throw new IllegalStateException("polygon access granted already");
        }
        polygons = access;
    }

    /**
     * Called once, by {@link Grid}'s static initialiser.
     *
     * @param access the access, not null
     * @throws IllegalStateException if it was granted already
     */
    public static synchronized void grant(GridAccess access) {
        if (grids != null) {
            throw new IllegalStateException("grid access granted already");
        }
        grids = access;
    }

    /**
     * Called once, by {@link Transform}'s static initialiser.
     *
     * @param access the access, not null
     * @throws IllegalStateException if it was granted already
     */
    public static synchronized void grantTransforms(TransformAccess access) {
        if (transforms != null) {
            throw new IllegalStateException("transform access granted already");
        }
        transforms = access;
    }

    /** The granted accesses as constants; loading this first initialises Polygon and Grid. */
    private static final class Granted {
        public static final PolygonAccess POLYGONS = initialised(Polygon.class) ? polygons : null;
        public static final GridAccess GRIDS = initialised(Grid.class) ? grids : null;
        public static final TransformAccess TRANSFORMS = initialised(Transform.class) ? transforms : null;

        private static boolean initialised(Class<?> type) {
            try {
                Class.forName(type.getName(), true, type.getClassLoader());
                return true;
            } catch (ClassNotFoundException e) {
                throw new AssertionError(e);
            }
        }
    }

    /** @param p the polygon @return its coordinates without a copy */
    public static float[] raw(Polygon p) {
        return Granted.POLYGONS.raw(p);
    }

    /** @param p the polygon @return its vertices in double without a copy */
    public static double[] corners(Polygon p) {
        return Granted.POLYGONS.corners(p);
    }

    /** @param p the polygon @return its winding if convex, else 0 */
    public static int convexWinding(Polygon p) {
        return Granted.POLYGONS.convexWinding(p);
    }

    /** @param p the polygon @return its first concave vertex, or -1 */
    public static int concaveVertex(Polygon p) {
        return Granted.POLYGONS.concaveVertex(p);
    }

    /** @param p the polygon @return its bounding box, kept */
    public static Rect bounds(Polygon p) {
        return Granted.POLYGONS.bounds(p);
    }

    /**
     * @param p the polygon @param xy its vertices' images @param scaleMin the map's smallest stretch
     * @param delta the rounding's reach @param verb what was done
     * @return the new polygon (see {@link PolygonAccess#image})
     */
    public static Polygon image(Polygon p, float[] xy, double scaleMin, double delta, Supplier<String> verb) {
        return Granted.POLYGONS.image(p, xy, scaleMin, delta, verb);
    }

    /** @see PolygonAccess#taken */
    public static Polygon taken(float[] xy) {
        return Granted.POLYGONS.taken(xy);
    }

    /** @see PolygonAccess#convexImage */
    public static Polygon convexImage(float[] xy) {
        return Granted.POLYGONS.convexImage(xy);
    }

    /** @param t the transform @return its entries in double */
    public static Affine affine(Transform t) {
        return Granted.TRANSFORMS.affine(t);
    }

    /** @param g the grid @return its cells without a copy */
    public static int[] cells(Grid g) {
        return Granted.GRIDS.cells(g);
    }
}
