package hitbox.sketchkit;

import java.io.File;
import java.util.List;

/**
 * What {@code gradle screenshots} starts: runs each sketch with the scripted input in its
 * {@code screenshot.txt} (see {@link Script}) and saves its last frame as
 * {@code screenshot.png} beside it; then, with every sketch's, the gallery itself as
 * {@code docs/gallery.png}, the README's picture.
 */
public final class Screenshots {
    private Screenshots() {
    }

    /**
     * Saves the screenshots.
     *
     * @param args nothing for every sketch, or sketch names
     */
    public static void main(String[] args) {
        if (!SketchRun.displayAvailable()) {
            System.err.println(Launcher.noDisplay("gradle screenshots"));
            System.exit(2);
        }
        Catalog catalog = Catalog.load();
        List<Catalog.SketchInfo> chosen = args.length == 0 ? catalog.sketches()
                : List.of(args).stream().map(n -> catalog.find(n).orElseThrow(() -> new IllegalArgumentException(
                        "No sketch named \"" + n + "\". The sketches are: " + catalog.names()))).toList();
        int failures = 0;
        for (Catalog.SketchInfo info : chosen) {
            Script script = info.readScript();
            try {
                SketchRun.of(info.newInstance()).script(script)
                        .saveFrame(script.frames(), info.screenshot())
                        .run();
                System.out.println("saved " + info.screenshot().getPath());
            } catch (AssertionError | RuntimeException e) {
                failures++;
                System.err.println(info.name() + ": " + e.getMessage());
            }
        }
        if (args.length == 0) {
            // Read the folders again so the gallery shows the screenshots just made.
            Catalog fresh = Catalog.load(catalog.root());
            File picture = new File(catalog.root().getAbsoluteFile().getParentFile(), "docs/gallery.png");
            SketchRun.of(new Gallery(fresh, info -> { })).frames(3).saveFrame(3, picture).run();
            System.out.println("saved " + picture.getPath());
        }
        // Closed sketch windows leave AWT threads behind; end the JVM explicitly.
        System.exit(failures == 0 ? 0 : 1);
    }
}
