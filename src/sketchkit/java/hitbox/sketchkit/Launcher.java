package hitbox.sketchkit;

import java.awt.GraphicsEnvironment;
import java.util.Optional;

import processing.core.PApplet;

/**
 * What {@code gradle run} starts: the gallery of every sketch, or one sketch by name
 * ({@code gradle run -Psketch=S02_CirclePoint}).
 */
public final class Launcher {
    private Launcher() {
    }

    /** The one line printed when there is no display to open a window on. */
    static final String NO_DISPLAY =
            "No display to open a window on. Run it under a virtual one: xvfb-run -a gradle run";

    /**
     * Opens the gallery (no arguments) or the named sketch.
     *
     * @param args nothing, or a sketch's folder name
     */
    public static void main(String[] args) {
        if (GraphicsEnvironment.isHeadless()) {
            System.err.println(NO_DISPLAY);
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
