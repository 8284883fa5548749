package hitbox.processing;

import hitbox.Shape;
import hitbox.Transform;
import hitbox.internal.Check;
import processing.awt.PGraphicsJava2D;
import processing.core.PGraphics;
import processing.core.PMatrix;
import processing.core.PMatrix2D;
import processing.core.PMatrix3D;

/**
 * Shapes as the sketch's current matrix draws them: what {@code translate}, {@code rotate}
 * and {@code scale} did to the drawing, applied to a library shape, so that what you test
 * is what you see.
 *
 * <pre>
 * pushMatrix();
 * translate(x, y);
 * rotate(angle);
 * rect(-20, -10, 40, 20);
 * Shape drawn = Drawn.shape(g, new Rect(-20, -10, 40, 20));  // the rect where it is on screen
 * popMatrix();
 * if (drawn.contains(mouseX, mouseY)) { ... }
 * </pre>
 *
 * <p>The shape comes back in the sketch's own coordinates (those of {@code mouseX} and
 * {@code mouseY}), whatever the {@code pixelDensity}. What kind it becomes is
 * {@link Shape#transformed}'s rule: a rect turned off the axes is a {@link hitbox.Polygon},
 * a circle under an uneven {@code scale} a turned {@link hitbox.Ellipse}; a
 * {@link hitbox.Capsule} under an uneven {@code scale} is refused.
 *
 * <p>2D renderers only (the default, {@code JAVA2D}, and {@code P2D}): a {@code P3D} matrix
 * can tilt the drawing out of the screen's plane, which no 2D shape follows, and is refused.
 */
public final class Drawn {
    private Drawn() {
    }

    /**
     * The current drawing matrix as a {@link Transform}: where a point drawn at (x, y) now
     * lands, in the sketch's coordinates. Same as {@code getMatrix()} read as
     * {@code Transform.of(m00, m01, m02, m10, m11, m12)}, with the {@code JAVA2D} renderer's
     * {@code pixelDensity} taken out.
     *
     * @param g where the sketch draws, e.g. the sketch's {@code g}
     * @return the transform, never null
     * @throws IllegalArgumentException if {@code g} is null, or a 3D renderer ({@code P3D})
     */
    public static Transform transform(PGraphics g) {
        Check.notNull("g", g);
        if (g.is3D()) {
            throw new IllegalArgumentException("Drawn needs a 2D renderer (the default, or P2D), but g is 3D ("
                    + g.getClass().getSimpleName() + "): a P3D matrix can tilt the drawing out of the screen,"
                    + " which no 2D shape follows");
        }
        PMatrix m = g.getMatrix();
        Transform t;
        if (m instanceof PMatrix2D m2) {
            t = Transform.of(m2.m00, m2.m01, m2.m02, m2.m10, m2.m11, m2.m12);
        } else if (m instanceof PMatrix3D m3) {
            // P2D keeps a 3D modelview; in 2D its z row and column are those of the identity
            t = Transform.of(m3.m00, m3.m01, m3.m03, m3.m10, m3.m11, m3.m13);
        } else {
            throw new IllegalArgumentException("Drawn cannot read the matrix of g (" + g.getClass().getSimpleName()
                    + "): getMatrix() gave " + m);
        }
        if (g instanceof PGraphicsJava2D && g.pixelDensity != 1) {
            // JAVA2D's matrix starts as scale(pixelDensity): from sketch units to the pixels it stores
            float toSketch = 1f / g.pixelDensity;
            t = t.then(Transform.scaling(toSketch, toSketch));
        }
        return t;
    }

    /**
     * The shape as the current matrix draws it: {@code shape.transformed(Drawn.transform(g))}.
     * Call it where you draw the shape (between {@code pushMatrix()} and {@code popMatrix()}),
     * with the coordinates you draw it at.
     *
     * @param g     where the sketch draws, e.g. the sketch's {@code g}
     * @param shape the shape in the coordinates it is drawn at, not null
     * @return the shape on screen, in the sketch's coordinates (a {@link hitbox.Polygon} for
     *         a turned rect), never null
     * @throws IllegalArgumentException if {@code g} or {@code shape} is null, {@code g} is a
     *                                  3D renderer, or the shape has no exact image under the
     *                                  matrix (a capsule under an uneven {@code scale}, see
     *                                  {@link Shape#transformed})
     */
    public static Shape shape(PGraphics g, Shape shape) {
        Check.notNull("shape", shape);
        return shape.transformed(transform(g));
    }
}
