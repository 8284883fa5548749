package hitbox.sketchkit;

import java.io.File;
import java.util.List;

/**
 * What {@code gradle screenshots} starts: runs each sketch with the scripted input in its
 * {@code screenshot.txt} (see {@link Script}) and saves its last frame as
 * {@code screenshot.png} beside it; then, with every sketch's, the whole gallery
 * ({@link Gallery#picture}) as {@code docs/gallery.png}, the README's picture.
 * {@code gradle galleryPicture} (the argument {@value #GALLERY_ONLY}) saves only that
 * picture, from the screenshots there are.
 */
public final class Screenshots {
    private Screenshots() {
    }

    /** The argument that saves only the gallery picture, from the screenshots there are. */
    public static final String GALLERY_ONLY = "--gallery";

    /**
     * Saves the screenshots.
     *
     * @param args nothing for every sketch and the gallery picture, sketch names, or
     *             {@value #GALLERY_ONLY} for the gallery picture alone
     */
    public static void main(String[] args) {
        if (!SketchRun.displayAvailable()) {
            System.err.println(Launcher.noDisplay("gradle screenshots"));
            System.exit(2);
        }
        Catalog catalog = Catalog.load();
        if (List.of(args).equals(List.of(GALLERY_ONLY))) {
            savePicture(catalog);
            System.exit(0);
        }
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
            savePicture(Catalog.load(catalog.root()));
        }
        // Closed sketch windows leave AWT threads behind; end the JVM explicitly.
        System.exit(failures == 0 ? 0 : 1);
    }

    /** Saves the whole gallery, every sketch, as {@code docs/gallery.png} beside the sketches folder. */
    private static void savePicture(Catalog catalog) {
        File picture = new File(catalog.root().getAbsoluteFile().getParentFile(), "docs/gallery.png");
        SketchRun.of(Gallery.picture(catalog)).frames(3).saveFrame(3, picture).run();
        System.out.println("saved " + picture.getPath() + " (" + catalog.sketches().size() + " sketches)");
    }
}
