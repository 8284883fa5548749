package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * The tutorial's ground program: snapped (3, and Snap in 4) the player lands exactly on the
 * ground and jumps only from it; with speed 0 only (1) it stays inside; looking at the next
 * position (2) it stops short, above the ground.
 */
class S07_SnapToEdgeTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** One frame's state, in the tutorial's variables, as the test saw it after draw(). */
    private record State(int frame, float playerY, float playerSpeedY, boolean jumping) {
        static State of(S07_SnapToEdge s) {
            return new State(s.frameCount, s.playerY, s.playerSpeedY, s.jumping);
        }
    }

    private static List<State> record(Script script) {
        List<State> states = new ArrayList<>();
        states.add(null);  // frames count from 1
        SketchRun.of(new S07_SnapToEdge()).script(script).everyFrame(s -> states.add(State.of(s))).run();
        return states;
    }

    /** How far the player's bottom is above the ground (negative: inside it). */
    private static float gap(State s) {
        S07_SnapToEdge level = new S07_SnapToEdge();
        return level.groundY - (s.playerY() + level.playerHeight);
    }

    /** Jumps pressed on the ground, in the air, and on the ground again. */
    private static Script jumps(char way) {
        return new Script().frames(200).key(1, way).key(40, ' ').key(45, ' ').key(120, 'j').key(121, 'k');
    }

    @Test
    void theTutorialsSnap_landsExactlyOnTheGround_andStaysThere() {
        List<State> states = record(new Script().frames(60));
        int landed = -1;
        for (int f = 1; f <= 60; f++) {
            assertTrue(gap(states.get(f)) >= 0, "never inside the ground after a frame, frame " + f);
            if (landed < 0 && gap(states.get(f)) == 0) {
                landed = f;
            }
        }
        assertTrue(landed > 1, "it fell, then landed");
        assertTrue(states.get(landed - 1).playerSpeedY() > 10, "falling fast: the move went into the ground, the snap took it back");
        for (int f = landed; f <= 60; f++) {
            assertEquals(0, gap(states.get(f)), "its bottom exactly on groundY, frame " + f);
            assertFalse(states.get(f).jumping(), "and it may jump, frame " + f);
        }
    }

    @Test
    void jump_onlyWhenNotAlreadyJumping() {
        List<State> states = record(jumps('3'));
        assertEquals(0, gap(states.get(39)), "on the ground when the first key comes");
        assertEquals(-15 + 1, states.get(41).playerSpeedY(), "that key jumps: playerSpeedY = -15, then gravity");
        assertTrue(states.get(41).jumping() && gap(states.get(41)) > 0, "and it is in the air, jumping");
        for (int f = 46; f <= 50; f++) {
            assertEquals(states.get(f - 1).playerSpeedY() + 1, states.get(f).playerSpeedY(), "a key in the air changes nothing: frame " + f);
        }
        assertTrue(states.get(121).playerSpeedY() < 0, "a key on the ground jumps again");
        assertTrue(states.get(122).playerSpeedY() > states.get(121).playerSpeedY(), "the second key, mid-jump, does not");
    }

    @Test
    void lKey_isSnap_likeKey4_frameForFrame() {
        List<State> four = record(jumps('4'));
        List<State> l = record(jumps('l'));
        assertEquals(four, l, "l runs Hitbox's Snap, as 4 does");
        S07_SnapToEdge s = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(3).key(1, 'l')).run().sketch();
        assertEquals(4, s.way);
        assertEquals(3, SketchRun.of(new S07_SnapToEdge()).frames(2).run().sketch().way, "the tutorial's snap by default");
    }

    @Test
    void theTutorialsSnap_andSnap_putThePlayerInTheSamePlace_everyFrame() {
        List<State> tutorial = record(jumps('3'));
        List<State> library = record(jumps('4'));
        int standing = 0;
        for (int f = 2; f < tutorial.size() - 1; f++) {
            assertEquals(tutorial.get(f).playerY(), library.get(f).playerY(), "frame " + f);
            if (tutorial.get(f).jumping() != library.get(f).jumping()) {
                // Coming down exactly onto the ground: Snap's >= lands it this frame, the
                // tutorial's > one frame later, after gravity has taken it 1 px in.
                assertEquals(0, gap(tutorial.get(f)), "they differ only exactly on the ground, frame " + f);
                assertTrue(tutorial.get(f).jumping() && tutorial.get(f).playerSpeedY() > 0, "frame " + f);
            }
            // Standing: on the ground this frame, the one before and the one after (no jump key).
            if (gap(library.get(f - 1)) == 0 && gap(library.get(f)) == 0 && gap(library.get(f + 1)) == 0) {
                standing++;
                // Where they differ: standing exactly on the ground is "on it" for Snap (>=),
                // so its speed stays 0; the tutorial's > lets gravity make it 1 every other frame.
                assertEquals(0, library.get(f).playerSpeedY(), "Snap: a standing player's speed stays 0, frame " + f);
                float before = tutorial.get(f - 1).playerSpeedY(), now = tutorial.get(f).playerSpeedY();
                assertTrue(now == 0 || now == 1, "the tutorial's: 0 or 1 while standing, frame " + f + ": " + now);
                if (before == 0 || before == 1) {
                    assertEquals(1 - before, now, "the tutorial's: 0 and 1 by turns while standing, frame " + f);
                }
            }
        }
        assertTrue(standing > 50, "they stood a while: " + standing + " frames");
    }

    @Test
    void speedZeroOnly_staysALittleBitInsideTheGround() {
        List<State> states = record(new Script().frames(90).key(1, '1'));
        int landed = -1;
        for (int f = 3; f < states.size() && landed < 0; f++) {
            if (gap(states.get(f)) < 0) {
                landed = f;
            }
        }
        assertTrue(landed > 0, "it went into the ground");
        assertTrue(gap(states.get(landed)) < -5, "by more than 5 px: " + gap(states.get(landed)));
        for (int f = landed; f < states.size(); f++) {
            assertEquals(gap(states.get(landed)), gap(states.get(f)), "and stays there, stopped, frame " + f);
            assertEquals(0, states.get(f).playerSpeedY(), "frame " + f);
        }
    }

    @Test
    void nextPosition_stopsShortAboveTheGround_thenCreepsDown_neverInside() {
        List<State> states = record(new Script().frames(90).key(1, '2'));
        float highestStop = 0;
        for (int f = 3; f < states.size(); f++) {
            State s = states.get(f);
            assertTrue(gap(s) >= 0, "never inside, frame " + f);
            if (s.playerSpeedY() == 0 && !s.jumping()) {
                highestStop = Math.max(highestStop, gap(s));
            }
        }
        assertTrue(highestStop > 5, "it stopped more than 5 px above the ground: " + highestStop);
        assertEquals(0, gap(states.get(90)), "and crept down onto it");
    }

    @Test
    void theScreen_saysWhereThePlayerStands() {
        // 1: a little inside, in red beside the player; 3: exactly on the ground, in green.
        SketchRun.Result<S07_SnapToEdge> sunk = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(60).key(1, '1')).run();
        SketchRun.Result<S07_SnapToEdge> snapped = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(60)).run();
        S07_SnapToEdge s = snapped.sketch();
        int x0 = (int) (s.playerX + s.playerWidth), y0 = (int) s.playerY;
        assertTrue(reddish(sunk.lastFrame(), x0, y0 - 10, x0 + 250, y0 + 60) > 30, "'a little bit inside the ground' in red");
        assertTrue(greenish(snapped.lastFrame(), x0, y0 - 10, x0 + 250, y0 + 60) > 30, "'standing exactly on the ground' in green");
        assertEquals(0, reddish(snapped.lastFrame(), x0, y0 - 10, x0 + 250, y0 + 60), "and nothing red");
    }

    @Test
    void overlay_showsWhereTheMoveWent_beforeTheSnap() {
        // Frame 21 is the landing: the move put the bottom 10 px into the ground.
        SketchRun.Result<S07_SnapToEdge> off = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(21)).run();
        SketchRun.Result<S07_SnapToEdge> on = SketchRun.of(new S07_SnapToEdge()).script(new Script().frames(21).key(2, 'd')).run();
        S07_SnapToEdge s = on.sketch();
        assertEquals(0, s.groundY - (s.playerY + s.playerHeight), "landed on frame 21");
        assertTrue(SketchPixels.differing(off.lastFrame(), on.lastFrame()) > 500, "the overlay changes what is drawn");
        // The outline where the move put it, below the snapped player: its bottom edge 10 px under the ground line.
        int bottom = (int) (s.groundY + 10);
        int red = reddish(on.lastFrame(), (int) s.playerX, bottom - 1, (int) (s.playerX + s.playerWidth), bottom + 1);
        assertTrue(red > 10, "the box where the move went is outlined in red: " + red);
        assertEquals(0, reddish(off.lastFrame(), (int) s.playerX, bottom - 1, (int) (s.playerX + s.playerWidth), bottom + 1));
    }

    /** Pixels of red text or lines (Overlay.HIT). */
    static int reddish(PImage image, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) {
                int c = image.get(x, y);
                n += ((c >> 16) & 0xFF) > 180 && ((c >> 8) & 0xFF) < 140 ? 1 : 0;
            }
        }
        return n;
    }

    /** Pixels of green text (Overlay.MISS). */
    static int greenish(PImage image, int x0, int y0, int x1, int y1) {
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
