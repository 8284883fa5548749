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
 * title and the second line of its header, in groups (see {@link Catalog.Group}): the
 * tutorial's sections in order, its homework, then what goes beyond the tutorial, each under
 * its own heading. A click opens that sketch in its own window.
 *
 * <p>Each sketch runs in a JVM of its own, so closing a sketch (which ends its program, as in
 * the Processing IDE) leaves the gallery open. {@link #picture(Catalog)} is the same gallery
 * tall enough to show every sketch at once, the README's picture.
 */
public final class Gallery extends PApplet {
    private static final int COLUMNS = 5;
    // 3:2, the shape of most sketches (600 x 400); other shapes are fitted inside, not squeezed.
    private static final int THUMB_W = 192;
    private static final int THUMB_H = 128;
    private static final int CELL_W = 208;
    private static final int CELL_H = 212;
    private static final int TOP = 64;
    private static final int HEADING_H = 34;
    private static final int MARGIN = 16;
    /** The window shows up to this many pixels of the grid and scrolls the rest. */
    private static final int WINDOW_GRID_H = 4 * CELL_H;

    private final Catalog catalog;
    private final Consumer<Catalog.SketchInfo> opener;
    private final boolean whole;
    /** The sketches in the order they are shown: by group, then in tutorial order. */
    private final List<Catalog.SketchInfo> shown = new ArrayList<>();
    /** Each shown sketch's cell, its top-left corner before any scrolling. */
    private final List<int[]> cells = new ArrayList<>();
    /** Each group's heading and where it is drawn, before any scrolling. */
    private final List<Catalog.Group> headings = new ArrayList<>();
    private final List<Integer> headingTops = new ArrayList<>();
    /** The bottom of the last row, before any scrolling. */
    private final int gridBottom;
    private final List<PImage> thumbs = new ArrayList<>();
    /** Each sketch's build problems ("" when it built), shown in place of its thumbnail. */
    private final List<String> errors = new ArrayList<>();
    private float scroll;
    private String status;

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
        this(catalog, opener, false);
    }

    private Gallery(Catalog catalog, Consumer<Catalog.SketchInfo> opener, boolean whole) {
        this.catalog = catalog;
        this.opener = opener != null ? opener : this::launch;
        this.whole = whole;
        this.status = whole ? "gradle run opens this gallery: click a sketch to open it."
                : "Click a sketch to open it. Close its window to come back.";
        int y = TOP;
        for (Catalog.Group group : Catalog.Group.values()) {
            List<Catalog.SketchInfo> members = catalog.sketches().stream().filter(s -> s.group() == group).toList();
            if (members.isEmpty()) {
                continue;
            }
            headings.add(group);
            headingTops.add(y);
            y += HEADING_H;
            for (int i = 0; i < members.size(); i++) {
                shown.add(members.get(i));
                cells.add(new int[] {MARGIN + (i % COLUMNS) * CELL_W, y + (i / COLUMNS) * CELL_H});
            }
            y += (members.size() + COLUMNS - 1) / COLUMNS * CELL_H;
        }
        gridBottom = y;
    }

    /**
     * The gallery as one picture: tall enough to show every sketch without scrolling, with
     * nothing to click ({@code gradle galleryPicture} saves it as {@code docs/gallery.png}).
     *
     * @param catalog the sketches to show
     * @return the gallery, not yet running
     */
    public static Gallery picture(Catalog catalog) {
        return new Gallery(catalog, info -> { }, true);
    }

    /**
     * Opens the gallery window.
     *
     * @param catalog the sketches to show
     */
    public static void open(Catalog catalog) {
        PApplet.runSketch(new String[] {"Hitbox"}, new Gallery(catalog));
    }

    /** Sizes the window to fit five columns and up to four rows (every row for the picture). */
    @Override
    public void settings() {
        int grid = Math.max(gridBottom - TOP, CELL_H);
        size(COLUMNS * CELL_W + 2 * MARGIN, TOP + (whole ? grid : Math.min(grid, WINDOW_GRID_H)) + MARGIN);
    }

    /** Loads the thumbnails. */
    @Override
    public void setup() {
        surface.setTitle("Hitbox: collision detection, one sketch per idea");
        for (Catalog.SketchInfo info : shown) {
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

    /** Draws the groups of sketches. */
    @Override
    public void draw() {
        background(24, 26, 32);
        int hovered = indexAt(mouseX, mouseY);
        for (int g = 0; g < headings.size(); g++) {
            float y = headingTops.get(g) - scroll;
            if (y + HEADING_H < TOP || y > height) {
                continue;
            }
            Catalog.Group group = headings.get(g);
            noStroke();
            fill(labelColour(group));
            rect(MARGIN, (int) y + 8, 4, 20);
            textAlign(LEFT, BASELINE);
            textSize(16);
            text(group.heading(), MARGIN + 12, y + 24);
            stroke(60, 66, 80);
            line(MARGIN + 24 + textWidth(group.heading()), y + 18, width - MARGIN - 12, y + 18);
        }
        for (int i = 0; i < shown.size(); i++) {
            float x = cells.get(i)[0];
            float y = cells.get(i)[1] - scroll;
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
            Catalog.SketchInfo info = shown.get(i);
            textAlign(LEFT, TOP);
            fill(235);
            textSize(13);
            text(info.title(), x + 6, y + THUMB_H + 10, THUMB_W, 36);
            fill(info.group() == Catalog.Group.TUTORIAL ? color(150) : labelColour(info.group()));
            textSize(11);
            text(label(info), x + 6, y + THUMB_H + 46, THUMB_W, 30);
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

    /** A group's colour for its heading, and for the labels of what is not a tutorial section. */
    private int labelColour(Catalog.Group group) {
        return switch (group) {
            case TUTORIAL -> color(235);
            case HOMEWORK -> color(140, 200, 240);
            case BEYOND -> color(240, 190, 110);
            case WORLD -> color(200, 160, 240);
            case OTHER -> color(170);
        };
    }

    /**
     * The line under a sketch's title: its header's second line as written ("Tutorial section
     * 2: Circle/Point", "Beyond the tutorial: fast objects"), or its folder name without one.
     *
     * @param info a sketch
     * @return the label the gallery shows
     */
    public static String label(Catalog.SketchInfo info) {
        return info.section().isEmpty() ? info.name() : info.section();
    }

    /**
     * The sketches in the order the gallery shows them: the groups of {@link Catalog.Group}
     * in order, each in tutorial order.
     *
     * @return the shown sketches
     */
    public List<Catalog.SketchInfo> shown() {
        return List.copyOf(shown);
    }

    /**
     * The groups the gallery shows a heading for, in order (only groups with a sketch).
     *
     * @return the groups
     */
    public List<Catalog.Group> groups() {
        return List.copyOf(headings);
    }

    /**
     * Where a sketch's thumbnail is drawn, for tests that click it.
     *
     * @param name the sketch's folder name
     * @return the thumbnail's centre, {x, y}, before any scrolling
     * @throws IllegalArgumentException if the gallery has no such sketch
     */
    public int[] thumbnailCentre(String name) {
        for (int i = 0; i < shown.size(); i++) {
            if (shown.get(i).name().equals(name)) {
                return new int[] {cells.get(i)[0] + 6 + THUMB_W / 2, cells.get(i)[1] + 6 + THUMB_H / 2};
            }
        }
        throw new IllegalArgumentException("No sketch named \"" + name + "\" in the gallery");
    }

    private int indexAt(float mx, float my) {
        if (my < TOP) {
            return -1;
        }
        for (int i = 0; i < cells.size(); i++) {
            int[] c = cells.get(i);
            float top = c[1] - scroll;
            if (mx >= c[0] && mx < c[0] + CELL_W && my >= top && my < top + CELL_H) {
                return i;
            }
        }
        return -1;
    }

    /** Opens the clicked sketch. */
    @Override
    public void mousePressed() {
        int i = indexAt(mouseX, mouseY);
        if (i >= 0 && !errors.get(i).isEmpty()) {
            status = shown.get(i).name() + " does not build: " + errors.get(i).lines().findFirst().orElse("");
        } else if (i >= 0) {
            opener.accept(shown.get(i));
        }
    }

    /** Scrolls when there are more sketches than fit. */
    @Override
    public void mouseWheel(MouseEvent event) {
        float max = Math.max(0, gridBottom + MARGIN - height);
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
