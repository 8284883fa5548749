package hitbox.web;

import hitbox.Collide;
import hitbox.internal.RawTests;
import org.teavm.jso.JSClass;
import org.teavm.jso.JSExport;

/**
 * The tutorial's tests ({@link Collide}) for JavaScript, as {@code Collide.circleCircle(...)}:
 * the same names, the same parameters (numbers; a polygon as an array [x0, y0, x1, y1, ...]).
 * Generated from Collide's signatures; each only calls its namesake. The browser keeps a few
 * more on plain floats (the ellipses, the capsules, one shape holding another), which Java asks
 * of the shapes: those call the same bodies the shapes answer by ({@code RawTests}).
 */
@JSClass(name = "Collide")
public final class CollideJs {
    private CollideJs() {
    }

    /**
     * {@link Collide#circlePoint}.
     *
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean circlePoint(float cx, float cy, float r, float px, float py) {
        return Collide.circlePoint(cx, cy, r, px, py);
    }

    /**
     * {@link Collide#circleCircle}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param r1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r2 as there
     * @return as there
     */
    @JSExport
    public static boolean circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return Collide.circleCircle(x1, y1, r1, x2, y2, r2);
    }

    /**
     * {@link Collide#rectPoint}.
     *
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean rectPoint(float rectX, float rectY, float rectW, float rectH, float px, float py) {
        return Collide.rectPoint(rectX, rectY, rectW, rectH, px, py);
    }

    /**
     * {@link Collide#rectRect}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param w1 as there
     * @param h1 as there
     * @param x2 as there
     * @param y2 as there
     * @param w2 as there
     * @param h2 as there
     * @return as there
     */
    @JSExport
    public static boolean rectRect(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        return Collide.rectRect(x1, y1, w1, h1, x2, y2, w2, h2);
    }

    /**
     * {@link Collide#circleRect}.
     *
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @return as there
     */
    @JSExport
    public static boolean circleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        return Collide.circleRect(cx, cy, r, rectX, rectY, rectW, rectH);
    }

    /**
     * {@link Collide#circleRect} with the shapes the other way round.
     *
     * @param x as there
     * @param y as there
     * @param w as there
     * @param h as there
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean rectCircle(float x, float y, float w, float h, float cx, float cy, float r) {
        return RawTests.rectCircle(x, y, w, h, cx, cy, r);  // the library asks it the one way round
    }

    /**
     * Does the first rectangle hold the second (edges included)? {@code Rect.contains(Shape)} on plain floats; false for NaN, infinite or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param w1 as there
     * @param h1 as there
     * @param x2 as there
     * @param y2 as there
     * @param w2 as there
     * @param h2 as there
     * @return as there
     */
    @JSExport
    public static boolean rectContainsRect(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        return RawTests.rectContainsRect(x1, y1, w1, h1, x2, y2, w2, h2);
    }

    /**
     * Does the first circle hold the second (outline included)? {@code Circle.contains(Shape)} on plain floats; false for NaN, infinite or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param r1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r2 as there
     * @return as there
     */
    @JSExport
    public static boolean circleContainsCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return RawTests.circleContainsCircle(x1, y1, r1, x2, y2, r2);
    }

    /**
     * Does the circle hold the rectangle (edges and outline included)? {@code Circle.contains(Rect)} on plain floats; false for NaN, infinite or negative values.
     *
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @return as there
     */
    @JSExport
    public static boolean circleContainsRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        // The library asks it of the shapes (Circle.contains); the export keeps its plain-float
        // form and its rule for bad values (false, never an exception) on the same kernel.
        return RawTests.circleContainsRect(cx, cy, r, rectX, rectY, rectW, rectH);
    }

    /**
     * Does the rectangle hold the circle (edges and outline included)? {@code Rect.contains(Circle)} on plain floats; false for NaN, infinite or negative values.
     *
     * @param x as there
     * @param y as there
     * @param w as there
     * @param h as there
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean rectContainsCircle(float x, float y, float w, float h, float cx, float cy, float r) {
        // As circleContainsRect: Rect.contains in the library, this form and its rule kept here.
        return RawTests.rectContainsCircle(x, y, w, h, cx, cy, r);
    }

    /**
     * {@link Collide#polygonPoint}.
     *
     * @param xy as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean polygonPoint(float[] xy, float px, float py) {
        return Collide.polygonPoint(xy, px, py);
    }

    /**
     * {@link Collide#rayCrossesEdge}.
     *
     * @param ax as there
     * @param ay as there
     * @param bx as there
     * @param by as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean rayCrossesEdge(float ax, float ay, float bx, float by, float px, float py) {
        return Collide.rayCrossesEdge(ax, ay, bx, by, px, py);
    }

    /**
     * {@link Collide#lineSide}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static int lineSide(float x1, float y1, float x2, float y2, float px, float py) {
        return Collide.lineSide(x1, y1, x2, y2, px, py);
    }

    /**
     * {@link Collide#lineLine}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param x3 as there
     * @param y3 as there
     * @param x4 as there
     * @param y4 as there
     * @return as there
     */
    @JSExport
    public static boolean lineLine(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
        return Collide.lineLine(x1, y1, x2, y2, x3, y3, x4, y4);
    }

    /**
     * {@link Collide#lineCircle}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean lineCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        return Collide.lineCircle(x1, y1, x2, y2, cx, cy, r);
    }

    /**
     * {@link Collide#lineRect}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @return as there
     */
    @JSExport
    public static boolean lineRect(float x1, float y1, float x2, float y2, float rectX, float rectY, float rectW, float rectH) {
        return Collide.lineRect(x1, y1, x2, y2, rectX, rectY, rectW, rectH);
    }

    /**
     * {@link Collide#polygonCircle}.
     *
     * @param xy as there
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean polygonCircle(float[] xy, float cx, float cy, float r) {
        return Collide.polygonCircle(xy, cx, cy, r);
    }

    /**
     * {@link Collide#polygonRect}.
     *
     * @param xy as there
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @return as there
     */
    @JSExport
    public static boolean polygonRect(float[] xy, float rectX, float rectY, float rectW, float rectH) {
        return Collide.polygonRect(xy, rectX, rectY, rectW, rectH);
    }

    /**
     * {@link Collide#polygonLine}.
     *
     * @param xy as there
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @return as there
     */
    @JSExport
    public static boolean polygonLine(float[] xy, float x1, float y1, float x2, float y2) {
        return Collide.polygonLine(xy, x1, y1, x2, y2);
    }

    /**
     * {@link Collide#polygonPolygon}.
     *
     * @param a as there
     * @param b as there
     * @return as there
     */
    @JSExport
    public static boolean polygonPolygon(float[] a, float[] b) {
        return Collide.polygonPolygon(a, b);
    }

    /**
     * {@link Collide#trianglePoint}.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param x3 as there
     * @param y3 as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean trianglePoint(float x1, float y1, float x2, float y2, float x3, float y3, float px, float py) {
        return Collide.trianglePoint(x1, y1, x2, y2, x3, y3, px, py);
    }

    /**
     * Is the point inside the ellipse? {@code Ellipse.contains(px, py)} on plain floats; false for NaN or negative values.
     *
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean ellipsePoint(float x, float y, float radiusX, float radiusY, float px, float py) {
        return RawTests.ellipsePoint(x, y, radiusX, radiusY, px, py);
    }

    /**
     * Do an ellipse and a circle overlap? {@code Ellipse.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @param cx as there
     * @param cy as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean ellipseCircle(float x, float y, float radiusX, float radiusY, float cx, float cy, float r) {
        return RawTests.ellipseCircle(x, y, radiusX, radiusY, cx, cy, r);
    }

    /**
     * Do an ellipse and a rectangle overlap? {@code Ellipse.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @return as there
     */
    @JSExport
    public static boolean ellipseRect(float x, float y, float radiusX, float radiusY, float rectX, float rectY, float rectW, float rectH) {
        return RawTests.ellipseRect(x, y, radiusX, radiusY, rectX, rectY, rectW, rectH);
    }

    /**
     * Does a segment reach into an ellipse? {@code Ellipse.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @return as there
     */
    @JSExport
    public static boolean ellipseLine(float x, float y, float radiusX, float radiusY, float x1, float y1, float x2, float y2) {
        return RawTests.ellipseLine(x, y, radiusX, radiusY, x1, y1, x2, y2);
    }

    /**
     * Do two ellipses overlap? {@code Ellipse.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param radiusX1 as there
     * @param radiusY1 as there
     * @param x2 as there
     * @param y2 as there
     * @param radiusX2 as there
     * @param radiusY2 as there
     * @return as there
     */
    @JSExport
    public static boolean ellipseEllipse(float x1, float y1, float radiusX1, float radiusY1, float x2, float y2, float radiusX2, float radiusY2) {
        return RawTests.ellipseEllipse(x1, y1, radiusX1, radiusY1, x2, y2, radiusX2, radiusY2);
    }

    /**
     * Do a polygon and an ellipse overlap? {@code Polygon.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param xy as there
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @return as there
     */
    @JSExport
    public static boolean polygonEllipse(float[] xy, float x, float y, float radiusX, float radiusY) {
        return RawTests.polygonEllipse(xy, x, y, radiusX, radiusY);
    }

    /**
     * Do an ellipse and a capsule overlap? {@code Ellipse.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean ellipseCapsule(float x, float y, float radiusX, float radiusY, float x1, float y1, float x2, float y2, float r) {
        return RawTests.ellipseCapsule(x, y, radiusX, radiusY, x1, y1, x2, y2, r);
    }

    /**
     * Is the point inside the capsule? {@code Capsule.contains(px, py)} on plain floats; false for NaN or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean capsulePoint(float x1, float y1, float x2, float y2, float r, float px, float py) {
        return RawTests.capsulePoint(x1, y1, x2, y2, r, px, py);
    }

    /**
     * Do a capsule and a circle overlap? {@code Capsule.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r1 as there
     * @param cx as there
     * @param cy as there
     * @param r2 as there
     * @return as there
     */
    @JSExport
    public static boolean capsuleCircle(float x1, float y1, float x2, float y2, float r1, float cx, float cy, float r2) {
        return RawTests.capsuleCircle(x1, y1, x2, y2, r1, cx, cy, r2);
    }

    /**
     * Do a capsule and a rectangle overlap? {@code Capsule.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r as there
     * @param rectX as there
     * @param rectY as there
     * @param rectW as there
     * @param rectH as there
     * @return as there
     */
    @JSExport
    public static boolean capsuleRect(float x1, float y1, float x2, float y2, float r, float rectX, float rectY, float rectW, float rectH) {
        return RawTests.capsuleRect(x1, y1, x2, y2, r, rectX, rectY, rectW, rectH);
    }

    /**
     * Does a segment reach into a capsule? {@code Capsule.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r as there
     * @param x3 as there
     * @param y3 as there
     * @param x4 as there
     * @param y4 as there
     * @return as there
     */
    @JSExport
    public static boolean capsuleLine(float x1, float y1, float x2, float y2, float r, float x3, float y3, float x4, float y4) {
        return RawTests.capsuleLine(x1, y1, x2, y2, r, x3, y3, x4, y4);
    }

    /**
     * Do two capsules overlap? {@code Capsule.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r1 as there
     * @param x3 as there
     * @param y3 as there
     * @param x4 as there
     * @param y4 as there
     * @param r2 as there
     * @return as there
     */
    @JSExport
    public static boolean capsuleCapsule(float x1, float y1, float x2, float y2, float r1, float x3, float y3, float x4, float y4, float r2) {
        return RawTests.capsuleCapsule(x1, y1, x2, y2, r1, x3, y3, x4, y4, r2);
    }

    /**
     * Do a polygon and a capsule overlap? {@code Polygon.overlaps} on plain floats; false for NaN or negative values.
     *
     * @param xy as there
     * @param x1 as there
     * @param y1 as there
     * @param x2 as there
     * @param y2 as there
     * @param r as there
     * @return as there
     */
    @JSExport
    public static boolean polygonCapsule(float[] xy, float x1, float y1, float x2, float y2, float r) {
        return RawTests.polygonCapsule(xy, x1, y1, x2, y2, r);
    }

    /**
     * {@link Collide#arcPoint}.
     *
     * @param x as there
     * @param y as there
     * @param radiusX as there
     * @param radiusY as there
     * @param start as there
     * @param stop as there
     * @param mode as there
     * @param px as there
     * @param py as there
     * @return as there
     */
    @JSExport
    public static boolean arcPoint(float x, float y, float radiusX, float radiusY, float start, float stop, int mode, float px, float py) {
        return Collide.arcPoint(x, y, radiusX, radiusY, start, stop, mode, px, py);
    }
}
