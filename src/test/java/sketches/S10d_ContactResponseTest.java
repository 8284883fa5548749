package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Circle;
import hitbox.Contact;
import hitbox.Manifold;
import hitbox.Shape;
import hitbox.Vec;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10d_ContactResponse: a ball (r 18) among a circle, a rectangle, a pentagon and the window's
 * edges; push out (1) puts it at the mouse but never inside a shape, bounce (2) reverses the
 * velocity's part along the contact normal, slide (3) removes it; both keep the part along
 * the surface.
 */
class S10d_ContactResponseTest {

    /** How far a pushed-out ball may still reach into a shape: float rounding only. */
    private static final float TOUCHING = 1e-3f;

    /**
     * A speed into a shape below this is float rounding (a ball sliding along a surface): the
     * library, deciding in double, may or may not see it as moving in.
     */
    private static final float MOVING = 1e-5f;

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The ball overlaps no shape and no window edge (beyond rounding). */
    private static void assertClear(S10d_ContactResponse s) {
        Circle ball = new Circle(s.x, s.y, s.r);
        for (Shape[] list : new Shape[][] {s.shapes, s.walls}) {
            for (Shape shape : list) {
                Contact c = ball.contact(shape);
                assertTrue(c == null || c.depth() < TOUCHING,
                        "the ball at (" + s.x + ", " + s.y + ") is " + (c == null ? 0 : c.depth()) + " inside " + shape);
            }
        }
    }

    /** A mouse path over the whole window and past its edges, row by row. */
    private static Script sweep(Script script, int from, int frames) {
        for (int f = 0; f < frames; f++) {
            int x = -40 + (f * 11) % 680;
            int y = -30 + (f / 62) * 23 % 460;
            script.mouse(from + f, x, y);
        }
        return script;
    }

    @Test
    void pushOut_ballNeverOverlapsAShape_andIsAtTheMouseWhenClear() {
        Set<Integer> pushedOutOf = new HashSet<>();
        int[] contacts = {0};
        SketchRun.of(new S10d_ContactResponse()).script(sweep(new Script(), 1, 1500).frames(1500)).everyFrame(s -> {
            assertEquals(s.PUSH, s.mode);
            assertClear(s);
            if (s.answers.isEmpty()) {
                assertEquals(s.mouseX, s.x, "no contact: the ball is at the mouse");
                assertEquals(s.mouseY, s.y);
            }
            for (S10d_ContactResponse.Answer a : s.answers) {
                contacts[0]++;
                pushedOutOf.add(a.shape);
            }
        }).run();
        assertTrue(contacts[0] > 100, "the mouse went into shapes, contacts: " + contacts[0]);
        assertEquals(Set.of(0, 1, 2, 3, 4, 5, 6), pushedOutOf, "pushed out of every shape and every window edge");
    }

    @Test
    void bounce_reversesTheNormalPart_andKeepsTheSurfacePart() {
        Script script = new Script().frames(4000).key(1, '2');
        // Throws now and then, at the mouse.
        sweep(script, 2, 3990);
        for (int f = 200; f < 4000; f += 250) {
            script.press(f).release(f + 1);
        }
        Set<Integer> bouncedOff = new HashSet<>();
        int[] into = {0};
        SketchRun.of(new S10d_ContactResponse()).script(script).everyFrame(s -> {
            assertClear(s);
            if (s.frameCount < 3) {
                return;   // the key reaches the sketch after frame 1
            }
            assertEquals(s.BOUNCE, s.mode);
            for (S10d_ContactResponse.Answer a : s.answers) {
                Contact c = a.contact;
                Vec n = new Vec(c.nx(), c.ny());
                Vec t = new Vec(-n.y(), n.x());
                Vec v0 = a.before;
                Vec v1 = a.after;
                if (v0.dot(n) > MOVING) {
                    into[0]++;
                    bouncedOff.add(a.shape);
                    assertEquals(-v0.dot(n), v1.dot(n), 1e-4f, "the part along the normal is reversed");
                } else {
                    assertEquals(v0.dot(n), v1.dot(n), 2 * MOVING, "moving away already (or sliding along): as it was");
                }
                assertEquals(v0.dot(t), v1.dot(t), 1e-4f, "the part along the surface is kept");
            }
        }).run();
        assertTrue(into[0] > 30, "bounces: " + into[0]);
        assertTrue(bouncedOff.containsAll(Set.of(0, 1, 2)), "bounced off the circle, the rect and the pentagon: " + bouncedOff);
    }

    @Test
    void slide_removesTheNormalPart_andKeepsTheSurfacePart() {
        // Start where the ball is, then chase a mouse that wanders behind the shapes.
        Script script = new Script().frames(3000).mouse(1, 300, 340).key(1, '3');
        int[][] targets = {{160, 100}, {560, 240}, {420, 40}, {60, 300}, {430, 380}, {250, 100}};
        for (int k = 0; k < 15; k++) {
            int[] p = targets[k % targets.length];
            script.mouse(3 + k * 200, p[0], p[1]);
        }
        Set<Integer> slidAlong = new HashSet<>();
        int[] into = {0};
        SketchRun.of(new S10d_ContactResponse()).script(script).everyFrame(s -> {
            assertClear(s);
            if (s.frameCount < 3) {
                return;   // the key reaches the sketch after frame 1
            }
            assertEquals(s.SLIDE, s.mode);
            for (S10d_ContactResponse.Answer a : s.answers) {
                Vec n = new Vec(a.contact.nx(), a.contact.ny());
                Vec t = new Vec(-n.y(), n.x());
                Vec v0 = a.before;
                Vec v1 = a.after;
                if (v0.dot(n) > MOVING) {
                    into[0]++;
                    slidAlong.add(a.shape);
                    assertEquals(0, v1.dot(n), 1e-4f, "the part along the normal is removed");
                } else {
                    assertEquals(v0.dot(n), v1.dot(n), 2 * MOVING, "moving away already (or sliding along): as it was");
                }
                assertEquals(v0.dot(t), v1.dot(t), 1e-4f, "the part along the surface is kept");
            }
        }).run();
        assertTrue(into[0] > 30, "slides: " + into[0]);
        assertTrue(slidAlong.containsAll(Set.of(0, 1, 2)), "slid along the circle, the rect and the pentagon: " + slidAlong);
    }

    @Test
    void pushOut_drawsTheShapeRed_andTheBallOutside() {
        SketchRun.Result<S10d_ContactResponse> r = SketchRun.of(new S10d_ContactResponse())
                .script(new Script().frames(4).mouse(1, 400, 120)).run();
        S10d_ContactResponse s = r.sketch();
        assertEquals(1, s.answers.size());
        assertEquals(1, s.answers.get(0).shape, "the rect");
        assertEquals(new Vec(0, -1), new Vec(s.answers.get(0).contact.nx(), s.answers.get(0).contact.ny()), "the ball is below the rect's middle: normal up, into it");
        assertEquals(158, s.y, 1e-3f, "pushed down out of the rect's bottom (y 140) to touch it");
        PImage frame = r.lastFrame();
        SketchPixels.assertColour(frame, 470, 90, Palette.HIT, "the rect");
        SketchPixels.assertColour(frame, 160, 230, Palette.OBSTACLE, "the circle, untouched");
        SketchPixels.assertColour(frame, Math.round(s.x) + 8, Math.round(s.y) + 8, Palette.PLAYER, "the ball");
    }

    @Test
    void overlay_drawsTheManifoldPoint_theBallsDeepestPointInTheShape() {
        // As the screenshot: the mouse in the pentagon, the maths on.
        SketchRun.Result<S10d_ContactResponse> r = SketchRun.of(new S10d_ContactResponse())
                .script(new Script().frames(10).mouse(1, 398, 262).key(2, 'd')).run();
        S10d_ContactResponse s = r.sketch();
        assertTrue(s.showMaths);
        S10d_ContactResponse.Answer a = s.shown;
        assertEquals(2, a.shape, "the pentagon");
        Manifold m = a.touch;
        assertEquals(a.contact, m.contact(), "the manifold's contact is the one the ball was pushed out by");
        assertEquals(1, m.pointCount(), "a ball meets anything at one point");
        // Where the mouse put the ball, its deepest point along the normal, inside the pentagon.
        assertEquals(a.ghostX + a.contact.nx() * s.r, m.x(0), 1e-3f);
        assertEquals(a.ghostY + a.contact.ny() * s.r, m.y(0), 1e-3f);
        assertTrue(s.shapes[2].contains(m.x(0), m.y(0)));
        SketchPixels.assertColour(r.lastFrame(), Math.round(m.x(0)), Math.round(m.y(0)), Overlay.TEXT,
                "the manifold point, a white dot");
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 398, 262).key(3, 'd').key(8, 'd');
        SketchRun.Result<S10d_ContactResponse> r = SketchRun.of(new S10d_ContactResponse()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 1000, "the overlay writes out the contact and draws the depth");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
