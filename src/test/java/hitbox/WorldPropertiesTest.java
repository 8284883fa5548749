package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;

/**
 * Properties of {@link World#move} over random worlds of every kind, turned and not, with every
 * reaction chosen at random per pair: the mover ends overlapping no body it slid on, touched or
 * bounced off (unless it overlapped it at the start); collisions come in the order met, each
 * crossed body once; the broad phase's box holds the shape; a teleport there and back gives the
 * same shape.
 */
class WorldPropertiesTest {

    @Property(tries = 300)
    void moves_neverEndInsideWhatBlocked(@ForAll long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        World w = WorldBruteForceTest.randomWorld(rnd, 5 + rnd.nextInt(30));
        for (Body b : w.bodies()) {
            if (rnd.nextInt(6) == 0) {
                b.oneWay(Side.TOP);
            }
        }
        List<Body> all = w.bodies();
        for (int k = 0; k < 10; k++) {
            Body m = all.get(rnd.nextInt(all.size()));
            Shape start = m.shape();
            Map<Body, Reaction> chosen = new HashMap<>();
            float scale = rnd.nextInt(3) == 0 ? 3000 : 60;
            float dx = (float) ((rnd.nextDouble() - 0.5) * scale), dy = (float) ((rnd.nextDouble() - 0.5) * scale);
            List<Collision> got = w.move(m, dx, dy, (me, o) -> {
                Reaction r = rnd.nextInt(5) == 0 ? null : Reaction.values()[rnd.nextInt(4)];
                assertFalse(chosen.containsKey(o), "asked twice about " + o);
                chosen.put(o, r);
                return r;
            });
            Shape end = m.shape();
            String what = "seed " + seed + ": " + start + " by (" + dx + ", " + dy + ") to " + end;
            float lastT = 0;
            java.util.Set<Body> crossed = new java.util.HashSet<>();
            for (Collision c : got) {
                assertTrue(c.hit().t() >= lastT, what + ": out of order " + got);
                lastT = c.hit().t();
                if (c.reaction() == Reaction.CROSS && !c.hit().alreadyOverlapping()) {
                    assertTrue(crossed.add(c.other()), what + ": crossed twice " + c.other());
                }
                assertEquals(m, c.mover());
                if (c.other().isSensor() || m.isSensor()) {
                    assertEquals(Reaction.CROSS, c.reaction());
                }
            }
            for (Body o : all) {
                if (o == m || !o.alive()) {
                    continue;
                }
                // A body never asked about was never met: it must not be overlapped either.
                Reaction r = chosen.containsKey(o) ? chosen.get(o) : Reaction.SLIDE;
                boolean blocks = r != null && r != Reaction.CROSS && !o.isSensor() && !m.isSensor() && m.accepts(o);
                boolean oneWayPassed = o.oneWay() != Side.NONE
                        && got.stream().noneMatch(c -> c.other() == o && c.reaction() != Reaction.CROSS);
                if (blocks && !oneWayPassed && !start.overlaps(o.shape())) {
                    assertFalse(end.overlaps(o.shape()), what + ": ends inside " + o + " " + o.shape() + " (" + r + ")");
                }
            }
            Rect box = m.bounds();
            assertTrue(box.x() <= Extents.minX(end) && box.y() <= Extents.minY(end) && box.x() + (double) box.w() >= Extents.maxX(end)
                    && box.y() + (double) box.h() >= Extents.maxY(end), what + ": box " + box);
        }
    }

    /**
     * A turned capsule's ends round to float at their own size, which can put its outline more
     * than one float step of the box edge's size outside it (the case a random world found:
     * ends near x = 8 and 25, radius 4.5, the box edge near 3.67). Many poses, fixed seed.
     */
    @org.junit.jupiter.api.Test
    void turnedShapes_boxHoldsTheRoundedShape_atManyPoses() {
        SplittableRandom rnd = new SplittableRandom(20261127);
        World w = new World();
        Shape[] homes = {new Capsule(8.1696205f, 845.62244f, 25.357727f, 831.1718f, 4.5f),
            new Capsule(0.3f, 0.7f, 30.1f, -9.9f, 4.5f), new Rect(0.1f, 0.2f, 26.3f, 7.7f),
            Polygon.of(0.1f, 0.3f, 9.7f, 1.1f, 3.3f, 8.9f), new Ellipse(3.3f, 4.4f, 9.1f, 2.3f),
            new Ellipse(3.3f, 4.4f, 9.1f, 2.3f, 0.7f),
            new Segment(0.7f, 0.1f, 17.3f, 5.9f)};
        for (Shape home : homes) {
            Body b = w.add(home);
            for (int i = 0; i < 20000; i++) {
                b.moveTo((float) (rnd.nextDouble() * 2000 - 1000), (float) (rnd.nextDouble() * 2000 - 1000));
                b.turnTo((float) (rnd.nextDouble() * 20 - 10));
                Shape s = b.shape();
                Rect box = b.bounds();
                assertTrue(box.x() <= Extents.minX(s) && box.y() <= Extents.minY(s) && box.x() + (double) box.w() >= Extents.maxX(s)
                        && box.y() + (double) box.h() >= Extents.maxY(s), "box " + box + " of " + s);
            }
        }
    }

    @Property(tries = 300)
    void teleports_thereAndBack_giveTheSameShape_andTheBoxHoldsIt(@ForAll long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        World w = WorldBruteForceTest.randomWorld(rnd, 3);
        for (Body b : w.bodies()) {
            Shape before = b.shape();
            float x = b.pivotX(), y = b.pivotY(), a = b.angle();
            b.moveTo(x + rnd.nextInt(2000) - 1000, y + rnd.nextInt(2000) - 1000);
            b.turnTo((float) (rnd.nextDouble() * 20 - 10));
            Shape turned = b.shape();
            Rect box = b.bounds();
            assertTrue(box.x() <= Extents.minX(turned) && box.y() <= Extents.minY(turned) && box.x() + (double) box.w() >= Extents.maxX(turned)
                    && box.y() + (double) box.h() >= Extents.maxY(turned), "box " + box + " of " + turned);
            b.moveTo(x, y).turnTo(a);
            assertEquals(before, b.shape());
        }
    }

    /**
     * {@code moveTo(x, y, angle)} is one teleport to the pose that {@code moveTo(x, y)} then
     * {@code turnTo(angle)} reach in two: the same pivot, angle, shape and box, and the same
     * pairs in the world (checked against a twin world moved the two-call way). A seeded loop
     * over 200 worlds, not a jqwik property: since 1.10 jqwik's maintainers ask AI coding
     * agents not to use it (its Anti-AI Usage Clause), and this test was written by one.
     */
    @org.junit.jupiter.api.Test
    void poseTeleport_sameAsMoveThenTurn() {
        for (long seed = 0; seed < 200; seed++) {
            poseTeleport(seed);
        }
    }

    private static void poseTeleport(long seed) {
        World one = WorldBruteForceTest.randomWorld(new SplittableRandom(seed), 3);
        World two = WorldBruteForceTest.randomWorld(new SplittableRandom(seed), 3);
        SplittableRandom rnd = new SplittableRandom(seed + 1);
        List<Body> a = one.bodies(), b = two.bodies();
        for (int i = 0; i < a.size(); i++) {
            float x = (float) (rnd.nextDouble() * 800 - 400), y = (float) (rnd.nextDouble() * 800 - 400);
            float angle = (float) (rnd.nextDouble() * 20 - 10);
            try {
                a.get(i).moveTo(x, y, angle);
            } catch (IllegalStateException gridBody) {
                continue;  // a grid's body does not move
            }
            b.get(i).moveTo(x, y).turnTo(angle);
            String where = "body " + i + " to (" + x + ", " + y + ") at " + angle;
            assertEquals(b.get(i).pivotX(), a.get(i).pivotX(), where);
            assertEquals(b.get(i).pivotY(), a.get(i).pivotY(), where);
            assertEquals(b.get(i).angle(), a.get(i).angle(), where);
            assertEquals(b.get(i).shape(), a.get(i).shape(), where);
            assertEquals(b.get(i).bounds(), a.get(i).bounds(), where);
        }
        List<String> pairsOne = new ArrayList<>(), pairsTwo = new ArrayList<>();
        one.pairs((p, q) -> pairsOne.add(one.bodies().indexOf(p) + "-" + one.bodies().indexOf(q)));
        two.pairs((p, q) -> pairsTwo.add(two.bodies().indexOf(p) + "-" + two.bodies().indexOf(q)));
        assertEquals(pairsTwo, pairsOne);
    }
}
