package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * {@link World#move(Body, float, float, CollisionFilter, List)}, the move that fills the
 * caller's list (issue 29): it is the move that hands back a {@link Collisions}, the same
 * collisions in the same order and the same end, judged against that form run on a twin world;
 * it adds after what the list holds, only the mover's own collisions (not a carrier's riders'),
 * and a list that refuses them leaves the world as it was.
 */
class WorldMoveIntoListTest {

    /** Two worlds built alike from a seed: bodies of every kind, a grid, characters and a carrier. */
    private static List<Body> scene(World w, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        List<Body> movers = new ArrayList<>();
        Grid g = new Grid(40, 30, 20);
        for (int col = 0; col < 40; col++) {
            g.set(col, 29, 1);
            if (rnd.nextInt(5) == 0) {
                g.set(col, 10 + rnd.nextInt(15), 1);
            }
        }
        w.add(g);
        for (int i = 0; i < 40; i++) {
            float x = rnd.nextInt(760), y = rnd.nextInt(540);
            switch (i % 5) {
                case 0 -> w.add(new Rect(x, y, 10 + rnd.nextInt(40), 10 + rnd.nextInt(20)));
                case 1 -> w.add(new Rect(-15, -8, 30, 16), x, y, (float) rnd.nextDouble() * 3);
                case 2 -> w.add(Polygon.of(x, y, x + 40, y + 10, x + 10, y + 30));
                case 3 -> w.add(new Circle(x, y, 4 + rnd.nextInt(10)));
                default -> w.add(new Segment(x, y, x + rnd.nextInt(60) - 30, y + rnd.nextInt(60) - 30));
            }
        }
        for (int i = 0; i < 12; i++) {
            float x = 20 + i * 60, y = 100 + rnd.nextInt(300);
            movers.add(switch (i % 4) {
                case 0 -> w.add(new Rect(x, y, 10, 14));
                case 1 -> w.add(new Circle(x, y, 6));
                case 2 -> w.addCharacter(new Rect(x, y, 10, 20)).body();
                default -> w.add(Polygon.regular(x, y, 8, 6, 0.3f));
            });
        }
        Body platform = w.add(new Rect(300, 560, 100, 10)).carrier(true);
        w.add(new Rect(340, 540, 10, 20));  // a rider
        movers.add(platform);
        return movers;
    }

    @Test
    void theMoveIntoAList_isTheMoveThatHandsBackCollisions() {
        for (long seed = 1; seed <= 30; seed++) {
            World a = new World(), b = new World();
            List<Body> ma = scene(a, seed), mb = scene(b, seed);
            List<Body> ba = a.bodies(), bb = b.bodies();
            SplittableRandom rnd = new SplittableRandom(seed * 31);
            List<Collision> out = new ArrayList<>();
            int met = 0;
            for (int frame = 0; frame < 40; frame++) {
                for (int i = 0; i < ma.size(); i++) {
                    float dx = (float) (rnd.nextDouble() * 24 - 12), dy = (float) (rnd.nextDouble() * 24 - 8);
                    CollisionFilter filter = rnd.nextInt(4) == 0 ? (m, o) -> Reaction.BOUNCE : (m, o) -> Reaction.SLIDE;
                    Collisions want = a.move(ma.get(i), dx, dy, filter);
                    out.clear();
                    Collision held = want.isEmpty() ? null : want.get(0);
                    if (held != null) {
                        out.add(held);  // something the list held before: kept, the move's after it
                    }
                    boolean finished = b.move(mb.get(i), dx, dy, filter, out);
                    String where = "seed " + seed + ", frame " + frame + ", mover " + i;
                    assertEquals(want.finished(), finished, where);
                    assertEquals(want.size() + (held == null ? 0 : 1), out.size(), where);
                    for (int k = 0; k < want.size(); k++) {
                        Collision x = want.get(k), y = out.get(k + (held == null ? 0 : 1));
                        assertEquals(ba.indexOf(x.mover()), bb.indexOf(y.mover()), where);
                        assertEquals(ba.indexOf(x.other()), bb.indexOf(y.other()), where);
                        assertEquals(x.reaction(), y.reaction(), where);
                        assertEquals(x.hit(), y.hit(), where);
                        assertEquals(x.x(), y.x(), where);
                        assertEquals(x.y(), y.y(), where);
                        assertEquals(x.cell(), y.cell(), where);
                    }
                    met += want.size();
                    assertEquals(ma.get(i).shape(), mb.get(i).shape(), where);
                }
                for (int i = 0; i < ba.size(); i++) {
                    assertEquals(ba.get(i).shape(), bb.get(i).shape(), "seed " + seed + ", body " + i);
                }
                List<BodyEvent> ea = a.step(), eb = b.step();  // the contacts the moves met, alike
                assertEquals(ea.size(), eb.size(), "seed " + seed + ", frame " + frame);
                for (int k = 0; k < ea.size(); k++) {
                    assertEquals(ea.get(k).kind(), eb.get(k).kind());
                    assertEquals(ba.indexOf(ea.get(k).a()), bb.indexOf(eb.get(k).a()));
                    assertEquals(ba.indexOf(ea.get(k).b()), bb.indexOf(eb.get(k).b()));
                }
            }
            assertTrue(met > 40, met + " collisions for seed " + seed + ": the scene is met");
        }
    }

    @Test
    void aCarrierFillsTheListWithItsOwnCollisionsOnly() {
        World w = new World();
        Body platform = w.add(new Rect(0, 100, 100, 10)).carrier(true);
        Body rider = w.add(new Rect(40, 80, 10, 20));
        Body wall = w.add(new Rect(150, 0, 10, 200));
        Body box = w.add(new Rect(85, 75, 10, 10));  // the rider meets this on the way
        List<Collision> out = new ArrayList<>();
        assertTrue(w.move(platform, 60, 0, (m, o) -> Reaction.SLIDE, out));
        assertEquals(1, out.size(), "the platform met the wall, and the rider's collision is not its: " + out);
        assertEquals(platform, out.get(0).mover());
        assertEquals(wall, out.get(0).other());
        assertEquals(new Rect(50, 100, 100, 10), platform.shape());
        assertEquals(new Rect(75, 80, 10, 20), rider.shape(), "the rider went as far as the box let it");
        assertEquals(List.of(), w.collisions().stream().filter(c -> c.other() == box && c.mover() != rider).toList());
        assertTrue(w.collisions().stream().anyMatch(c -> c.mover() == rider && c.other() == box), "the rider met the box");
    }

    @Test
    void aCharactersBody_walksByItsRules() {
        World w = new World();
        w.add(new Rect(-200, 300, 200, 20));  // a floor, then a ramp up to the right (30 degrees)
        w.add(Polygon.of(0, 300, 400, 300, 400, 70));
        CharacterBody hero = w.addCharacter(new Rect(-40, 270, 20, 30));
        List<Collision> out = new ArrayList<>();
        float startY = hero.body().pivotY();
        for (int f = 0; f < 60; f++) {
            w.move(hero.body(), 2, 1, (m, o) -> Reaction.SLIDE, out);
        }
        assertTrue(hero.onGround(), "it stands on the ramp");
        float walked = hero.body().pivotX() + 30, right = hero.body().pivotX() + 10;
        assertTrue(walked > 100, "it walked on up the ramp: " + walked);
        assertEquals(300 - right * 230 / 400, hero.body().pivotY() + 15, 0.5, "its bottom corner on the ramp");
        assertTrue(hero.body().pivotY() < startY - 50, "it climbed: " + hero.body().pivotY());
        assertFalse(out.isEmpty());
    }

    @Test
    void aListThatRefusesTheCollisions_leavesTheWorldAsItWas() {
        World w = new World();
        Body platform = w.add(new Rect(0, 100, 100, 10)).carrier(true);
        Body rider = w.add(new Rect(40, 80, 10, 20));
        w.add(new Rect(150, 0, 10, 200));
        Body ball = w.add(new Circle(300, 50, 5));
        w.add(new Rect(280, 60, 40, 10));
        w.step();
        List<Collision> none = Collections.unmodifiableList(new ArrayList<>());
        for (Body m : List.of(platform, ball)) {
            float dx = m == platform ? 60 : 10;  // each meets something: the wall, the box under the ball
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> w.move(m, dx, 10, (p, o) -> Reaction.SLIDE, none));
            assertTrue(e.getMessage().startsWith("out "), e.getMessage());
        }
        assertEquals(new Rect(0, 100, 100, 10), platform.shape());
        assertEquals(new Rect(40, 80, 10, 20), rider.shape());
        assertEquals(new Circle(300, 50, 5), ball.shape());
        List<BodyEvent> changes = new ArrayList<>();
        w.step(changes);
        assertEquals(List.of(), changes, "the refused moves left no collision for the step");
        assertThrows(IllegalArgumentException.class, () -> w.move(ball, 1, 1, (p, o) -> Reaction.SLIDE, null));
        // A move that meets nothing adds nothing, even to a list that refuses additions.
        assertTrue(w.move(ball, -100, 0, (p, o) -> Reaction.SLIDE, none));
        assertEquals(new Circle(200, 50, 5), ball.shape());
    }
}
