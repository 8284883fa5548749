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

    /** What kind of answer the question asks for; the agreement check and the nudge use it. */
    enum Kind { OVERLAP, CONTACT, RAY, SWEEP }

    final Kind kind;
    /** The first shape (the mover of a sweep); null for rays. */
    final Shape[] a = new Shape[N];
    /** The second shape (the target of a ray, the obstacle of a sweep). */
    final Shape[] b = new Shape[N];
    /** The ray's origin and direction (ox, oy, dx, dy) or the sweep's motion (vx, vy); else null. */
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
