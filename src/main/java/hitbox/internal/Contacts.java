package hitbox.internal;

import hitbox.*;

/**
 * The table behind {@link Shape#contact}: every pair of shape kinds routed to the code for
 * that pair, plus the one tie rule every contact uses.
 *
 * <p>This class is longer than most (about 480 lines) because the table is one place for all
 * 21 unordered pairs of kinds, with the two-circle and two-box contacts on plain floats that
 * used to be {@code Contact}'s raw forms (issue 30 kept them here, as the kernels they are).
 */
public final class Contacts {
    private Contacts() {
    }

    /**
     * The shortest push seen so far (not to be confused with {@link Earliest}, the first
     * entry of a sweep), with the tie rule of {@link Contact}: among equal depths
     * the more vertical normal wins, then the larger {@code nx * ny}, then the larger ny,
     * then the larger nx. The keys after the first are unchanged when every normal is
     * reversed, or (for the last two) only meet between exactly opposite normals, so
     * {@code contact(b, a)} picks the reverse of {@code contact(a, b)} whenever the input is
     * not symmetric.
     */
    public static final class Shortest {
        public double nx;
        public double ny;
        public double depth = Double.POSITIVE_INFINITY;
        /**
         * An absolute slack for ties, for searches whose candidates are only placed to within
         * a tolerance of their own (see {@link Clearance}); 0 for the exact pairs.
         */
        public final double tolerance;
        /**
         * Are the candidates offered from the second shape's side ({@code contact(b, a)}, to
         * be reported for {@code contact(a, b)})? Then the tie rule is applied to the normals
         * as they will be reported, turned round, so the rule does not depend on which shape
         * the pair's code puts first.
         */
        public final boolean flip;

        public Shortest() {
            this(0, false);
        }

        public Shortest(double tolerance) {
            this(tolerance, false);
        }

        public Shortest(double tolerance, boolean flip) {
            this.tolerance = tolerance;
            this.flip = flip;
        }

        /**
         * Keeps (nx, ny, depth) if it is shorter than the best so far, or ties and wins.
         * Depths within {@link Contact#TIE} of each other (relative), or within the search's
         * tolerance, tie: the same distance reached through different arithmetic (a square
         * root here, a division there) must not let rounding pick the direction.
         */
        public void offer(double nx, double ny, double depth) {
            if (beats(nx, ny, depth, this.nx, this.ny, this.depth, tolerance, flip)) {
                this.nx = nx;
                this.ny = ny;
                this.depth = depth;
            }
        }

        /**
         * The rule of {@link #offer}, on plain values, for searches that keep their best in
         * locals so as to allocate nothing: does (nx, ny, depth) beat the best so far
         * (bx, by, best)?
         */
        public static boolean beats(double nx, double ny, double depth, double bx, double by, double best,
                             double tolerance, boolean flip) {
            double slack = Math.max(Contact.TIE * Math.min(depth, best), tolerance);
            if (depth < best - slack) {
                return true;
            }
            if (!(depth <= best + slack)) {
                return false;
            }
            double f = flip ? -1 : 1;
            // The keys are read from computed unit normals, so they carry the rounding of the
            // arithmetic behind them, or a search's own tolerance: keys that close are equal.
            double keyTie = tolerance > 0 ? Tolerance.SEARCH_KEY_TIE : Contact.TIE;
            return preferred(f * nx, f * ny, f * bx, f * by, keyTie);
        }

        /**
         * Can nothing at distance {@code bound} or more beat (or tie with) the best so far?
         * For pruning a search; uses the same slack as the tie rule, so that a candidate that
         * ties is still looked at.
         */
        public boolean beyond(double bound) {
            return bound > depth + slack(depth);
        }

        private double slack(double d) {
            return Math.max(Contact.TIE * d, tolerance);
        }

        public boolean found() {
            return depth != Double.POSITIVE_INFINITY;
        }

        /** The best push as a contact (turned round if {@link #flip}), or null if nothing was offered. */
        public Contact contact() {
            double f = flip ? -1 : 1;
            return found() ? Contacts.of(f * nx, f * ny, depth) : null;
        }
    }

    /**
     * Is unit normal (nx, ny) preferred to (ox, oy) when both push equally far? Each key of
     * the rule (|ny|, then nx * ny, then ny, then nx) decides only when the two differ by
     * more than {@code keyTie}; closer than that they are equal, and the next key decides.
     * A key is a unit normal's component or a product of two, so the computed normals'
     * rounding (about 1e-16) or a search's angle tolerance is what {@code keyTie} must
     * cover: the rule, not that rounding, then picks between mirror images such as
     * (0.866, 0.5) and (0.866, -0.5), whose |ny| are equal but for an ulp. Normals equal in
     * every key are the same direction to within {@code keyTie}: the first one stays.
     */
    public static boolean preferred(double nx, double ny, double ox, double oy, double keyTie) {
        double key = Math.abs(ny) - Math.abs(oy);
        if (Math.abs(key) > keyTie) {
            return key > 0;
        }
        key = nx * ny - ox * oy;
        if (Math.abs(key) > keyTie) {
            return key > 0;
        }
        key = ny - oy;
        if (Math.abs(key) > keyTie) {
            return key > 0;
        }
        key = nx - ox;
        return key > keyTie;
    }

    /** The four axis directions. */
    private static final int[][] AXES = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};

    /**
     * The contact of any two shapes, normal from a to b: every pair of kinds routed through
     * {@link ShapeKind} to the code for it. A pair with a curved kind goes to the support
     * search (or the concave-polygon search); a circle with a rectangle or polygon is worked
     * from the circle's side and reported from a's; rectangles and polygons go to the
     * separating-axis search. One small method per first kind, as in {@link Overlaps}: one
     * switch over both kinds was too large for the JIT to inline into a caller's loop (about
     * 600 bytes of bytecode, over its 325), which cost a call on every contact.
     */
    public static Contact between(Shape a, Shape b) {
        ShapeKind kb = ShapeKind.of(b);
        return switch (ShapeKind.of(a)) {
            case SEGMENT -> throw withoutArea("a", a);
            case ELLIPSE, CAPSULE -> curved(a, b, kb);
            case CIRCLE -> circleFirst((Circle) a, b, kb);
            case RECT -> rectFirst((Rect) a, b, kb);
            case POLYGON -> polygonFirst((Polygon) a, b, kb);
        };
    }

    /** A circle first, against a shape of kind kb. */
    private static Contact circleFirst(Circle c, Shape b, ShapeKind kb) {
        return switch (kb) {
            case SEGMENT -> throw withoutArea("b", b);
            case ELLIPSE, CAPSULE -> curved(c, b, kb);
            case CIRCLE -> {
                Circle d = (Circle) b;
                yield circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
            }
            case RECT -> {
                Rect r = (Rect) b;
                yield circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h(), false);
            }
            case POLYGON -> circlePolygon(c.x(), c.y(), c.r(), (Polygon) b, false);
        };
    }

    /**
     * A rectangle first, against a shape of kind kb. Against a circle: computed from the
     * circle's side, reported from the rectangle's (the tie rule sees a's normals).
     */
    private static Contact rectFirst(Rect r, Shape b, ShapeKind kb) {
        return switch (kb) {
            case SEGMENT -> throw withoutArea("b", b);
            case ELLIPSE, CAPSULE -> curved(r, b, kb);
            case CIRCLE -> {
                Circle c = (Circle) b;
                yield circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h(), true);
            }
            case RECT -> {
                Rect q = (Rect) b;
                yield rectRect(r.x(), r.y(), r.w(), r.h(), q.x(), q.y(), q.w(), q.h());
            }
            case POLYGON -> polygonal(r, false, b, true);
        };
    }

    /** A polygon first, against a shape of kind kb; against a circle, worked from the circle's side. */
    private static Contact polygonFirst(Polygon p, Shape b, ShapeKind kb) {
        return switch (kb) {
            case SEGMENT -> throw withoutArea("b", b);
            case ELLIPSE, CAPSULE -> curved(p, b, kb);
            case CIRCLE -> {
                Circle c = (Circle) b;
                yield circlePolygon(c.x(), c.y(), c.r(), p, true);
            }
            case RECT -> polygonal(p, true, b, false);
            case POLYGON -> polygonal(p, true, b, true);
        };
    }

    /** The refusal of a shape without area (a segment): there is no inside to push out of. */
    private static IllegalArgumentException withoutArea(String which, Shape s) {
        return new IllegalArgumentException("contact needs two shapes with area, but " + which
                + " is a " + s.getClass().getSimpleName() + ", which has none: there is no inside to push out of. Use"
                + " overlaps(...) to test a segment for a hit, or a sweep or ray cast to find"
                + " where a moving shape first touches it");
    }

    /**
     * A pair with a curved shape (an ellipse or a capsule) and any shape with area: a concave
     * polygon by {@link CurvedClearance} (the whole polygon, not its nearest piece), anything
     * else by {@link Supports}.
     */
    private static Contact curved(Shape a, Shape b, ShapeKind kb) {
        if (!kb.hasArea()) {
            throw withoutArea("b", b);
        }
        if (!Overlaps.test(a, b)) {
            return null;
        }
        if (concave(a, ShapeKind.of(a))) {
            return CurvedClearance.contact(b, (Polygon) a, true);
        }
        if (concave(b, kb)) {
            return CurvedClearance.contact(a, (Polygon) b, false);
        }
        return Supports.contact(a, b);
    }

    /** Is the shape, of kind k, a concave polygon? */
    private static boolean concave(Shape s, ShapeKind k) {
        return k == ShapeKind.POLYGON && !((Polygon) s).isConvex();
    }

    /**
     * A circle (first) against a rectangle, valid values; normal from the circle to the
     * rectangle, or from the rectangle to the circle if {@code flip}.
     */
    public static Contact circleRect(float cx, float cy, float r, float rx, float ry, float rw, float rh, boolean flip) {
        if (!RawTests.circleRect(cx, cy, r, rx, ry, rw, rh)) {
            return null;
        }
        double right = (double) rx + rw;
        double bottom = (double) ry + rh;
        double dx = Lines.clamp(cx, rx, right) - cx;
        double dy = Lines.clamp(cy, ry, bottom) - cy;
        double dist = Math.sqrt(dx * dx + dy * dy);
        double f = flip ? -1 : 1;
        if (dist > 0) {
            return Contacts.of(f * dx / dist, f * dy / dist, r - dist);
        }
        // The centre is in the closed rectangle: leave through the nearest edge. The circle
        // going up out of the top means the rectangle moves down, normal (0, 1).
        Shortest best = new Shortest(0, flip);
        best.offer(0, 1, (double) cy - ry + r);
        best.offer(0, -1, bottom - cy + r);
        best.offer(1, 0, (double) cx - rx + r);
        best.offer(-1, 0, right - cx + r);
        return best.contact();
    }

    /** A scratch array per thread for a rectangle's four corners ({@link #polygonal}). */
    private static final ThreadLocal<double[]> RECT_CORNERS = ThreadLocal.withInitial(() -> new double[8]);

    /**
     * A polygon's cached corners, or a rectangle's written into {@code scratch}, the same
     * values as {@link Polygons#corners}.
     */
    private static double[] cornersOf(Shape s, boolean polygon, double[] scratch) {
        return polygon ? HiddenParts.corners((Polygon) s) : Polygons.corners((Rect) s, scratch);
    }

    /**
     * Rectangles and polygons, at least one of them a polygon: each shape with whether it is
     * the polygon (else the rectangle), as the caller's switch over the kinds found.
     */
    private static Contact polygonal(Shape a, boolean polygonA, Shape b, boolean polygonB) {
        boolean convexA = !polygonA || ((Polygon) a).isConvex();
        boolean convexB = !polygonB || ((Polygon) b).isConvex();
        if (convexA && convexB) {
            // Boxes that do not overlap are apart (touching ones too: the shapes are open).
            Rect r = a.bounds(), s = b.bounds();
            if (!RawTests.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h())) {
                return null;
            }
            // A polygon's cached corners, or a rectangle's written into this thread's scratch
            // array (two rectangles went to rectRect), so that nothing is allocated
            // but the answer. The search decides apart exactly and only reads them.
            double[] scratch = polygonA && polygonB ? null : RECT_CORNERS.get();
            return FaceQuery.convexPolygons(cornersOf(a, polygonA, scratch), windingOf(a, polygonA), r,
                    cornersOf(b, polygonB, scratch), windingOf(b, polygonB), s);
        }
        return Clearance.polygons(Clearance.Parts.of(a), Clearance.Parts.of(b));
    }

    /**
     * A convex polygon's winding, or a rectangle's: its corners go top-left, top-right,
     * bottom-right, bottom-left, which with y growing down turns as +1 (a flat rectangle may
     * take either).
     */
    private static int windingOf(Shape s, boolean polygon) {
        return polygon ? HiddenParts.convexWinding((Polygon) s) : 1;
    }

    /**
     * A circle (first) against a polygon (second). The closest boundary feature (an edge or a
     * vertex) gives the answer, which is the minimum translation for a convex polygon, and for
     * any polygon when the radius is 0; a concave polygon and a real circle are handed to
     * {@link Clearance#circle}, since pushing out of the nearest edge can land the circle in
     * another part of the polygon.
     */
    public static Contact circlePolygon(float cx, float cy, float r, Polygon p, boolean flip) {
        float[] xy = HiddenParts.raw(p);
        Contact near = closestFeature(cx, cy, r, xy, flip);
        if (near == null || r == 0 || p.isConvex()) {
            return near;
        }
        // The search cannot come back empty for shapes that overlap; if rounding ever made it,
        // the closest-feature answer is still a push that clears the nearest edge.
        Contact clear = CircleClearance.circle(cx, cy, r, xy, flip);
        return clear != null ? clear : near;
    }

    /**
     * The circle pushed out through the polygon's closest edge or vertex: the circle leaves
     * along the feature's outward direction so that it ends at distance r from it. Normal from
     * the circle to the polygon (or the other way if {@code flip}); null when the circle does
     * not overlap (its centre is outside and at least r from the outline). Features whose
     * distances differ only by rounding (within {@link Contact#TIE}) are all offered, so the
     * tie rule decides between them, not the rounding. A centre exactly on a convex corner
     * may leave in any direction of the corner's cone of outward directions, all equally
     * short: the cone's ends (the edge normals) and the axis directions inside it are offered.
     */
    public static Contact closestFeature(float cx, float cy, float r, float[] xy, boolean flip) {
        int n = xy.length / 2;
        // Each edge's nearest point to the centre: its interior or its first vertex. The
        // second vertex is the next edge's first, so it is not repeated. The distances are
        // worked out again in the loop below rather than kept in an array: the same sums give
        // the same doubles, and a contact then allocates only its answer.
        double min = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            min = Math.min(min, partDistance2(xy, i, cx, cy, nearestPart(xy, i, cx, cy)));
        }
        boolean inside = RawTests.polygonPoint(xy, cx, cy);
        double dist = Math.sqrt(min);
        double depth = inside ? r + dist : r - dist;
        if (!(depth > 0)) {
            return null;
        }
        // Every feature at the least distance is offered, so ties follow the rule in Shortest.
        double turn = Polygons.winding(xy);
        Shortest best = new Shortest(0, flip);
        double near = min + 2 * Contact.TIE * min;
        for (int i = 0; i < n; i++) {
            int part = nearestPart(xy, i, cx, cy);
            if (!(partDistance2(xy, i, cx, cy, part) <= near)) {
                continue;
            }
            if (part == EDGE) {
                // The circle leaves along the edge's outward normal; the polygon goes the other way.
                double[] out = Polygons.outwardNormal(xy, i, turn);
                best.offer(-out[0], -out[1], depth);
            } else if (dist > 0) {
                double vx = (double) xy[2 * i] - cx, vy = (double) xy[2 * i + 1] - cy;
                double sign = inside ? -1 : 1;
                best.offer(sign * vx / dist, sign * vy / dist, depth);
            } else {
                // The centre is on vertex i: leave along either neighbouring edge's normal, or,
                // at a convex corner, along any direction between them (an axis one, say).
                for (int e : new int[] {(i + n - 1) % n, i}) {
                    double[] out = Polygons.outwardNormal(xy, e, turn);
                    if (out != null) {
                        best.offer(-out[0], -out[1], depth);
                    }
                }
                int h = Polygons.distinctNeighbour(xy, i, n - 1), k = Polygons.distinctNeighbour(xy, i, 1);
                double ax = (double) xy[2 * h] - xy[2 * i], ay = (double) xy[2 * h + 1] - xy[2 * i + 1];
                double bx = (double) xy[2 * k] - xy[2 * i], by = (double) xy[2 * k + 1] - xy[2 * i + 1];
                if (turn * Lines.orient(xy[2 * h], xy[2 * h + 1], xy[2 * i], xy[2 * i + 1], xy[2 * k], xy[2 * k + 1]) > 0) {
                    for (int[] d : AXES) {
                        // In the outward cone: pointing away from both neighbouring edges.
                        if (d[0] * ax + d[1] * ay <= 0 && d[0] * bx + d[1] * by <= 0) {
                            best.offer(-d[0], -d[1], depth);
                        }
                    }
                }
            }
        }
        return best.contact();
    }

    /** Parts of an edge nearest a point: its first vertex, its interior, its far vertex. */
    private static final int FIRST = -1, EDGE = 0, FAR = 1;

    /** Which part of edge i (vertex i to vertex i + 1) is nearest the centre. */
    private static int nearestPart(float[] xy, int i, float cx, float cy) {
        int j = (i + 1) % (xy.length / 2);
        // Relative to the centre: differences of floats are exact in double.
        double px = (double) xy[2 * i] - cx, py = (double) xy[2 * i + 1] - cy;
        double ex = ((double) xy[2 * j] - cx) - px, ey = ((double) xy[2 * j + 1] - cy) - py;
        double len2 = ex * ex + ey * ey;
        double along = -(px * ex + py * ey);
        return len2 == 0 || along <= 0 ? FIRST : along < len2 ? EDGE : FAR;
    }

    /**
     * The squared distance from the centre to that part of edge i; infinity for its far
     * vertex, which the next edge offers as its first (or something nearer).
     */
    private static double partDistance2(float[] xy, int i, float cx, float cy, int part) {
        double px = (double) xy[2 * i] - cx, py = (double) xy[2 * i + 1] - cy;
        if (part == FIRST) {
            return px * px + py * py;
        }
        if (part == FAR) {
            return Double.POSITIVE_INFINITY;
        }
        int j = (i + 1) % (xy.length / 2);
        double ex = ((double) xy[2 * j] - cx) - px, ey = ((double) xy[2 * j + 1] - cy) - py;
        double cross = ex * (-py) - ey * (-px);
        return cross * cross / (ex * ex + ey * ey);
    }

    /**
     * A contact from double-precision results. The depth is rounded to float and kept above
     * 0, and held at {@code Float.MAX_VALUE} for shapes so big that it is past the float
     * range (found by fuzzing); the normal is a unit vector already.
     */
    public static Contact of(double nx, double ny, double depth) {
        return new Contact((float) nx, (float) ny, Math.max(Check.held(depth), Float.MIN_VALUE));
    }

    /**
     * The contact of two circles given by plain floats, or null when they do not overlap (and
     * for NaN, infinite or negative values): the normal from the first centre to the second,
     * the depth {@code r1 + r2 - dist}; circles with one centre get (0, 1) and {@code r1 + r2}.
     */
    public static Contact circleCircle(float x1, float y1, float r1, float x2, float y2, float r2) {
        if (Check.notFinite(x1, y1, r1, x2, y2) || Check.notFinite(r2, 0, 0, 0, 0) || r1 < 0 || r2 < 0
                || !RawTests.circleCircle(x1, y1, r1, x2, y2, r2)) {
            return null;
        }
        double dx = (double) x2 - x1;
        double dy = (double) y2 - y1;
        double dist = Math.sqrt(dx * dx + dy * dy);
        double reach = (double) r1 + r2;
        if (dist == 0) {
            return of(0, 1, reach);
        }
        return of(dx / dist, dy / dist, reach - dist);
    }

    /**
     * The contact of two rectangles given by plain floats, or null when they do not overlap
     * (and for NaN, infinite or negative values): the first rectangle's shortest way out of
     * the second, an axis normal.
     */
    public static Contact rectRect(float x1, float y1, float w1, float h1,
                                   float x2, float y2, float w2, float h2) {
        if (Check.notFinite(x1, y1, w1, h1, x2) || Check.notFinite(y2, w2, h2, 0, 0)
                || w1 < 0 || h1 < 0 || w2 < 0 || h2 < 0 || !RawTests.rectRect(x1, y1, w1, h1, x2, y2, w2, h2)) {
            return null;
        }
        // The first rectangle's shortest way out of the second (exact depths, exact ties in
        // the tie rule's order): the same push Snap.pushOut makes.
        Side side = RectPush.leastOverlap(x1, y1, w1, h1, x2, y2, w2, h2);
        return of(RectPush.normalX(side), RectPush.normalY(side), RectPush.depth(side, x1, y1, w1, h1, x2, y2, w2, h2));
    }
}
