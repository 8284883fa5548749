package hitbox;

import hitbox.internal.Extents;
import hitbox.internal.PlacedOverlaps;
import hitbox.internal.Placement;

import java.util.Comparator;
import java.util.List;
import java.util.function.Predicate;

/**
 * The queries of a {@link World}: what a point, a shape, a body and a ray meet, each answer
 * put into the caller's list. The candidates come from the world's broad phase
 * ({@code World.gather}, {@code World.rayCandidates}), a grid's body is answered by the
 * {@link GridCollider}, and the filter is asked through the world ({@code World.keep}), which
 * keeps it from changing the world. Nothing is made but the answers (and a ray's hits).
 */
final class WorldQueries {

    /** Ray hits by distance, equal distances in the order the bodies were added. */
    private static final Comparator<BodyHit> NEAREST = (p, q) -> p.distance() != q.distance()
            ? Float.compare(p.distance(), q.distance()) : Integer.compare(p.body().serial, q.body().serial);

    private final World world;
    private final GridCollider grids;
    /** A shape query's shape as numbers (see {@link #meets}); read only during the query. */
    private final Placement probe = new Placement();

    WorldQueries(World world, GridCollider grids) {
        this.world = world;
        this.grids = grids;
    }

    /** The bodies the filter keeps whose shape holds a point, added to out in the order added. */
    void point(float x, float y, Predicate<Body> filter, List<Body> out) {
        world.gather(x, y, x, y);
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body b = world.candidate(i);
            boolean in = b.grid != null ? grids.holds(b.grid, x, y) : b.shape().contains(x, y);
            if (in && world.keep(filter, b)) {
                out.add(b);
            }
        }
    }

    /** The bodies the filter keeps (not {@code except}) whose shape overlaps a shape, added to out in the order added. */
    void shape(Shape shape, Body except, Predicate<Body> filter, List<Body> out) {
        Placement q = probe.of(shape) ? probe : null;
        world.gather(Extents.minX(shape), Extents.minY(shape), Extents.maxX(shape), Extents.maxY(shape));
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body b = world.candidate(i);
            if (b == except) {
                continue;
            }
            boolean meets = b.grid != null ? grids.meets(b.grid, shape) : meets(b, q, shape);
            if (meets && world.keep(filter, b)) {
                out.add(b);
            }
        }
    }

    /**
     * Does a body (not a grid's) overlap a shape, given as numbers too where it can be (q, or
     * null)? On the numbers where both have them, so a body that moved makes no shape for it,
     * as in the world's pair tests.
     */
    private static boolean meets(Body b, Placement q, Shape shape) {
        Placement p = q == null ? null : b.placement();
        return p != null ? PlacedOverlaps.test(p, q) : b.shape().overlaps(shape);
    }

    /** The bodies the filter keeps that a body overlaps now, added to out in the order added. */
    void overlapping(Body body, Predicate<Body> filter, List<Body> out) {
        // The body's tight box (at or a hair outside its shape) gathers; the pair test a step
        // makes decides (on the bodies' numbers where they have them: no shape made).
        world.gather(body.boxX, body.boxY, (double) body.boxX + body.boxW, (double) body.boxY + body.boxH);
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body b = world.candidate(i);
            if (b != body && world.overlap(body, b) && world.keep(filter, b)) {
                out.add(b);
            }
        }
    }

    /**
     * The hits of a ray on the bodies the filter keeps, nearest first, added to out; with
     * {@code firstOnly} the nearest alone.
     */
    void ray(Ray ray, Predicate<Body> filter, boolean firstOnly, List<BodyHit> out) {
        int from = out.size();
        world.rayCandidates(ray);
        BodyHit nearest = null;
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body b = world.candidate(i);
            BodyHit hit;
            if (b.grid != null) {
                hit = grids.ray(b, b.grid, ray);
            } else {
                RayHit h = ray.cast(b.shape());
                hit = h == null ? null : new BodyHit(b, h, -1);
            }
            if (hit != null && world.keep(filter, b)) {
                if (firstOnly) {
                    if (nearest == null || NEAREST.compare(hit, nearest) < 0) {
                        nearest = hit;
                    }
                } else {
                    out.add(hit);
                }
            }
        }
        if (firstOnly) {
            if (nearest != null) {
                out.add(nearest);
            }
        } else if (out.size() - from > 1) {
            if (from == 0) {
                out.sort(NEAREST);
            } else {
                out.subList(from, out.size()).sort(NEAREST);
            }
        }
    }
}
