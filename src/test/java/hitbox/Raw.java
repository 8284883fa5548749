package hitbox;

/**
 * The raw-float forms issue 30 took out of {@code Sweep}, {@code Contact}, {@code Separation}
 * and {@code Ray}, written as the one public call that answers the same question on shapes,
 * so that the tests written against them keep their cases and their oracles and now pin the
 * surviving call. Each makes the shapes and asks; bad values are refused by the shapes'
 * constructors (the deleted forms answered "no hit" instead, a rule that went with them).
 */
final class Raw {
    private Raw() {
    }

    private static float time(Hit hit) {
        return hit == null ? Float.POSITIVE_INFINITY : hit.t();
    }

    // ---------------------------------------------------------------- Sweep

    static float sweepCircleCircle(float x, float y, float r, float vx, float vy, float ox, float oy, float or) {
        return time(sweepCircleCircleHit(x, y, r, vx, vy, ox, oy, or));
    }

    static float sweepCircleRect(float x, float y, float r, float vx, float vy, float ox, float oy, float ow, float oh) {
        return time(sweepCircleRectHit(x, y, r, vx, vy, ox, oy, ow, oh));
    }

    static Hit sweepRectRectHit(float x, float y, float w, float h, float vx, float vy, float ox, float oy, float ow, float oh) {
        return Sweep.timeOfImpact(new Rect(x, y, w, h), vx, vy, new Rect(ox, oy, ow, oh));
    }

    static Hit sweepCircleCircleHit(float x, float y, float r, float vx, float vy, float ox, float oy, float or) {
        return Sweep.timeOfImpact(new Circle(x, y, r), vx, vy, new Circle(ox, oy, or));
    }

    static Hit sweepCircleRectHit(float cx, float cy, float r, float vx, float vy, float rectX, float rectY, float rectW, float rectH) {
        return Sweep.timeOfImpact(new Circle(cx, cy, r), vx, vy, new Rect(rectX, rectY, rectW, rectH));
    }

    static Hit sweepRectSegmentHit(float x, float y, float w, float h, float vx, float vy, float x1, float y1, float x2, float y2) {
        return Sweep.timeOfImpact(new Rect(x, y, w, h), vx, vy, new Segment(x1, y1, x2, y2));
    }

    static Hit sweepCircleSegmentHit(float cx, float cy, float r, float vx, float vy, float x1, float y1, float x2, float y2) {
        return Sweep.timeOfImpact(new Circle(cx, cy, r), vx, vy, new Segment(x1, y1, x2, y2));
    }

    // ---------------------------------------------------------------- Contact

    static Contact contactCircleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return new Circle(x1, y1, r1).contact(new Circle(x2, y2, r2));
    }

    static Contact contactCircleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        return new Circle(cx, cy, r).contact(new Rect(rectX, rectY, rectW, rectH));
    }

    static Contact contactRectCircle(float rectX, float rectY, float rectW, float rectH, float cx, float cy, float r) {
        return new Rect(rectX, rectY, rectW, rectH).contact(new Circle(cx, cy, r));
    }

    static Contact contactRectRect(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        return new Rect(x1, y1, w1, h1).contact(new Rect(x2, y2, w2, h2));
    }

    static Contact contactEllipseCircle(float x, float y, float radiusX, float radiusY, float cx, float cy, float r) {
        return new Ellipse(x, y, radiusX, radiusY).contact(new Circle(cx, cy, r));
    }

    static Contact contactEllipseRect(float x, float y, float radiusX, float radiusY, float rectX, float rectY, float rectW, float rectH) {
        return new Ellipse(x, y, radiusX, radiusY).contact(new Rect(rectX, rectY, rectW, rectH));
    }

    static Contact contactEllipseEllipse(float x1, float y1, float radiusX1, float radiusY1, float x2, float y2, float radiusX2, float radiusY2) {
        return new Ellipse(x1, y1, radiusX1, radiusY1).contact(new Ellipse(x2, y2, radiusX2, radiusY2));
    }

    static Contact contactCapsuleCircle(float x1, float y1, float x2, float y2, float r, float cx, float cy, float cr) {
        return new Capsule(x1, y1, x2, y2, r).contact(new Circle(cx, cy, cr));
    }

    static Contact contactCapsuleRect(float x1, float y1, float x2, float y2, float r, float rectX, float rectY, float rectW, float rectH) {
        return new Capsule(x1, y1, x2, y2, r).contact(new Rect(rectX, rectY, rectW, rectH));
    }

    static Contact contactCapsuleCapsule(float ax1, float ay1, float ax2, float ay2, float r1, float bx1, float by1, float bx2, float by2, float r2) {
        return new Capsule(ax1, ay1, ax2, ay2, r1).contact(new Capsule(bx1, by1, bx2, by2, r2));
    }

    static Contact contactEllipseCapsule(float x, float y, float radiusX, float radiusY, float x1, float y1, float x2, float y2, float r) {
        return new Ellipse(x, y, radiusX, radiusY).contact(new Capsule(x1, y1, x2, y2, r));
    }

    // ---------------------------------------------------------------- Separation (0 when they overlap)

    private static float distance(Shape a, Shape b) {
        Separation s = Separation.between(a, b);
        return s == null ? 0 : s.distance();
    }

    /** A point as a shape: a circle of radius 0 (it has no inside, as a point). */
    private static Circle point(float x, float y) {
        return new Circle(x, y, 0);
    }

    static float separationCirclePoint(float cx, float cy, float r, float px, float py) {
        return distance(new Circle(cx, cy, r), point(px, py));
    }

    static float separationRectPoint(float rectX, float rectY, float rectW, float rectH, float px, float py) {
        return distance(new Rect(rectX, rectY, rectW, rectH), point(px, py));
    }

    static float separationRectRect(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        return distance(new Rect(x1, y1, w1, h1), new Rect(x2, y2, w2, h2));
    }

    static float separationCircleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        return distance(new Circle(cx, cy, r), new Rect(rectX, rectY, rectW, rectH));
    }

    static float separationLinePoint(float x1, float y1, float x2, float y2, float px, float py) {
        return distance(new Segment(x1, y1, x2, y2), point(px, py));
    }

    static float separationLineCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        return distance(new Segment(x1, y1, x2, y2), new Circle(cx, cy, r));
    }

    static float separationLineLine(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
        return distance(new Segment(x1, y1, x2, y2), new Segment(x3, y3, x4, y4));
    }

    static float separationLineRect(float x1, float y1, float x2, float y2, float rectX, float rectY, float rectW, float rectH) {
        return distance(new Segment(x1, y1, x2, y2), new Rect(rectX, rectY, rectW, rectH));
    }

    static float separationPolygonPoint(float[] xy, float px, float py) {
        return distance(Polygon.of(xy), point(px, py));
    }

    static float separationPolygonCircle(float[] xy, float cx, float cy, float r) {
        return distance(Polygon.of(xy), new Circle(cx, cy, r));
    }

    static float separationPolygonRect(float[] xy, float rectX, float rectY, float rectW, float rectH) {
        return distance(Polygon.of(xy), new Rect(rectX, rectY, rectW, rectH));
    }

    static float separationPolygonLine(float[] xy, float x1, float y1, float x2, float y2) {
        return distance(Polygon.of(xy), new Segment(x1, y1, x2, y2));
    }

    static float separationPolygonPolygon(float[] a, float[] b) {
        return distance(Polygon.of(a), Polygon.of(b));
    }

    // ---------------------------------------------------------------- Ray

    private static float distance(RayHit hit) {
        return hit == null ? Float.POSITIVE_INFINITY : hit.distance();
    }

    static float rayDistanceToEllipse(float ox, float oy, float dx, float dy, float maxDistance, float x, float y, float radiusX, float radiusY) {
        return distance(new Ray(ox, oy, dx, dy, maxDistance).cast(new Ellipse(x, y, radiusX, radiusY)));
    }

    static float rayDistanceToCapsule(float ox, float oy, float dx, float dy, float maxDistance, float x1, float y1, float x2, float y2, float r) {
        return distance(new Ray(ox, oy, dx, dy, maxDistance).cast(new Capsule(x1, y1, x2, y2, r)));
    }
}
