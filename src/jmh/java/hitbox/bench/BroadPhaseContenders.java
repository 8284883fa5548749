package hitbox.bench;

import java.util.Iterator;

import hitbox.BroadPhase;
import hitbox.PairConsumer;
import org.dyn4j.collision.CollisionPair;
import org.dyn4j.collision.broadphase.AABBProducer;
import org.dyn4j.collision.broadphase.DynamicAABBTree;
import org.dyn4j.collision.broadphase.StaticValueAABBExpansionMethod;
import org.jbox2d.callbacks.TreeCallback;
import org.jbox2d.collision.AABB;
import org.jbox2d.collision.broadphase.DynamicTree;
import org.jbox2d.common.Vec2;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import org.locationtech.jts.index.SpatialIndex;
import org.locationtech.jts.index.hprtree.HPRtree;
import org.locationtech.jts.index.strtree.STRtree;

/**
 * Everything that takes part in the broad-phase race: Hitbox's structures and the peers, each
 * used the way its documentation suggests for "every overlapping pair, every frame". Each
 * counts the pairs that {@link BroadPhaseWorld#overlap} confirms, so all must give the same
 * count (checked before each measurement).
 */
final class BroadPhaseContenders {
    private BroadPhaseContenders() {
    }

    /** One contender: loads the world once, then each frame takes in the moved boxes and counts the pairs. */
    interface Contender {
        void load(BroadPhaseWorld world);

        long frame();
    }

    static Contender of(String name) {
        switch (name) {
            case "bruteForce": return new Ours(BroadPhase.bruteForce());
            case "grid": return new Ours(BroadPhase.grid());
            case "quadtree": return new Ours(BroadPhase.quadtree());
            case "sweepAndPrune": return new Ours(BroadPhase.sweepAndPrune());
            case "dynamicTree": return new Ours(BroadPhase.dynamicTree());
            case "plainLoop": return new PlainLoop();
            case "jtsSTRtree": return new Jts(false);
            case "jtsHPRtree": return new Jts(true);
            case "dyn4jAABBTree": return new Dyn4j();
            case "jbox2dDynamicTree": return new JBox2D();
            default: throw new IllegalArgumentException("no contender " + name);
        }
    }

    /** A Hitbox broad phase: put every box, then pairs. */
    static final class Ours implements Contender, PairConsumer {
        private final BroadPhase bp;
        private BroadPhaseWorld world;
        private long count;

        Ours(BroadPhase bp) {
            this.bp = bp;
        }

        @Override
        public void load(BroadPhaseWorld w) {
            world = w;
        }

        @Override
        public long frame() {
            BroadPhaseWorld w = world;
            for (int i = 0; i < w.n; i++) {
                bp.put(i, w.x[i], w.y[i], w.w[i], w.h[i]);
            }
            count = 0;
            bp.pairs(this);
            return count;
        }

        @Override
        public void pair(int a, int b) {
            count++;
        }
    }

    /**
     * A plain loop over every pair, each tested as Collide.rectRect: the checks that section 10's
     * R-trees and quadtrees cut down. The tutorial writes no such loop; its section 8 loops over
     * one rectangle's obstacles.
     */
    static final class PlainLoop implements Contender {
        private BroadPhaseWorld world;

        @Override
        public void load(BroadPhaseWorld w) {
            world = w;
        }

        @Override
        public long frame() {
            BroadPhaseWorld w = world;
            long count = 0;
            for (int i = 0; i < w.n; i++) {
                for (int j = i + 1; j < w.n; j++) {
                    if (w.overlap(i, j)) {
                        count++;
                    }
                }
            }
            return count;
        }
    }

    /**
     * JTS 1.20: an STRtree or HPRtree built afresh each frame (they are static indexes: built
     * once, then queried), then a query per box with its own envelope. Envelopes are reused;
     * the ids are boxed once, up front.
     */
    static final class Jts implements Contender, ItemVisitor {
        private final boolean hilbert;
        private BroadPhaseWorld world;
        private Envelope[] envelopes;
        private Integer[] boxed;
        private int current;
        private long count;

        Jts(boolean hilbert) {
            this.hilbert = hilbert;
        }

        @Override
        public void load(BroadPhaseWorld w) {
            world = w;
            envelopes = new Envelope[w.n];
            boxed = new Integer[w.n];
            for (int i = 0; i < w.n; i++) {
                envelopes[i] = new Envelope();
                boxed[i] = i;
            }
        }

        @Override
        public long frame() {
            BroadPhaseWorld w = world;
            SpatialIndex index = hilbert ? new HPRtree() : new STRtree();
            for (int i = 0; i < w.n; i++) {
                envelopes[i].init(w.x[i], (double) w.x[i] + w.w[i], w.y[i], (double) w.y[i] + w.h[i]);
                index.insert(envelopes[i], boxed[i]);
            }
            if (index instanceof HPRtree hpr) {
                hpr.build();
            } else {
                ((STRtree) index).build();
            }
            count = 0;
            for (int i = 0; i < w.n; i++) {
                current = i;
                index.query(envelopes[i], this);
            }
            return count;
        }

        @Override
        public void visitItem(Object item) {
            int j = (Integer) item;
            if (j > current && world.overlap(current, j)) {
                count++;
            }
        }
    }

    /**
     * dyn4j 6.0.0's DynamicAABBTree, its broadphase detector: the boxes as items, AABBs grown
     * by 2 pixels (as ours), updated each frame, then every pair by a full detection.
     */
    static final class Dyn4j implements Contender {
        private BroadPhaseWorld world;
        private DynamicAABBTree<Item> tree;
        private Item[] items;

        /** A box of the world, by index. */
        static final class Item {
            final int index;

            Item(int index) {
                this.index = index;
            }
        }

        @Override
        public void load(BroadPhaseWorld w) {
            world = w;
            AABBProducer<Item> producer = new AABBProducer<>() {
                @Override
                public org.dyn4j.geometry.AABB compute(Item item) {
                    org.dyn4j.geometry.AABB out = new org.dyn4j.geometry.AABB(0, 0, 0, 0);
                    compute(item, out);
                    return out;
                }

                @Override
                public void compute(Item item, org.dyn4j.geometry.AABB out) {
                    int i = item.index;
                    org.dyn4j.geometry.AABB.setFromPoints(w.x[i], w.y[i], (double) w.x[i] + w.w[i], (double) w.y[i] + w.h[i], out);
                }
            };
            tree = new DynamicAABBTree<>((a, b) -> true, producer, new StaticValueAABBExpansionMethod<>(2), w.n);
            items = new Item[w.n];
            for (int i = 0; i < w.n; i++) {
                items[i] = new Item(i);
                tree.add(items[i]);
            }
        }

        @Override
        public long frame() {
            for (Item item : items) {
                tree.update(item);
            }
            long count = 0;
            Iterator<CollisionPair<Item>> pairs = tree.detectIterator(true);
            while (pairs.hasNext()) {
                CollisionPair<Item> p = pairs.next();
                int a = p.getFirst().index, b = p.getSecond().index;
                if (a != b && world.overlap(a, b)) {  // its full detection also pairs each item with itself
                    count++;
                }
            }
            return count;
        }
    }

    /**
     * JBox2D 2.2.1.1's DynamicTree (Box2D's b2DynamicTree in Java): a proxy per box, moved each
     * frame with its displacement when it has left its fat box, then a query per box. Box2D works in metres and grows its
     * boxes by 0.1 m, so the world is given to it at 20 pixels a metre, which makes that 2
     * pixels, as ours; the query boxes are a hair larger, so rounding in the scaling loses no
     * pair, and every candidate is decided by the same exact test.
     */
    static final class JBox2D implements Contender, TreeCallback {
        private static final float METRES = 1 / 20f;
        private BroadPhaseWorld world;
        private final DynamicTree tree = new DynamicTree();
        private int[] proxy;
        private int[] indexOfProxy;
        private float[] lastX;
        private float[] lastY;
        private final AABB box = new AABB();
        private final Vec2 move = new Vec2();
        private int current;
        private long count;

        @Override
        public void load(BroadPhaseWorld w) {
            world = w;
            proxy = new int[w.n];
            indexOfProxy = new int[2 * w.n + 16];
            lastX = new float[w.n];
            lastY = new float[w.n];
            for (int i = 0; i < w.n; i++) {
                set(i, 0);
                proxy[i] = tree.createProxy(box, null);
                if (proxy[i] >= indexOfProxy.length) {
                    indexOfProxy = java.util.Arrays.copyOf(indexOfProxy, 2 * proxy[i]);
                }
                indexOfProxy[proxy[i]] = i;
                lastX[i] = w.x[i];
                lastY[i] = w.y[i];
            }
        }

        private void set(int i, float pad) {
            BroadPhaseWorld w = world;
            box.lowerBound.set(w.x[i] * METRES - pad, w.y[i] * METRES - pad);
            box.upperBound.set((w.x[i] + w.w[i]) * METRES + pad, (w.y[i] + w.h[i]) * METRES + pad);
        }

        @Override
        public long frame() {
            BroadPhaseWorld w = world;
            for (int i = 0; i < w.n; i++) {
                set(i, 0);
                move.set((w.x[i] - lastX[i]) * METRES, (w.y[i] - lastY[i]) * METRES);
                // 2.2.1.1's moveProxy tests containment the wrong way round and re-inserts every
                // proxy that moves; asking first, as Box2D itself does, gives the tree its due.
                AABB fat = tree.getFatAABB(proxy[i]);
                if (!(fat.lowerBound.x <= box.lowerBound.x && fat.lowerBound.y <= box.lowerBound.y
                        && box.upperBound.x <= fat.upperBound.x && box.upperBound.y <= fat.upperBound.y)) {
                    tree.moveProxy(proxy[i], box, move);
                }
                lastX[i] = w.x[i];
                lastY[i] = w.y[i];
            }
            count = 0;
            for (int i = 0; i < w.n; i++) {
                current = i;
                set(i, 1e-4f);
                tree.query(this, box);
            }
            return count;
        }

        @Override
        public boolean treeCallback(int proxyId) {
            int j = indexOfProxy[proxyId];
            if (j > current && world.overlap(current, j)) {
                count++;
            }
            return true;
        }
    }
}
