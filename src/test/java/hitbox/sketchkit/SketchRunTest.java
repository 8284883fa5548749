package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.EventQueue;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import processing.core.PApplet;

/**
 * Which exceptions fail a run: the sketch's own (setup(), draw(), on Processing's animation
 * thread) do, naming the frame; what the AWT event thread throws while Processing repaints does
 * not, as in the IDE, where Processing prints it and the sketch goes on. The one exception on the
 * animation thread that is not the sketch's, the window-buffer race before the first frame, runs
 * the sketch again once with a new instance.
 */
class SketchRunTest {

    @BeforeEach
    void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    /** A sketch that throws in setup(), in draw() at a frame, or on the AWT event thread. */
    public static class Thrower extends PApplet {
        final boolean inSetup;
        final int inDrawAt;
        final boolean onEventThread;

        Thrower(boolean inSetup, int inDrawAt, boolean onEventThread) {
            this.inSetup = inSetup;
            this.inDrawAt = inDrawAt;
            this.onEventThread = onEventThread;
        }

        @Override
        public void settings() {
            size(100, 100);
        }

        @Override
        public void setup() {
            if (inSetup) {
                throw new IllegalStateException("thrown in setup");
            }
            if (onEventThread) {
                // Before the first frame, when the run cannot yet tell its animation thread by
                // identity: give runSketch() time to return and the run its handler, then have
                // the event thread throw and wait until it has.
                delay(500);
                CountDownLatch thrown = new CountDownLatch(1);
                EventQueue.invokeLater(() -> {
                    throw new IllegalStateException("thrown on the AWT event thread");
                });
                EventQueue.invokeLater(thrown::countDown);
                try {
                    thrown.await(5, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }

        @Override
        public void draw() {
            if (frameCount == inDrawAt) {
                throw new IllegalStateException("thrown in draw");
            }
            background(0);
        }
    }

    @Test
    void aThrowInSetup_failsTheRun() {
        AssertionError e = assertThrows(AssertionError.class,
                () -> SketchRun.of(new Thrower(true, -1, false)).frames(5).run());
        assertTrue(e.getMessage().contains("thrown in setup"), e.getMessage());
    }

    @Test
    void aThrowInDraw_failsTheRun() {
        AssertionError e = assertThrows(AssertionError.class,
                () -> SketchRun.of(new Thrower(false, 3, false)).frames(10).run());
        assertTrue(e.getMessage().contains("thrown in draw"), e.getMessage());
    }

    @Test
    void aThrowOnTheAwtEventThread_isPrintedAndTheSketchGoesOn() {
        SketchRun.Result<Thrower> r = SketchRun.of(new Thrower(false, -1, true)).frames(20).run();
        assertEquals(20, r.framesDrawn());
    }

    // The window-buffer race. The real one cannot be provoked on demand: AWT's event thread has
    // to replace the window's buffers between the moment Processing's first render takes the
    // buffer strategy and the moment it draws into it. The harness sees of it only the thread,
    // the moment (before the first post()) and the stack, so these sketches throw, on the
    // animation thread before frame 1, a NullPointerException carrying the race's stack as AWT
    // and Processing 4.5 make it (PSurfaceAWT's animation thread: callDraw() -> render() ->
    // BufferStrategy.getDrawGraphics()). No seam in SketchRun is needed for it.

    /** The stack of the race, top first, as the animation thread dies with it. */
    private static final StackTraceElement[] RACE_STACK = {
        new StackTraceElement("java.awt.Component$FlipBufferStrategy", "getDrawGraphics", "Component.java", 4215),
        new StackTraceElement("processing.awt.PSurfaceAWT", "render", "PSurfaceAWT.java", 280),
        new StackTraceElement("processing.awt.PSurfaceAWT$9", "callDraw", "PSurfaceAWT.java", 1518),
        new StackTraceElement("processing.core.PSurfaceNone$AnimationThread", "run", "PSurfaceNone.java", 345),
    };

    /** The race's exception, with its stack, optionally with one frame put in below the top. */
    private static NullPointerException race(StackTraceElement... inserted) {
        NullPointerException e = new NullPointerException(
                "Cannot invoke \"java.awt.Image.getGraphics()\" because \"this.drawBuffer\" is null");
        List<StackTraceElement> stack = new ArrayList<>(List.of(RACE_STACK));
        stack.addAll(1, List.of(inserted));
        e.setStackTrace(stack.toArray(new StackTraceElement[0]));
        return e;
    }

    /**
     * A sketch whose windows lose the window race before frame 1 as long as {@link #racesLeft}
     * says so (shared by its instances, as the race is by the windows), then run normally.
     */
    public static class RaceLoser extends PApplet {
        static final AtomicInteger racesLeft = new AtomicInteger();
        static final AtomicInteger made = new AtomicInteger();
        /** Throws at this frame (not before frame 1) a race-like NPE, or a plain one in draw(). */
        int raceAtFrame;
        boolean plainNpeInDraw;
        /** A value a test may give it, shared by two instances as it is (a Hitbox shape). */
        hitbox.Rect box;
        /** A thing a test may change: two instances cannot share it. */
        final List<String> notes = new ArrayList<>();

        public RaceLoser() {
            made.incrementAndGet();
        }

        @Override
        public void settings() {
            size(100, 100);
        }

        @Override
        public void setup() {
            if (racesLeft.getAndDecrement() > 0) {
                throw race();
            }
        }

        @Override
        public void draw() {
            background(frameCount * 10 % 256);
            if (frameCount == raceAtFrame) {
                throw race();
            }
            if (plainNpeInDraw && frameCount == 2) {
                String none = frameCount > 0 ? null : "";
                none.length();
            }
        }
    }

    /** The same sketch with no public no-arg constructor: it cannot be made again. */
    public static class RaceLoserWithArgument extends RaceLoser {
        public RaceLoserWithArgument(int unused) {
        }
    }

    @Test
    void theRaceBeforeFrame1_runsAgainOnceWithANewInstance_andThatRunPasses() {
        RaceLoser.racesLeft.set(1);
        RaceLoser passed = new RaceLoser();
        RaceLoser.made.set(0);
        List<RaceLoser> checked = new ArrayList<>();
        List<Integer> frames = new ArrayList<>();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream stderr = System.err;
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        SketchRun.Result<RaceLoser> r;
        try {
            r = SketchRun.of(passed).frames(12).capture(5).everyFrame(s -> {
                frames.add(s.frameCount);
                if (!checked.contains(s)) {
                    checked.add(s);
                }
            }).run();
        } finally {
            System.setErr(stderr);
        }
        assertEquals(12, r.framesDrawn(), "the second window ran every frame");
        assertEquals(1, RaceLoser.made.get(), "one new instance, made once");
        assertNotSame(passed, r.sketch(), "the result holds the instance that ran");
        assertEquals(List.of(r.sketch()), checked, "the checks saw only the instance that ran");
        assertEquals(List.of(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12), frames, "checked after each frame, from frame 1");
        assertEquals(0, passed.frameCount, "the first instance never finished a frame");
        assertEquals(0xFF323232, r.frame(5).get(50, 50), "frame 5 captured from the new instance: background(50)");
        String printed = err.toString(StandardCharsets.UTF_8);
        assertTrue(printed.contains("SketchRun: RaceLoser lost the window-buffer race")
                && printed.contains("ran it again once with a new RaceLoser"), printed);
    }

    @Test
    void theRaceAgainOnTheSecondWindow_failsNamingTheRace() {
        RaceLoser.racesLeft.set(2);
        AssertionError e = assertThrows(AssertionError.class, () -> SketchRun.of(new RaceLoser()).frames(5).run());
        assertTrue(e.getMessage().contains("window-buffer race") && e.getMessage().contains("lost it too"), e.getMessage());
    }

    @Test
    void theRace_withNoPublicNoArgConstructor_failsNamingTheRace() {
        RaceLoser.racesLeft.set(1);
        AssertionError e = assertThrows(AssertionError.class, () -> SketchRun.of(new RaceLoserWithArgument(0)).frames(5).run());
        assertTrue(e.getMessage().contains("window-buffer race") && e.getMessage().contains("no public no-arg constructor"),
                e.getMessage());
    }

    @Test
    void theRace_onASketchGivenValuesBeforeTheRun_runsAgainWithThoseValues() {
        // The values a test set (a number, a shape) are given to the new instance: the same sketch.
        RaceLoser.racesLeft.set(1);
        RaceLoser given = new RaceLoser();
        given.raceAtFrame = 99;
        given.box = new hitbox.Rect(1, 2, 3, 4);
        SketchRun.Result<RaceLoser> r = SketchRun.of(given).frames(5).run();
        assertEquals(5, r.framesDrawn());
        assertNotSame(given, r.sketch(), "the new instance ran");
        assertEquals(99, r.sketch().raceAtFrame);
        assertEquals(new hitbox.Rect(1, 2, 3, 4), r.sketch().box);
    }

    @Test
    void theRace_onASketchChangedBeforeTheRun_failsNamingTheRaceAndTheField() {
        // A list the test changed cannot be given to a new instance: running it would test
        // another sketch.
        RaceLoser.racesLeft.set(1);
        RaceLoser changed = new RaceLoser();
        changed.notes.add("set by the test");
        AssertionError e = assertThrows(AssertionError.class, () -> SketchRun.of(changed).frames(5).run());
        assertTrue(e.getMessage().contains("window-buffer race") && e.getMessage().contains("notes was [set by the test]"),
                e.getMessage());
    }

    @Test
    void aSketchNpeInDraw_stillFails() {
        RaceLoser.racesLeft.set(0);
        RaceLoser s = new RaceLoser();
        s.plainNpeInDraw = true;
        AssertionError e = assertThrows(AssertionError.class, () -> SketchRun.of(s).frames(5).run());
        assertTrue(e.getMessage().contains("threw after frame 1") && e.getCause() instanceof NullPointerException,
                e.getMessage());
    }

    @Test
    void theRaceAfterTheFirstFrame_stillFails() {
        RaceLoser.racesLeft.set(0);
        RaceLoser s = new RaceLoser();
        s.raceAtFrame = 3;
        AssertionError e = assertThrows(AssertionError.class, () -> SketchRun.of(s).frames(5).run());
        assertTrue(e.getMessage().contains("threw after frame 2"), e.getMessage());
        assertFalse(e.getMessage().contains("window-buffer race"), e.getMessage());
    }

    @Test
    void onlyTheRacesStack_isTheRace() {
        assertTrue(SketchRun.isWindowRace(race(), RaceLoser.class));
        assertFalse(SketchRun.isWindowRace(race(new StackTraceElement(RaceLoser.class.getName(), "draw", null, 1)),
                RaceLoser.class), "a frame of the sketch's class");
        assertFalse(SketchRun.isWindowRace(race(new StackTraceElement(RaceLoser.class.getName() + "$Ball", "show", null, 1)),
                RaceLoser.class), "a frame of a class inside the sketch");
        assertFalse(SketchRun.isWindowRace(race(new StackTraceElement("hitbox.processing.Overlay", "guide", null, 1)),
                RaceLoser.class), "a frame of hitbox");
        assertFalse(SketchRun.isWindowRace(race(new StackTraceElement("processing.core.PApplet", "handleDraw", null, 1)),
                RaceLoser.class), "Processing outside its surface, where the sketch's methods run");
        NullPointerException elsewhere = race();
        StackTraceElement[] stack = elsewhere.getStackTrace();
        stack[0] = new StackTraceElement("java.awt.image.BufferedImage", "getGraphics", null, 1);
        elsewhere.setStackTrace(stack);
        assertFalse(SketchRun.isWindowRace(elsewhere, RaceLoser.class), "thrown outside a buffer strategy");
        IllegalStateException notNpe = new IllegalStateException("Component must have a valid peer");
        notNpe.setStackTrace(RACE_STACK);
        assertFalse(SketchRun.isWindowRace(notNpe, RaceLoser.class), "not the NullPointerException");
    }
}
