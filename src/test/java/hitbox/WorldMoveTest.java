package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * {@link World#move}: rectangles that slide end exactly where {@link Sweep#move} puts them, the
 * four reactions, one-way platforms, carrying platforms, tile seams and grids.
 */
class WorldMoveTest {

    // ------------------------------------------------------------------ against Sweep.move

    @Test
    void rectSlidingAmongRects_endsExactlyWhereSweepMovePutsIt() {
        SplittableRandom rnd = new SplittableRandom(20);
        int moves = 0, hits = 0;
        for (int world = 0; world < 300; world++) {
            World w = world % 3 == 0 ? new World(BroadPhase.dynamicTree()) : new World();
            List<Rect> rects = new ArrayList<>();
            int n = 1 + rnd.nextInt(25);
            for (int i = 0; i < n; i++) {
                Rect r = new Rect(coord(rnd), coord(rnd), size(rnd), size(rnd));
                rects.add(r);
                w.add(r);
            }
            Rect start = new Rect(coord(rnd), coord(rnd), size(rnd), size(rnd));
            Body mover = w.add(start);
            for (int frame = 0; frame < 6; frame++) {
                Rect at = (Rect) mover.shape();
                float dx = speed(rnd), dy = speed(rnd);
                Sweep.Move want = Sweep.move(at, dx, dy, rects);
                List<Collision> got = w.move(mover, dx, dy);
                assertEquals(new Rect(want.x(), want.y(), at.w(), at.h()), mover.shape(),
                        "world " + world + " frame " + frame + ": " + at + " by (" + dx + ", " + dy + ")");
                Set<Side> sides = EnumSet.noneOf(Side.class);
                for (Collision c : got) {
                    if (!c.hit().alreadyOverlapping()) {
                        sides.add(c.hit().side());
                        assertEquals(Reaction.SLIDE, c.reaction());
                        hits++;
                    }
                }
                assertEquals(want.sides(), sides, "the sides met");
                moves++;
            }
        }
        assertTrue(hits > 300, "enough moves met something: " + hits + " of " + moves);
    }

    @Test
    void rectSliding_farFromTheOrigin_andWithFractions_isStillExact() {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int world = 0; world < 200; world++) {
            World w = new World();
            List<Rect> rects = new ArrayList<>();
            float ox = (float) (rnd.nextDouble() * 2e6 - 1e6), oy = (float) (rnd.nextDouble() * 2e6 - 1e6);
            for (int i = 0; i < 12; i++) {
                Rect r = new Rect(ox + coord(rnd) + 0.3f * i, oy + coord(rnd) - 0.7f, size(rnd) + 0.25f, size(rnd));
                rects.add(r);
                w.add(r);
            }
            Body mover = w.add(new Rect(ox + coord(rnd), oy + coord(rnd), 7.5f, 12.125f));
            for (int frame = 0; frame < 5; frame++) {
                Rect at = (Rect) mover.shape();
                float dx = speed(rnd) * 1.37f, dy = speed(rnd) * 0.91f;
                Sweep.Move want = Sweep.move(at, dx, dy, rects);
                w.move(mover, dx, dy);
                assertEquals(new Rect(want.x(), want.y(), at.w(), at.h()), mover.shape());
            }
        }
    }

    @Test
    void teleportedRect_keepsItsSizeExactly() {
        World w = new World();
        Body b = w.add(new Rect(10.1f, 20.3f, 30.7f, 5.9f));
        b.moveTo(b.pivotX() + 0.37f, b.pivotY() - 1234.5f);
        b.moveTo(b.pivotX() - 0.37f, b.pivotY() + 1234.5f);
        Rect r = (Rect) b.shape();
        assertEquals(30.7f, r.w());
        assertEquals(5.9f, r.h());
        b.moveTo(b.pivotX(), b.pivotY());
        assertEquals(30.7f, ((Rect) b.shape()).w());
    }

    // ------------------------------------------------------------------ the reactions

    @Test
    void touch_stopsAtTheOther() {
        World w = new World();
        Body wall = w.add(new Rect(100, 0, 10, 100));
        Body ball = w.add(new Circle(50, 50, 10));
        List<Collision> c = w.move(ball, 100, 20, (m, o) -> Reaction.TOUCH);
        assertEquals(1, c.size());
        assertEquals(wall, c.get(0).other());
        assertEquals(Side.LEFT, c.get(0).hit().side());
        Circle end = (Circle) ball.shape();
        assertEquals(90, end.x(), 1e-3);
        assertEquals(58, end.y(), 1e-3);
        assertFalse(end.overlaps(wall.shape()));
    }

    @Test
    void slide_goesOnAlongTheWall() {
        World w = new World();
        w.add(new Rect(100, 0, 10, 200));
        Body ball = w.add(new Circle(50, 50, 10));
        w.move(ball, 100, 20);
        Circle end = (Circle) ball.shape();
        assertEquals(90, end.x(), 1e-3);
        assertEquals(70, end.y(), 1e-3);
    }

    @Test
    void cross_passesThrough_andReportsOnce() {
        World w = new World();
        Body coin = w.add(new Circle(100, 50, 5));
        Body ball = w.add(new Circle(50, 50, 10));
        List<Collision> c = w.move(ball, 100, 0, (m, o) -> Reaction.CROSS);
        assertEquals(1, c.size());
        assertEquals(coin, c.get(0).other());
        assertEquals(Reaction.CROSS, c.get(0).reaction());
        assertEquals(150, ((Circle) ball.shape()).x(), 1e-3);
    }

    @Test
    void sensor_neverBlocks_butIsReported() {
        World w = new World();
        Body sensor = w.add(new Rect(80, 0, 10, 100)).sensor(true);
        Body ball = w.add(new Circle(50, 50, 10));
        List<Collision> c = w.move(ball, 100, 0);
        assertEquals(List.of(sensor), c.stream().map(Collision::other).toList());
        assertEquals(Reaction.CROSS, c.get(0).reaction());
        assertEquals(150, ((Circle) ball.shape()).x(), 1e-3);
    }

    @Test
    void bounce_mirrorsTheRestOfTheMove() {
        World w = new World();
        w.add(new Rect(100, 0, 10, 200));
        Body ball = w.add(new Circle(50, 50, 10));
        List<Collision> c = w.move(ball, 60, 0, (m, o) -> Reaction.BOUNCE);
        assertEquals(1, c.size());
        assertEquals(1, c.get(0).nx(), 1e-6);
        Circle end = (Circle) ball.shape();
        assertEquals(70, end.x(), 1e-3);  // 40 to the wall, 20 back
    }

    @Test
    void collisionsComeInTheOrderMet_withGrowingT() {
        World w = new World();
        for (int i = 0; i < 5; i++) {
            w.add(new Circle(300 - 50 * i, 50, 5)).sensor(true);
        }
        Body ball = w.add(new Circle(0, 50, 10));
        List<Collision> c = w.move(ball, 400, 0);
        assertEquals(5, c.size());
        for (int i = 1; i < c.size(); i++) {
            assertTrue(c.get(i).hit().t() >= c.get(i - 1).hit().t());
            assertTrue(((Circle) c.get(i).other().shape()).x() > ((Circle) c.get(i - 1).other().shape()).x());
        }
    }

    @Test
    void ignoredOthers_andLayers() {
        World w = new World();
        Body wall = w.add(new Rect(100, 0, 10, 200));
        Body ball = w.add(new Circle(50, 50, 10));
        assertTrue(w.move(ball, 100, 0, (m, o) -> null).isEmpty());
        assertEquals(150, ((Circle) ball.shape()).x(), 1e-3);
        ball.moveTo(50, 50);
        wall.layers(2, -1);
        ball.layers(1, ~2);
        int[] asked = {0};
        assertTrue(w.move(ball, 100, 0, (m, o) -> {
            asked[0]++;
            return Reaction.SLIDE;
        }).isEmpty());
        assertEquals(0, asked[0], "layers come before the filter");
    }

    @Test
    void alreadyOverlapping_doesNotBlock_andIsReportedFirst() {
        World w = new World();
        Body wall = w.add(new Rect(40, 0, 40, 200));
        Body ball = w.add(new Circle(50, 50, 10));
        List<Collision> c = w.move(ball, 100, 0);
        assertEquals(1, c.size());
        assertTrue(c.get(0).hit().alreadyOverlapping());
        assertEquals(wall, c.get(0).other());
        assertEquals(150, ((Circle) ball.shape()).x(), 1e-3);
    }

    // ------------------------------------------------------------------ platforms

    @Test
    void oneWayPlatform_passedFromBelowAndTheSide_stoodOnFromAbove() {
        World w = new World();
        Body platform = w.add(new Rect(0, 100, 200, 10)).oneWay(Side.TOP);
        Body player = w.add(new Rect(50, 130, 20, 20));
        List<Collision> up = w.move(player, 0, -60);
        assertTrue(up.isEmpty(), "jumps through from below: " + up);
        assertEquals(70, ((Rect) player.shape()).y(), 1e-4);
        List<Collision> down = w.move(player, 0, 40);
        assertEquals(1, down.size());
        assertTrue(down.get(0).landed());
        assertEquals(platform, down.get(0).other());
        assertEquals(80, ((Rect) player.shape()).y(), 1e-4);
        // From the side, level with it: passes.
        player.moveTo(-50, 105);
        assertTrue(w.move(player, 300, 0).isEmpty());
        // Halfway in and falling: falls through (it overlapped at the start).
        player.moveTo(100, 105);
        w.move(player, 0, 50);
        assertEquals(155, player.pivotY(), 1e-4);
    }

    @Test
    void carrier_takesWhatStandsOnItAlong() {
        World w = new World();
        Body platform = w.add(new Rect(0, 100, 100, 10)).carrier(true);
        Body rider = w.add(new Rect(40, 80, 10, 20));
        Body beside = w.add(new Rect(200, 80, 10, 20));
        w.move(platform, 30, 0);
        assertEquals(new Rect(70, 80, 10, 20), rider.shape());
        assertEquals(new Rect(200, 80, 10, 20), beside.shape());
        w.move(platform, 5, -25);
        assertEquals(new Rect(75, 55, 10, 20), rider.shape());
        assertEquals(new Rect(35, 75, 100, 10), platform.shape());
        w.move(platform, -5, 40);
        assertEquals(new Rect(70, 95, 10, 20), rider.shape());
        assertEquals(new Rect(30, 115, 100, 10), platform.shape());
        // Stopped short by a wall: the rider moves as far as the platform did.
        w.add(new Rect(150, 100, 10, 40));
        w.move(platform, 50, 0);
        assertEquals(new Rect(50, 115, 100, 10), platform.shape());
        assertEquals(new Rect(90, 95, 10, 20), rider.shape());
        // Up into a ceiling: the rider stops under it, the platform passes nothing.
        w.add(new Rect(0, 60, 140, 10));
        w.move(platform, 0, -30);
        assertEquals(new Rect(90, 70, 10, 20), rider.shape());
        assertEquals(new Rect(50, 90, 100, 10), platform.shape());
    }

    // ------------------------------------------------------------------ seams and grids

    @Test
    void slidingAlongAFloorOfTiles_neverCatchesOnTheSeams() {
        World w = new World();
        for (int i = 0; i < 40; i++) {
            w.add(new Rect(i * 16, 200, 16, 16));
        }
        for (int i = 0; i < 40; i++) {
            w.add(new Rect(0, 200 - 16 - i * 16, 16, 16));  // a wall of tiles on the left
        }
        Shape[] movers = {new Rect(100, 150, 12, 20), new Circle(100, 150, 7), Polygon.of(95, 150, 105, 150, 105, 170, 95, 170),
            new Capsule(100, 150, 100, 165, 5), new Ellipse(100, 150, 6, 9)};
        for (Shape s : movers) {
            Body b = w.add(s);
            w.move(b, 0, 100);  // land on the floor
            float y = b.pivotY();
            for (int f = 0; f < 60; f++) {
                float before = b.pivotX();
                w.move(b, 3.3f, 2);  // walk right, pressing down
                assertEquals(before + 3.3f, b.pivotX(), 1e-3, s.getClass().getSimpleName() + " frame " + f);
                assertEquals(y, b.pivotY(), 1e-3);
            }
            for (int f = 0; f < 80; f++) {
                w.move(b, -5, 2);
            }
            assertEquals(16, Extents.minX(b.shape()), 1e-3, "stopped at the wall");
            for (int f = 0; f < 30; f++) {
                float before = b.pivotY();
                w.move(b, -2, -3.1f);  // up along the wall, pressing left
                assertEquals(before - 3.1f, b.pivotY(), 1e-3, s.getClass().getSimpleName() + " up the wall " + f);
            }
            w.remove(b);
        }
    }

    @Test
    void aGridInTheWorld_actsAsItsSolidCells_likeGridMove() {
        Grid g = Grid.parse("""
                ##########
                #........#
                #..##....#
                #........#
                #.....#..#
                ##########
                """, 32);
        World w = new World();
        Body grid = w.add(g);
        SplittableRandom rnd = new SplittableRandom(3);
        int met = 0;
        for (int i = 0; i < 300; i++) {
            Rect start = new Rect(40 + rnd.nextInt(240), 40 + rnd.nextInt(120), 6 + rnd.nextInt(20), 6 + rnd.nextInt(20));
            if (g.overlapsSolid(new Rect(start.x(), start.y(), start.w(), start.h()))) {
                continue;
            }
            Body b = w.add(start);
            float dx = rnd.nextInt(200) - 100, dy = rnd.nextInt(200) - 100;
            Sweep.Move want = g.move(start, dx, dy);
            List<Collision> c = w.move(b, dx, dy);
            assertEquals(new Rect(want.x(), want.y(), start.w(), start.h()), b.shape(), start + " by " + dx + ", " + dy);
            for (Collision k : c) {
                assertEquals(grid, k.other());
                assertTrue(g.isSolid(k.cell() % g.cols(), k.cell() / g.cols()));
                met++;
            }
            w.remove(b);
        }
        assertTrue(met > 50);
        Body ball = w.add(new Circle(100, 100, 8));
        w.move(ball, 500, 300);
        assertFalse(g.overlapsSolid(new Rect(ball.shape().bounds().x() + 1, ball.shape().bounds().y() + 1, 14, 14)));
        assertEquals(1, w.queryPoint(5, 5).size());
        assertTrue(w.queryPoint(50, 50).isEmpty());
    }

    // ------------------------------------------------------------------ turning

    @Test
    void turningBody_isDrawnAsTranslateRotate() {
        World w = new World();
        Body b = w.add(new Rect(-20, -10, 40, 20), 100, 50, 0);
        assertEquals(new Rect(80, 40, 40, 20), b.shape());
        b.turnTo((float) (Math.PI / 2));
        Shape s = b.shape();
        assertTrue(s instanceof Polygon);
        assertEquals(90, Extents.minX(s), 1e-3);
        assertEquals(110, Extents.maxX(s), 1e-3);
        assertEquals(30, Extents.minY(s), 1e-3);
        assertEquals(70, Extents.maxY(s), 1e-3);
        assertTrue(b.bounds().x() <= Extents.minX(s) && b.bounds().x() + b.bounds().w() >= Extents.maxX(s));
        // Clockwise on screen: the local point (20, 0) goes to (100, 70) after a quarter turn.
        assertTrue(s.contains(100, 68));
        assertFalse(s.contains(119, 50));
        Body e = w.add(new Ellipse(0, 0, 10, 5), 0, 0, 0.5f);
        assertEquals(0.5f, ((Ellipse) e.shape()).angle(), 1e-6);
        assertNotNull(w.queryPoint(100, 68));
    }

    // ------------------------------------------------------------------ helpers

    private static float coord(SplittableRandom rnd) {
        return rnd.nextInt(400);
    }

    private static float size(SplittableRandom rnd) {
        return rnd.nextInt(5) == 0 ? rnd.nextInt(3) : 2 + rnd.nextInt(60);
    }

    private static float speed(SplittableRandom rnd) {
        return switch (rnd.nextInt(4)) {
            case 0 -> 0;
            case 1 -> rnd.nextInt(21) - 10;
            case 2 -> rnd.nextInt(401) - 200;
            default -> rnd.nextInt(20001) - 10000;
        };
    }
}
