package hitbox.sketchkit;

import java.lang.reflect.Field;
import java.util.Optional;

import processing.core.PApplet;

/**
 * What {@code gradle run} starts: the gallery of every sketch, or one sketch by name
 * ({@code gradle run -Psketch=S02_CirclePoint}).
 *
 * <p>A sketch that does not build, or that throws, ends the program with its problem named by
 * tab and line and a non-zero exit code, rather than leaving an empty window open.
 */
public final class Launcher {
    private Launcher() {
    }

    /**
     * The one line printed when there is no display to open a window on.
     *
     * @param command what to run under the virtual display, e.g. "gradle run"
     * @return the message
     */
    static String noDisplay(String command) {
        return "No display to open a window on. Run it under a virtual one: xvfb-run -a " + command;
    }

    /**
     * What {@code gradle run} says with no display: it shows windows to a person, so the advice
     * is a desktop, X forwarding or {@code DISPLAY}, not a virtual display nobody sees.
     * ({@code gradle/sketches.gradle} says the same before building anything.)
     */
    static final String NO_DISPLAY_TO_SHOW = "No display: gradle run opens the sketches in windows, and DISPLAY is not set.\n"
            + "Run it in a desktop session (a terminal on the desktop), over ssh with X forwarding (ssh -X <host>),\n"
            + "or with DISPLAY set to a running X server (export DISPLAY=:0).";

    /**
     * Opens the gallery (no arguments) or the named sketch.
     *
     * @param args nothing, or a sketch's folder name
     */
    public static void main(String[] args) {
        if (!SketchRun.displayAvailable()) {
            System.err.println(NO_DISPLAY_TO_SHOW);
            System.exit(2);
        }
        Catalog catalog = Catalog.load();
        if (args.length == 0) {
            Gallery.open(catalog);
            return;
        }
        Optional<Catalog.SketchInfo> found = catalog.find(args[0]);
        if (found.isEmpty()) {
            System.err.println("No sketch named \"" + args[0] + "\". The sketches are: " + catalog.names());
            System.exit(2);
        }
        Catalog.SketchInfo sketch = found.get();
        if (!sketch.errors().isEmpty()) {
            System.err.print(sketch.name() + " does not build:\n" + sketch.errors());
            System.exit(1);
        }
        PApplet instance = sketch.newInstance();
        PApplet.runSketch(new String[] {PApplet.ARGS_SKETCH_FOLDER + "=" + sketch.folder().getAbsolutePath(),
                sketch.name()}, instance);
        // Processing's own handler prints an exception and leaves the window open; this one
        // names the tab and line and ends the program, as the IDE stops a sketch that throws.
        Thread.setDefaultUncaughtExceptionHandler((thread, thrown) -> fail(sketch, thrown));
        // An exception in setup() may have reached Processing's handler before this one was
        // set: look for it while the first frames start.
        for (int i = 0; i < 20; i++) {
            Throwable early = processingsUncaught();
            if (early != null) {
                fail(sketch, early);
            }
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private static void fail(Catalog.SketchInfo sketch, Throwable thrown) {
        String where = sketch.locate(thrown);
        System.err.println(sketch.name() + " stopped" + (where.isEmpty() ? "" : " at " + where) + ": " + thrown);
        thrown.printStackTrace();
        System.exit(1);
    }

    /** What Processing's own uncaught-exception handler kept, if anything. */
    private static Throwable processingsUncaught() {
        try {
            Field field = PApplet.class.getDeclaredField("uncaughtThrowable");
            field.setAccessible(true);
            return (Throwable) field.get(null);
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
    }
}
