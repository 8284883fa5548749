package hitbox.bench;

import java.util.Random;

import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;

/**
 * One question of the narrow-phase table: {@value #N} cases, each a pair of Hitbox shapes
 * (a point is a {@link Segment} of length 0), and for rays and sweeps a direction or motion.
 * Every contender gets the same cases, converted once to its own types (see {@link NarrowPeers});
 * only the conversion is shared, never an answer.
 *
 * <p>The cases come from a seeded generator: coordinates are whole or half numbers, so some
 * pairs touch exactly (where the peers' touching rules differ from Hitbox's); the boxes of
 * every pair overlap or touch, as after a broad phase, unless a miss cannot have overlapping
 * boxes (two rectangles, a point in a rectangle: then up to {@code N / 16} pairs whose boxes
 * only touch, and misses anywhere); and half the cases are hits by Hitbox's answer.
 */
final class NarrowCase {
    /** Cases per question; every benchmark method answers all of them once per call. */
    static final int N = 1024;

    /**
     * What kind of answer the question asks for; the agreement check and the nudge use it.
     * APART: a distance between shapes that do not overlap; CONTAIN: does the first hold the
     * second; TURN: two polygons that both move and turn (the motions in {@link #v}).
     */
    enum Kind { OVERLAP, CONTACT, RAY, SWEEP, APART, CONTAIN, TURN }

    final Kind kind;
    /** The first shape (the mover of a sweep); null for rays. */
    final Shape[] a = new Shape[N];
    /** The second shape (the target of a ray, the obstacle of a sweep). */
    final Shape[] b = new Shape[N];
    /**
     * The ray's origin and direction (ox, oy, dx, dy), the sweep's motion (vx, vy), or the two
     * turning movers' (pivotAX, pivotAY, vax, vay, turnA, pivotBX, pivotBY, vbx, vby, turnB);
     * else null.
     */
    final float[][] v = new float[N][];
    /** The shapes' raw floats, in the order the {@code Collide} methods take them. */
    final float[][] ra = new float[N][];
    final float[][] rb = new float[N][];

    NarrowCase(Kind kind) {
        this.kind = kind;
    }

    /** A generator of one random shape. */
    interface Gen {
        Shape next(Random random);
    }

    /** Does Hitbox say case i is a hit, with its second shape moved by (dx, dy)? */
    boolean hitAt(int i, float dx, float dy) {
        Shape moved = b[i].translated(dx, dy);
        switch (kind) {
            case RAY:
                return new hitbox.Ray(v[i][0], v[i][1], v[i][2], v[i][3]).cast(moved) != null;
            case APART:
                return hitbox.Separation.between(a[i], moved) != null;
            case CONTAIN:
                return a[i].contains(moved);
            case TURN: {
                float[] m = v[i];
                return hitbox.Sweep.turningTimeOfImpact((Polygon) a[i], m[0], m[1], m[2], m[3], m[4],
                        (Polygon) moved, m[5] + dx, m[6] + dy, m[7], m[8], m[9]) != null;
            }
            case SWEEP:
                if (a[i] instanceof Polygon p && !(moved instanceof Circle) && !(moved instanceof Rect)) {
                    return hitbox.Sweep.turningTimeOfImpact(p, 0, 0, v[i][0], v[i][1], 0, moved) != null;
                }
                return hitbox.Sweep.timeOfImpact(a[i], v[i][0], v[i][1], moved) != null;
            default:
                return a[i].overlaps(moved);
        }
    }

    /**
     * Is case i on the edge of Hitbox's answer: does moving the second shape by {@code step}
     * in one of eight directions change it? A peer that answers such a case the other way
     * differs by its touching rule or its skin, not by a wrong answer.
     */
    boolean borderline(int i, float step) {
        boolean here = hitAt(i, 0, 0);
        for (int k = 0; k < 8; k++) {
            double angle = k * Math.PI / 4;
            if (hitAt(i, (float) (step * Math.cos(angle)), (float) (step * Math.sin(angle))) != here) {
                return true;
            }
        }
        return false;
    }

    /**
     * How far a point of case i moves in its motion, in pixels, to turn a time into a
     * distance: the sweep's motion, or for two turning movers the bound the turning sweep
     * itself uses, |va - vb| + |turnA| Ra + |turnB| Rb (R a body's farthest vertex from its
     * pivot); 1 for the other kinds.
     */
    double scale(int i) {
        if (kind == Kind.SWEEP) {
            return Math.hypot(v[i][0], v[i][1]);
        }
        if (kind == Kind.TURN) {
            float[] m = v[i];
            return Math.hypot(m[2] - m[7], m[3] - m[8]) + Math.abs(m[4]) * reach(a[i], m[0], m[1])
                    + Math.abs(m[9]) * reach(b[i], m[5], m[6]);
        }
        return 1;
    }

    /** The size of case i, for a relative tolerance: the largest coordinate of either box, or 1. */
    double size(int i) {
        double s = 1;
        for (Shape shape : new Shape[] {a[i], b[i]}) {
            if (shape == null) continue;
            Rect r = shape.bounds();
            s = Math.max(s, Math.max(Math.max(Math.abs(r.x()), Math.abs(r.y())), Math.max(Math.abs(r.right()), Math.abs(r.bottom()))));
        }
        return s;
    }

    // ---------------------------------------------------------------- independent checks

    /**
     * Where a peer and Hitbox disagree beyond every touching rule and tolerance: an
     * independent check of case i that shares no code with Hitbox. Returns what the peer's
     * answer gets wrong when the check shows Hitbox right and the peer wrong, else null (the
     * difference then fails the run). Circle in circle: exact arithmetic (the cases' whole and
     * half numbers square exactly in double). Two turning movers: the motion sampled at 4,000
     * times, each body placed in double (turned about its pivot, moved) as a JTS polygon, and
     * JTS's relate and distance asked whether the two overlap or how far apart they are.
     */
    String verdict(int i, double[] want, double[] got, double tolerance) {
        if (kind == Kind.CONTAIN && a[i] instanceof Circle o && b[i] instanceof Circle c) {
            double dx = (double) c.x() - o.x(), dy = (double) c.y() - o.y(), room = (double) o.r() - c.r();
            boolean held = room >= 0 && dx * dx + dy * dy <= room * room;
            if (held == (want != null) && held != (got != null)) {
                return held ? "held circles it counts as not held (checked exactly)"
                        : "WRONG (checked exactly): circles not held it counts as held, by their extents on x alone";
            }
            return null;
        }
        if (kind == Kind.TURN) {
            return turnVerdict(i, want == null ? Double.NaN : want[0], got == null ? Double.NaN : got[0], tolerance);
        }
        if (kind == Kind.CONTACT && want != null && got != null && a[i] instanceof Polygon p && b[i] instanceof Polygon r
                && p.isConvex() && r.isConvex()) {
            double least = leastDepth(p.coordinates(), r.coordinates());
            if (Math.abs(want[0] - least) > tolerance || got[0] <= least + tolerance) return null;
            return got[0] <= 1.02 * least + 0.001 + tolerance
                    ? "with a face up to 2% deeper than the least (checked by separating axes in double): Box2D's bias to the first shape's face, k_relativeTol"
                    : "WRONG (checked by separating axes in double): a face more than 2% deeper than the least (its search for the deepest face stops at a local best)";
        }
        return null;
    }

    /**
     * Does a contact-points answer for case i put a point deeper than the tolerance more than
     * the tolerance outside either shape (by JTS's distance to the polygon)?
     */
    boolean pointOutside(int i, double[] m, double tolerance) {
        if (!(a[i] instanceof Polygon p) || !(b[i] instanceof Polygon r)) return false;
        org.locationtech.jts.geom.Geometry gp = NarrowPeers.jts(p), gr = NarrowPeers.jts(r);
        for (int k = 0; k < (int) m[3]; k++) {
            if (m[6 + 3 * k] <= tolerance) continue;
            org.locationtech.jts.geom.Point at = JTS.createPoint(new org.locationtech.jts.geom.Coordinate(m[4 + 3 * k], m[5 + 3 * k]));
            if (gp.distance(at) > tolerance || gr.distance(at) > tolerance) return true;
        }
        return false;
    }

    /** A verdict that the peer's answer is within the question's tolerance after all (a gap, not a time, within it). */
    static final String WITHIN_TOLERANCE = "within tolerance";

    /**
     * The least depth of two overlapping convex polygons: over every edge's normal of both, the
     * overlap of their projections, least of all (the separating axis theorem), in double.
     */
    static double leastDepth(float[] p, float[] q) {
        double least = Double.POSITIVE_INFINITY;
        for (float[] edges : new float[][] {p, q}) {
            for (int k = 0, n = edges.length / 2; k < n; k++) {
                int j = (k + 1) % n;
                double ex = (double) edges[2 * j] - edges[2 * k], ey = (double) edges[2 * j + 1] - edges[2 * k + 1], len = Math.hypot(ex, ey);
                double nx = -ey / len, ny = ex / len;
                double[] sp = span(p, nx, ny), sq = span(q, nx, ny);
                least = Math.min(least, Math.min(sp[1] - sq[0], sq[1] - sp[0]));
            }
        }
        return least;
    }

    private static double[] span(float[] xy, double nx, double ny) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < xy.length; k += 2) {
            double d = xy[k] * nx + xy[k + 1] * ny;
            lo = Math.min(lo, d);
            hi = Math.max(hi, d);
        }
        return new double[] {lo, hi};
    }

    private static final int SAMPLES = 4000;

    private String turnVerdict(int i, double hitbox, double peer, double tolerance) {
        double first = Double.NaN; // the first sampled time at which the two overlap
        for (int k = 0; k <= SAMPLES; k++) {
            double t = (double) k / SAMPLES;
            if (overlapAt(i, t)) {
                first = t;
                break;
            }
        }
        // Hitbox must not have passed an overlap, and its hit must be followed by one (else: inconclusive)
        if (!Double.isNaN(first) && (Double.isNaN(hitbox) || first < hitbox)) return null;
        if (!Double.isNaN(hitbox) && (Double.isNaN(first) || first > hitbox + 2.0 / SAMPLES) && !overlapAt(i, Math.min(1, hitbox + 1e-3))) {
            return null;
        }
        double slack = tolerance / Math.max(scale(i), 1e-9);
        if (!Double.isNaN(hitbox) && Double.isNaN(peer)) {
            return "WRONG (checked by sampling): hits it misses (the bodies overlap just after Hitbox's time)";
        }
        if (!Double.isNaN(hitbox) && peer < hitbox - slack) {
            // still apart at its time: a conservative stop; by how much is the honest measure
            double gap = gapAt(i, peer);
            return gap <= 0 ? null : gap <= tolerance ? WITHIN_TOLERANCE
                    : "times short of the contact, still over " + tolerance + " px apart at its time (checked by sampling)";
        }
        if (!Double.isNaN(hitbox) && peer > hitbox + slack) {
            return "WRONG (checked by sampling): times past the first contact (overlapping before its time)";
        }
        return null;
    }

    /** The turning body of case i (first or second) at time t, placed in double, as a JTS polygon. */
    private org.locationtech.jts.geom.Geometry posed(int i, boolean first, double t) {
        float[] m = v[i];
        int o = first ? 0 : 5;
        float[] xy = ((Polygon) (first ? a[i] : b[i])).coordinates();
        double px = m[o], py = m[o + 1], cos = Math.cos(t * m[o + 4]), sin = Math.sin(t * m[o + 4]);
        org.locationtech.jts.geom.Coordinate[] ring = new org.locationtech.jts.geom.Coordinate[xy.length / 2 + 1];
        for (int k = 0; k <= xy.length / 2; k++) {
            int j = k % (xy.length / 2);
            double x = xy[2 * j] - px, y = xy[2 * j + 1] - py;
            ring[k] = new org.locationtech.jts.geom.Coordinate(px + t * m[o + 2] + x * cos - y * sin, py + t * m[o + 3] + x * sin + y * cos);
        }
        return JTS.createPolygon(ring);
    }

    private static final org.locationtech.jts.geom.GeometryFactory JTS = new org.locationtech.jts.geom.GeometryFactory();

    /** Do the two turning bodies of case i overlap (interiors meet) at time t, by JTS? */
    private boolean overlapAt(int i, double t) {
        return posed(i, true, t).relate(posed(i, false, t), "T********");
    }

    /** How far apart the two turning bodies of case i are at time t, by JTS. */
    private double gapAt(int i, double t) {
        return org.locationtech.jts.operation.distance.DistanceOp.distance(posed(i, true, t), posed(i, false, t));
    }

    /** The farthest vertex of a polygon from (px, py). */
    static double reach(Shape s, double px, double py) {
        float[] xy = ((Polygon) s).coordinates();
        double r = 0;
        for (int k = 0; k < xy.length; k += 2) {
            r = Math.max(r, Math.hypot(xy[k] - px, xy[k + 1] - py));
        }
        return r;
    }

    // ---------------------------------------------------------------- building the cases

    /**
     * Pairs from two generators, half hits: each shape drawn in a 200 x 200 square, kept when
     * the two boxes overlap (after many tries, when the hits or misses still missing seem not
     * to exist with overlapping boxes, any pair).
     */
    static NarrowCase pairs(Kind kind, long seed, Gen first, Gen second) {
        NarrowCase q = new NarrowCase(kind);
        Random random = new Random(seed);
        int hits = 0, misses = 0, tries = 0, touching = 0;
        while (hits + misses < N) {
            tries++;
            Shape s = first.next(random), t = second.next(random);
            Rect p = s.bounds(), r = t.bounds();
            boolean boxesTouch = boxesOverlap(p, r) && !hitbox.Collide.rectRect(p.x(), p.y(), p.w(), p.h(), r.x(), r.y(), r.w(), r.h());
            if (tries < 200_000 && (!boxesOverlap(p, r) || (boxesTouch && touching == N / 16))) {
                continue;
            }
            boolean hit = s.overlaps(t);
            if (hit ? hits == N / 2 : misses == N / 2) {
                continue;
            }
            if (boxesTouch) {
                touching++;
            }
            int i = hits + misses;
            q.a[i] = s;
            q.b[i] = t;
            if (hit) hits++; else misses++;
        }
        q.fillRaw();
        return q;
    }

    /**
     * Rays at a target, half hits: the origin outside the target's box (the peers' ray
     * tests answer for a ray starting outside), aimed at a whole-number point near the box.
     */
    static NarrowCase rays(long seed, Gen target) {
        NarrowCase q = new NarrowCase(Kind.RAY);
        Random random = new Random(seed);
        int hits = 0, misses = 0;
        while (hits + misses < N) {
            Shape t = target.next(random);
            Rect box = t.bounds();
            float ox = half(random, 300) - 50, oy = half(random, 300) - 50;
            if (ox >= box.x() - 1 && ox <= box.right() + 1 && oy >= box.y() - 1 && oy <= box.bottom() + 1) {
                continue;
            }
            float tx = box.x() - 10 + random.nextInt((int) box.w() + 21);
            float ty = box.y() - 10 + random.nextInt((int) box.h() + 21);
            if (tx == ox && ty == oy) {
                continue;
            }
            float[] ray = {ox, oy, tx - ox, ty - oy};
            boolean hit = new hitbox.Ray(ray[0], ray[1], ray[2], ray[3]).cast(t) != null;
            if (hit ? hits == N / 2 : misses == N / 2) {
                continue;
            }
            int i = hits + misses;
            q.b[i] = t;
            q.v[i] = ray;
            if (hit) hits++; else misses++;
        }
        q.fillRaw();
        return q;
    }

    /**
     * Sweeps, half hits: a mover apart from the obstacle at the start (the peers' times of
     * impact start from apart), moving up to 150 pixels on each axis, whose swept box meets
     * the obstacle's box.
     */
    static NarrowCase sweeps(long seed, Gen mover, Gen obstacle) {
        NarrowCase q = new NarrowCase(Kind.SWEEP);
        Random random = new Random(seed);
        int hits = 0, misses = 0;
        while (hits + misses < N) {
            Shape s = mover.next(random), t = obstacle.next(random);
            float vx = random.nextInt(301) - 150, vy = random.nextInt(301) - 150;
            Rect from = s.bounds(), to = s.translated(vx, vy).bounds();
            float x0 = Math.min(from.x(), to.x()), y0 = Math.min(from.y(), to.y());
            Rect swept = new Rect(x0, y0, Math.max(from.right(), to.right()) - x0, Math.max(from.bottom(), to.bottom()) - y0);
            if ((vx == 0 && vy == 0) || s.overlaps(t) || !boxesOverlap(swept, t.bounds())) {
                continue;
            }
            q.a[hits + misses] = s;
            q.b[hits + misses] = t;
            q.v[hits + misses] = new float[] {vx, vy};
            boolean hit = q.hitAt(hits + misses, 0, 0);
            if (hit ? hits == N / 2 : misses == N / 2) {
                continue;
            }
            if (hit) hits++; else misses++;
        }
        q.fillRaw();
        return q;
    }

    /**
     * Pairs that do not overlap, at varied gaps, every one answered by Hitbox's separation:
     * half are random pairs whose boxes are at most 40 pixels apart; the other half are placed
     * exactly, the second shape's extreme point towards the first (a vertex, or a circle's
     * end of radius along an axis) put on the first shape's extreme point the other way (both
     * whole or half numbers, so the move is exact and the two touch), then moved on away from
     * it by a gap of 0 (1 case in 4 of those: touching, distance 0) to 40 pixels, and by up to
     * 20 pixels across.
     */
    static NarrowCase apart(long seed, Gen first, Gen second) {
        NarrowCase q = new NarrowCase(Kind.APART);
        Random random = new Random(seed);
        int i = 0;
        while (i < N) {
            Shape s = first.next(random), t = second.next(random);
            if (i % 2 == 1) {
                // 0 right, 1 down, 2 left, 3 up: t goes on that side of s
                int side = random.nextInt(4);
                float[] from = extreme(s, side), to = extreme(t, (side + 2) % 4);
                float gap = random.nextInt(4) == 0 ? 0 : half(random, 40);
                float across = gap == 0 ? 0 : half(random, 41) - 20;
                float along = side < 2 ? gap : -gap;
                float dx = from[0] - to[0] + (side % 2 == 0 ? along : across);
                float dy = from[1] - to[1] + (side % 2 == 0 ? across : along);
                t = t.translated(dx, dy);
            } else {
                Rect p = s.bounds(), r = t.bounds();
                if (Math.max(r.x() - p.right(), p.x() - r.right()) > 40 || Math.max(r.y() - p.bottom(), p.y() - r.bottom()) > 40) {
                    continue;
                }
            }
            if (hitbox.Separation.between(s, t) == null) {
                continue;
            }
            q.a[i] = s;
            q.b[i] = t;
            i++;
        }
        q.fillRaw();
        return q;
    }

    /** The point of a circle or polygon farthest to one side: 0 right (+x), 1 down (+y), 2 left, 3 up. */
    private static float[] extreme(Shape s, int side) {
        float sx = side == 0 ? 1 : side == 2 ? -1 : 0, sy = side == 1 ? 1 : side == 3 ? -1 : 0;
        if (s instanceof Circle c) {
            return new float[] {c.x() + sx * c.r(), c.y() + sy * c.r()};
        }
        float[] xy = ((Polygon) s).coordinates();
        int best = 0;
        for (int k = 2; k < xy.length; k += 2) {
            if (sx * xy[k] + sy * xy[k + 1] > sx * xy[best] + sy * xy[best + 1]) best = k;
        }
        return new float[] {xy[best], xy[best + 1]};
    }

    /** A shape to test for being inside a given one. */
    interface Inner {
        Shape next(Random random, Shape outer);
    }

    /**
     * Containment cases, half held by Hitbox's answer: an outer shape and an inner candidate
     * made near it (inside, touching its outline from inside, or partly out), whose boxes
     * overlap or touch.
     */
    static NarrowCase containing(long seed, Gen outer, Inner inner) {
        NarrowCase q = new NarrowCase(Kind.CONTAIN);
        Random random = new Random(seed);
        int yes = 0, no = 0;
        while (yes + no < N) {
            Shape s = outer.next(random), t = inner.next(random, s);
            if (t == null || !boxesOverlap(s.bounds(), t.bounds())) {
                continue;
            }
            boolean held = s.contains(t);
            if (held ? yes == N / 2 : no == N / 2) {
                continue;
            }
            q.a[yes + no] = s;
            q.b[yes + no] = t;
            if (held) yes++; else no++;
        }
        q.fillRaw();
        return q;
    }

    /** A rectangle in or near a rectangle: a side on the outer one's edge (touching from inside) in 1 case of 4 per axis. */
    static final Inner RECT_IN_RECT = (r, s) -> {
        Rect o = (Rect) s;
        float w = 1 + r.nextInt((int) o.w()), h = 1 + r.nextInt((int) o.h());
        return new Rect(place(r, o.x(), o.w(), w), place(r, o.y(), o.h(), h), w, h);
    };

    /** Where an inner span of length n goes in an outer one at x of length m: on either end, within, or a few pixels past. */
    private static float place(Random r, float x, float m, float n) {
        switch (r.nextInt(8)) {
            case 0: return x;
            case 1: return x + m - n;
            default: return x - 4 + half(r, (int) (m - n) + 9);
        }
    }

    /**
     * A circle in or near a circle: radius 1 to the outer's; in 1 case of 3 touching it from
     * inside (its centre at r1 - r2 from the outer's, along an axis or as a 3-4-5 triangle),
     * else anywhere within the outer radius of the outer centre.
     */
    static final Inner CIRCLE_IN_CIRCLE = (r, s) -> {
        Circle o = (Circle) s;
        int r1 = (int) o.r(), r2 = 1 + r.nextInt(r1);
        float dx, dy;
        if (r.nextInt(3) == 0) {
            int d = r1 - r2;
            if (d % 5 == 0 && r.nextBoolean()) {
                dx = (r.nextBoolean() ? 3 : -3) * d / 5f;
                dy = (r.nextBoolean() ? 4 : -4) * d / 5f;
            } else {
                int side = r.nextInt(4);
                dx = side == 0 ? d : side == 2 ? -d : 0;
                dy = side == 1 ? d : side == 3 ? -d : 0;
            }
        } else {
            dx = half(r, r1) * (r.nextBoolean() ? 1 : -1);
            dy = half(r, r1) * (r.nextBoolean() ? 1 : -1);
        }
        return new Circle(o.x() + dx, o.y() + dy, r2);
    };

    /**
     * A convex polygon in or near a convex 8-gon: half are 3 to 7 of its own vertices (inside,
     * touching its outline from inside at those vertices and along the edges they keep), half
     * the 8-gon shrunk by half towards its centroid and rounded to half pixels; each, in 1
     * case of 2, then moved by up to 3 pixels on each axis.
     */
    static final Inner POLY_IN_POLY = (r, s) -> {
        float[] xy = ((Polygon) s).coordinates();
        int n = xy.length / 2;
        float[] in;
        if (r.nextBoolean()) {
            int keep = 3 + r.nextInt(n - 3);
            boolean[] kept = new boolean[n];
            for (int k = 0; k < keep; k++) {
                int j;
                do {
                    j = r.nextInt(n);
                } while (kept[j]);
                kept[j] = true;
            }
            in = new float[2 * keep];
            for (int k = 0, m = 0; k < n; k++) {
                if (!kept[k]) continue;
                in[m++] = xy[2 * k];
                in[m++] = xy[2 * k + 1];
            }
        } else {
            hitbox.Vec c = ((Polygon) s).centroid();
            in = new float[2 * n];
            for (int k = 0; k < n; k++) {
                in[2 * k] = Math.round(c.x() + xy[2 * k]) / 2f;
                in[2 * k + 1] = Math.round(c.y() + xy[2 * k + 1]) / 2f;
            }
        }
        if (r.nextBoolean()) {
            float dx = half(r, 7) - 3, dy = half(r, 7) - 3;
            for (int k = 0; k < in.length; k += 2) {
                in[k] += dx;
                in[k + 1] += dy;
            }
        }
        try {
            Polygon p = Polygon.of(in);
            return p.isConvex() ? p : null;
        } catch (IllegalArgumentException e) {
            return null; // a degenerate shrink: draw another
        }
    };

    /**
     * Two convex 8-gons that both move (up to 100 pixels on each axis) and turn (up to 1
     * radian either way) about their centroids (rounded to floats), apart by more than a
     * pixel at the start, and half hits by Hitbox's answer; the bodies' paths come within
     * reach of each other.
     */
    static NarrowCase turning(long seed) {
        NarrowCase q = new NarrowCase(Kind.TURN);
        Random random = new Random(seed);
        int hits = 0, misses = 0;
        while (hits + misses < N) {
            Polygon s = (Polygon) OCTAGON.next(random), t = (Polygon) OCTAGON.next(random);
            hitbox.Vec cs = s.centroid(), ct = t.centroid();
            float[] m = {cs.x(), cs.y(), random.nextInt(201) - 100, random.nextInt(201) - 100, (float) (2 * random.nextDouble() - 1),
                ct.x(), ct.y(), random.nextInt(201) - 100, random.nextInt(201) - 100, (float) (2 * random.nextDouble() - 1)};
            // the closest approach of the pivots, moving straight, within the two reaches (and 20 pixels)
            double rx = (double) ct.x() - cs.x(), ry = (double) ct.y() - cs.y(), wx = m[7] - m[2], wy = m[8] - m[3];
            double w2 = wx * wx + wy * wy, u = w2 == 0 ? 0 : Math.max(0, Math.min(1, -(rx * wx + ry * wy) / w2));
            double closest = Math.hypot(rx + u * wx, ry + u * wy);
            hitbox.Separation gap = hitbox.Separation.between(s, t);
            if (gap == null || gap.distance() <= 1 || closest > reach(s, cs.x(), cs.y()) + reach(t, ct.x(), ct.y()) + 20) {
                continue;
            }
            int i = hits + misses;
            q.a[i] = s;
            q.b[i] = t;
            q.v[i] = m;
            boolean hit = q.hitAt(i, 0, 0);
            if (hit ? hits == N / 2 : misses == N / 2) {
                continue;
            }
            if (hit) hits++; else misses++;
        }
        q.fillRaw();
        return q;
    }

    /**
     * Turned boxes: a rectangle of 10 to 70 by 10 to 70 pixels about a whole or half-pixel
     * centre, square to the axes in 1 case of 4, else turned by a random angle (so some
     * boxes lie face to face, two contact points, and some corner first).
     */
    static final Gen BOX = r -> {
        float cx = half(r, 200), cy = half(r, 200);
        Rect box = Rect.centered(cx, cy, 10 + r.nextInt(61), 10 + r.nextInt(61));
        return Polygon.of(box).rotated(r.nextInt(4) == 0 ? 0 : (float) (r.nextDouble() * Math.PI), cx, cy);
    };

    /**
     * The broad phase's test, closed as most broad phases are, so that touching pairs (and a
     * point on an outline) reach the narrow phase. On raw floats: through {@code Shape.overlaps}
     * it would teach the JIT a rectangle pair at the call site the shape contenders are timed
     * through.
     */
    private static boolean boxesOverlap(Rect p, Rect q) {
        return p.x() <= q.right() && q.x() <= p.right() && p.y() <= q.bottom() && q.y() <= p.bottom();
    }

    private void fillRaw() {
        for (int i = 0; i < N; i++) {
            ra[i] = a[i] == null ? null : raw(a[i]);
            rb[i] = raw(b[i]);
        }
    }

    /** A shape's floats as Collide takes them: a polygon's coordinates, a point's x and y. */
    static float[] raw(Shape s) {
        if (s instanceof Circle c) return new float[] {c.x(), c.y(), c.r()};
        if (s instanceof Rect r) return new float[] {r.x(), r.y(), r.w(), r.h()};
        if (s instanceof Segment g) {
            return g.x1() == g.x2() && g.y1() == g.y2() ? new float[] {g.x1(), g.y1()} : new float[] {g.x1(), g.y1(), g.x2(), g.y2()};
        }
        if (s instanceof Ellipse e) return new float[] {e.x(), e.y(), e.rx(), e.ry()};
        if (s instanceof Capsule k) return new float[] {k.x1(), k.y1(), k.x2(), k.y2(), k.r()};
        return ((Polygon) s).coordinates();
    }

    // ---------------------------------------------------------------- the shape generators

    /** A whole or half number in [0, range). */
    static float half(Random random, int range) {
        return random.nextInt(2 * range) / 2f;
    }

    static final Gen CIRCLE = r -> new Circle(half(r, 200), half(r, 200), 5 + r.nextInt(40));
    static final Gen RECT = r -> new Rect(half(r, 200), half(r, 200), 5 + r.nextInt(60), 5 + r.nextInt(60));
    static final Gen POINT = r -> {
        float x = half(r, 200), y = half(r, 200);
        return new Segment(x, y, x, y);
    };
    static final Gen SEGMENT = r -> {
        float x = half(r, 200), y = half(r, 200);
        return new Segment(x, y, x + r.nextInt(121) - 60, y + r.nextInt(121) - 60 + 0.5f);
    };
    static final Gen ELLIPSE = r -> new Ellipse(half(r, 200), half(r, 200), 5 + r.nextInt(40), 5 + r.nextInt(40));
    static final Gen CAPSULE = r -> {
        float x = half(r, 200), y = half(r, 200);
        return new Capsule(x, y, x + r.nextInt(81) - 40, y + r.nextInt(81) - 40 + 0.5f, 3 + r.nextInt(20));
    };
    static final Gen TRIANGLE = r -> {
        while (true) {
            float x = half(r, 200), y = half(r, 200);
            float[] xy = {x, y, x + r.nextInt(61) - 30, y + r.nextInt(61) - 30, x + r.nextInt(61) - 30, y + r.nextInt(61) - 30};
            if ((xy[2] - x) * (xy[5] - y) != (xy[3] - y) * (xy[4] - x)) {
                return Polygon.of(xy);
            }
        }
    };
    /** A convex 8-gon: eight sorted random angles on a circle, rounded to half pixels. */
    static final Gen OCTAGON = r -> ring(r, 8, false);
    /** A concave 16-gon: a star whose inner corners are at 40 to 70% of the outer radius. */
    static final Gen STAR16 = r -> ring(r, 16, true);

    private static Polygon ring(Random r, int sides, boolean star) {
        while (true) {
            float cx = half(r, 200), cy = half(r, 200), radius = 15 + r.nextInt(35);
            double[] angles = new double[sides];
            for (int k = 0; k < sides; k++) {
                angles[k] = star ? (k + 0.3 * r.nextDouble()) * 2 * Math.PI / sides : r.nextDouble() * 2 * Math.PI;
            }
            java.util.Arrays.sort(angles);
            float[] xy = new float[2 * sides];
            for (int k = 0; k < sides; k++) {
                double rk = star && k % 2 == 1 ? radius * (0.4 + 0.3 * r.nextDouble()) : radius;
                xy[2 * k] = Math.round(2 * (cx + rk * Math.cos(angles[k]))) / 2f;
                xy[2 * k + 1] = Math.round(2 * (cy + rk * Math.sin(angles[k]))) / 2f;
            }
            try {
                Polygon p = Polygon.of(xy);
                if (p.isConvex() != star && p.area() > 50 && distinctAngles(angles)) {
                    return p;
                }
            } catch (IllegalArgumentException e) {
                // a degenerate ring: draw another
            }
        }
    }

    /** Corners at least 0.2 radians apart, so rounding cannot fold an edge back. */
    private static boolean distinctAngles(double[] sorted) {
        for (int k = 1; k < sorted.length; k++) {
            if (sorted[k] - sorted[k - 1] < 0.2) return false;
        }
        return 2 * Math.PI - sorted[sorted.length - 1] + sorted[0] >= 0.2;
    }
}
