package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 28's character, played as a game plays it: gravity every frame, a walk, a jump. Judged
 * by where it ends against the terrain's own geometry (the slope's line, the step's top).
 */
class CharacterBodyTest {

    static final float GRAVITY = 0.5f;

    /** A floor at y = 400 and a slope rising to the right from x = 200 at the given angle. */
    static World slopeWorld(float degrees) {
        World w = new World();
        w.add(new Rect(-400, 400, 1600, 40));
        double rise = 300 * Math.tan(Math.toRadians(degrees));
        w.add(Polygon.of(200, 400, 500, (float) (400 - rise), 500, 400));
        w.add(new Rect(500, (float) (400 - rise), 400, (float) rise));  // a plateau at the top
        return w;
    }

    /** One frame of a game: gravity, a walk, and a stop when on the ground. Returns the new vy. */
    static float frame(CharacterBody hero, float vx, float vy) {
        vy += GRAVITY;
        hero.move(vx, vy);
        return hero.onGround() ? 0 : vy;
    }

    @ParameterizedTest
    @ValueSource(floats = {10, 25, 40, 45})
    void walksUpASlope_atItsCommandedSidewaysSpeed_onTheGroundEveryFrame(float degrees) {
        World w = slopeWorld(degrees);
        CharacterBody hero = w.addCharacter(new Rect(100, 370, 20, 30));
        double tan = Math.tan(Math.toRadians(degrees));
        float vy = 0;
        for (int f = 0; f < 200; f++) {
            float x = hero.body().pivotX();
            vy = frame(hero, 2, vy);
            assertEquals(x + 2, hero.body().pivotX(), 1e-3, degrees + " degrees, frame " + f);
            assertTrue(hero.onGround(), degrees + " degrees, frame " + f + " in the air at " + hero.body().shape());
            Shape s = hero.body().shape();
            // Its foot stands on the ground's line: the floor, the slope or the plateau.
            double foot = Extents.maxX(s) <= 200 ? 400 : Extents.maxX(s) >= 500 ? 400 - 300 * tan : 400 - (Extents.maxX(s) - 200) * tan;
            assertTrue(Extents.maxY(s) <= foot + 1e-3 && Extents.maxY(s) >= foot - 0.1, degrees + " degrees, frame " + f + ": foot at "
                    + Extents.maxY(s) + ", ground at " + foot);
        }
        assertTrue(hero.body().pivotX() > 500, "stopped at " + hero.body().shape());
    }

    @Test
    void walksDownASlopeWithSnap_onTheGroundEveryFrame() {
        World w = slopeWorld(30);
        CharacterBody hero = w.addCharacter(new Rect(600, 100, 20, 30)).snap(4);
        float vy = 0;
        for (int f = 0; f < 20; f++) {
            vy = frame(hero, 0, vy);  // land on the plateau
        }
        assertTrue(hero.onGround());
        for (int f = 0; f < 200; f++) {
            float x = hero.body().pivotX();
            vy = frame(hero, -2, vy);
            assertEquals(x - 2, hero.body().pivotX(), 1e-3, "frame " + f);
            assertTrue(hero.onGround(), "frame " + f + " left the ground at " + hero.body().shape());
        }
        CharacterBody noSnap = slopeWorld(30).addCharacter(new Rect(480, 200, 20, 30));
        float vz = 0;
        int airborne = 0;
        for (int f = 0; f < 120; f++) {
            vz = frame(noSnap, -2, vz);
            airborne += noSnap.onGround() ? 0 : 1;
        }
        assertTrue(airborne > 20, "without snap, walking down a 30-degree slope at 2 px a frame leaves the ground");
    }

    @ParameterizedTest
    @ValueSource(floats = {15, 30, 44})
    void standsStillOnASlope_underGravity(float degrees) {
        World w = slopeWorld(degrees);
        CharacterBody hero = w.addCharacter(new Rect(320, 100, 20, 30));
        float vy = 0;
        for (int f = 0; f < 80; f++) {
            vy = frame(hero, 0, vy);
        }
        assertTrue(hero.onGround());
        Shape rest = hero.body().shape();
        for (int f = 0; f < 120; f++) {
            vy = frame(hero, 0, vy);
            assertEquals(rest, hero.body().shape(), degrees + " degrees: drifted at frame " + f);
            assertTrue(hero.onGround());
        }
        Vec n = hero.groundNormal();
        assertEquals(-Math.sin(Math.toRadians(degrees)), n.x(), 1e-5);
        assertEquals(-Math.cos(Math.toRadians(degrees)), n.y(), 1e-5);
        assertEquals(1, Math.hypot(n.x(), n.y()), 1e-6);
        assertTrue(hero.ground() != null && hero.ground().shape() instanceof Polygon);
    }

    @Test
    void slopesSteeperThanMaxSlope_areWallsItSlidesDown() {
        World w = slopeWorld(60);
        CharacterBody hero = w.addCharacter(new Rect(330, 100, 20, 30));
        float vy = 0;
        float lowest = 0;
        for (int f = 0; f < 60; f++) {
            vy = frame(hero, 0, vy);
            assertTrue(hero.body().pivotY() >= lowest, "went up a steep slope");
            lowest = hero.body().pivotY();
        }
        assertTrue(Extents.maxY(hero.body().shape()) > 399, "did not slide down: " + hero.body().shape());
        // Walking into it from the floor does not climb it.
        CharacterBody walker = slopeWorld(60).addCharacter(new Rect(100, 370, 20, 30));
        float wy = 0;
        for (int f = 0; f < 120; f++) {
            wy = frame(walker, 2, wy);
        }
        assertTrue(Extents.maxY(walker.body().shape()) >= 400 - 1e-3 - 40, "climbed a 60-degree slope: " + walker.body().shape());
        assertTrue(Extents.maxX(walker.body().shape()) < 200 + 40 / Math.tan(Math.toRadians(60)) + 1, walker.body().shape().toString());
        assertTrue(walker.onWall());
        assertEquals(60f, slopeWorld(10).addCharacter(new Rect(0, 0, 1, 1)).maxSlope(60).maxSlope());
    }

    /** A character with a step height of 10 that walks for 100 frames into a ledge at x = 300. */
    static CharacterBody walkIntoALedge(float ledge) {
        World w = new World();
        w.add(new Rect(0, 400, 800, 40));
        w.add(new Rect(300, 400 - ledge, 500, ledge));
        CharacterBody hero = w.addCharacter(new Rect(200, 370, 20, 30)).stepHeight(10);
        float vy = 0;
        for (int f = 0; f < 100; f++) {
            vy = frame(hero, 2, vy);
        }
        return hero;
    }

    @ParameterizedTest
    @ValueSource(floats = {4, 9.5f, 10})
    void stepsUpToStepHeight_areClimbed(float ledge) {
        CharacterBody hero = walkIntoALedge(ledge);
        Shape s = hero.body().shape();
        assertTrue(Extents.minX(s) > 350, ledge + " px: did not climb, at " + s);
        assertEquals(400 - ledge, Extents.maxY(s), 1e-3, ledge + " px: not on the step's top");
        assertTrue(hero.onGround());
    }

    @ParameterizedTest
    @ValueSource(floats = {10.5f, 14, 30})
    void higherLedges_areWalls(float ledge) {
        CharacterBody hero = walkIntoALedge(ledge);
        Shape s = hero.body().shape();
        assertEquals(300, Extents.maxX(s), 1e-3, ledge + " px: " + s);
        assertEquals(400, Extents.maxY(s), 1e-3);
        assertTrue(hero.onWall() && hero.onGround());
    }

    @Test
    void aStaircase_isClimbedStepByStep() {
        World w = new World();
        w.add(new Rect(0, 400, 800, 40));
        for (int i = 0; i < 8; i++) {
            w.add(new Rect(300 + 24 * i, 400 - 8 * (i + 1), 24, 8 * (i + 1)));
        }
        w.add(new Rect(492, 336, 300, 64));  // the landing at the top
        CharacterBody hero = w.addCharacter(new Rect(200, 370, 16, 30)).stepHeight(9);
        float vy = 0;
        for (int f = 0; f < 150; f++) {
            vy = frame(hero, 2, vy);
        }
        assertEquals(400 - 64, Extents.maxY(hero.body().shape()), 1e-3, "at " + hero.body().shape());
    }

    @Test
    void spawnedInsideTheFloor_isPushedOutTheShortWay() {
        World w = new World();
        Body floor = w.add(new Rect(0, 400, 800, 40));
        CharacterBody hero = w.addCharacter(new Rect(100, 375, 20, 30));  // 5 px into the floor
        Collisions got = hero.move(0, 0);
        Shape s = hero.body().shape();
        assertFalse(s.overlaps(floor.shape()));
        assertEquals(400, Extents.maxY(s), 0.1);
        assertEquals(100, Extents.minX(s), 1e-6);
        assertTrue(got.stream().anyMatch(c -> c.other() == floor && c.hit().alreadyOverlapping()), got.toString());
        // A platform teleported into it: the next move pushes it out upwards, the short way.
        Body plank = w.add(new Rect(300, 300, 100, 10));
        CharacterBody other = w.addCharacter(new Rect(340, 280, 20, 30));
        plank.moveTo(350, 303);  // its top at 298, two pixels into the character's feet (310)
        other.move(0, 1);
        assertFalse(other.body().shape().overlaps(plank.shape()));
        assertTrue(Extents.maxY(other.body().shape()) <= 298 + 1e-3 && Extents.maxY(other.body().shape()) >= 297.9, other.body().shape().toString());
    }

    @Test
    void spawnedAcrossASegment_walksOffIt() {
        World w = new World();
        w.add(new Rect(0, 400, 800, 40));
        Body line = w.add(new Segment(100, 350, 200, 390));  // across the character's head
        CharacterBody hero = w.addCharacter(new Rect(140, 370, 20, 30));
        Collisions got = hero.move(5, 1);  // a segment has no inside to push out of: it is walked off
        assertTrue(got.stream().anyMatch(c -> c.other() == line && c.hit().alreadyOverlapping()), got.toString());
        assertEquals(new Rect(145, 370, 20, 30), hero.body().shape());
        assertTrue(hero.onGround());
    }

    @Test
    void spawnedInsideAGridsCell_isPushedOutAndStandsOnIt() {
        World w = new World();
        Grid grid = new Grid(10, 10, 20);
        for (int col = 0; col < 10; col++) {
            grid.set(col, 5, Grid.SOLID);  // a floor of cells from y = 100 to 120
        }
        w.add(grid);
        CharacterBody hero = w.addCharacter(new Rect(30, 85, 10, 20));  // 5 px into the floor
        hero.move(0, 1);
        assertEquals(100, Extents.maxY(hero.body().shape()), 1e-3);
        assertTrue(hero.onGround());
        for (int f = 0; f < 40; f++) {
            hero.move(2, 1);
            assertEquals(100, Extents.maxY(hero.body().shape()), 1e-3);
        }
        assertEquals(110, Extents.minX(hero.body().shape()), 1e-3);
    }

    @Test
    void ridesACarrier_withItsOwnFilter() {
        for (boolean ghost : new boolean[] {true, false}) {
            World w = new World();
            Body platform = w.add(new Rect(100, 300, 120, 10)).carrier(true);
            Body pillar = w.add(new Rect(260, 200, 10, 95));  // stands in the rider's way, above the platform's path
            CollisionFilter filter = (m, o) -> ghost && o == pillar ? Reaction.CROSS : Reaction.SLIDE;
            CharacterBody hero = w.addCharacter(new Rect(140, 270, 20, 30));
            float vy = 0;
            for (int f = 0; f < 5; f++) {
                vy += GRAVITY;
                hero.move(0, vy, filter);
                vy = hero.onGround() ? 0 : vy;
            }
            assertSame(platform, hero.ground());
            for (int f = 0; f < 60; f++) {
                w.move(platform, 2, 0);
                vy += GRAVITY;
                hero.move(0, vy, filter);
                vy = hero.onGround() ? 0 : vy;
            }
            float x = hero.body().shape().bounds().x();
            if (ghost) {
                assertEquals(260, x, 1e-3, "a rider whose filter crosses the pillar is carried through it");
            } else {
                assertEquals(240, x, 1e-3, "a rider that slides on the pillar is held by it");
            }
        }
    }

    @Test
    void ridesAPlatformThatGoesUpAndDown() {
        World w = new World();
        Body lift = w.add(new Rect(100, 300, 80, 10)).carrier(true);
        CharacterBody hero = w.addCharacter(new Rect(130, 260, 20, 30));
        float vy = 0;
        for (int f = 0; f < 30; f++) {
            vy = frame(hero, 0, vy);
        }
        for (int f = 0; f < 120; f++) {
            w.move(lift, 0, f < 60 ? -2 : 2);
            vy = frame(hero, 0, vy);
            assertEquals(Extents.minY(lift.shape()), Extents.maxY(hero.body().shape()), 1e-3, "frame " + f);
            assertTrue(hero.onGround());
        }
    }

    @Test
    void aFloorOfSeparateTiles_neverSnagsIt() {
        World w = new World();
        for (int i = 0; i < 30; i++) {
            float x = 16 * i;
            switch (i % 3) {
                case 0 -> w.add(new Rect(x, 400, 16, 16));
                case 1 -> w.add(Polygon.of(x, 400, x + 16, 400, x + 16, 416, x, 416));
                default -> w.add(new Rect(-8, -8, 16, 16), x + 8, 408, 1e-7f);  // turned a hair: rounds to the same line
            }
        }
        for (Shape s : new Shape[] {new Rect(20, 370, 20, 30), new Circle(30, 388, 12), Polygon.regular(30, 388, 12, 6, 0)}) {
            CharacterBody hero = w.addCharacter(s);
            float vy = 0;
            for (int f = 0; f < 10; f++) {
                vy = frame(hero, 0, vy);
            }
            for (int f = 0; f < 180; f++) {
                float x = hero.body().pivotX();
                vy = frame(hero, 2, vy);
                assertEquals(x + 2, hero.body().pivotX(), 1e-3, s + " snagged at frame " + f + ": " + hero.body().shape());
                assertTrue(hero.onGround());
            }
            w.remove(hero.body());
        }
    }

    @Test
    void topDown_slidesAlongTurnedWallsAndRoundRocks() {
        World w = new World();
        Body wall = w.add(new Rect(-300, -10, 600, 20), 300, 300, (float) Math.toRadians(30));
        CharacterBody ship = w.addCharacter(new Circle(200, 150, 10)).up(0, 0);
        double tx = Math.cos(Math.toRadians(30)), ty = Math.sin(Math.toRadians(30));
        for (int f = 0; f < 100; f++) {
            ship.move(0, 3);  // straight down into the wall
        }
        assertTrue(ship.onWall() && !ship.onGround() && ship.groundNormal() == null);
        float x = ship.body().pivotX(), y = ship.body().pivotY();
        for (int f = 0; f < 40; f++) {
            ship.move(2, 1.5f);  // mostly along it, pressing in
        }
        double along = (ship.body().pivotX() - x) * tx + (ship.body().pivotY() - y) * ty;
        assertTrue(along > 0.99 * 40 * (2 * tx + 1.5 * ty), "slid only " + along);
        assertTrue(WorldSlideTest.gap(ship.body().shape(), wall.shape()) <= 0.1);
        // A round rock met off-centre: it gets round.
        World rocks = new World();
        rocks.add(new Circle(300, 300, 40));
        CharacterBody s2 = rocks.addCharacter(new Rect(100, 280, 16, 16)).up(0, 0);
        for (int f = 0; f < 200; f++) {
            s2.move(2, 0);
        }
        assertTrue(Extents.minX(s2.body().shape()) > 340, "stuck at " + s2.body().shape());
    }

    @Test
    void ceilingsAndWalls_areReported() {
        World w = new World();
        w.add(new Rect(0, 400, 800, 40));
        w.add(new Rect(0, 300, 800, 20));  // a ceiling 80 px above the floor
        w.add(new Rect(400, 320, 20, 80));  // a wall
        CharacterBody hero = w.addCharacter(new Rect(100, 370, 20, 30));
        hero.move(0, 1);
        assertTrue(hero.onGround() && !hero.onCeiling() && !hero.onWall());
        hero.move(0, -100);  // jump into the ceiling
        assertTrue(hero.onCeiling() && !hero.onGround());
        assertEquals(320, Extents.minY(hero.body().shape()), 1e-3);
        assertNull(hero.ground());
        for (int f = 0; f < 200; f++) {
            hero.move(3, 5);
        }
        assertTrue(hero.onWall() && hero.onGround());
        assertEquals(400, Extents.maxX(hero.body().shape()), 1e-3);
    }

    @Test
    void badSettings_areRefusedAndChangeNothing() {
        World w = new World();
        CharacterBody hero = w.addCharacter(new Rect(0, 0, 10, 10)).maxSlope(30).stepHeight(4).snap(2).up(0, -2);
        assertThrows(IllegalArgumentException.class, () -> hero.maxSlope(90));
        assertThrows(IllegalArgumentException.class, () -> hero.maxSlope(-1));
        assertThrows(IllegalArgumentException.class, () -> hero.stepHeight(Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> hero.snap(Float.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> hero.up(Float.NaN, 1));
        assertEquals(30, hero.maxSlope());
        assertEquals(4, hero.stepHeight());
        assertEquals(2, hero.snap());
        assertEquals(new Vec(0, -1), hero.up());
        w.remove(hero.body());
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> hero.move(1, 1));
        assertTrue(e.getMessage().contains("removed"), e.getMessage());
    }
}
