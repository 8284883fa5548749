package hitbox.sketchkit;

import java.util.Optional;

import processing.core.PApplet;

/**
 * What {@code gradle run} starts: the gallery of every sketch, or one sketch by name
 * ({@code gradle run -Psketch=S02_CirclePoint}).
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
     * Opens the gallery (no arguments) or the named sketch.
     *
     * @param args nothing, or a sketch's folder name
     */
    public static void main(String[] args) {
        if (!SketchRun.displayAvailable()) {
            System.err.println(noDisplay("gradle run"));
            System.exit(2);
        }
        Catalog catalog = Catalog.load();
        if (args.length == 0) {
            Gallery.open(catalog);
            return;
        }
        Optional<Catalog.SketchInfo> sketch = catalog.find(args[0]);
        if (sketch.isEmpty()) {
            System.err.println("No sketch named \"" + args[0] + "\". The sketches are: " + catalog.names());
            System.exit(2);
        }
        PApplet.runSketch(new String[] {sketch.get().name()}, sketch.get().newInstance());
    }
}
