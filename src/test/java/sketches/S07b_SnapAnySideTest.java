package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import hitbox.Collide;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/**
 * The arrow-key rectangle is snapped flush against whichever side of the center rectangle it
 * runs into, never ends a frame inside it, and the ifs and Snap.pushBack move it alike.
 */
class S07b_SnapAnySideTest {

    private static final String[] ARROWS = {"LEFT", "RIGHT", "UP", "DOWN"};

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** A long random walk on the arrow keys, one or two held at a time. */
    private static Script walk(boolean snapCall) {
        Random random = new Random(11);
        Script script = new Script().frames(6000);
        if (snapCall) {
            script.key(1, 'l');
        }
        for (int f = 3; f < 5900; ) {
            int length = 10 + random.nextInt(80);
            script.hold(f, ARROWS[random.nextInt(4)], length);
            if (random.nextBoolean()) {
                script.hold(f + random.nextInt(length), ARROWS[random.nextInt(4)], 1 + random.nextInt(length));
            }
            f += length + 1;
        }
        return script;
    }

    private static List<float[]> positions(Script script) {
        List<float[]> states = new ArrayList<>();
        SketchRun.of(new S07b_SnapAnySide()).script(script).everyFrame(s -> states.add(new float[] {s.playerX, s.playerY})).run();
        return states;
    }

    /** A tour round the center rectangle (250, 130, 100 x 140), from the player's start at (60, 60). */
    private static Script tour(boolean snapCall) {
        Script script = new Script().frames(400);
        if (snapCall) {
            script.key(1, 'l');
        }
        String[] moves = {"RIGHT 40", "DOWN 20",                // onto the top
                          "RIGHT 30", "DOWN 30", "LEFT 20",     // against the right side
                          "DOWN 20", "LEFT 20", "UP 20",        // up against the bottom
                          "LEFT 30", "UP 10", "RIGHT 30"};      // against the left side
        int f = 3;
        for (String move : moves) {
            String[] w = move.split(" ");
            int length = Integer.parseInt(w[1]);
            script.hold(f, w[0], length);
            f += length + 2;
        }
        return script;
    }

    @ParameterizedTest(name = "Snap.pushBack: {0}")
    @ValueSource(booleans = {false, true})
    void aTourRoundIt_restsFlushAgainstEverySide_andNeverEndsInside(boolean snapCall) {
        Map<String, Integer> rested = new HashMap<>();
        SketchRun.of(new S07b_SnapAnySide()).script(tour(snapCall)).everyFrame(s -> {
            assertNotInside(s);
            rested.merge(s.touchedSide(), 1, Integer::sum);
        }).run();
        for (String side : new String[] {"left", "right", "top", "bottom"}) {
            assertTrue(rested.getOrDefault(side, 0) > 5, "rested against the " + side + " side: " + rested);
        }
    }

    @ParameterizedTest(name = "Snap.pushBack: {0}")
    @ValueSource(booleans = {false, true})
    void randomWalk_neverEndsInside_norOutOfTheWindow(boolean snapCall) {
        Map<String, Integer> rested = new HashMap<>();
        SketchRun.of(new S07b_SnapAnySide()).script(walk(snapCall)).everyFrame(s -> {
            assertNotInside(s);
            rested.merge(s.touchedSide(), 1, Integer::sum);
        }).run();
        assertTrue(rested.size() >= 3, "the walk ran into at least two sides: " + rested);
    }

    private static void assertNotInside(S07b_SnapAnySide s) {
        assertFalse(Collide.rectRect(s.playerX, s.playerY, s.playerWidth, s.playerHeight,
                s.centerRectX, s.centerRectY, s.centerRectWidth, s.centerRectHeight),
                "inside the center rectangle at (" + s.playerX + ", " + s.playerY + "), frame " + s.frameCount);
        assertTrue(s.playerX >= 0 && s.playerX + s.playerWidth <= s.width && s.playerY >= 0 && s.playerY + s.playerHeight <= s.height,
                "in the window, frame " + s.frameCount);
    }

    @Test
    void theIfs_andSnapPushBack_moveItAlike_everyFrame() {
        List<float[]> ifs = positions(walk(false));
        List<float[]> call = positions(walk(true));
        List<float[]> ifsTour = positions(tour(false));
        List<float[]> callTour = positions(tour(true));
        ifs.addAll(ifsTour);
        call.addAll(callTour);
        assertEquals(ifs.size(), call.size());
        for (int f = 0; f < ifs.size(); f++) {
            assertEquals(ifs.get(f)[0], call.get(f)[0], "playerX, frame " + (f + 1));
            assertEquals(ifs.get(f)[1], call.get(f)[1], "playerY, frame " + (f + 1));
        }
    }

    @Test
    void heldIntoASide_itStaysFlushAgainstIt_andTheSideLightsUp() {
        // Down beside the rectangle, then right into it: 5 px steps would end 0 to 4 px short
        // or inside; the snap puts its right edge exactly on the left side.
        Script script = new Script().frames(80).hold(3, "DOWN", 30).hold(35, "RIGHT", 50);
        List<float[]> states = new ArrayList<>();
        SketchRun.Result<S07b_SnapAnySide> r = SketchRun.of(new S07b_SnapAnySide()).script(script)
                .everyFrame(s -> states.add(new float[] {s.playerX + s.playerWidth})).run();
        S07b_SnapAnySide s = r.sketch();
        int flush = -1;
        for (int f = 0; f < states.size(); f++) {
            if (states.get(f)[0] == s.centerRectX && flush < 0) {
                flush = f;
            }
        }
        assertTrue(flush > 0 && flush < 70, "it reached the left side: frame " + (flush + 1));
        for (int f = flush; f < states.size(); f++) {
            assertEquals(s.centerRectX, states.get(f)[0], "pushing on, it stays flush, frame " + (f + 1));
        }
        assertEquals("left", s.touchedSide());
        SketchPixels.assertColour(r.lastFrame(), (int) s.centerRectX, (int) (s.centerRectY + 10), Palette.ACCENT, "the left side, lit");
        SketchPixels.assertColour(r.lastFrame(), (int) (s.centerRectX + s.centerRectWidth), (int) (s.centerRectY + 10), 0xFFFFFFFF,
                "the right side, plain white");
    }
}
