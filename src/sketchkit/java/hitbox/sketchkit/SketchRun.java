package hitbox.sketchkit;

import java.awt.EventQueue;
import java.awt.Frame;
import java.awt.GraphicsEnvironment;
import java.io.File;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

import processing.awt.PSurfaceAWT;
import processing.core.PApplet;
import processing.core.PConstants;
import processing.core.PImage;
import processing.event.KeyEvent;
import processing.event.MouseEvent;

/**
 * Runs a sketch in a real window for a fixed number of frames, with scripted input, and hands
 * back what it drew: the harness behind the display tests and {@code gradle screenshots}.
 *
 * <p>It acts between frames through Processing's {@code registerMethod("pre"/"post")}, so the
 * sketch runs unchanged. By default the frame rate is uncapped, so 10,000 frames take seconds
 * rather than minutes; {@link #realTime()} keeps the sketch's own rate.
 * <pre>
 * SketchRun.Result&lt;S02_CirclePoint&gt; r = SketchRun.of(new S02_CirclePoint())
 *         .script(new Script().frames(30).mouse(1, 200, 200))
 *         .everyFrame(s -&gt; assertTrue(s.width &gt; 0))
 *         .run();
 * int colour = r.lastFrame().get(200, 200);
 * </pre>
 *
 * @param <S> the sketch's class, so checks can read its fields
 */
public final class SketchRun<S extends PApplet> {
    /** How long a sketch may go without finishing a frame before the run fails. */
    private static final long STALL_MILLIS = 30_000;

    /** The name Processing gives the thread that runs setup(), draw() and the event methods. */
    private static final String ANIMATION_THREAD = "Animation Thread";

    private final S sketch;
    private Script script = new Script();
    private int frames = -1;
    private boolean fast = true;
    private File folder;
    private final List<Consumer<? super S>> checks = new ArrayList<>();
    private final Map<Integer, File> saves = new HashMap<>();
    private final List<Integer> captures = new ArrayList<>();

    private SketchRun(S sketch) {
        this.sketch = Objects.requireNonNull(sketch, "sketch");
    }

    /**
     * Prepares a run of a sketch instance that has not been started.
     *
     * @param sketch a new sketch, e.g. {@code new S01_EdgeBounce()}
     * @param <S>    its class
     * @return the run, to configure and then {@link #run()}
     */
    public static <S extends PApplet> SketchRun<S> of(S sketch) {
        return new SketchRun<>(sketch);
    }

    /**
     * Where a sketch's {@code sketchPath()} points, so that {@code loadImage("map.png")} reads
     * its {@code data/} folder as in the IDE: its folder under the sketches folder when there
     * is one, else the working directory.
     *
     * @param sketch a sketch
     * @return its folder
     */
    public static File sketchFolder(PApplet sketch) {
        File folder = new File(System.getProperty(Catalog.SKETCHES_PROPERTY, "sketches"), sketch.getClass().getSimpleName());
        return folder.isDirectory() ? folder : new File(".");
    }

    /** @return true if windows can be opened (a display, real or {@code xvfb-run -a}) */
    public static boolean displayAvailable() {
        return !GraphicsEnvironment.isHeadless();
    }

    /** The message display tests skip with when there is no display. */
    public static final String NO_DISPLAY =
            "no display: sketch tests open real windows; run them under xvfb-run -a gradle test";

    /**
     * @param input the scripted input; its frame count is used unless {@link #frames} is set
     * @return this run
     */
    public SketchRun<S> script(Script input) {
        this.script = Objects.requireNonNull(input, "input");
        return this;
    }

    /**
     * @param count how many frames to run (draw() calls), overriding the script's count
     * @return this run
     */
    public SketchRun<S> frames(int count) {
        if (count < 1) {
            throw new IllegalArgumentException("frames must be >= 1, was " + count);
        }
        this.frames = count;
        return this;
    }

    /**
     * Sets the sketch's folder, whose {@code data/} its {@code loadImage()} and
     * {@code loadStrings()} read, when it is not under the sketches folder.
     *
     * @param sketchFolder the folder that holds the sketch's tabs
     * @return this run
     */
    public SketchRun<S> folder(File sketchFolder) {
        this.folder = Objects.requireNonNull(sketchFolder, "sketchFolder");
        return this;
    }

    /**
     * Keeps the sketch's own frame rate instead of running as fast as possible.
     *
     * @return this run
     */
    public SketchRun<S> realTime() {
        this.fast = false;
        return this;
    }

    /**
     * Adds a check run after every frame's draw(), on the sketch's thread; an exception or
     * failed assertion in it stops the run and fails it with the frame number.
     *
     * @param check reads the sketch's fields
     * @return this run
     */
    public SketchRun<S> everyFrame(Consumer<? super S> check) {
        checks.add(Objects.requireNonNull(check, "check"));
        return this;
    }

    /**
     * Saves what a frame drew as a PNG.
     *
     * @param frame the frame, from 1
     * @param png   where to save it
     * @return this run
     */
    public SketchRun<S> saveFrame(int frame, File png) {
        saves.put(frame, png);
        return this;
    }

    /**
     * Keeps a copy of what a frame drew, for {@link Result#frame(int)}.
     *
     * @param frame the frame, from 1
     * @return this run
     */
    public SketchRun<S> capture(int frame) {
        captures.add(frame);
        return this;
    }

    /**
     * Opens the window, runs the frames with the scripted input, closes the window.
     *
     * @return what the run saw
     * @throws AssertionError if the sketch threw, a check failed, or the sketch stalled
     * @throws IllegalStateException if there is no display
     */
    public Result<S> run() {
        if (!displayAvailable()) {
            throw new IllegalStateException(NO_DISPLAY);
        }
        int total = frames > 0 ? frames : script.frames();
        FrameHooks hooks = new FrameHooks(total);
        sketch.registerMethod("pre", hooks);
        sketch.registerMethod("post", hooks);
        String name = sketch.getClass().getSimpleName();
        PApplet.runSketch(new String[] {PApplet.ARGS_LOCATION + "=40,40",
                PApplet.ARGS_SKETCH_FOLDER + "=" + (folder != null ? folder : sketchFolder(sketch)).getAbsolutePath(), name}, sketch);
        // runSketch() installs Processing's own handler, which only prints; this one replaces
        // it and also ends the wait. Only this run's animation thread counts: it runs setup(),
        // draw() and the sketch's event methods. Before its first frame it is known by
        // Processing's name for it. The AWT event thread runs no sketch code, only
        // Processing's repaints, which can race the animation thread for the window's buffer
        // while it opens (an NPE in java.awt.Component$FlipBufferStrategy); Processing prints
        // those and the sketch goes on, so they are printed here too, not failed.
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
            Thread mine = hooks.thread;
            boolean sketchThread = mine != null ? mine == t : ANIMATION_THREAD.equals(t.getName());
            if (sketchThread) {
                hooks.fail(e);
            } else {
                e.printStackTrace();
            }
        });
        try {
            hooks.await(name);
        } finally {
            close(sketch, hooks.thread);
        }
        return new Result<>(sketch, hooks.framesDone, hooks.images, hooks.last);
    }

    private static void close(PApplet sketch, Thread animation) {
        sketch.noLoop();
        sketch.dispose();
        // The animation thread shows one last frame after it is told to stop; the window must
        // outlive it, or that frame fails on a buffer that is gone.
        if (animation != null) {
            try {
                animation.join(5_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (sketch.getSurface() instanceof PSurfaceAWT surface
                && surface.getNative() instanceof PSurfaceAWT.SmoothCanvas canvas) {
            Frame frame = canvas.getFrame();
            EventQueue.invokeLater(frame::dispose);
        }
    }

    /**
     * The pre/post callbacks Processing calls around each frame; public only because
     * Processing finds them by reflection.
     */
    public final class FrameHooks {
        private final int total;
        private final AtomicReference<Throwable> failure = new AtomicReference<>();
        private final Map<Integer, PImage> images = new HashMap<>();
        private volatile PImage last;
        private volatile boolean finished;
        private volatile int framesDone;
        private volatile Thread thread;
        private int mouseX;
        private int mouseY;
        private boolean pressed;

        FrameHooks(int total) {
            this.total = total;
        }

        /** Called by Processing before each draw(): applies this frame's scripted input. */
        public void pre() {
            if (finished) {
                return;
            }
            thread = Thread.currentThread();
            int frame = sketch.frameCount;  // 1 on the first draw()
            if (frame == 1 && fast) {
                sketch.frameRate(100_000);
            }
            long now = sketch.millis();
            for (Script.Step step : script.steps()) {
                if (step.frame() == frame) {
                    apply(step, now);
                }
            }
        }

        private void apply(Script.Step step, long now) {
            switch (step.kind()) {
                case MOUSE -> {
                    mouseX = step.x();
                    mouseY = step.y();
                    // Set now so this frame's draw() sees it; the event calls mouseMoved()/Dragged().
                    sketch.mouseX = mouseX;
                    sketch.mouseY = mouseY;
                    int action = pressed ? MouseEvent.DRAG : MouseEvent.MOVE;
                    sketch.postEvent(new MouseEvent(null, now, action, 0, mouseX, mouseY, pressed ? PConstants.LEFT : 0, 0));
                }
                case PRESS -> {
                    pressed = true;
                    sketch.postEvent(new MouseEvent(null, now, MouseEvent.PRESS, 0, mouseX, mouseY, PConstants.LEFT, 1));
                }
                case RELEASE -> {
                    pressed = false;
                    sketch.postEvent(new MouseEvent(null, now, MouseEvent.RELEASE, 0, mouseX, mouseY, PConstants.LEFT, 1));
                    sketch.postEvent(new MouseEvent(null, now, MouseEvent.CLICK, 0, mouseX, mouseY, PConstants.LEFT, 1));
                }
                case KEY_DOWN -> {
                    sketch.postEvent(new KeyEvent(null, now, KeyEvent.PRESS, 0, step.key(), step.keyCode(), false));
                    if (step.key() != PConstants.CODED) {
                        sketch.postEvent(new KeyEvent(null, now, KeyEvent.TYPE, 0, step.key(), 0, false));
                    }
                }
                case KEY_UP -> sketch.postEvent(new KeyEvent(null, now, KeyEvent.RELEASE, 0, step.key(), step.keyCode(), false));
            }
        }

        /** Called by Processing after each draw(): checks, saves, and stops after the last frame. */
        public void post() {
            if (finished) {
                return;
            }
            int frame = sketch.frameCount;
            try {
                for (Consumer<? super S> check : checks) {
                    check.accept(sketch);
                }
                File png = saves.get(frame);
                if (png != null) {
                    File dir = png.getAbsoluteFile().getParentFile();
                    if (dir != null) {
                        dir.mkdirs();
                    }
                    sketch.get().save(png.getAbsolutePath());
                }
                if (captures.contains(frame)) {
                    images.put(frame, sketch.get());
                }
                framesDone = frame;
                if (frame >= total) {
                    last = sketch.get();
                    // Stop here, on the sketch's thread, so its fields are those of frame N.
                    sketch.noLoop();
                    finished = true;
                }
            } catch (Throwable t) {
                fail(new AssertionError("frame " + frame + ": " + t.getMessage(), t));
            }
        }

        void fail(Throwable t) {
            failure.compareAndSet(null, t);
            sketch.noLoop();
            finished = true;
        }

        void await(String name) {
            long lastProgress = System.currentTimeMillis();
            int seen = -1;
            while (!finished) {
                try {
                    Thread.sleep(20);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new AssertionError(name + " was interrupted", e);
                }
                if (framesDone != seen) {
                    seen = framesDone;
                    lastProgress = System.currentTimeMillis();
                } else if (System.currentTimeMillis() - lastProgress > STALL_MILLIS) {
                    throw new AssertionError(name + " stopped drawing after frame " + framesDone + " of " + total);
                }
            }
            Throwable t = failure.get();
            if (t instanceof AssertionError a) {
                throw new AssertionError(name + ", " + a.getMessage(), a.getCause() != null ? a.getCause() : a);
            }
            if (t != null) {
                throw new AssertionError(name + " threw after frame " + framesDone + ": " + t, t);
            }
        }
    }

    /**
     * What a run saw.
     *
     * @param sketch      the sketch, stopped, with its fields as the last frame left them
     * @param framesDrawn how many times draw() ran
     * @param images    the frames kept with {@link #capture(int)}, by frame number
     * @param lastFrame what the last frame drew
     * @param <S>       the sketch's class
     */
    public record Result<S extends PApplet>(S sketch, int framesDrawn, Map<Integer, PImage> images, PImage lastFrame) {

        /**
         * @param frame a frame kept with {@link SketchRun#capture(int)}
         * @return what it drew
         * @throws IllegalArgumentException if that frame was not captured
         */
        public PImage frame(int frame) {
            PImage image = images.get(frame);
            if (image == null) {
                throw new IllegalArgumentException("frame " + frame + " was not captured: call capture(" + frame + ") before run()");
            }
            return image;
        }
    }
}
