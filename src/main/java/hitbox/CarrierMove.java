package hitbox;

import java.util.Arrays;

/**
 * A carrier's move ({@link Body#carrier(boolean)}): the bodies standing on it found, the
 * carrier and they moved in the order that keeps them on it (the riders first when it goes
 * up, after it otherwise), and everything put back when a filter refuses the move. Its
 * riders, the filter that lets them through and the places to put back are kept from move to
 * move, so a platform that moves every frame makes nothing but what its move hands back.
 *
 * <p>Owned by one {@link World}; a move is never asked from inside another (the world refuses
 * moves from its callbacks), so one set of scratch serves.
 */
final class CarrierMove {
    private final World world;
    private final BodyTable table;
    private final ContactTracker tracker;

    /** The riders of the move under way, and how many. */
    private Body[] riders = new Body[4];
    private int riderCount;
    /** The carrier and a candidate rider as they stand, and a probe's hit (t, nx, ny). */
    private final Spot carrier = new Spot(), rider = new Spot();
    private final float[] probeHit = new float[3];

    /** Each moved body's place before the move, to put back: the carrier's first, then each rider's. */
    private Spot[] keptSpot = Spot.grown(new Spot[0], 5);
    private double[] keptTx = new double[5], keptTy = new double[5];
    private float[] keptBox = new float[40];
    private boolean[] keptDirty = new boolean[5];

    /** The carrier's own filter, for {@link #passRiders}, during a move. */
    private CollisionFilter filter;
    /** The carrier's filter with its riders let through (they move with it): made once. */
    private final CollisionFilter passRiders = (m, o) -> isRider(o) ? null : filter.react(m, o);

    CarrierMove(World world, BodyTable table, ContactTracker tracker) {
        this.world = world;
        this.table = table;
        this.tracker = tracker;
    }

    /** A carrier's move, checked already: the riders go first when it goes up, after it otherwise. */
    Collisions move(Body p, float dx, float dy, CollisionFilter filter) {
        findRiders(p);
        grow(riderCount + 1);
        keep(0, p);
        for (int i = 0; i < riderCount; i++) {
            keep(i + 1, riders[i]);
        }
        this.filter = filter;
        world.holdCollisions();
        table.holdFlush = true;
        try {
            Collisions out;
            float px = p.pivotX(), py = p.pivotY();
            if (dy < 0) {
                for (int i = 0; i < riderCount; i++) {
                    world.moveRider(riders[i], dx, dy);
                }
                out = world.moveOne(p, dx, dy, filter);  // a rider a ceiling stopped stops it too
                // Stopped short (a ceiling): the riders come back down with it.
                float cx = p.pivotX() - px - dx, cy = p.pivotY() - py - dy;
                if (cx != 0 || cy != 0) {
                    for (int i = 0; i < riderCount; i++) {
                        world.moveRider(riders[i], cx, cy);
                    }
                }
            } else {
                out = world.moveOne(p, dx, dy, passRiders);
                float ax = p.pivotX() - px, ay = p.pivotY() - py;
                for (int i = 0; i < riderCount; i++) {
                    world.moveRider(riders[i], ax, ay);
                }
            }
            world.releaseCollisions();
            table.holdFlush = false;
            table.flushIfMany();
            return out;
        } catch (RuntimeException e) {
            putBack(0, p);
            for (int i = 0; i < riderCount; i++) {
                putBack(i + 1, riders[i]);
            }
            world.dropHeldCollisions();
            throw e;
        } finally {
            table.holdFlush = false;
            this.filter = null;
            Arrays.fill(riders, 0, riderCount, null);  // no body kept alive by the scratch
            riderCount = 0;
        }
    }

    /**
     * The bodies standing on a carrier now, into {@link #riders}: touching its top from above
     * (a drop of a hundredth of a pixel would land them on it), layers accepting, not
     * sensors, grids or carriers. Asked of their places as numbers where they are boxes or
     * circles ({@link Spot}), so nothing is made.
     */
    private void findRiders(Body p) {
        riderCount = 0;
        carrier.set(p);
        float probe = 2 * Mover.SKIN;
        world.gather(p.boxX, p.boxY - 2 * probe, (double) p.boxX + p.boxW, (double) p.boxY + p.boxH);
        for (int i = 0, n = world.candidateCount(); i < n; i++) {
            Body o = world.candidate(i);
            if (o == p || o.grid != null || o.sensor || o.carrier || !p.accepts(o)) {
                continue;
            }
            rider.set(o);
            if (rider.overlaps(carrier)) {
                continue;
            }
            if (rider.sweep(0, probe, carrier, probeHit) == Side.TOP) {
                if (riderCount == riders.length) {
                    riders = Arrays.copyOf(riders, 2 * riderCount);
                }
                riders[riderCount++] = o;
            }
        }
    }

    private boolean isRider(Body o) {
        for (int i = 0; i < riderCount; i++) {
            if (riders[i] == o) {
                return true;
            }
        }
        return false;
    }

    /** Room to keep n bodies' places. */
    private void grow(int n) {
        if (keptSpot.length < n) {
            int m = Math.max(n, 2 * keptSpot.length);
            keptSpot = Spot.grown(keptSpot, m);
            keptTx = Arrays.copyOf(keptTx, m);
            keptTy = Arrays.copyOf(keptTy, m);
            keptBox = Arrays.copyOf(keptBox, 8 * m);
            keptDirty = Arrays.copyOf(keptDirty, m);
        }
    }

    /** Keeps a body's place (its translation, where it stands, its boxes) in slot i. */
    private void keep(int i, Body b) {
        keptSpot[i].set(b);
        keptTx[i] = b.tx;
        keptTy[i] = b.ty;
        int k = 8 * i;
        keptBox[k] = b.boxX;
        keptBox[k + 1] = b.boxY;
        keptBox[k + 2] = b.boxW;
        keptBox[k + 3] = b.boxH;
        keptBox[k + 4] = b.fatX;
        keptBox[k + 5] = b.fatY;
        keptBox[k + 6] = b.fatW;
        keptBox[k + 7] = b.fatH;
        keptDirty[i] = b.dirtyIndex >= 0;
    }

    /** Puts a body back as kept in slot i; no flush happened meanwhile, so the broad phase is as it was. */
    private void putBack(int i, Body b) {
        keptSpot[i].placeInto(b, keptTx[i], keptTy[i]);
        int k = 8 * i;
        table.box(b, keptBox[k], keptBox[k + 1], keptBox[k + 2], keptBox[k + 3]);
        b.fat(keptBox[k + 4], keptBox[k + 5], keptBox[k + 6], keptBox[k + 7]);
        if (!keptDirty[i] && b.dirtyIndex >= 0) {
            table.undirty(b);
        }
        tracker.changed(b);
    }
}
