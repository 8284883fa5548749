package hitbox.sketchkit;

import java.awt.EventQueue;
import java.awt.Frame;
import java.awt.GraphicsEnvironment;
import java.io.File;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
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
     * <p>The run may end up with another instance of the same class: see {@link #run()}. A test
     * that keeps its own reference to the sketch it passed here reads the instance that ran only
     * through the checks' parameter and {@link Result#sketch()}, never through that reference.
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
     * <p>One failure is not the sketch's: while the window opens, AWT's repaint on the event
     * thread can race Processing's first render on the animation thread for the window's buffer,
     * and the render dies with a {@code NullPointerException} inside
     * {@code java.awt.Component$FlipBufferStrategy}, the animation thread with it. When exactly
     * that happens (on this run's animation thread, before the first frame's {@code post}, with
     * no frame of the sketch's class or of {@code hitbox} on the stack, only AWT and Processing's
     * surface), the window is closed and the run starts once more, with a new instance made by
     * the sketch class's public no-arg constructor and the same script, checks, saves and
     * captures; a line on standard error says so. The second instance is the one the checks are
     * given and {@link Result#sketch()} returns: a test that kept a reference to the sketch it
     * passed to {@link #of} must read the run's state through those, not through its reference.
     * A sketch that a test changed before the run (a field that differs from a new instance's)
     * is run again with the same values set on the new instance, where each is a value two
     * instances can share (a number, text, an enum, a Hitbox shape, a record of such values); one
     * changed in a field that holds another object (a list, a grid, an array) is not run again,
     * since a new one would not be the same sketch.
     *
     * @return what the run saw
     * @throws AssertionError if the sketch threw, a check failed, or the sketch stalled; or if the
     *         window race struck and the run could not be repeated, or struck again
     * @throws IllegalStateException if there is no display
     */
    public Result<S> run() {
        if (!displayAvailable()) {
            throw new IllegalStateException(NO_DISPLAY);
        }
        String name = sketch.getClass().getSimpleName();
        // Taken before the sketch runs, to tell later whether a new instance is the same sketch.
        Map<String, Object> valuesAsPassed = values(sketch);
        Map<String, String> asPassed = described(valuesAsPassed);
        FrameHooks first = attempt(sketch);
        if (first.race == null) {
            return first.result();
        }
        String race = name + " lost the window-buffer race between AWT's repaint and Processing's first render"
                + " before frame 1 (" + first.race + " in " + first.race.getStackTrace()[0] + ")";
        S fresh = freshInstance(race, asPassed, valuesAsPassed);
        System.err.println("SketchRun: " + race + "; ran it again once with a new " + name);
        FrameHooks second = attempt(fresh);
        if (second.race != null) {
            throw new AssertionError(race + ", and the new " + name + " lost it too", second.race);
        }
        return second.result();
    }

    /** One window: runs an instance until its last frame, a failure, a stall or the window race. */
    private FrameHooks attempt(S instance) {
        int total = frames > 0 ? frames : script.frames();
        FrameHooks hooks = new FrameHooks(instance, total);
        instance.registerMethod("pre", hooks);
        instance.registerMethod("post", hooks);
        String name = instance.getClass().getSimpleName();
        takeProcessingsUncaught();  // a run before this one may have left one
        PApplet.runSketch(new String[] {PApplet.ARGS_LOCATION + "=40,40",
                PApplet.ARGS_SKETCH_FOLDER + "=" + (folder != null ? folder : sketchFolder(instance)).getAbsolutePath(), name}, instance);
        // runSketch() installs Processing's own handler, which prints and keeps; this one replaces
        // it and also ends the wait. Only this run's animation thread counts: it runs setup(),
        // draw() and the sketch's event methods. Before its first frame it is known by
        // Processing's name for it. The AWT event thread runs no sketch code, only
        // Processing's repaints, which can race the animation thread for the window's buffer
        // while it opens (an NPE in java.awt.Component$FlipBufferStrategy); Processing prints
        // those and the sketch goes on, so they are printed here too, not failed. When the
        // animation thread is the one that loses that race, it dies: see run().
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
            Thread mine = hooks.thread;
            boolean sketchThread = mine != null ? mine == t : ANIMATION_THREAD.equals(t.getName());
            if (!sketchThread) {
                e.printStackTrace();
            } else {
                animationThreadDied(hooks, instance, t, e);
            }
        });
        // runSketch() installs Processing's handler first thing, so what a thread threw before
        // the line above ran went to Processing's, which prints it and keeps it. If the
        // animation thread is gone by then, that was its death: a sketch that throws at once in
        // setup() (the race, or a bug) would otherwise leave the wait to time out as a stall.
        // (Thrown by another thread, the AWT one repainting, it was printed, as above.)
        Throwable early = takeProcessingsUncaught();
        if (early != null && !animationThreadAlive()) {
            animationThreadDied(hooks, instance, null, early);
        }
        try {
            hooks.await(name);
        } finally {
            close(instance, hooks.thread);
        }
        return hooks;
    }

    /** The animation thread died of e: the window race before frame 1 ends the wait to run again, anything else fails. */
    private void animationThreadDied(FrameHooks hooks, S instance, Thread t, Throwable e) {
        if (!hooks.posted && isWindowRace(e, instance.getClass())) {
            hooks.lostRace(t, e);
        } else {
            hooks.fail(e);
        }
    }

    /** Is a thread of Processing's animation-thread name still running (given a moment to end)? */
    private static boolean animationThreadAlive() {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (ANIMATION_THREAD.equals(t.getName())) {
                try {
                    t.join(200);  // one that has just thrown is on its way out
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                if (t.isAlive()) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * What Processing's own uncaught-exception handler kept ({@code PApplet.uncaughtThrowable},
     * which it sets besides printing), cleared; null if nothing, or if the field cannot be read
     * (another Processing).
     */
    private static Throwable takeProcessingsUncaught() {
        try {
            java.lang.reflect.Field f = PApplet.class.getDeclaredField("uncaughtThrowable");
            f.setAccessible(true);
            Throwable was = (Throwable) f.get(null);
            f.set(null, null);
            return was;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
    }

    /**
     * Whether a throwable is the window-buffer race and nothing else: a NullPointerException
     * thrown inside one of AWT's buffer strategies, with only the JDK's and Processing's surface
     * code on the stack. A frame of the sketch's class, of {@code hitbox}, or of Processing
     * outside its surface (PApplet, where the sketch's own methods run) makes it the sketch's.
     *
     * @param e      what the animation thread threw
     * @param sketch the sketch's class
     * @return true only for the race
     */
    static boolean isWindowRace(Throwable e, Class<?> sketch) {
        StackTraceElement[] stack = e.getStackTrace();
        if (!(e instanceof NullPointerException) || e.getCause() != null || stack.length == 0) {
            return false;
        }
        String top = stack[0].getClassName();
        if (!top.startsWith("java.awt.Component$") || !top.endsWith("BufferStrategy")) {
            return false;
        }
        String own = sketch.getName();
        for (StackTraceElement frame : stack) {
            String c = frame.getClassName();
            if (c.equals(own) || c.startsWith(own + "$") || c.startsWith("hitbox.")) {
                return false;
            }
            boolean jdk = c.startsWith("java.") || c.startsWith("javax.") || c.startsWith("sun.") || c.startsWith("jdk.");
            boolean surface = c.startsWith("processing.awt.PSurface") || c.startsWith("processing.core.PSurface");
            if (!jdk && !surface) {
                return false;
            }
        }
        return true;
    }

    /**
     * A new instance of the sketch's class for the second window, given the values a test set
     * on the one it passed (numbers, text, enums, Hitbox shapes and records of such values,
     * which two instances can share), or why there can be none.
     */
    @SuppressWarnings("unchecked")
    private S freshInstance(String race, Map<String, String> asPassed, Map<String, Object> valuesAsPassed) {
        Class<? extends PApplet> type = sketch.getClass();
        S fresh;
        try {
            Constructor<? extends PApplet> constructor = type.getConstructor();
            fresh = (S) constructor.newInstance();
        } catch (NoSuchMethodException | IllegalAccessException | InstantiationException e) {
            throw new AssertionError(race + "; not run again: " + type.getName() + " has no public no-arg constructor", e);
        } catch (InvocationTargetException e) {
            throw new AssertionError(race + "; not run again: a new " + type.getSimpleName() + " threw " + e.getCause(), e.getCause());
        }
        Map<String, String> plain = fields(fresh);
        Map<String, Field> own = ownFields(type);
        for (Map.Entry<String, String> field : asPassed.entrySet()) {
            String other = plain.get(field.getKey());
            if (field.getValue().equals(other)) {
                continue;
            }
            Object value = valuesAsPassed.get(field.getKey());
            if (!shareable(value) || !given(own.get(field.getKey()), fresh, value)) {
                throw new AssertionError(race + "; not run again: the sketch was changed before the run (its "
                        + field.getKey() + " was " + field.getValue() + ", a new one's is " + other
                        + ", an object a new one cannot share), so a new one would not be the same sketch");
            }
        }
        return fresh;
    }

    /** Can two sketches hold this same value, neither changing it: a value, not a thing? */
    private static boolean shareable(Object value) {
        if (value == null || value instanceof String || value instanceof Boolean || value instanceof Character
                || value instanceof Enum<?> || value instanceof hitbox.Shape) {
            return true;  // a Hitbox shape is immutable, a Polygon too
        }
        if (value instanceof Integer || value instanceof Float || value instanceof Double || value instanceof Long
                || value instanceof Short || value instanceof Byte) {
            return true;  // boxed primitives only: an AtomicInteger is a Number too, and changes
        }
        if (value instanceof Unreadable) {
            return false;
        }
        if (value instanceof Record r) {
            for (java.lang.reflect.RecordComponent c : r.getClass().getRecordComponents()) {
                try {
                    java.lang.reflect.Method read = c.getAccessor();
                    read.setAccessible(true);
                    if (!shareable(read.invoke(r))) {
                        return false;
                    }
                } catch (ReflectiveOperationException | RuntimeException e) {
                    return false;
                }
            }
            return true;
        }
        return false;
    }

    /** Sets a field of the new instance to the passed one's value; false if it cannot be set. */
    private static boolean given(Field field, PApplet fresh, Object value) {
        if (field == null || Modifier.isFinal(field.getModifiers())) {
            return false;
        }
        try {
            field.setAccessible(true);
            field.set(fresh, value);
            return true;
        } catch (IllegalAccessException | RuntimeException e) {
            return false;
        }
    }

    /** The fields a sketch's own classes declare, not static, by {@code Class.name}, in order. */
    private static Map<String, Field> ownFields(Class<?> type) {
        Map<String, Field> out = new LinkedHashMap<>();
        for (Class<?> c = type; c != PApplet.class && c != null; c = c.getSuperclass()) {
            for (Field f : c.getDeclaredFields()) {
                if (!Modifier.isStatic(f.getModifiers()) && !f.isSynthetic()) {
                    out.put(c.getSimpleName() + "." + f.getName(), f);
                }
            }
        }
        return out;
    }

    /** A field whose value could not be read: never shared, never equal to a new one's (no retry). */
    private record Unreadable(Exception why) {
        @Override
        public String toString() {
            return "unreadable (" + why + ")";
        }
    }

    /** The sketch's own fields' values, by {@code Class.name} (an {@link Unreadable} where reading failed). */
    private static Map<String, Object> values(PApplet sketch) {
        Map<String, Object> out = new LinkedHashMap<>();
        for (Map.Entry<String, Field> field : ownFields(sketch.getClass()).entrySet()) {
            Object value;
            try {
                field.getValue().setAccessible(true);
                value = field.getValue().get(sketch);
            } catch (RuntimeException | IllegalAccessException e) {
                value = new Unreadable(e);
            }
            out.put(field.getKey(), value);
        }
        return out;
    }

    /**
     * The fields a sketch's own classes declare, each as text that two instances share when
     * they hold the same values: numbers, text and enums by value, arrays element by element,
     * other objects by their {@code toString()} when their class writes one, else by class only.
     * Comparing these tells a sketch as its constructor left it from one a test set up.
     */
    private static Map<String, String> fields(PApplet sketch) {
        return described(values(sketch));
    }

    /** {@link #fields}' text of values already read. */
    private static Map<String, String> described(Map<String, Object> values) {
        Map<String, String> out = new LinkedHashMap<>();
        for (Map.Entry<String, Object> field : values.entrySet()) {
            out.put(field.getKey(), describe(field.getValue()));
        }
        return out;
    }

    private static String describe(Object value) {
        if (value == null) {
            return "null";
        }
        Class<?> type = value.getClass();
        if (type.isArray()) {
            if (!type.getComponentType().isPrimitive()) {
                Object[] items = (Object[]) value;
                StringBuilder b = new StringBuilder("[");
                for (Object item : items) {
                    b.append(b.length() > 1 ? ", " : "").append(describe(item));
                }
                return b.append(']').toString();
            }
            return Arrays.deepToString(new Object[] {value});
        }
        if (value instanceof Number || value instanceof CharSequence || value instanceof Character
                || value instanceof Boolean || value instanceof Enum<?>) {
            return String.valueOf(value);
        }
        try {
            return type.getMethod("toString").getDeclaringClass() == Object.class ? type.getName() : value.toString();
        } catch (NoSuchMethodException e) {
            throw new AssertionError(e);  // every class has toString()
        }
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
        private final S sketch;
        private final int total;
        private final AtomicReference<Throwable> failure = new AtomicReference<>();
        private final Map<Integer, PImage> images = new HashMap<>();
        private volatile PImage last;
        private volatile boolean finished;
        private volatile int framesDone;
        private volatile Thread thread;
        /** Set when post() is first called: the first frame has been drawn. */
        private volatile boolean posted;
        /** What the animation thread threw when it lost the window race, see run(). */
        private volatile Throwable race;
        private int mouseX;
        private int mouseY;
        private boolean pressed;

        FrameHooks(S sketch, int total) {
            this.sketch = sketch;
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
            posted = true;
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

        /** The animation thread died of the window race: the wait ends without a failure. */
        void lostRace(Thread animation, Throwable t) {
            thread = animation;
            race = t;
            finished = true;
        }

        Result<S> result() {
            return new Result<>(sketch, framesDone, images, last);
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
     * @param sketch      the sketch, stopped, with its fields as the last frame left them: the one
     *                    passed to {@link SketchRun#of}, or the new one if the run was repeated
     *                    after the window race (see {@link SketchRun#run()})
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
