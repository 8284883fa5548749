package hitbox.internal;

/**
 * The bodies of {@code hitbox.Collide}'s tests on plain floats: the tutorial's {@code if}s made
 * exact, and section 10's pairs. {@code Collide} holds the promise (the javadoc, the names a
 * learner reads) and answers by calling these; the kernels call these directly, so no kernel
 * calls back up into the API. Each method's contract is its {@code Collide} namesake's, where
 * it has one: for a float NaN or a negative size, false.
 *
 * <p>This class is longer than most (about 500 lines): it is every raw test's body, one
 * method per pair. The ones the API no longer names on floats (the ellipses' and capsules'
 * pairs, a rectangle first against a circle, a circle or a rectangle holding the other) are
 * the bodies of the shapes' answers ({@code Ellipse} and {@code Capsule} state how exactly
 * each pair is decided), and the browser's plain-float forms answer by them.
 */
public final class RawTests {
    private RawTests() {
    }

    /** The band of {@link #circleCircle}'s float filter: outside it the float squares decide. */
    private static final float FILTER_BELOW = 1 - 0x1p-18f, FILTER_ABOVE = 1 + 0x1p-18f;
    /** Below this a float square may be subnormal, where the filter's relative band does not hold. */
    private static final float FILTER_TINY = 0x1p-100f;

    public static boolean circlePoint(float cx, float cy, float r, float px, float py) {
        return circleCircle(cx, cy, r, px, py, 0);  // a point is a circle of radius 0 (and r = 0 contains none)
    }

    public static boolean circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        // A filter: the squares in float decide wherever they differ by more than rounding
        // could move them (a band of 2^-18 either way, against at most about 2^-22 of
        // relative error in each side: two differences, two squares and a sum; the sum of the
        // radii and its square), for a reach squared neither tiny (where subnormals lose the
        // relative bound) nor infinite; the rest (nearly touching, NaN, a negative radius,
        // extreme sizes) goes to Discs.centresCloser, in double with its own band and exact
        // inside it. The same answer on every input, about a fifth faster than the double
        // form alone (FilterFormsBench's circleCircle_floatBand against it, 1.85 against 2.29 ns).
        float fx = x2 - x1, fy = y2 - y1, d2 = fx * fx + fy * fy, sum = r1 + r2, rr = sum * sum;
        if ((d2 < rr * FILTER_BELOW | d2 > rr * FILTER_ABOVE) & rr > FILTER_TINY & rr <= Float.MAX_VALUE
                & r1 >= 0 & r2 >= 0) {
            return d2 < rr;
        }
        return r1 >= 0 && r2 >= 0 && Discs.centresCloser(x1, y1, r1, x2, y2, r2);
    }

    public static boolean rectPoint(float rectX, float rectY, float rectW, float rectH, float px, float py) {
        return px > rectX && px < (double) rectX + rectW && py > rectY && py < (double) rectY + rectH;
    }

    public static boolean rectRect(float x1, float y1, float w1, float h1,
                                   float x2, float y2, float w2, float h2) {
        // The sizes' signs last: the same answer (all eight must hold), but most misses are
        // settled by the first comparison (RectRectFormsBench: about 1.3x faster apart).
        return (double) x1 + w1 > x2 && x1 < (double) x2 + w2
                && (double) y1 + h1 > y2 && y1 < (double) y2 + h2
                && w1 >= 0 && h1 >= 0 && w2 >= 0 && h2 >= 0;
    }

    public static boolean circleRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        if (!(r >= 0 && rectW >= 0 && rectH >= 0)) {
            return false;
        }
        double dx = cx - Lines.clamp(cx, rectX, (double) rectX + rectW);
        double dy = cy - Lines.clamp(cy, rectY, (double) rectY + rectH);
        double d2 = dx * dx + dy * dy;
        if (d2 == 0) {
            // The centre is in the closed rectangle (NaN cannot get here: clamp passes it on,
            // and NaN is not 0). A real circle's inside covers the centre, so the two meet,
            // even for a zero-size rectangle; a circle of radius 0 is a point, which must be
            // strictly inside. A NaN radius fails both tests.
            return r > 0 || (r == 0 && rectPoint(rectX, rectY, rectW, rectH, cx, cy));
        }
        return d2 < (double) r * r;
    }

    public static boolean rectCircle(float x, float y, float w, float h, float cx, float cy, float r) {
        return circleRect(cx, cy, r, x, y, w, h);
    }

    public static boolean rectContainsRect(float x1, float y1, float w1, float h1,
                                           float x2, float y2, float w2, float h2) {
        return Containment.finite(x1, y1, w1, h1) && Containment.finite(x2, y2, w2, h2) && w1 >= 0 && h1 >= 0
                && w2 >= 0 && h2 >= 0 && Containment.rectRect(x1, y1, w1, h1, x2, y2, w2, h2);
    }

    public static boolean circleContainsCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        return Containment.finite(x1, y1, r1, x2) && Containment.finite(y2, r2, 0, 0) && r1 >= 0 && r2 >= 0
                && Containment.circleCircle(x1, y1, r1, x2, y2, r2);
    }

    public static boolean circleContainsRect(float cx, float cy, float r, float rectX, float rectY, float rectW, float rectH) {
        return Containment.finite(cx, cy, r, rectX) && Containment.finite(rectY, rectW, rectH, 0) && r >= 0
                && rectW >= 0 && rectH >= 0 && Containment.circleRect(cx, cy, r, rectX, rectY, rectW, rectH);
    }

    public static boolean rectContainsCircle(float x, float y, float w, float h, float cx, float cy, float r) {
        return Containment.finite(x, y, w, h) && Containment.finite(cx, cy, r, 0) && w >= 0 && h >= 0 && r >= 0
                && Containment.rectCircle(x, y, w, h, cx, cy, r);
    }

    public static boolean polygonPoint(float[] xy, float px, float py) {
        Check.notNull("xy", xy);
        if (px != px || py != py) {
            return false;
        }
        // The vertices are checked for NaN only when the answer would be "inside": the loop
        // takes a NaN without throwing (every comparison with it is false), and "outside" is
        // already the NaN rule's answer, so most calls skip the scan.
        return Polygons.contains(xy, px, py) && !Check.nan(xy);
    }

    public static boolean rayCrossesEdge(float ax, float ay, float bx, float by, float px, float py) {
        if (Check.nan(ax, ay, bx, by, px) || Float.isNaN(py)) {
            return false;
        }
        return Polygons.rayCrossing(ax, ay, bx, by, px, py) > 0;
    }

    public static int lineSide(float x1, float y1, float x2, float y2, float px, float py) {
        double o = Lines.orient(x1, y1, x2, y2, px, py);
        return o > 0 ? 1 : (o < 0 ? -1 : 0);
    }

    public static boolean lineLine(float x1, float y1, float x2, float y2,
                                   float x3, float y3, float x4, float y4) {
        if (Check.nan(x1, y1, x2, y2, x3) || Check.nan(y3, x4, y4, 0, 0)) {
            return false;
        }
        return Lines.segmentsMeet(x1, y1, x2, y2, x3, y3, x4, y4);
    }

    public static boolean lineCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        if (Check.nan(x1, y1, x2, y2, cx) || Check.nan(cy, r, 0, 0, 0)) {
            return false;
        }
        if (!(r > 0)) {
            return false;
        }
        if (circlePoint(cx, cy, r, x1, y1) || circlePoint(cx, cy, r, x2, y2)) {
            return true;
        }
        return betweenEndsInCircle(x1, y1, x2, y2, cx, cy, r);
    }

    /**
     * Does the segment pass through the open disc between its ends: the closest point of its
     * line to the centre strictly between the ends, nearer than r (exact)? With its ends
     * tested on their own, this is {@link #lineCircle}; no check of its input.
     */
    private static boolean betweenEndsInCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
        double dx = (double) x2 - x1;
        double dy = (double) y2 - y1;
        double fx = (double) cx - x1;
        double fy = (double) cy - y1;
        double along = fx * dx + fy * dy;
        double length2 = dx * dx + dy * dy;
        if (!(along > 0 && along < length2)) {
            return false; // the closest point is an end, and both ends are outside
        }
        double cross = dx * fy - dy * fx; // distance to the line times the length
        return Lines.signOfProductDifference(cross, cross, (double) r * r, length2) < 0;
    }

    public static boolean lineRect(float x1, float y1, float x2, float y2,
                                   float rectX, float rectY, float rectW, float rectH) {
        if (Check.nan(x1, y1, x2, y2, rectX) || Check.nan(rectY, rectW, rectH, 0, 0)) {
            return false;
        }
        if (!(rectW > 0 && rectH > 0)) {
            return false;
        }
        double right = (double) rectX + rectW;
        double bottom = (double) rectY + rectH;
        // The segment's box against the rectangle, written as comparisons: Math.max and
        // Math.min (NaN is ruled out above) cost branches that mispredict on mixed cases.
        if (!((x1 > rectX || x2 > rectX) && (x1 < right || x2 < right)
                && (y1 > rectY || y2 > rectY) && (y1 < bottom || y2 < bottom))) {
            return false;
        }
        if (x1 == x2 && y1 == y2) {
            return true; // a point, and the test above put it strictly inside
        }
        double o1 = Lines.orient(x1, y1, x2, y2, rectX, rectY);
        double o2 = Lines.orient(x1, y1, x2, y2, right, rectY);
        double o3 = Lines.orient(x1, y1, x2, y2, right, bottom);
        double o4 = Lines.orient(x1, y1, x2, y2, rectX, bottom);
        return (o1 > 0 || o2 > 0 || o3 > 0 || o4 > 0) && (o1 < 0 || o2 < 0 || o3 < 0 || o4 < 0);
    }

    public static boolean polygonCircle(float[] xy, float cx, float cy, float r) {
        if (Check.nan(Check.notNull("xy", xy)) || Check.nan(cx, cy, r, 0, 0)) {
            return false;
        }
        int n = xy.length / 2;
        if (!(r >= 0) || n < 3) {
            return false;
        }
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (lineCircle(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], cx, cy, r)) {
                return true;
            }
        }
        return Polygons.contains(xy, cx, cy);
    }

    /**
     * {@link #polygonCircle} for a {@code Polygon}'s outline (no NaN, three vertices or more)
     * and a circle with no NaN: the same answer, without the checks the raw form makes on
     * every call, and each vertex tested against the circle once (each edge's test through
     * {@link #lineCircle} tests both its ends).
     */
    public static boolean polygonCircleChecked(float[] xy, float cx, float cy, float r) {
        if (!(r >= 0)) {
            return false;
        }
        if (r > 0) {
            int n = xy.length / 2;
            for (int i = 0; i < n; i++) {
                if (circlePoint(cx, cy, r, xy[2 * i], xy[2 * i + 1])) {
                    return true;
                }
            }
            for (int i = 0, h = n - 1; i < n; h = i++) {
                if (betweenEndsInCircle(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], cx, cy, r)) {
                    return true;
                }
            }
        }
        return Polygons.contains(xy, cx, cy);
    }

    public static boolean polygonRect(float[] xy, float rectX, float rectY, float rectW, float rectH) {
        if (Check.nan(Check.notNull("xy", xy)) || Check.nan(rectX, rectY, rectW, rectH, 0)) {
            return false;
        }
        if (!(rectW >= 0 && rectH >= 0)) {
            return false;
        }
        if (rectW == 0 || rectH == 0) {
            return polygonLine(xy, rectX, rectY, rectX + rectW, rectY + rectH);
        }
        int w = Polygons.winding(xy);
        if (w == 0) {
            return false;
        }
        return polygonRectWound(xy, w, rectX, rectY, rectW, rectH);
    }

    /**
     * {@link #polygonRect} for a {@code Polygon}'s outline, whose winding is known (kept with
     * a convex polygon) and which holds no NaN, and a rectangle with width and height above 0
     * and no NaN: the checks and the winding the raw form works out on every call, left out.
     */
    public static boolean polygonRectWound(float[] xy, int w, float rectX, float rectY, float rectW, float rectH) {
        int n = xy.length / 2;
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (lineRect(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], rectX, rectY, rectW, rectH)) {
                return true;
            }
        }
        return Polygons.stepsInside(xy, w, rectX, rectY, 1, 1);
    }

    public static boolean polygonLine(float[] xy, float x1, float y1, float x2, float y2) {
        if (Check.nan(Check.notNull("xy", xy)) || Check.nan(x1, y1, x2, y2, 0)) {
            return false;
        }
        if (Polygons.contains(xy, x1, y1)) {
            return true;
        }
        int w = Polygons.winding(xy);
        return w != 0 && Polygons.segmentCrossesInto(xy, w, x1, y1, x2, y2);
    }

    public static boolean polygonPolygon(float[] a, float[] b) {
        Check.notNull("a", a);
        Check.notNull("b", b);
        // The convex path takes a NaN without throwing (its orientations pass NaN on, and
        // every comparison with NaN is false), so the arrays are scanned for NaN only when it
        // answers "overlap"; "apart" is already the NaN rule's answer.
        int ca = Polygons.convexWinding(a);
        if (ca != 0) {
            // An edge of convex a with every vertex of b on or outside its line proves "apart"
            // whatever b is, so b's convexity is checked only after a's edges found no gap.
            // Proof: a's open inside lies strictly on the inner side of each of its edge lines
            // (a convex polygon is the intersection of those half-planes). The inside of any
            // polygon b, convex or not, simple or not (read even-odd), lies in the convex hull
            // of b's vertices; that hull is in the closed outer half-plane of the edge line,
            // so b's inside, an open set, is in the open outer half-plane, disjoint from a's.
            if (Polygons.edgeSeparates(a, ca, b)) {
                return false;
            }
            int cb = Polygons.convexWinding(b);
            if (cb != 0) {
                return !Polygons.edgeSeparates(b, cb, a) && !Check.nan(a) && !Check.nan(b);
            }
        }
        if (Check.nan(a) || Check.nan(b)) {
            return false; // the general path below would reach exact arithmetic, which takes no NaN
        }
        int wa = Polygons.winding(a);
        int wb = Polygons.winding(b);
        if (wa == 0 || wb == 0 || Polygons.boundsApart(a, b)) {
            return false;
        }
        int n = a.length / 2;
        for (int i = 0; i < n; i++) {
            if (Polygons.contains(b, a[2 * i], a[2 * i + 1])) {
                return true;
            }
        }
        for (int i = 0, h = n - 1; i < n; h = i++) {
            if (Polygons.segmentCrossesInto(b, wb, a[2 * h], a[2 * h + 1], a[2 * i], a[2 * i + 1])) {
                return true;
            }
        }
        // No point of a's outline is inside b: b is wholly inside a, or wholly outside it.
        // Inside needs every vertex of b in a's closed box; a vertex beyond it settles
        // "outside" at once, with no exact arithmetic (the usual case: boxes that cross).
        if (!Polygons.boxWithin(b, a)) {
            return false;
        }
        int m = Polygons.leftmost(b);
        int prev = Polygons.distinctNeighbour(b, m, b.length / 2 - 1);
        int next = Polygons.distinctNeighbour(b, m, 1);
        // The leftmost corner is convex, so the sum of its two edge directions points inside;
        // summed exactly, since a corner can be thinner than a double's rounding.
        return Polygons.stepsInsideExact(a, wa, b[2 * m], b[2 * m + 1], b[2 * prev], b[2 * prev + 1],
                b[2 * next], b[2 * next + 1]);
    }

    public static boolean trianglePoint(float x1, float y1, float x2, float y2, float x3, float y3,
                                        float px, float py) {
        // No NaN check: an orientation with NaN in it is NaN, neither > 0 nor < 0, so NaN
        // input answers false by the same comparisons. The third edge is looked at only
        // when the first two put the point on the same side, which half the misses do not.
        double o1 = Lines.orient(x1, y1, x2, y2, px, py);
        double o2 = Lines.orient(x2, y2, x3, y3, px, py);
        if (o1 > 0 ? !(o2 > 0) : !(o1 < 0 && o2 < 0)) {
            return false;
        }
        double o3 = Lines.orient(x3, y3, x1, y1, px, py);
        return o1 > 0 ? o3 > 0 : o3 < 0;
    }

    public static boolean ellipsePoint(float x, float y, float radiusX, float radiusY, float px, float py) {
        // No NaN check of its own: a NaN radius fails Ellipses.point's "> 0", and a NaN
        // position makes its side NaN, which counts as outside.
        return Ellipses.point(x, y, radiusX, radiusY, px, py);
    }

    public static boolean ellipseCircle(float x, float y, float radiusX, float radiusY, float cx, float cy, float r) {
        if (Check.nan(x, y, radiusX, radiusY, cx) || Check.nan(cy, r, 0, 0, 0) || !(radiusX >= 0 && radiusY >= 0 && r >= 0)) {
            return false;
        }
        if (r == 0) {
            return Ellipses.point(x, y, radiusX, radiusY, cx, cy);
        }
        if (radiusX == 0 || radiusY == 0) {
            return circleRect(cx, cy, r, x - radiusX, y - radiusY, 2 * radiusX, 2 * radiusY);
        }
        if (radiusX == radiusY) {
            return circleCircle(x, y, radiusX, cx, cy, r); // a circle: exact on the touching rule
        }
        return Ellipses.circle(x, y, radiusX, radiusY, cx, cy, r);
    }

    public static boolean ellipseRect(float x, float y, float radiusX, float radiusY, float rectX, float rectY, float rectW, float rectH) {
        if (Check.nan(x, y, radiusX, radiusY, rectX) || Check.nan(rectY, rectW, rectH, 0, 0)
                || !(radiusX >= 0 && radiusY >= 0 && rectW >= 0 && rectH >= 0)) {
            return false;
        }
        if (radiusX == 0 || radiusY == 0) {
            return rectRect(x - radiusX, y - radiusY, 2 * radiusX, 2 * radiusY, rectX, rectY, rectW, rectH);
        }
        return Ellipses.rect(x, y, radiusX, radiusY, rectX, rectY, rectW, rectH);
    }

    public static boolean ellipseLine(float x, float y, float radiusX, float radiusY, float x1, float y1, float x2, float y2) {
        if (Check.nan(x, y, radiusX, radiusY, x1) || Check.nan(y1, x2, y2, 0, 0) || !(radiusX > 0 && radiusY > 0)) {
            return false;
        }
        return Ellipses.segment(x, y, radiusX, radiusY, x1, y1, x2, y2, false);
    }

    public static boolean ellipseEllipse(float x1, float y1, float radiusX1, float radiusY1,
                                         float x2, float y2, float radiusX2, float radiusY2) {
        if (Check.nan(x1, y1, radiusX1, radiusY1, x2) || Check.nan(y2, radiusX2, radiusY2, 0, 0)
                || !(radiusX1 >= 0 && radiusY1 >= 0 && radiusX2 >= 0 && radiusY2 >= 0)) {
            return false;
        }
        if (radiusX1 == 0 || radiusY1 == 0) {
            return ellipseRect(x2, y2, radiusX2, radiusY2, x1 - radiusX1, y1 - radiusY1, 2 * radiusX1, 2 * radiusY1);
        }
        if (radiusX2 == 0 || radiusY2 == 0) {
            return ellipseRect(x1, y1, radiusX1, radiusY1, x2 - radiusX2, y2 - radiusY2, 2 * radiusX2, 2 * radiusY2);
        }
        // An ellipse with equal radii is a circle, whose pairs are exact on the touching rule;
        // the general ellipse search is not, where a circle touches at a point off the axes.
        if (radiusX1 == radiusY1) {
            return ellipseCircle(x2, y2, radiusX2, radiusY2, x1, y1, radiusX1);
        }
        if (radiusX2 == radiusY2) {
            return ellipseCircle(x1, y1, radiusX1, radiusY1, x2, y2, radiusX2);
        }
        if (Ellipses.before(x2, y2, radiusX2, radiusY2, x1, y1, radiusX1, radiusY1)) {
            return Ellipses.ellipse(x2, y2, radiusX2, radiusY2, x1, y1, radiusX1, radiusY1);
        }
        return Ellipses.ellipse(x1, y1, radiusX1, radiusY1, x2, y2, radiusX2, radiusY2);
    }

    public static boolean polygonEllipse(float[] xy, float x, float y, float radiusX, float radiusY) {
        if (Check.nan(Check.notNull("xy", xy)) || Check.nan(x, y, radiusX, radiusY, 0)
                || !(radiusX >= 0 && radiusY >= 0) || xy.length < 6) {
            return false;
        }
        if (radiusX == 0 || radiusY == 0) {
            return polygonRect(xy, x - radiusX, y - radiusY, 2 * radiusX, 2 * radiusY);
        }
        return Ellipses.polygon(xy, x, y, radiusX, radiusY);
    }

    public static boolean ellipseCapsule(float x, float y, float radiusX, float radiusY,
                                         float x1, float y1, float x2, float y2, float r) {
        if (Check.nan(x, y, radiusX, radiusY, x1) || Check.nan(y1, x2, y2, r, 0)
                || !(radiusX >= 0 && radiusY >= 0 && r >= 0)) {
            return false;
        }
        if (radiusX == 0 || radiusY == 0) {
            return capsuleRect(x1, y1, x2, y2, r, x - radiusX, y - radiusY, 2 * radiusX, 2 * radiusY);
        }
        if (radiusX == radiusY) {
            return capsuleCircle(x1, y1, x2, y2, r, x, y, radiusX); // a circle: exact on the touching rule
        }
        if (r == 0) {
            return Ellipses.segment(x, y, radiusX, radiusY, x1, y1, x2, y2, false);
        }
        int sure = Ellipses.capsuleQuick(radiusX, radiusY, (double) x1 - x, (double) y1 - y, (double) x2 - x, (double) y2 - y, r);
        if (sure != 0) {
            return sure > 0;
        }
        return Ellipses.segmentWithin(x, y, radiusX, radiusY, x1, y1, x2, y2, r);
    }

    public static boolean capsulePoint(float x1, float y1, float x2, float y2, float r, float px, float py) {
        if (Check.nan(x1, y1, x2, y2, r) || Check.nan(px, py, 0, 0, 0) || !(r > 0)) {
            return false;
        }
        return Capsules.pointWithin(x1, y1, x2, y2, px, py, r);
    }

    public static boolean capsuleCircle(float x1, float y1, float x2, float y2, float r1, float cx, float cy, float r2) {
        if (Check.nan(x1, y1, x2, y2, r1) || Check.nan(cx, cy, r2, 0, 0) || !(r1 >= 0 && r2 >= 0)) {
            return false;
        }
        return Capsules.pointWithin(x1, y1, x2, y2, cx, cy, (double) r1 + r2);
    }

    public static boolean capsuleRect(float x1, float y1, float x2, float y2, float r,
                                      float rectX, float rectY, float rectW, float rectH) {
        if (Check.nan(x1, y1, x2, y2, r) || Check.nan(rectX, rectY, rectW, rectH, 0) || !(r >= 0 && rectW >= 0 && rectH >= 0)) {
            return false;
        }
        if (r == 0) {
            return lineRect(x1, y1, x2, y2, rectX, rectY, rectW, rectH);
        }
        return Capsules.rect(x1, y1, x2, y2, r, rectX, rectY, rectW, rectH);
    }

    public static boolean capsuleLine(float x1, float y1, float x2, float y2, float r,
                                      float x3, float y3, float x4, float y4) {
        if (Check.nan(x1, y1, x2, y2, r) || Check.nan(x3, y3, x4, y4, 0)) {
            return false;
        }
        return Capsules.segmentsWithin(x1, y1, x2, y2, x3, y3, x4, y4, r);
    }

    public static boolean capsuleCapsule(float x1, float y1, float x2, float y2, float r1,
                                         float x3, float y3, float x4, float y4, float r2) {
        if (Check.nan(x1, y1, x2, y2, r1) || Check.nan(x3, y3, x4, y4, r2) || !(r1 >= 0 && r2 >= 0)) {
            return false;
        }
        return Capsules.segmentsWithin(x1, y1, x2, y2, x3, y3, x4, y4, (double) r1 + r2);
    }

    public static boolean polygonCapsule(float[] xy, float x1, float y1, float x2, float y2, float r) {
        if (Check.nan(Check.notNull("xy", xy)) || Check.nan(x1, y1, x2, y2, r) || !(r >= 0) || xy.length < 6) {
            return false;
        }
        if (r == 0) {
            return polygonLine(xy, x1, y1, x2, y2);
        }
        return Capsules.polygon(xy, x1, y1, x2, y2, r);
    }

    public static boolean arcPoint(float x, float y, float radiusX, float radiusY, float start, float stop, int mode,
                                   float px, float py) {
        if (Check.nan(x, y, radiusX, radiusY, start) || Check.nan(stop, px, py, 0, 0) || !(radiusX > 0 && radiusY > 0)) {
            return false;
        }
        return Arcs.contains(x, y, radiusX, radiusY, start, stop, mode, px, py);
    }
}
