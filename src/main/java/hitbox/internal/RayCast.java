package hitbox.internal;

import hitbox.*;

import java.util.Arrays;

/**
 * One ray cast of a broad phase ({@link BroadPhase#raycast}): the structure hands it candidate
 * slots, it measures each one with {@link Ray#distanceToRect}, then visits the hits sorted by
 * distance and id. The structures prune with {@link #mayEnter}, {@link #enter} and
 * {@link #exit}.
 *
 * <p>A class of its own, apart from {@link AbstractBroadPhase}, because the region tests are
 * the ray's geometry, the same for every structure; only {@link #consider} reads the stored
 * boxes, through the broad phase it was made for.
 */
public final class RayCast {
    /** The broad phase whose boxes this cast measures. */
    private final AbstractBroadPhase phase;
    public float ox;
    public float oy;
    public float dx;
    public float dy;
    private float maxDistance;
    /** How far the ray reaches in units of (dx, dy); infinite for an endless ray. */
    public double limit;
    private long[] hits = new long[16];
    private int hitCount;

    public RayCast(AbstractBroadPhase phase) {
        this.phase = phase;
    }

    public void run(Ray ray, RayVisitor out) {
        ox = ray.ox();
        oy = ray.oy();
        dx = ray.dx();
        dy = ray.dy();
        maxDistance = ray.maxDistance();
        limit = limit(dx, dy, maxDistance);
        hitCount = 0;
        phase.findRayCandidates(this);
        // A distance is 0 or more, so its bits sort as the distance does; the id breaks ties.
        Arrays.sort(hits, 0, hitCount);
        for (int i = 0; i < hitCount; i++) {
            long key = hits[i];
            if (!out.hit((int) key, Float.intBitsToFloat((int) (key >>> 32)))) {
                break;
            }
        }
    }

    /** Measures the box in a slot and keeps it if the ray goes into it. */
    public void consider(int slot) {
        phase.tally++;
        double[] box = phase.box;
        float d = rectDistance(ox, oy, dx, dy, maxDistance,
                (float) box[4 * slot], (float) box[4 * slot + 2], phase.ws[slot], phase.hs[slot]);
        if (d != Float.POSITIVE_INFINITY) {
            if (hitCount == hits.length) {
                hits = Arrays.copyOf(hits, hitCount * 2);
            }
            hits[hitCount++] = (long) Float.floatToRawIntBits(d) << 32 | phase.ids[slot];
        }
    }

    /**
     * Could the ray go into anything inside this region (edges included)? Conservative: the
     * region is widened by a hair so rounding never turns a hit away; the exact answer is
     * {@link #consider}'s.
     */
    public boolean mayEnter(double minX, double minY, double maxX, double maxY) {
        return enter(minX, minY, maxX, maxY) <= exit(minX, minY, maxX, maxY);
    }

    /** Where (in units of the direction) the ray enters the widened region, at least 0. */
    public double enter(double minX, double minY, double maxX, double maxY) {
        double padX = pad(minX, maxX), padY = pad(minY, maxY);
        return Math.max(0, Math.max(slabIn(minX - padX, maxX + padX, ox, dx), slabIn(minY - padY, maxY + padY, oy, dy)));
    }

    /** Where (in units of the direction) the ray leaves the widened region, at most its reach. */
    public double exit(double minX, double minY, double maxX, double maxY) {
        double padX = pad(minX, maxX), padY = pad(minY, maxY);
        return Math.min(limit, Math.min(slabOut(minX - padX, maxX + padX, ox, dx), slabOut(minY - padY, maxY + padY, oy, dy)));
    }

    private static double pad(double lo, double hi) {
        return Tolerance.pad(lo, hi);
    }

    private static double slabIn(double lo, double hi, float o, float d) {
        if (d == 0) {
            return lo <= o && o <= hi ? Double.NEGATIVE_INFINITY : Double.POSITIVE_INFINITY;
        }
        return d > 0 ? (lo - o) / d : (hi - o) / d;
    }

    private static double slabOut(double lo, double hi, float o, float d) {
        if (d == 0) {
            return lo <= o && o <= hi ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        }
        return d > 0 ? (hi - o) / d : (lo - o) / d;
    }

    /** How far the ray reaches in units of its direction; exactly 1 when it ends at (ox + dx, oy + dy). */
    public static double limit(float dx, float dy, float maxDistance) {
        if (maxDistance == Float.POSITIVE_INFINITY) {
            return Slabs.INF;
        }
        double length = length(dx, dy);
        return maxDistance == (float) length ? 1 : maxDistance / length;
    }

    /**
     * The direction's length: in double the squares of floats are exact and their sum cannot
     * overflow or underflow, so a plain square root is as good as {@link Math#hypot} here, at
     * a third of its cost.
     */
    public static double length(double dx, double dy) {
        return Math.sqrt(dx * dx + dy * dy);
    }

    /**
     * How far along a checked ray (finite, not of length 0) its origin is from the rectangle,
     * +Infinity if it misses within {@code maxDistance}; 0 from inside: the body of
     * {@code Ray.distanceToRect}, which checks the arguments first.
     */
    public static float rectDistance(float ox, float oy, float dx, float dy, float maxDistance,
                                     float rx, float ry, float rw, float rh) {
        double s = RawTests.rectPoint(rx, ry, rw, rh, ox, oy) ? 0
                : Slabs.boxTime((double) rx - ox, (double) rx + rw - ox, (double) ry - oy, (double) ry + rh - oy,
                        dx, dy, limit(dx, dy, maxDistance));
        return distance(s, dx, dy);
    }

    /** A ray parameter (in units of the direction) as a distance in float; +Infinity for {@link Slabs#INF}. */
    public static float distance(double s, float dx, float dy) {
        return s == Slabs.INF ? Float.POSITIVE_INFINITY : (float) (s * length(dx, dy));
    }
}