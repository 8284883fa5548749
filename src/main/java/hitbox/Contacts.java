package hitbox;

/**
 * The table behind {@link Contact#between}: every pair of shape kinds routed to the code for
 * that pair, plus the one tie rule every contact uses.
 */
final class Contacts {
    private Contacts() {
    }

    /**
     * The shortest push seen so far, with the tie rule of {@link Contact}: among equal depths
     * the more vertical normal wins, then the larger {@code nx * ny}, then the larger ny,
     * then the larger nx. The keys after the first are unchanged when every normal is
     * reversed, or (for the last two) only meet between exactly opposite normals, so
     * {@code contact(b, a)} picks the reverse of {@code contact(a, b)} whenever the input is
     * not symmetric.
     */
    static final class Best {
        double nx;
        double ny;
        double depth = Double.POSITIVE_INFINITY;
        /**
         * An absolute slack for ties, for searches whose candidates are only placed to within
         * a tolerance of their own (see {@link Clearance}); 0 for the exact pairs.
         */
        final double tolerance;

        Best() {
            this(0);
        }

        Best(double tolerance) {
            this.tolerance = tolerance;
        }

        /**
         * Keeps (nx, ny, depth) if it is shorter than the best so far, or ties and wins.
         * Depths within {@link Contact#TIE} of each other (relative), or within the search's
         * tolerance, tie: the same distance reached through different arithmetic (a square
         * root here, a division there) must not let rounding pick the direction.
         */
        void offer(double nx, double ny, double depth) {
            double slack = slack(Math.min(depth, this.depth));
            if (depth < this.depth - slack || (depth <= this.depth + slack && preferred(nx, ny, this.nx, this.ny))) {
                this.nx = nx;
                this.ny = ny;
                this.depth = depth;
            }
        }

        /**
         * Can nothing at distance {@code bound} or more beat (or tie with) the best so far?
         * For pruning a search; uses the same slack as the tie rule, so that a candidate that
         * ties is still looked at.
         */
        boolean beyond(double bound) {
            return bound > depth + slack(depth);
        }

        private double slack(double d) {
            return Math.max(Contact.TIE * d, tolerance);
        }

        boolean found() {
            return depth != Double.POSITIVE_INFINITY;
        }

        /** The best push as a contact, or null if nothing was offered. */
        Contact contact() {
            return found() ? Contact.of(nx, ny, depth) : null;
        }
    }

    /** Is normal (nx, ny) preferred to (ox, oy) when both push equally far? */
    static boolean preferred(double nx, double ny, double ox, double oy) {
        if (Math.abs(ny) != Math.abs(oy)) {
            return Math.abs(ny) > Math.abs(oy);
        }
        if (nx * ny != ox * oy) {
            return nx * ny > ox * oy;
        }
        if (ny != oy) {
            return ny > oy;
        }
        return nx > ox;
    }

    static Contact between(Shape a, Shape b) {
        if (a instanceof Segment || b instanceof Segment) {
            String which = a instanceof Segment ? "a" : "b";
            throw new IllegalArgumentException("contact needs two shapes with area, but " + which
                    + " is a Segment, which has none: there is no inside to push out of. Use"
                    + " overlaps(...) to test a segment for a hit, or a sweep or ray cast to find"
                    + " where a moving shape first touches it");
        }
        if (a instanceof Circle c) {
            if (b instanceof Circle d) {
                return Contact.circleCircle(c.x(), c.y(), c.r(), d.x(), d.y(), d.r());
            }
            if (b instanceof Rect r) {
                return Contact.circleRect(c.x(), c.y(), c.r(), r.x(), r.y(), r.w(), r.h());
            }
            return circlePolygon(c.x(), c.y(), c.r(), (Polygon) b);
        }
        if (b instanceof Circle) {
            Contact c = between(b, a);
            return c == null ? null : c.flipped();
        }
        if (a instanceof Rect r && b instanceof Rect s) {
            return Contact.rectRect(r.x(), r.y(), r.w(), r.h(), s.x(), s.y(), s.w(), s.h());
        }
        return polygonal(a, b);
    }

    /** Rectangles and polygons, at least one of them a polygon. */
    private static Contact polygonal(Shape a, Shape b) {
        boolean convexA = !(a instanceof Polygon p) || p.isConvex();
        boolean convexB = !(b instanceof Polygon p) || p.isConvex();
        if (convexA && convexB) {
            return SeparatingAxis.contact(Polygons.corners(a), Polygons.corners(b));
        }
        return Clearance.polygons(Clearance.Parts.of(a), Clearance.Parts.of(b));
    }

    /**
     * A circle (first) against a polygon (second). The closest boundary feature (an edge or a
     * vertex) gives the answer, which is the minimum translation for a convex polygon, and for
     * any polygon when the radius is 0; a concave polygon and a real circle are handed to
     * {@link Clearance#circle}, since pushing out of the nearest edge can land the circle in
     * another part of the polygon.
     */
    static Contact circlePolygon(float cx, float cy, float r, Polygon p) {
        float[] xy = p.raw();
        Contact near = closestFeature(cx, cy, r, xy);
        if (near == null || r == 0 || p.isConvex()) {
            return near;
        }
        // The search cannot come back empty for shapes that overlap; if rounding ever made it,
        // the closest-feature answer is still a push that clears the nearest edge.
        Contact clear = Clearance.circle(cx, cy, r, xy);
        return clear != null ? clear : near;
    }

    /**
     * The circle pushed out through the polygon's closest edge or vertex: the circle leaves
     * along the feature's outward direction so that it ends at distance r from it. Normal from
     * the circle to the polygon; null when the circle does not overlap (its centre is outside
     * and at least r from the outline).
     */
    static Contact closestFeature(float cx, float cy, float r, float[] xy) {
        int n = xy.length / 2;
        // Each edge's nearest point to the centre: its interior (distance^2, edge) or its
        // first vertex. The second vertex is the next edge's first, so it is not repeated.
        double[] d2 = new double[n];
        boolean[] interior = new boolean[n];
        double min = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            // Relative to the centre: differences of floats are exact in double.
            double px = (double) xy[2 * i] - cx, py = (double) xy[2 * i + 1] - cy;
            double qx = (double) xy[2 * j] - cx, qy = (double) xy[2 * j + 1] - cy;
            double ex = qx - px, ey = qy - py;
            double len2 = ex * ex + ey * ey;
            double along = -(px * ex + py * ey);
            if (len2 == 0 || along <= 0) {
                d2[i] = px * px + py * py;
            } else if (along < len2) {
                double cross = ex * (-py) - ey * (-px);
                d2[i] = cross * cross / len2;
                interior[i] = true;
            } else {
                // The far vertex is nearest; the next edge offers it (or something nearer).
                d2[i] = Double.POSITIVE_INFINITY;
            }
            min = Math.min(min, d2[i]);
        }
        boolean inside = Collide.polygonPoint(xy, cx, cy);
        double dist = Math.sqrt(min);
        double depth = inside ? r + dist : r - dist;
        if (!(depth > 0)) {
            return null;
        }
        // Every feature at the least distance is offered, so ties follow the rule in Best.
        double turn = Polygons.winding(xy);
        Best best = new Best();
        for (int i = 0; i < n; i++) {
            if (d2[i] != min) {
                continue;
            }
            if (interior[i]) {
                // The circle leaves along the edge's outward normal; the polygon goes the other way.
                double[] out = Polygons.outwardNormal(xy, i, turn);
                best.offer(-out[0], -out[1], depth);
            } else if (dist > 0) {
                double vx = (double) xy[2 * i] - cx, vy = (double) xy[2 * i + 1] - cy;
                double sign = inside ? -1 : 1;
                best.offer(sign * vx / dist, sign * vy / dist, depth);
            } else {
                // The centre is on vertex i: leave along either neighbouring edge's normal.
                for (int e : new int[] {(i + n - 1) % n, i}) {
                    double[] out = Polygons.outwardNormal(xy, e, turn);
                    if (out != null) {
                        best.offer(-out[0], -out[1], depth);
                    }
                }
            }
        }
        return best.contact();
    }
}
