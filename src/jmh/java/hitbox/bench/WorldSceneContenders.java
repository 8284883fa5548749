package hitbox.bench;

import java.util.Arrays;
import java.util.Iterator;

import hitbox.BroadPhase;
import hitbox.PairConsumer;
import hitbox.Shape;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Segment;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.NarrowphaseCollisionData;
import org.dyn4j.world.World;
import org.dyn4j.world.WorldCollisionData;
import org.dyn4j.world.listener.CollisionListenerAdapter;
import org.jbox2d.callbacks.DebugDraw;
import org.jbox2d.callbacks.TreeCallback;
import org.jbox2d.callbacks.TreeRayCastCallback;
import org.jbox2d.collision.AABB;
import org.jbox2d.collision.RayCastInput;
import org.jbox2d.collision.broadphase.BroadPhaseStrategy;
import org.jbox2d.collision.broadphase.DynamicTree;
import org.jbox2d.collision.shapes.CircleShape;
import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.BodyDef;
import org.jbox2d.dynamics.BodyType;
import org.jbox2d.dynamics.FixtureDef;
import org.jbox2d.dynamics.contacts.Contact;
import org.jbox2d.pooling.normal.DefaultWorldPool;

/**
 * The world benchmark's contenders ({@link WorldSceneBench}): each takes the scene's bodies
 * once, then each frame takes in where every body now stands and finds every overlapping pair.
 * Detection only: no contact points beyond what an engine cannot skip, no response, no solver.
 */
final class WorldSceneContenders {
    private WorldSceneContenders() {
    }

    static Contender of(String name) {
        return switch (name) {
            case "hitboxWorld" -> new HitboxWorld(false);
            case "hitboxWorldStep" -> new HitboxWorld(true);
            case "hitboxParts" -> new HitboxParts();
            case "dyn4jWorld" -> new Dyn4jWorld();
            case "jbox2dWorld" -> new JBox2DWorld();
            default -> throw new IllegalArgumentException("no contender " + name);
        };
    }

    /** One contender: counts the pairs it finds, and keeps them too while {@link #keep} is on (for the checks). */
    abstract static class Contender {
        protected WorldScene scene;
        protected long count;
        private boolean keep;
        private long[] kept = new long[64];
        private int keptCount;

        abstract void load(WorldScene scene);

        /** Takes in where every body stands now, finds the pairs; returns how many. */
        abstract long frame();

        protected final void found(int a, int b) {
            count++;
            if (keep) {
                if (keptCount == kept.length) {
                    kept = Arrays.copyOf(kept, 2 * keptCount);
                }
                kept[keptCount++] = key(a, b);
            }
        }

        /** One frame, keeping its pairs: sorted keys {@code min << 32 | max}. */
        final long[] framePairs() {
            keep = true;
            keptCount = 0;
            try {
                frame();
            } finally {
                keep = false;
            }
            long[] out = Arrays.copyOf(kept, keptCount);
            Arrays.sort(out);
            return out;
        }

        static long key(int a, int b) {
            return (long) Math.min(a, b) << 32 | Math.max(a, b);
        }
    }

    /**
     * Hitbox's {@code World}: a body per scene body, its shape given once in its own frame
     * ({@code World.add(shape, x, y, angle)}); each frame every moving body is teleported
     * ({@code moveTo(x, y)}, or {@code moveTo(x, y, angle)} for those that turn), then {@code World.pairs} hands
     * over every overlapping pair; or ({@code hitboxWorldStep}) {@code World.step()} reports the
     * contacts as events, ENTER or STAY for each pair that overlaps now (EXIT for those that no
     * longer do, not counted).
     */
    static final class HitboxWorld extends Contender {
        private final boolean events;
        private final java.util.function.BiConsumer<hitbox.Body, hitbox.Body> pair =
                (a, b) -> found((Integer) a.data(), (Integer) b.data());
        private hitbox.World world;
        private hitbox.Body[] bodies;

        /** @param events the contacts as {@code World.step()}'s events rather than {@code World.pairs}' callback */
        HitboxWorld(boolean events) {
            this.events = events;
        }

        @Override
        void load(WorldScene s) {
            scene = s;
            world = new hitbox.World();
            bodies = new hitbox.Body[s.n];
            for (int i = 0; i < s.n; i++) {
                bodies[i] = world.add(home(s, i), s.x[i], s.y[i], s.angle[i]);
                bodies[i].data(i);
            }
            world.step();
        }

        /** Body i's shape in its own frame, in pixels. */
        static Shape home(WorldScene s, int i) {
            float a = s.p[i], b = s.q[i];
            return switch (s.kind[i]) {
                case WorldScene.CIRCLE -> new hitbox.Circle(0, 0, a);
                case WorldScene.ELLIPSE -> new hitbox.Ellipse(0, 0, a, b);
                case WorldScene.BOX -> hitbox.Rect.centered(0, 0, a, b);
                case WorldScene.LINE -> new hitbox.Segment(-a, -b, a, b);
                default -> hitbox.Polygon.of(s.corners[i]);
            };
        }

        @Override
        long frame() {
            WorldScene s = scene;
            for (int i = 0; i < s.n; i++) {
                if (s.moves(i)) {
                    if (s.spin[i] != 0) {
                        bodies[i].moveTo(s.x[i], s.y[i], s.angle[i]);
                    } else {
                        bodies[i].moveTo(s.x[i], s.y[i]);
                    }
                }
            }
            count = 0;
            if (events) {
                for (hitbox.BodyEvent e : world.step()) {
                    if (e.kind() != hitbox.BodyEvent.Kind.EXIT) {
                        found((Integer) e.a().data(), (Integer) e.b().data());
                    }
                }
            } else {
                world.pairs(pair);
            }
            return count;
        }
    }

    /**
     * Hitbox as a box of parts, the way a sketch without a world has to do it: a new shape for
     * every body every frame (turned rects and polygons through {@code Polygon.of(rect).rotated} and
     * {@code Polygon.of}), put into a {@code BroadPhase.grid()}, each pair it reports decided by
     * {@code Shape.overlaps}.
     */
    static final class HitboxParts extends Contender implements PairConsumer {
        private final BroadPhase grid = BroadPhase.grid();
        private Shape[] shapes;

        @Override
        void load(WorldScene s) {
            scene = s;
            shapes = new Shape[s.n];
        }

        @Override
        long frame() {
            WorldScene s = scene;
            for (int i = 0; i < s.n; i++) {
                Shape shape = s.shape(i);
                shapes[i] = shape;
                grid.put(i, shape);
            }
            count = 0;
            grid.pairs(this);
            return count;
        }

        @Override
        public void pair(int a, int b) {
            if ((scene.moves(a) || scene.moves(b)) && shapes[a].overlaps(shapes[b])) {
                found(a, b);
            }
        }
    }

    /**
     * The scale the peers get the scene at: Box2D and dyn4j are tuned for bodies of 0.1 to 10
     * metres (their tolerances and box margins are in metres), so the scene's size unit becomes
     * one metre.
     */
    static double metresPerPixel(WorldScene s) {
        return 1 / s.size;
    }

    /**
     * dyn4j 6.0.0's {@code World}, detecting without solving: each body's transform set (its
     * previous transform too, so the swept box the broad phase asks for is the body itself, as
     * after a teleport), then the world's own detection ({@code AbstractCollisionWorld.detect}:
     * its DynamicAABBTree broad phase with its default 0.2 m margin, then its narrow phase on
     * each pair whose boxes overlap). A collision listener counts each pair the narrow phase
     * confirms and returns false, which is dyn4j's documented way to stop a pair there, so no
     * contact manifold is made; the world's hand-over to the solver (contact constraints) is
     * overridden to do nothing.
     */
    static final class Dyn4jWorld extends Contender {
        private DetectingWorld world;
        private Body[] bodies;
        private double scale;

        /** dyn4j's World with its protected detection step made callable, and nothing handed to a solver. */
        static final class DetectingWorld extends World<Body> {
            void detectOnly() {
                detect();
            }

            @Override
            protected void processCollisions(Iterator<WorldCollisionData<Body>> collisions) {
                while (collisions.hasNext()) {
                    collisions.next();  // the iterator runs the narrow phase as it goes
                }
            }
        }

        @Override
        void load(WorldScene s) {
            scene = s;
            scale = metresPerPixel(s);
            world = new DetectingWorld();
            world.getSettings().setAtRestDetectionEnabled(false);
            bodies = new Body[s.n];
            for (int i = 0; i < s.n; i++) {
                Body b = new Body();
                BodyFixture f = b.addFixture(convex(s, i, scale));
                f.setUserData(i);
                b.setMass(s.moves(i) ? MassType.NORMAL : MassType.INFINITE);
                b.setAtRestDetectionEnabled(false);
                bodies[i] = b;
                place(i);
                world.addBody(b);
            }
            world.addCollisionListener(new CollisionListenerAdapter<Body, BodyFixture>() {
                @Override
                public boolean collision(NarrowphaseCollisionData<Body, BodyFixture> data) {
                    found((Integer) data.getFixture1().getUserData(), (Integer) data.getFixture2().getUserData());
                    return false;  // detected: no manifold, no contact
                }
            });
        }

        /** Body i's shape in its own frame, in metres. */
        static Convex convex(WorldScene s, int i, double scale) {
            double a = s.p[i] * scale, b = s.q[i] * scale;
            switch (s.kind[i]) {
                case WorldScene.CIRCLE:
                    return Geometry.createCircle(a);
                case WorldScene.ELLIPSE:
                    return Geometry.createEllipse(2 * a, 2 * b);
                case WorldScene.BOX:
                    return Geometry.createRectangle(a, b);
                case WorldScene.LINE:
                    return new Segment(new Vector2(-a, -b), new Vector2(a, b));
                default: {
                    float[] c = s.corners[i];
                    Vector2[] v = new Vector2[4];
                    for (int k = 0; k < 4; k++) {
                        v[k] = new Vector2(c[2 * k] * scale, c[2 * k + 1] * scale);
                    }
                    return Geometry.createPolygon(v);
                }
            }
        }

        private void place(int i) {
            Body b = bodies[i];
            b.getTransform().setTranslation(scene.x[i] * scale, scene.y[i] * scale);
            b.getTransform().setRotation(scene.angle[i]);
            b.getPreviousTransform().set(b.getTransform());
        }

        @Override
        long frame() {
            WorldScene s = scene;
            for (int i = 0; i < s.n; i++) {
                if (s.moves(i)) {
                    place(i);
                }
            }
            count = 0;
            world.detectOnly();
            return count;
        }
    }

    /**
     * JBox2D 2.2.1.1's {@code World} (Box2D 2.2.1 in Java), stepped without its solver: each
     * moving body teleported with {@code Body.setTransform} (which moves its proxy in the broad
     * phase and looks for new pairs, as Box2D 2.2 does), then the contact manager's
     * {@code collide()}, the narrow phase of {@code World.step}; a pair counts when its contact
     * is touching. Box2D has no ellipse: each is the octagon around it (its most vertices is
     * 8), and it cannot collide two edges, so each line is a box 0.001 m thick; so its answers for ellipses may add pairs up to 8% of an ellipse's radius apart; its
     * polygons and edges carry a 0.01 m skin, so it counts pairs up to 0.02 m apart. The broad
     * phase's tree is JBox2D's own with one fix: 2.2.1.1's {@code moveProxy} tests containment
     * the wrong way round and re-inserts every proxy that moves; asking first, as Box2D itself
     * does, gives it its due (docs/benchmarks.md, broad phases).
     */
    static final class JBox2DWorld extends Contender {
        private org.jbox2d.dynamics.World world;
        private org.jbox2d.dynamics.Body[] bodies;
        private float scale;
        private final Vec2 at = new Vec2();

        /** JBox2D's DynamicTree (its moveProxy is final), with the fat-box test asked the right way round first. */
        static final class FixedTree implements BroadPhaseStrategy {
            private final DynamicTree tree = new DynamicTree();

            @Override
            public boolean moveProxy(int proxyId, AABB aabb, Vec2 displacement) {
                AABB fat = tree.getFatAABB(proxyId);
                if (fat.lowerBound.x <= aabb.lowerBound.x && fat.lowerBound.y <= aabb.lowerBound.y
                        && aabb.upperBound.x <= fat.upperBound.x && aabb.upperBound.y <= fat.upperBound.y) {
                    return false;
                }
                return tree.moveProxy(proxyId, aabb, displacement);
            }

            @Override
            public int createProxy(AABB aabb, Object userData) {
                return tree.createProxy(aabb, userData);
            }

            @Override
            public void destroyProxy(int proxyId) {
                tree.destroyProxy(proxyId);
            }

            @Override
            public Object getUserData(int proxyId) {
                return tree.getUserData(proxyId);
            }

            @Override
            public AABB getFatAABB(int proxyId) {
                return tree.getFatAABB(proxyId);
            }

            @Override
            public void query(TreeCallback callback, AABB aabb) {
                tree.query(callback, aabb);
            }

            @Override
            public void raycast(TreeRayCastCallback callback, RayCastInput input) {
                tree.raycast(callback, input);
            }

            @Override
            public int computeHeight() {
                return tree.computeHeight();
            }

            @Override
            public int getHeight() {
                return tree.getHeight();
            }

            @Override
            public int getMaxBalance() {
                return tree.getMaxBalance();
            }

            @Override
            public float getAreaRatio() {
                return tree.getAreaRatio();
            }

            @Override
            public int getInsertionCount() {
                return tree.getInsertionCount();
            }

            @Override
            public void drawTree(DebugDraw draw) {
                tree.drawTree(draw);
            }
        }

        @Override
        void load(WorldScene s) {
            scene = s;
            scale = (float) metresPerPixel(s);
            world = new org.jbox2d.dynamics.World(new Vec2(0, 0), new DefaultWorldPool(100, 10), new FixedTree());
            bodies = new org.jbox2d.dynamics.Body[s.n];
            for (int i = 0; i < s.n; i++) {
                BodyDef def = new BodyDef();
                def.type = s.moves(i) ? BodyType.DYNAMIC : BodyType.STATIC;
                def.allowSleep = false;
                def.position.set(s.x[i] * scale, s.y[i] * scale);
                def.angle = s.angle[i];
                def.userData = i;
                bodies[i] = world.createBody(def);
                FixtureDef fd = new FixtureDef();
                fd.shape = shape(s, i, scale);
                fd.density = 1;
                bodies[i].createFixture(fd);
            }
        }

        static org.jbox2d.collision.shapes.Shape shape(WorldScene s, int i, float scale) {
            float a = s.p[i] * scale, b = s.q[i] * scale;
            switch (s.kind[i]) {
                case WorldScene.CIRCLE: {
                    CircleShape c = new CircleShape();
                    c.m_radius = a;
                    return c;
                }
                case WorldScene.ELLIPSE: {
                    Vec2[] v = new Vec2[8];
                    double grow = 1 / Math.cos(Math.PI / 8);
                    for (int k = 0; k < 8; k++) {
                        double t = Math.PI / 4 * k;
                        v[k] = new Vec2((float) (a * grow * Math.cos(t)), (float) (b * grow * Math.sin(t)));
                    }
                    PolygonShape p = new PolygonShape();
                    p.set(v, 8);
                    return p;
                }
                case WorldScene.BOX: {
                    PolygonShape p = new PolygonShape();
                    p.setAsBox(a / 2, b / 2);
                    return p;
                }
                case WorldScene.LINE: {
                    // Box2D cannot collide an edge with an edge, so a line is a box 0.001 m thick.
                    double length = Math.hypot(a, b), thin = 0.0005;
                    float nx = (float) (-b / length * thin), ny = (float) (a / length * thin);
                    PolygonShape p = new PolygonShape();
                    p.set(new Vec2[] {new Vec2(-a - nx, -b - ny), new Vec2(a - nx, b - ny), new Vec2(a + nx, b + ny), new Vec2(-a + nx, -b + ny)}, 4);
                    return p;
                }
                default: {
                    float[] c = s.corners[i];
                    Vec2[] v = new Vec2[4];
                    for (int k = 0; k < 4; k++) {
                        v[k] = new Vec2(c[2 * k] * scale, c[2 * k + 1] * scale);
                    }
                    PolygonShape p = new PolygonShape();
                    p.set(v, 4);
                    return p;
                }
            }
        }

        @Override
        long frame() {
            WorldScene s = scene;
            for (int i = 0; i < s.n; i++) {
                if (s.moves(i)) {
                    at.set(s.x[i] * scale, s.y[i] * scale);
                    bodies[i].setTransform(at, s.angle[i]);
                }
            }
            world.getContactManager().findNewContacts();
            world.getContactManager().collide();
            count = 0;
            for (Contact c = world.getContactList(); c != null; c = c.getNext()) {
                if (c.isTouching()) {
                    found((Integer) c.getFixtureA().getBody().getUserData(), (Integer) c.getFixtureB().getBody().getUserData());
                }
            }
            return count;
        }
    }

    /** dyn4j's shapes in pixels, for measuring how far apart or how deep the pairs that contenders disagree on are. */
    static final class Referee {
        private final WorldScene scene;
        private final Convex[] convex;
        private final org.dyn4j.collision.narrowphase.Gjk gjk = new org.dyn4j.collision.narrowphase.Gjk();

        Referee(WorldScene s) {
            scene = s;
            convex = new Convex[s.n];
            for (int i = 0; i < s.n; i++) {
                convex[i] = Dyn4jWorld.convex(s, i, 1);
            }
        }

        private org.dyn4j.geometry.Transform at(int i) {
            org.dyn4j.geometry.Transform t = new org.dyn4j.geometry.Transform();
            t.setTranslation(scene.x[i], scene.y[i]);
            t.setRotation(scene.angle[i]);
            return t;
        }

        /** How far apart bodies a and b are, in pixels (0 when they overlap). */
        double gap(int a, int b) {
            org.dyn4j.collision.narrowphase.Separation sep = new org.dyn4j.collision.narrowphase.Separation();
            return gjk.distance(convex[a], at(a), convex[b], at(b), sep) ? sep.getDistance() : 0;
        }

        /** How deep bodies a and b overlap, in pixels (0 when apart). */
        double depth(int a, int b) {
            Penetration pen = new Penetration();
            return gjk.detect(convex[a], at(a), convex[b], at(b), pen) ? pen.getDepth() : 0;
        }
    }
}
