package hitbox.bench;

import java.util.Random;

import hitbox.Circle;
import hitbox.Ellipse;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Shape;

/**
 * The world benchmark's scene, after detect-collisions' stress test ({@code src/demo/stress.js}):
 * n bodies in 1024 x 768, a fifth each circles, ellipses, boxes, lines and four-sided polygons,
 * their sizes from {@code sqrt(1024 * 768 / (50 n))} (so the bodies cover about the same share of
 * the screen at every n: 3.97 px at 1,000 bodies, 1.25 at 10,000, 0.40 at 100,000), each with a
 * random angle and direction. About 5% stand still (placed so that no two of them overlap, so
 * every engine's rule for pairs of standing bodies gives the same answer); of the others, every
 * other one turns by up to 0.05 radians a frame, and every one moves 0.5 px a frame (the stress
 * test's speed of 1 at its time scale of 0.5), turning back from the screen's edges. One frame:
 * {@link #step()}, then the contenders find every overlapping pair.
 *
 * <p>Unlike the stress test, the bodies bounce off the screen's edges only, not off each other:
 * then the motion does not depend on anyone's answers, so every contender sees the very same
 * frames, and the benchmark times detection alone, with no response.
 *
 * <p>Each body's shape is kept in its own frame (centred on the body: the stress test's
 * {@code center: true}); a body at (x, y) turned by a has the shape turned by a about its origin
 * then moved by (x, y), as Processing's {@code translate(x, y); rotate(a);} draws it.
 */
final class WorldScene {
    static final float WIDTH = 1024;
    static final float HEIGHT = 768;
    static final int CIRCLE = 0;
    static final int ELLIPSE = 1;
    static final int BOX = 2;
    static final int LINE = 3;
    static final int POLYGON = 4;

    final int n;
    /** The stress test's size unit: the smallest body is about this big. */
    final float size;
    final int[] kind;
    /** Circle: radius. Ellipse: the two radii. Box: width and height. Line: the half extents (end at +-). */
    final float[] p;
    final float[] q;
    /** A polygon's four corners in its own frame, x0, y0, ... x3, y3, counter-clockwise in y-up terms; null for the others. */
    final float[][] corners;
    final float[] x;
    final float[] y;
    final float[] angle;
    final float[] vx;
    final float[] vy;
    final float[] spin;
    final boolean[] standing;
    /** The largest distance from a body's origin to a point of its shape (for the checks and the placing). */
    final float[] reach;

    WorldScene(int n, long seed) {
        this.n = n;
        size = (float) Math.sqrt(WIDTH * HEIGHT / (n * 50.0));
        kind = new int[n];
        p = new float[n];
        q = new float[n];
        corners = new float[n][];
        x = new float[n];
        y = new float[n];
        angle = new float[n];
        vx = new float[n];
        vy = new float[n];
        spin = new float[n];
        standing = new boolean[n];
        reach = new float[n];
        Random random = new Random(seed);
        StandingPlaces places = new StandingPlaces(size);
        for (int i = 0; i < n; i++) {
            kind[i] = i % 5;
            float lo = size, hi = 1.25f * size;
            switch (kind[i]) {
                case CIRCLE -> {
                    p[i] = between(random, lo, hi);
                    reach[i] = p[i];
                }
                case ELLIPSE -> {
                    p[i] = between(random, lo, hi);
                    q[i] = between(random, lo, hi);
                    reach[i] = Math.max(p[i], q[i]);
                }
                case BOX -> {
                    p[i] = between(random, lo, hi);
                    q[i] = between(random, lo, hi);
                    reach[i] = (float) Math.hypot(p[i] / 2, q[i] / 2);
                }
                case LINE -> {
                    p[i] = between(random, lo, hi) / 2;
                    q[i] = between(random, lo, hi) / 2;
                    reach[i] = (float) Math.hypot(p[i], q[i]);
                }
                default -> {
                    corners[i] = quad(random, lo, hi);
                    float r = 0;
                    for (int k = 0; k < 8; k += 2) {
                        r = Math.max(r, (float) Math.hypot(corners[i][k], corners[i][k + 1]));
                    }
                    reach[i] = r;
                }
            }
            standing[i] = random.nextFloat() < 0.05f;
            do {
                x[i] = random.nextFloat() * WIDTH;
                y[i] = random.nextFloat() * HEIGHT;
            } while (standing[i] && !places.free(x[i], y[i], reach[i]));
            if (standing[i]) {
                places.add(x[i], y[i], reach[i]);
            }
            angle[i] = (float) (2 * Math.PI * random.nextDouble());
            double direction = 2 * Math.PI * random.nextDouble();
            if (!standing[i]) {
                vx[i] = (float) (0.5 * Math.cos(direction));
                vy[i] = (float) (0.5 * Math.sin(direction));
                spin[i] = i % 2 == 1 ? (random.nextFloat() - random.nextFloat()) * 0.05f : 0;
            }
        }
    }

    private static float between(Random random, float lo, float hi) {
        return lo + random.nextFloat() * (hi - lo);
    }

    /**
     * The stress test's polygon: a corner in each quadrant, {@code (-a, b), (c, d), (e, -f),
     * (-g, -h)} with each number between the two sizes, drawn again until convex (dyn4j and
     * JBox2D take convex polygons only), then centred on the corners' mean.
     */
    private static float[] quad(Random random, float lo, float hi) {
        while (true) {
            float[] c = {
                -between(random, lo, hi), between(random, lo, hi),
                between(random, lo, hi), between(random, lo, hi),
                between(random, lo, hi), -between(random, lo, hi),
                -between(random, lo, hi), -between(random, lo, hi),
            };
            // In y-up terms these corners go clockwise; turn them round, counter-clockwise as dyn4j asks.
            float[] ccw = {c[6], c[7], c[4], c[5], c[2], c[3], c[0], c[1]};
            if (convex(ccw)) {
                float mx = (ccw[0] + ccw[2] + ccw[4] + ccw[6]) / 4, my = (ccw[1] + ccw[3] + ccw[5] + ccw[7]) / 4;
                for (int k = 0; k < 8; k += 2) {
                    ccw[k] -= mx;
                    ccw[k + 1] -= my;
                }
                return ccw;
            }
        }
    }

    /** Every turn a left turn (counter-clockwise in y-up terms), by a clear margin. */
    private static boolean convex(float[] c) {
        for (int k = 0; k < 8; k += 2) {
            double ax = c[(k + 2) % 8] - c[k], ay = c[(k + 3) % 8] - c[k + 1];
            double bx = c[(k + 4) % 8] - c[(k + 2) % 8], by = c[(k + 5) % 8] - c[(k + 3) % 8];
            if (ax * by - ay * bx <= 0.05 * Math.hypot(ax, ay) * Math.hypot(bx, by)) {
                return false;
            }
        }
        return true;
    }

    /** One frame of motion: every moving body moves, turns back from an edge its centre went past, and every other one turns. */
    void step() {
        for (int i = 0; i < n; i++) {
            float nx = x[i] + vx[i], ny = y[i] + vy[i];
            if (nx < 0 || nx > WIDTH) {
                vx[i] = -vx[i];
            } else {
                x[i] = nx;
            }
            if (ny < 0 || ny > HEIGHT) {
                vy[i] = -vy[i];
            } else {
                y[i] = ny;
            }
            float a = angle[i] + spin[i];
            // Kept within a turn, so the float angle keeps its precision however long the run.
            angle[i] = a > (float) Math.PI ? a - (float) (2 * Math.PI) : a < (float) -Math.PI ? a + (float) (2 * Math.PI) : a;
        }
    }

    boolean moves(int i) {
        return !standing[i];
    }

    /** Body i's shape where it stands now, as a new Hitbox shape (what a sketch without a world makes every frame). */
    Shape shape(int i) {
        float cx = x[i], cy = y[i], a = angle[i];
        switch (kind[i]) {
            case CIRCLE:
                return new Circle(cx, cy, p[i]);
            case ELLIPSE:
                return new Ellipse(cx, cy, p[i], q[i], a);
            case BOX:
                return Polygon.of(Rect.centered(cx, cy, p[i], q[i])).rotated(a, cx, cy);
            case LINE: {
                double cos = Math.cos(a), sin = Math.sin(a);
                double ex = p[i] * cos - q[i] * sin, ey = p[i] * sin + q[i] * cos;
                return new Segment((float) (cx - ex), (float) (cy - ey), (float) (cx + ex), (float) (cy + ey));
            }
            default: {
                double cos = Math.cos(a), sin = Math.sin(a);
                float[] c = corners[i], xy = new float[8];
                for (int k = 0; k < 8; k += 2) {
                    xy[k] = (float) (cx + c[k] * cos - c[k + 1] * sin);
                    xy[k + 1] = (float) (cy + c[k] * sin + c[k + 1] * cos);
                }
                return Polygon.of(xy);
            }
        }
    }

    /** The standing bodies placed so far, in a coarse grid of their bounding circles, so that no two overlap. */
    private static final class StandingPlaces {
        private final float cell;
        private final java.util.Map<Long, java.util.List<float[]>> cells = new java.util.HashMap<>();

        StandingPlaces(float size) {
            cell = 4 * size;
        }

        boolean free(float px, float py, float r) {
            long cx = (long) Math.floor(px / cell), cy = (long) Math.floor(py / cell);
            for (long a = cx - 1; a <= cx + 1; a++) {
                for (long b = cy - 1; b <= cy + 1; b++) {
                    for (float[] other : cells.getOrDefault(a * 1_000_003L + b, java.util.List.of())) {
                        if (Math.hypot(px - other[0], py - other[1]) <= r + other[2] + 1e-3 * cell) {
                            return false;
                        }
                    }
                }
            }
            return true;
        }

        void add(float px, float py, float r) {
            long key = (long) Math.floor(px / cell) * 1_000_003L + (long) Math.floor(py / cell);
            cells.computeIfAbsent(key, k -> new java.util.ArrayList<>()).add(new float[] {px, py, r});
        }
    }
}
