package hitbox.internal;

/**
 * Processing's {@code arc()}, read the way Processing 4 draws it (PGraphics.arc and
 * PGraphicsJava2D.arcImpl), for {@link Collide#arcPoint}:
 * <ul>
 *   <li>nothing is drawn unless {@code stop > start} (so NaN, equal angles and a stop before
 *       the start draw nothing), and nothing for an infinite angle;</li>
 *   <li>while {@code start < 0}, both angles have {@code TWO_PI} added, in float; then a span
 *       over {@code TWO_PI} is cut to {@code stop = start + TWO_PI} (start unchanged); angles
 *       beyond {@code TWO_PI} are otherwise kept, and read modulo a turn;</li>
 *   <li>the angles become degrees ({@code -angle * RAD_TO_DEG}, in float) for
 *       {@link java.awt.geom.Arc2D}, whose angles are the ellipse's parametric angles: the
 *       point at angle a is {@code (x + rx cos a, y + ry sin a)}, clockwise on screen as a
 *       grows; an extent of 360 degrees or more is the whole ellipse;</li>
 *   <li>the fill: {@code PIE} (and a mode of 0, or any other than OPEN and CHORD) is the
 *       slice from the centre; {@code OPEN} and {@code CHORD} both fill the part of the
 *       ellipse cut off by the chord between the arc's ends, on the arc's side.</li>
 * </ul>
 */
public final class Arcs {
    private Arcs() {
    }

    /** Processing's constants (PConstants). */
    public static final int OPEN = 1, CHORD = 2;
    private static final float TWO_PI = (float) (2.0 * Math.PI);
    private static final float RAD_TO_DEG = 180.0f / (float) Math.PI;
    /** More turns than this to bring start up to 0 and Processing's own loop would not end in a frame; nothing is drawn. */
    private static final int MAX_TURNS = 1 << 22;

    /**
     * The arc's start angle and its extent, in radians as Java2D receives them, or null when
     * Processing draws nothing. An extent of {@code 2 pi} or more is the whole ellipse.
     */
    public static double[] normalised(float start, float stop) {
        if (Float.isInfinite(start) || Float.isInfinite(stop) || !(stop > start)) {
            return null;
        }
        int turns = 0;
        while (start < 0) {
            float next = start + TWO_PI;
            if (next == start || ++turns > MAX_TURNS) {
                return null; // Processing would loop for ever
            }
            start = next;
            stop += TWO_PI;
        }
        if (stop - start > TWO_PI) {
            stop = start + TWO_PI;
        }
        float startDeg = -start * RAD_TO_DEG;
        float stopDeg = -stop * RAD_TO_DEG;
        float sweep = stopDeg - startDeg;
        return new double[] {Math.toRadians(-startDeg), Math.toRadians(-sweep), -sweep >= 360 ? 1 : 0};
    }

    /** Is the point strictly inside the filled arc (radii > 0, no NaN)? */
    public static boolean contains(float x, float y, float a, float b, float start, float stop, int mode, float px, float py) {
        double[] arc = normalised(start, stop);
        if (arc == null || !Ellipses.point(x, y, a, b, px, py)) {
            return false;
        }
        if (arc[2] != 0) {
            return true; // a whole turn: the whole ellipse
        }
        double s = arc[0], e = arc[1];
        double u = ((double) px - x) / a, v = ((double) py - y) / b;
        if (mode == OPEN || mode == CHORD) {
            double ax = StrictMath.cos(s), ay = StrictMath.sin(s);
            double bx = StrictMath.cos(s + e), by = StrictMath.sin(s + e);
            double mx = StrictMath.cos(s + e / 2), my = StrictMath.sin(s + e / 2);
            double side = (bx - ax) * (v - ay) - (by - ay) * (u - ax);
            double arcSide = (bx - ax) * (my - ay) - (by - ay) * (mx - ax);
            return side != 0 && (side > 0) == (arcSide > 0);
        }
        if (u == 0 && v == 0) {
            return false; // the slice's corner is on its outline
        }
        double rel = Math.IEEEremainder(Math.atan2(v, u) - s, 2 * Math.PI);
        if (rel < 0) {
            rel += 2 * Math.PI;
        }
        return rel > 0 && rel < e;
    }
}
