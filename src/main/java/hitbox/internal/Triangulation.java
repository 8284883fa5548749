package hitbox.internal;

import java.util.ArrayList;
import java.util.List;

/**
 * Cutting a simple polygon into pieces: triangles by ear clipping, and convex pieces by
 * merging triangles back where they stay convex. {@link Clearance} searches the overlap of
 * concave shapes piece by piece. Vertices are {@code x0, y0, x1, y1, ...} in double; pieces
 * and cuts are vertex indices. Orientation tests only, exact ({@link Lines#orient}); the
 * winding is the sign of the exact area.
 *
 * <p>Reference: D. Eberly, "Triangulation by Ear Clipping", 2002; S. Hertel, K. Mehlhorn,
 * "Fast triangulation of simple polygons", 1983.
 */
public final class Triangulation {
    private Triangulation() {
    }

    /**
     * Cuts a simple polygon into convex pieces: triangles by ear clipping, then, cut by cut,
     * the two pieces on either side are merged whenever the union is still convex (Hertel and
     * Mehlhorn's method: at most four times the fewest pieces possible, usually far fewer
     * than triangles). Pieces are vertex indices in the polygon's winding; the cuts kept are
     * added to {@code cuts}, each as two vertex indices.
     *
     * <p>Reference: S. Hertel, K. Mehlhorn, "Fast triangulation of simple polygons", 1983.
     */
    public static List<int[]> convexPieces(double[] xy, List<int[]> cuts) {
        List<int[]> diagonals = new ArrayList<>();
        List<int[]> pieces = triangulate(xy, diagonals);
        double turn = Polygons.areaSign(xy);
        for (int[] d : diagonals) {
            int p = pieceWithEdge(pieces, d[0], d[1]);
            int q = pieceWithEdge(pieces, d[1], d[0]);
            if (p < 0 || q < 0) {
                cuts.add(d);
                continue;
            }
            int[] merged = merge(pieces.get(p), pieces.get(q), d[0], d[1]);
            if (convexAt(xy, merged, d[0], turn) && convexAt(xy, merged, d[1], turn)) {
                pieces.set(p, merged);
                pieces.remove(q);
            } else {
                cuts.add(d);
            }
        }
        return pieces;
    }

    /** The piece that runs from vertex u straight to vertex w, or -1. */
    private static int pieceWithEdge(List<int[]> pieces, int u, int w) {
        for (int k = 0; k < pieces.size(); k++) {
            int[] p = pieces.get(k);
            for (int i = 0; i < p.length; i++) {
                if (p[i] == u && p[(i + 1) % p.length] == w) {
                    return k;
                }
            }
        }
        return -1;
    }

    /** Piece p (with edge u to w) and piece q (with edge w to u) joined along that edge. */
    private static int[] merge(int[] p, int[] q, int u, int w) {
        int[] out = new int[p.length + q.length - 2];
        int i = 0;
        while (p[i] != w) {
            i++;
        }
        int k = 0;
        for (int s = 0; s < p.length; s++) {
            out[k++] = p[(i + s) % p.length]; // w ... u, all of p
        }
        int j = 0;
        while (q[j] != u) {
            j++;
        }
        for (int s = 1; s < q.length - 1; s++) {
            out[k++] = q[(j + s) % q.length]; // after u, up to before w
        }
        return out;
    }

    /** Does the piece turn with the polygon (or go straight) at vertex v? */
    private static boolean convexAt(double[] xy, int[] piece, int v, double turn) {
        int n = piece.length;
        for (int i = 0; i < n; i++) {
            if (piece[i] == v) {
                return orient(xy, piece[(i + n - 1) % n], v, piece[(i + 1) % n]) * turn >= 0;
            }
        }
        return false;
    }

    /**
     * Cuts a simple polygon into triangles by ear clipping; each triangle is three vertex
     * indices in the polygon's winding, and each cut (two vertex indices) is added to
     * {@code diagonals}. Straight vertices (on the line between their neighbours) are dropped
     * on the way; they change nothing. Orientation tests only, exact for whole numbers.
     *
     * <p>Reference: D. Eberly, "Triangulation by Ear Clipping", 2002.
     *
     * @throws IllegalArgumentException if the polygon has no area or crosses itself (then no
     *                                  ear can be found)
     */
    public static List<int[]> triangulate(double[] xy, List<int[]> diagonals) {
        int n = xy.length / 2;
        double turn = Polygons.areaSign(xy);
        if (turn == 0) {
            throw new IllegalArgumentException("the polygon has no area, so it cannot be cut into triangles");
        }
        int[] v = new int[n];
        for (int i = 0; i < n; i++) {
            v[i] = i;
        }
        int count = n;
        List<int[]> triangles = new ArrayList<>(n - 2);
        while (count > 3) {
            boolean cut = false;
            for (int k = 0; k < count && !cut; k++) {
                int a = v[(k + count - 1) % count], b = v[k], c = v[(k + 1) % count];
                double o = orient(xy, a, b, c);
                if (o == 0) {
                    // Straight: b lies on the way from a to c, so dropping it changes nothing.
                    cut = true;
                } else if (o * turn > 0 && isEar(xy, v, count, a, b, c, turn)) {
                    triangles.add(new int[] {a, b, c});
                    diagonals.add(new int[] {a, c});
                    cut = true;
                }
                if (cut) {
                    System.arraycopy(v, k + 1, v, k, count - k - 1);
                    count--;
                }
            }
            if (!cut) {
                throw new IllegalArgumentException("the polygon crosses itself, so it cannot be cut into triangles");
            }
        }
        if (orient(xy, v[0], v[1], v[2]) != 0) {
            triangles.add(new int[] {v[0], v[1], v[2]});
        }
        return triangles;
    }

    /** Is triangle a, b, c (turning with the polygon) free of every other remaining vertex? */
    private static boolean isEar(double[] xy, int[] v, int count, int a, int b, int c, double turn) {
        for (int k = 0; k < count; k++) {
            int i = v[k];
            if (i == a || i == b || i == c) {
                continue;
            }
            // In the closed triangle: a vertex on the cut a-c would make the cut touch the outline.
            if (orient(xy, a, b, i) * turn >= 0 && orient(xy, b, c, i) * turn >= 0 && orient(xy, c, a, i) * turn >= 0) {
                return false;
            }
        }
        return true;
    }

    private static double orient(double[] xy, int a, int b, int c) {
        return Lines.orient(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], xy[2 * c], xy[2 * c + 1]);
    }
}
