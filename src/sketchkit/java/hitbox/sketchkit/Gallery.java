package hitbox.sketchkit;

import java.io.File;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import processing.core.PApplet;
import processing.core.PImage;
import processing.event.MouseEvent;

/**
 * The window {@code gradle run} opens: every sketch as a thumbnail of its screenshot, with its
 * title and tutorial section, in tutorial order. A click opens that sketch in its own window.
 *
 * <p>Each sketch runs in a JVM of its own, so closing a sketch (which ends its program, as in
 * the Processing IDE) leaves the gallery open.
 */
public final class Gallery extends PApplet {
    private static final int COLUMNS = 5;
    // 3:2, the shape of most sketches (600 x 400); other shapes are fitted inside, not squeezed.
    private static final int THUMB_W = 192;
    private static final int THUMB_H = 128;
    private static final int CELL_W = 208;
    private static final int CELL_H = 212;
    private static final int TOP = 64;
    private static final int MARGIN = 16;

    private final Catalog catalog;
    private final Consumer<Catalog.SketchInfo> opener;
    private final List<PImage> thumbs = new ArrayList<>();
    /** Each sketch's build problems ("" when it built), shown in place of its thumbnail. */
    private final List<String> errors = new ArrayList<>();
    private float scroll;
    private String status = "Click a sketch to open it. Close its window to come back.";

    /**
     * A gallery that opens each clicked sketch in a JVM of its own.
     *
     * @param catalog the sketches to show
     */
    public Gallery(Catalog catalog) {
        this(catalog, null);
    }

    /**
     * A gallery with its own way of opening a sketch (tests use this to see what a click does).
     *
     * @param catalog the sketches to show
     * @param opener  what a click on a sketch does; null to start it in a JVM of its own
     */
    public Gallery(Catalog catalog, Consumer<Catalog.SketchInfo> opener) {
        this.catalog = catalog;
        this.opener = opener != null ? opener : this::launch;
    }

    /**
     * Opens the gallery window.
     *
     * @param catalog the sketches to show
     */
    public static void open(Catalog catalog) {
        PApplet.runSketch(new String[] {"Hitbox"}, new Gallery(catalog));
    }

    /** Sizes the window to fit four columns and up to four rows. */
    @Override
    public void settings() {
        int rows = Math.max(1, (catalog.sketches().size() + COLUMNS - 1) / COLUMNS);
        size(COLUMNS * CELL_W + 2 * MARGIN, Math.min(TOP + rows * CELL_H + MARGIN, TOP + 4 * CELL_H));
    }

    /** Loads the thumbnails. */
    @Override
    public void setup() {
        surface.setTitle("Hitbox: collision detection, one sketch per idea");
        for (Catalog.SketchInfo info : catalog.sketches()) {
            File png = info.screenshot();
            PImage image = png.isFile() ? loadImage(png.getAbsolutePath()) : null;
            if (image != null) {
                float scale = Math.min((float) THUMB_W / image.width, (float) THUMB_H / image.height);
                image.resize(Math.round(image.width * scale), Math.round(image.height * scale));
            }
            thumbs.add(image);
            errors.add(info.errors());
        }
    }

    /** Draws the grid of sketches. */
    @Override
    public void draw() {
        background(24, 26, 32);
        List<Catalog.SketchInfo> sketches = catalog.sketches();
        int hovered = indexAt(mouseX, mouseY);
        for (int i = 0; i < sketches.size(); i++) {
            float x = cellLeft(i);
            float y = cellTop(i) - scroll;
            if (y + CELL_H < TOP || y > height) {
                continue;
            }
            noStroke();
            fill(i == hovered ? color(60, 70, 96) : color(38, 42, 52));
            rect(x, y, CELL_W - 12, CELL_H - 12, 6);
            PImage thumb = thumbs.get(i);
            if (!errors.get(i).isEmpty()) {
                // A sketch that does not build shows its first problem, by tab and line.
                fill(90, 30, 34);
                rect(x + 6, y + 6, THUMB_W, THUMB_H);
                fill(255, 200, 200);
                textAlign(LEFT, TOP);
                textSize(11);
                text("does not build:\n" + errors.get(i).lines().findFirst().orElse(""), x + 12, y + 12, THUMB_W - 12, THUMB_H - 12);
            } else if (thumb != null) {
                image(thumb, x + 6 + (THUMB_W - thumb.width) / 2f, y + 6 + (THUMB_H - thumb.height) / 2f);
            } else {
                fill(60);
                rect(x + 6, y + 6, THUMB_W, THUMB_H);
                fill(160);
                textAlign(CENTER, CENTER);
                text("no screenshot yet", x + 6 + THUMB_W / 2f, y + 6 + THUMB_H / 2f);
            }
            Catalog.SketchInfo info = sketches.get(i);
            textAlign(LEFT, TOP);
            fill(235);
            textSize(13);
            text(info.title(), x + 6, y + THUMB_H + 10, THUMB_W, 36);
            fill(150);
            textSize(11);
            text(info.section().isEmpty() ? info.name() : info.section(), x + 6, y + THUMB_H + 46, THUMB_W, 30);
        }
        // The header is drawn last so thumbnails scroll under it.
        noStroke();
        fill(24, 26, 32);
        rect(0, 0, width, TOP - 8);
        fill(255);
        textAlign(LEFT, BASELINE);
        textSize(20);
        text("Hitbox sketches", MARGIN, 32);
        fill(170);
        textSize(12);
        text(status, MARGIN, 50);
    }

    /**
     * Where a sketch's thumbnail is drawn, for tests that click it.
     *
     * @param index the sketch's place in the catalog
     * @return the thumbnail's centre, {x, y}, before any scrolling
     */
    public static int[] thumbnailCentre(int index) {
        return new int[] {cellLeft(index) + 6 + THUMB_W / 2, cellTop(index) + 6 + THUMB_H / 2};
    }

    /** The left edge of sketch {@code index}'s cell. */
    private static int cellLeft(int index) {
        return MARGIN + (index % COLUMNS) * CELL_W;
    }

    /** The top edge of sketch {@code index}'s cell, before any scrolling. */
    private static int cellTop(int index) {
        return TOP + (index / COLUMNS) * CELL_H;
    }

    private int indexAt(float mx, float my) {
        if (my < TOP) {
            return -1;
        }
        int col = (int) ((mx - MARGIN) / CELL_W);
        int row = (int) ((my - TOP + scroll) / CELL_H);
        int i = row * COLUMNS + col;
        boolean inColumn = mx >= MARGIN && col < COLUMNS;
        return inColumn && i >= 0 && i < catalog.sketches().size() ? i : -1;
    }

    /** Opens the clicked sketch. */
    @Override
    public void mousePressed() {
        int i = indexAt(mouseX, mouseY);
        if (i >= 0 && !errors.get(i).isEmpty()) {
            status = catalog.sketches().get(i).name() + " does not build: " + errors.get(i).lines().findFirst().orElse("");
        } else if (i >= 0) {
            opener.accept(catalog.sketches().get(i));
        }
    }

    /** Scrolls when there are more sketches than fit. */
    @Override
    public void mouseWheel(MouseEvent event) {
        int rows = (catalog.sketches().size() + COLUMNS - 1) / COLUMNS;
        float max = Math.max(0, TOP + rows * CELL_H - height);
        scroll = constrain(scroll + event.getCount() * 40, 0, max);
    }

    /** Starts the sketch in a JVM of its own, on the same class path. */
    private void launch(Catalog.SketchInfo info) {
        String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
        ProcessBuilder pb = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                "-D" + Catalog.SKETCHES_PROPERTY + "=" + catalog.root().getAbsolutePath(),
                Launcher.class.getName(), info.name());
        pb.inheritIO();
        try {
            pb.start();
            status = "Opened " + info.title() + ". Close its window to come back; the gallery stays open.";
        } catch (IOException e) {
            status = "Could not open " + info.name() + ": " + e.getMessage();
        }
    }
}
