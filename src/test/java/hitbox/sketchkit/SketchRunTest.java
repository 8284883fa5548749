package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.EventQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import processing.core.PApplet;

/**
 * Which exceptions fail a run: the sketch's own (setup(), draw(), on Processing's animation
 * thread) do, naming the frame; what the AWT event thread throws while Processing repaints does
 * not, as in the IDE, where Processing prints it and the sketch goes on.
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
}
