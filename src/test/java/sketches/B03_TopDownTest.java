package sketches;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Body;
import hitbox.Circle;
import hitbox.Collision;
import hitbox.Polygon;
import hitbox.Ray;
import hitbox.Reaction;
import hitbox.RayHit;
import hitbox.Segment;
import hitbox.Shape;
import hitbox.processing.Drawn;
import hitbox.processing.Palette;
import processing.awt.PGraphicsJava2D;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * Turning rocks, turned walls and a ship drawn with translate and rotate, tested as drawn; the
 * ship a character body seen from above (up(0, 0)), sliding along the walls and round the
 * rocks; the sentry's line of sight by a ray cast through the world, checked against every
 * body by hand.
 */
class B03_TopDownTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** Is (x, y) at least d from the shape's outline (both it and a ring of radius d about it agree)? */
    private static boolean clearOfOutline(Shape s, float x, float y, float d) {
        boolean in = s.contains(x, y);
        for (int i = 0; i < 16; i++) {
            double t = 2 * Math.PI * i / 16;
            if (s.contains(x + d * (float) Math.cos(t), y + d * (float) Math.sin(t)) != in) {
                return false;
            }
        }
        return true;
    }

    @Test
    void rocksAndShip_drawnWithTranslateAndRotate_areWhereTheirShapesSayTheyAre() {
        int[] inside = {0};
        int[] outside = {0};
        SketchRun.Result<B03_TopDown> r = SketchRun.of(new B03_TopDown()).frames(150).run();
        B03_TopDown s = r.sketch();
        PImage f = r.lastFrame();
        List<Shape> all = new ArrayList<>();
        for (Body rock : s.rocks) {
            all.add(rock.shape());
        }
        for (Body wall : s.walls) {
            all.add(wall.shape());
        }
        all.add(s.ship.body().shape());
        Segment line = new Segment(s.sentryX, s.sentryY, s.ship.body().pivotX(), s.ship.body().pivotY());
        for (Body b : s.world.bodies()) {
            Shape shape = b.shape();
            assertTrue(b.angle() != 0 && shape instanceof Polygon, "a turned body stands as a polygon: " + b);
            // The ship is red for a few frames after a contact, blue otherwise.
            List<Integer> colours = b == s.ship.body() ? List.of(Palette.PLAYER, Palette.HIT)
                    : s.walls.contains(b) ? List.of(Palette.NEUTRAL) : List.of(Palette.OBSTACLE);
            for (int y = (int) Extents.minY(shape) - 3; y <= Extents.maxY(shape) + 3; y += 2) {
                for (int x = (int) Extents.minX(shape) - 3; x <= Extents.maxX(shape) + 3; x += 2) {
                    float px = x + 0.5f, py = y + 0.5f;
                    boolean underText = y >= s.height - 20 || y < 50 && x < 330;   // the hint bar, the label
                    if (x < 0 || y < 0 || x >= s.width || underText || !clearOfOutline(shape, px, py, 2)
                            || line.overlaps(new Circle(px, py, 5)) || new Circle(s.sentryX, s.sentryY, 14).contains(px, py)) {
                        continue;
                    }
                    if (shape.contains(px, py)) {
                        assertTrue(colours.contains(f.get(x, y)), "(" + x + ", " + y + ") inside " + b + " is drawn in its colour, not "
                                + Integer.toHexString(f.get(x, y)));
                        inside[0]++;
                    } else if (all.stream().allMatch(o -> !o.contains(px, py) && clearOfOutline(o, px, py, 2))) {
                        assertEquals(Palette.BACKGROUND, f.get(x, y), "(" + x + ", " + y + ") outside every body is background");
                        outside[0]++;
                    }
                }
            }
        }
        assertTrue(inside[0] > 1000 && outside[0] > 500, "pixels checked: " + inside[0] + " inside, " + outside[0] + " outside");
    }

    @Test
    void everyBody_isTheShapeTheDrawingMatrixPutsOnScreen() {
        // The sketch's drawTurned, on an off-screen PGraphics: translate(x, y); rotate(angle);
        // then the shape in its own frame. Drawn.shape reads the matrix; the body must agree.
        B03_TopDown s = SketchRun.of(new B03_TopDown()).frames(90).run().sketch();
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(600, 400);
        g.beginDraw();
        for (Body b : s.world.bodies()) {
            g.pushMatrix();
            g.translate(b.pivotX(), b.pivotY());
            g.rotate(b.angle());
            Polygon drawn = (Polygon) Drawn.shape(g, b.homeShape());
            g.popMatrix();
            Polygon body = (Polygon) b.shape();
            assertEquals(drawn.size(), body.size(), b.toString());
            for (int i = 0; i < body.size(); i++) {
                assertEquals(drawn.x(i), body.x(i), 1e-3f, b + " corner " + i + " x");
                assertEquals(drawn.y(i), body.y(i), 1e-3f, b + " corner " + i + " y");
            }
        }
        g.endDraw();
    }

    @Test
    void leftAndRight_turnTheShip_andItsShapeTurnsWithIt() {
        Script script = new Script().frames(40).hold(1, "LEFT", 20);
        float[] last = {Float.NaN};
        int[] turned = {0};
        SketchRun.of(new B03_TopDown()).script(script).everyFrame(s -> {
            Body ship = s.ship.body();
            if (s.left && !Float.isNaN(last[0])) {
                assertEquals(last[0] - 0.08f, ship.angle(), 1e-5f, "frame " + s.frameCount);
                turned[0]++;
            }
            last[0] = ship.angle();
            // The nose, (16, 0) in the ship's own frame, is the first corner of its shape now.
            Polygon p = (Polygon) ship.shape();
            float a = ship.angle();
            assertEquals(ship.pivotX() + 16 * (float) Math.cos(a), p.x(0), 1e-3f, "the nose x");
            assertEquals(ship.pivotY() + 16 * (float) Math.sin(a), p.y(0), 1e-3f, "the nose y");
        }).run();
        assertTrue(turned[0] >= 15, "frames turned left: " + turned[0]);
    }

    @Test
    void sentry_seesTheShipExactlyWhenNoRockIsNearerOnTheRay() {
        int[] seen = {0};
        int[] hidden = {0};
        SketchRun.of(new B03_TopDown()).frames(600).everyFrame(s -> {
            if (s.sight == null && !s.seen) {
                return;   // the ship right on the sentry: no ray
            }
            Ray ray = Ray.between(s.sentryX, s.sentryY, s.ship.body().pivotX(), s.ship.body().pivotY());
            RayHit toShip = ray.cast(s.ship.body().shape());
            assertNotNull(toShip, "the ray towards the ship's position reaches its outline");
            float nearestRock = Float.POSITIVE_INFINITY;   // or wall
            List<Body> inTheWay = new ArrayList<>(s.rocks);
            inTheWay.addAll(s.walls);
            for (Body rock : inTheWay) {
                RayHit h = ray.cast(rock.shape());
                if (h != null) {
                    nearestRock = Math.min(nearestRock, h.distance());
                }
            }
            boolean expected = toShip.distance() < nearestRock;
            assertEquals(expected, s.seen, "frame " + s.frameCount + ": ship at " + toShip.distance() + ", nearest rock or wall at " + nearestRock);
            if (!s.seen) {
                assertEquals(nearestRock, s.sight.distance(), 1e-3f, "the ray stops at the nearest rock or wall");
            }
            seen[0] += s.seen ? 1 : 0;
            hidden[0] += s.seen ? 0 : 1;
        }).run();
        assertTrue(seen[0] > 50 && hidden[0] > 20, "frames seen: " + seen[0] + ", hidden: " + hidden[0]);
    }

    @Test
    void ship_slidesAlongRocksAndWalls_andEndsEachMoveOutsideThose_itMet() {
        int[] slides = {0};
        boolean[] metAWall = {false};
        SketchRun.of(new B03_TopDown()).frames(900).everyFrame(s -> {
            for (Collision c : s.met) {
                assertTrue(s.rocks.contains(c.other()) || s.walls.contains(c.other()), "the ship meets rocks and walls only");
                assertEquals(Reaction.SLIDE, c.reaction(), "it slides along them");
                if (!c.hit().alreadyOverlapping()) {
                    slides[0]++;
                    metAWall[0] |= s.walls.contains(c.other());
                    Shape ship = s.ship.body().shape();
                    assertFalse(ship.overlaps(c.other().shape()), "frame " + s.frameCount + ": the ship ends clear of what it slid along");
                }
            }
        }).run();
        assertTrue(slides[0] > 0 && metAWall[0], "the demo slides along rocks and a wall: " + slides[0]);
    }

    @Test
    void ship_thrustingStraightAtARockOffCentre_getsRoundIt() {
        // Pointing up from (300, 200), it thrusts at rock 5 (at (320, 100)), 20 pixels left of
        // the rock's middle: it meets the rock's underside, slides left along it and round its
        // flank, never stopping, and goes on up past it.
        Script script = new Script().frames(92).hold(1, "UP", 91);
        int[] met = {-1};
        int[] past = {-1};
        float[] last = {Float.NaN, Float.NaN};
        SketchRun.Result<B03_TopDown> r = SketchRun.of(new B03_TopDown()).script(script).everyFrame(s -> {
            Body rock = s.rocks.get(5);
            Body ship = s.ship.body();
            assertFalse(ship.shape().overlaps(rock.shape()), "frame " + s.frameCount + ": never inside the rock");
            for (Collision c : s.met) {
                if (c.other() == rock && met[0] < 0) {
                    met[0] = s.frameCount;
                    assertTrue(Extents.minY(ship.shape()) > rock.pivotY(), "it meets the rock's lower half");
                }
            }
            if (met[0] > 0 && past[0] < 0 && Extents.maxY(ship.shape()) < Extents.minY(rock.shape())) {
                past[0] = s.frameCount;
            }
            if (met[0] > 0 && met[0] < s.frameCount && past[0] < 0) {
                float moved = (float) Math.hypot(ship.pivotX() - last[0], ship.pivotY() - last[1]);
                assertTrue(moved > 0.5f, "frame " + s.frameCount + ": round the rock, it never stops: moved " + moved);
            }
            last[0] = ship.pivotX();
            last[1] = ship.pivotY();
        }).run();
        assertTrue(met[0] > 0, "the ship met the rock");
        assertTrue(past[0] > met[0], "and got round it, above it: frames " + met[0] + ", " + past[0]);
        // What is drawn: the ship's colour on its body, above the rock.
        B03_TopDown s = r.sketch();
        Body ship = s.ship.body();
        int x = Math.round(ship.pivotX() + 4 * (float) Math.cos(ship.angle()));
        int y = Math.round(ship.pivotY() + 4 * (float) Math.sin(ship.angle()));
        if (ship.pivotY() > 0) {
            assertTrue(List.of(Palette.PLAYER, Palette.HIT).contains(r.lastFrame().get(x, y)), "the ship drawn at (" + x + ", " + y + ")");
        }
    }

    @Test
    void ship_flownIntoATurnedWall_slidesAlongIt_neverStopping() {
        // It turns right to point along +x, thrusts, and meets wall 0 (at (400, 210), turned
        // by 1 radian) at a slant: from then on it slides down along the wall, every frame.
        Script script = new Script().frames(90).hold(1, "RIGHT", 20).hold(22, "UP", 67);
        int[] along = {0};
        float[] last = {Float.NaN, Float.NaN};
        SketchRun.of(new B03_TopDown()).script(script).everyFrame(s -> {
            Body wall = s.walls.get(0);
            Body ship = s.ship.body();
            assertFalse(ship.shape().overlaps(wall.shape()), "frame " + s.frameCount + ": never inside the wall");
            boolean touching = false;
            for (Collision c : s.met) {
                touching |= c.other() == wall;
            }
            if (touching && !Float.isNaN(last[0])) {
                float dx = ship.pivotX() - last[0], dy = ship.pivotY() - last[1];
                float alongWall = dx * (float) Math.cos(1.0) + dy * (float) Math.sin(1.0);
                assertTrue(alongWall > 0.5f, "frame " + s.frameCount + ": slides along the wall: (" + dx + ", " + dy + ")");
                along[0]++;
            }
            last[0] = ship.pivotX();
            last[1] = ship.pivotY();
        }).run();
        assertTrue(along[0] > 10, "frames sliding along the wall: " + along[0]);
    }

    /** Do two bodies meet by their layers: Box2D's rule, each one's category in the other's mask. */
    private static boolean meet(Body a, Body b) {
        return (a.category() & b.mask()) != 0 && (b.category() & a.mask()) != 0;
    }

    @Test
    void rocks_ignoreEachOther_byTheirLayers() {
        B03_TopDown s = SketchRun.of(new B03_TopDown()).frames(1).run().sketch();
        for (Body a : s.rocks) {
            assertTrue(meet(a, s.ship.body()), "rock and ship meet");
            for (Body b : s.rocks) {
                assertFalse(meet(a, b), "rocks do not meet rocks");
            }
            for (Body w : s.walls) {
                assertTrue(meet(w, s.ship.body()), "wall and ship meet");
                assertFalse(meet(a, w), "rocks and walls do not meet");
            }
        }
    }

    @Test
    void overlayKey_drawsWhatTheWorldSees_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).key(3, 'd').key(8, 'd');
        SketchRun.Result<B03_TopDown> r = SketchRun.of(new B03_TopDown()).script(script).capture(2).capture(6).run();
        assertTrue(SketchPixels.differing(r.frame(2), r.frame(6)) > 1000, "boxes, cells and the ray's answer");
        SketchRun.Result<B03_TopDown> plain = SketchRun.of(new B03_TopDown()).frames(12).run();
        assertEquals(0, SketchPixels.differing(plain.lastFrame(), r.lastFrame()), "pressing d again hides it");
    }
}
