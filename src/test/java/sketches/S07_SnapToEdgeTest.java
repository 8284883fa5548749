package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import hitbox.Collide;
import hitbox.Rect;
import hitbox.Side;
import hitbox.processing.Overlay;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/** The player lands, jumps only from the ground, bumps its head, stops at walls, and never ends a frame inside anything. */
class S07_SnapToEdgeTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** The screenshot's walk: fall to the ground, walk under the shelf, jump into it, then walk right into the crate. */
    private static Script tour() {
        return new Script().frames(260).hold(40, "RIGHT", 53).key(95, ' ').hold(130, "RIGHT", 120);
    }

    /** One frame's state, as the test saw it after draw(). */
    private record State(int frame, float x, float y, float vx, float vy, boolean onGround, Side xSide, Side ySide) {
        static State of(S07_SnapToEdge s) {
            return new State(s.frameCount, s.x, s.y, s.vx, s.vy, s.onGround, s.xSide, s.ySide);
        }
    }

    private static List<State> record(Script script) {
        List<State> states = new ArrayList<>();
        states.add(null);  // frames count from 1
        SketchRun.of(new S07_SnapToEdge()).script(script).everyFrame(s -> states.add(State.of(s))).run();
        return states;
    }

    @ParameterizedTest(name = "way {0}")
    @ValueSource(chars = {'3', '4'})
    void longWalkWithJumps_neverEndsAFrameInsideAnything(char way) {
        Random random = new Random(7);
        Script script = new Script().frames(8000).key(1, way);
        for (int f = 3; f < 7900; ) {
            int length = 5 + random.nextInt(60);
            script.hold(f, random.nextBoolean() ? "LEFT" : "RIGHT", length);
            if (random.nextInt(3) > 0) {
                script.hold(f + random.nextInt(length), random.nextBoolean() ? "UP" : "SPACE", 1);
            }
            f += length + 1 + random.nextInt(8);
        }
        Set<Rect> stoodOn = new HashSet<>();
        int[] walls = new int[1];
        SketchRun.of(new S07_SnapToEdge()).script(script).everyFrame(s -> {
            for (Rect o : s.solids) {
                assertFalse(Collide.rectRect(s.x, s.y, s.w, s.h, o.x(), o.y(), o.w(), o.h()),
                        "the player at (" + s.x + ", " + s.y + ") is inside " + o);
            }
            assertTrue(s.x >= 0 && s.x + s.w <= s.width, "inside the window across, x = " + s.x);
            if (s.onGround) {
                stoodOn.add(s.yHit);
            }
            if (s.xSide.isWall()) {
                walls[0]++;
            }
        }).run();
        // The walk is a real test only if it met more than the floor.
        assertTrue(stoodOn.size() >= 2, "stood on the ground and at least one platform: " + stoodOn);
        assertTrue(walls[0] > 0, "walked into a side");
    }

    @Test
    void falling_landsAndStandsExactlyOnTheGround() {
        List<State> states = record(new Script().frames(60));
        S07_SnapToEdge level = new S07_SnapToEdge();
        assertFalse(states.get(1).onGround(), "it starts in the air");
        State last = states.get(60);
        assertTrue(last.onGround(), "it has landed");
        assertEquals(level.ground.y(), last.y() + level.h, "its bottom is on the ground's top");
        assertEquals(0, last.vy(), "and it stopped falling");
        int landed = -1;
        for (int f = 1; f <= 60 && landed < 0; f++) {
            if (states.get(f).onGround()) {
                landed = f;
                assertEquals(Side.TOP, states.get(f).ySide(), "landing is the ground's TOP side");
            }
        }
        for (int f = landed; f <= 60; f++) {
            assertTrue(states.get(f).onGround(), "once down it stays down, frame " + f);
        }
    }

    @Test
    void jump_onlyFromTheGround() {
        S07_SnapToEdge level = new S07_SnapToEdge();
        // Frames 5 and 10: jump pressed in mid-air (it falls until about frame 27); frame 60: on the ground.
        List<State> states = record(new Script().frames(70).key(5, ' ').hold(10, "UP", 1).key(60, ' '));
        for (int f = 2; f <= 20; f++) {
            float expected = Math.min(states.get(f - 1).vy() + level.gravity, level.maxFall);
            assertFalse(states.get(f).onGround(), "still in the air at frame " + f);
            assertEquals(expected, states.get(f).vy(), "a jump in the air changes nothing: frame " + f);
        }
        assertTrue(states.get(60).onGround(), "on the ground when the third press comes");
        assertEquals(-level.jumpSpeed + level.gravity, states.get(61).vy(), "that press jumps");
        assertFalse(states.get(61).onGround(), "and leaves the ground");
    }

    @Test
    void jumpUnderTheShelf_bumpsItsHeadAndStopsGoingUp() {
        S07_SnapToEdge level = new S07_SnapToEdge();
        List<State> states = record(tour());
        int bump = -1;
        for (int f = 1; f < states.size() && bump < 0; f++) {
            if (states.get(f).ySide() == Side.BOTTOM) {
                bump = f;
            }
        }
        assertTrue(bump > 0, "the jump under the shelf hits its BOTTOM side");
        State at = states.get(bump);
        assertTrue(states.get(bump - 1).vy() < 0, "it was going up");
        assertEquals(level.shelf.bottom(), at.y(), "its head touches the shelf's underside");
        assertEquals(0, at.vy(), "it stops going up");
        assertTrue(states.get(bump + 1).vy() > 0, "and falls back");
    }

    @Test
    void walkingIntoTheCrate_stopsAtItsSide() {
        S07_SnapToEdge level = new S07_SnapToEdge();
        List<State> states = record(tour());
        int first = -1;
        for (int f = 1; f < states.size() && first < 0; f++) {
            if (states.get(f).xSide() == Side.LEFT) {
                first = f;
            }
        }
        assertTrue(first > 0, "walking right it runs into the crate's LEFT side");
        // RIGHT is held until frame 250: it stays against the crate, however long it pushes.
        for (int f = first; f < 250; f++) {
            State s = states.get(f);
            assertEquals(level.crate.x() - level.w, s.x(), "standing against the crate at frame " + f);
            assertEquals(Side.LEFT, s.xSide(), "pushing into its LEFT side at frame " + f);
            assertEquals(0, s.vx(), "stopped at frame " + f);
        }
    }

    @Test
    void overlay_showsTheOverlapAndTheSideHit() {
        S07_SnapToEdge level = new S07_SnapToEdge();
        Script plain = new Script().frames(102).hold(40, "RIGHT", 53).key(95, ' ');
        Script maths = new Script().frames(102).hold(40, "RIGHT", 53).key(95, ' ').key(2, 'd');
        SketchRun.Result<S07_SnapToEdge> off = SketchRun.of(new S07_SnapToEdge()).script(plain).run();
        SketchRun.Result<S07_SnapToEdge> on = SketchRun.of(new S07_SnapToEdge()).script(maths).run();
        assertEquals(Side.BOTTOM, on.sketch().ySide, "frame 102 is the head bump");
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame()) > 500, "the overlay changes what is drawn");
        int sideY = (int) level.shelf.bottom();
        int midX = (int) (level.shelf.x() + level.shelf.w() / 2) - 30;  // along the shelf, clear of the player
        assertEquals(Overlay.GUIDE, on.lastFrame().get(midX, sideY), "the BOTTOM side is marked");
        float px = on.sketch().x + on.sketch().w / 2;
        assertEquals(Overlay.HIT, on.lastFrame().get((int) px, sideY - 2), "the overlap with the shelf is red");
        assertTrue(off.lastFrame().get(midX, sideY) != Overlay.GUIDE, "no mark without the overlay");
    }

    private static List<State> record(Script script, char way) {
        return record(script.key(1, way));
    }

    @Test
    void theTutorialsSnap_andSnapPushBack_moveThePlayerExactlyAlike() {
        // The tour walks, jumps into the shelf's underside and pushes against the crate.
        List<State> tutorial = record(tour(), '3');
        List<State> library = record(tour(), '4');
        for (int f = 2; f < tutorial.size(); f++) {
            assertEquals(library.get(f), tutorial.get(f), "frame " + f);
        }
    }

    @Test
    void sink_stopsFalling_butStaysInside_andSinksOnThrough() {
        S07_SnapToEdge level = new S07_SnapToEdge();
        List<State> states = record(new Script().frames(90), '1');
        float groundTop = level.ground.y();
        int landed = -1;
        for (int f = 2; f < states.size() && landed < 0; f++) {
            if (states.get(f).y() + level.h > groundTop) {
                landed = f;
            }
        }
        assertTrue(landed > 0, "it reached the ground");
        assertTrue(states.get(landed).onGround() && states.get(landed).vy() == 0, "stopped, where it is: inside");
        for (int f = landed + 1; f < states.size(); f++) {
            assertTrue(states.get(f).y() > states.get(f - 1).y(), "it sinks further every frame: frame " + f);
        }
        assertTrue(states.get(90).y() + level.h - groundTop > 20, "deep in the ground by frame 90");
    }

    @Test
    void stopShort_hangsAboveTheGround_thenCreepsDown_neverInside() {
        S07_SnapToEdge level = new S07_SnapToEdge();
        float groundTop = level.ground.y();
        float[] highest = {0};
        List<State> states = new ArrayList<>();
        SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(90).key(1, '2')).everyFrame(s -> {
            for (Rect o : s.solids) {
                assertFalse(Collide.rectRect(s.x, s.y, s.w, s.h, o.x(), o.y(), o.w(), o.h()), "never inside, frame " + s.frameCount);
            }
            if (s.onGround) {
                highest[0] = Math.max(highest[0], groundTop - (s.y + s.h));
            }
            states.add(State.of(s));
        }).run();
        assertTrue(highest[0] > 5, "it stopped more than 5 px above the ground: " + highest[0]);
        State last = states.get(states.size() - 1);
        float gap = groundTop - (last.y() + level.h);
        assertTrue(gap >= 0 && gap < level.gravity, "and crept down to within one gravity step: " + gap);
    }

    @Test
    void theScreen_saysHowTheWaysStand() {
        // 1: sunk into the ground; 4: standing exactly on it. Red and green labels beside the player.
        SketchRun.Result<S07_SnapToEdge> sunk = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(60).key(1, '1')).run();
        SketchRun.Result<S07_SnapToEdge> snapped = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(60)).run();
        int x0 = (int) (sunk.sketch().x + sunk.sketch().w), y0 = (int) sunk.sketch().y;
        assertTrue(reddish(sunk.lastFrame(), x0, y0 - 10, x0 + 200, y0 + 40) > 30, "'sunk ... px into it' in red");
        x0 = (int) (snapped.sketch().x + snapped.sketch().w);
        y0 = (int) snapped.sketch().y;
        assertTrue(greenish(snapped.lastFrame(), x0, y0 - 10, x0 + 200, y0 + 40) > 30, "'standing exactly on it' in green");
        assertEquals(0, reddish(snapped.lastFrame(), x0, y0 - 10, x0 + 200, y0 + 40), "and nothing red");
        // And the sunk part of the player is hidden by the ground it is in.
        SketchPixels.assertColour(sunk.lastFrame(), (int) sunk.sketch().x + 5, (int) sunk.sketch().ground.y() + 2, Palette.OBSTACLE, "the ground in front");
    }

    /** Pixels of a red label's text (Overlay.HIT, anti-aliased over its dark box). */
    private static int reddish(PImage image, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                int c = image.get(x, y);
                n += ((c >> 16) & 0xFF) > 180 && ((c >> 8) & 0xFF) < 140 ? 1 : 0;
            }
        }
        return n;
    }

    /** Pixels of a green label's text (Overlay.MISS). */
    private static int greenish(PImage image, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                int c = image.get(x, y);
                n += ((c >> 8) & 0xFF) > 180 && ((c >> 16) & 0xFF) < 160 ? 1 : 0;
            }
        }
        return n;
    }
}
