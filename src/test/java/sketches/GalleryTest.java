package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import hitbox.sketchkit.Catalog;
import hitbox.sketchkit.Catalog.Group;
import hitbox.sketchkit.Gallery;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * The gallery shows every sketch found in the folders, grouped by what its header's second
 * line says (the tutorial's sections, the homework, beyond the tutorial), and a click opens
 * the one clicked; its picture, the README's, shows every sketch.
 */
class GalleryTest {
    private static final int BACKGROUND = 0xFF181A20;

    @TempDir
    Path root;

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private void sketch(String name, String header) throws IOException {
        Path folder = Files.createDirectories(root.resolve(name));
        Files.writeString(folder.resolve(name + ".pde"), header + "void setup() {\n  size(600, 400);\n}\n");
    }

    @Test
    void click_opensTheClickedSketch() {
        Catalog catalog = Catalog.load();
        assumeTrue(catalog.sketches().size() >= 2, "needs two sketches");
        List<String> opened = new ArrayList<>();
        Gallery gallery = new Gallery(catalog, info -> opened.add(info.name()));
        List<Catalog.SketchInfo> shown = gallery.shown();
        String first = shown.get(0).name();
        String other = shown.get(Math.min(shown.size() - 1, 5)).name();
        int[] a = gallery.thumbnailCentre(first);
        int[] b = gallery.thumbnailCentre(other);
        SketchRun.of(gallery)
                .script(new Script().frames(20).click(3, a[0], a[1]).click(8, b[0], b[1])
                        .click(13, 2, 2))  // the header: opens nothing
                .run();
        assertEquals(List.of(first, other), opened);
    }

    @Test
    void draw_showsEveryThumbnail() {
        Catalog catalog = Catalog.load();
        assumeTrue(!catalog.sketches().isEmpty(), "needs a sketch");
        Gallery gallery = new Gallery(catalog, info -> { });
        SketchRun.Result<Gallery> r = SketchRun.of(gallery).frames(3).run();
        int[] c = gallery.thumbnailCentre(gallery.shown().get(0).name());
        assertTrue(r.lastFrame().get(c[0], c[1]) != BACKGROUND, "the first thumbnail is drawn");
    }

    @Test
    void groups_tutorialThenHomeworkThenBeyond_eachUnderItsHeading_withItsOwnLabel() throws IOException {
        sketch("S10e_Fast", "/**\n * Fast objects\n * Beyond the tutorial: fast objects and tunnelling\n */\n");
        sketch("S01_Edges", "/**\n * Edges\n * Tutorial section 1: Edges\n *\n * Homework: not a section line.\n */\n");
        sketch("H01_Maze", "/**\n * A maze\n * Homework 1: a maze\n */\n");
        sketch("S02_Mine", "// a sketch of your own, no header\n");
        sketch("S03_Later", "/**\n * Circles\n * Two circles.\n * Tutorial section 3: Circle/Circle\n */\n");
        Catalog catalog = Catalog.load(root.toFile());

        Gallery gallery = Gallery.picture(catalog);

        assertEquals(List.of(Group.TUTORIAL, Group.HOMEWORK, Group.BEYOND, Group.OTHER), gallery.groups());
        assertEquals(List.of("S01_Edges", "H01_Maze", "S10e_Fast", "S02_Mine", "S03_Later"),
                gallery.shown().stream().map(Catalog.SketchInfo::name).toList(),
                "the groups in order, and within each the tutorial order of the folders");
        Catalog.SketchInfo beyond = catalog.find("S10e_Fast").orElseThrow();
        assertEquals(Group.BEYOND, beyond.group());
        assertEquals("Beyond the tutorial: fast objects and tunnelling", Gallery.label(beyond),
                "a sketch beyond the tutorial says so under its title, never a tutorial section");
        assertEquals("Tutorial section 1: Edges", Gallery.label(catalog.find("S01_Edges").orElseThrow()),
                "the section line is the one after the title; later prose is not");
        assertEquals(Group.OTHER, catalog.find("S03_Later").orElseThrow().group(),
                "a section line below other words, not right after the title, does not count");
        assertEquals("S02_Mine", Gallery.label(catalog.find("S02_Mine").orElseThrow()), "no header: the folder name");

        // Each group starts a new row, at the left, below the group before it.
        int[] previous = null;
        for (String name : List.of("S01_Edges", "H01_Maze", "S10e_Fast", "S02_Mine")) {
            int[] c = gallery.thumbnailCentre(name);
            if (previous != null) {
                assertEquals(previous[0], c[0], name + " starts its group's row at the left");
                assertTrue(c[1] > previous[1], name + " is below the group before it");
            }
            previous = c;
        }
        int[] first = gallery.thumbnailCentre("S02_Mine");
        int[] second = gallery.thumbnailCentre("S03_Later");
        assertEquals(first[1], second[1], "sketches of one group share a row");

        // Drawn: every card, and the beyond group's heading in its own colour above its row.
        SketchRun.Result<Gallery> r = SketchRun.of(gallery).frames(3).run();
        PImage frame = r.lastFrame();
        for (Catalog.SketchInfo info : catalog.sketches()) {
            int[] c = gallery.thumbnailCentre(info.name());
            assertTrue(c[1] < frame.height, info.name() + " is inside the picture");
            assertTrue(frame.get(c[0], c[1]) != BACKGROUND, info.name() + "'s card is drawn");
        }
        int[] b = gallery.thumbnailCentre("S10e_Fast");
        int[] h = gallery.thumbnailCentre("H01_Maze");
        assertTrue(colourIn(frame, 0, h[1] + 110, frame.width, b[1] - 70, 0xFFF0BE6E),
                "the \"Beyond the tutorial\" heading is drawn between the homework row and its own");
        assertFalse(colourIn(frame, 0, 0, frame.width, h[1] + 110, 0xFFF0BE6E),
                "nothing above the beyond group is drawn in its colour");
    }

    @Test
    void worldGroup_hasARowOfItsOwn_afterBeyondTheTutorial() throws IOException {
        sketch("S10e_Fast", "/**\n * Fast objects\n * Beyond the tutorial: fast objects\n */\n");
        sketch("S10i_Blade", "/**\n * A blade\n * Beyond the tutorial: turning sweeps\n */\n");
        sketch("B02_Jump", "/**\n * A platformer\n * Beyond the tutorial: the world, a platformer\n */\n");
        sketch("H02b_Again", "/**\n * Homework 2 again\n * Beyond the tutorial: the world, homework 2 again\n */\n");
        sketch("H01_Maze", "/**\n * A maze\n * Homework 1: a maze\n */\n");
        Catalog catalog = Catalog.load(root.toFile());

        Gallery gallery = Gallery.picture(catalog);

        assertEquals(List.of(Group.HOMEWORK, Group.BEYOND, Group.WORLD), gallery.groups());
        assertEquals(List.of("H01_Maze", "S10e_Fast", "S10i_Blade", "B02_Jump", "H02b_Again"),
                gallery.shown().stream().map(Catalog.SketchInfo::name).toList());
        assertEquals("Beyond the tutorial: the world, a platformer", Gallery.label(catalog.find("B02_Jump").orElseThrow()));
        int[] beyond = gallery.thumbnailCentre("S10e_Fast");
        int[] world = gallery.thumbnailCentre("B02_Jump");
        assertEquals(beyond[0], world[0], "the world's row starts at the left");
        assertTrue(world[1] > gallery.thumbnailCentre("S10i_Blade")[1], "below the beyond row, not beside it");
        assertEquals(world[1], gallery.thumbnailCentre("H02b_Again")[1], "the world's sketches share their row");
    }

    @Test
    void picture_ofTheRealSketches_showsEveryOneOfThem_eachInAGroup() {
        Catalog catalog = Catalog.load();
        assumeTrue(!catalog.sketches().isEmpty(), "needs a sketch");
        Gallery picture = Gallery.picture(catalog);
        assertEquals(catalog.sketches().size(), picture.shown().size(), "every sketch is shown");
        for (Catalog.SketchInfo info : catalog.sketches()) {
            assertTrue(info.group() != Group.OTHER, info.name() + "'s second header line is \"" + info.section()
                    + "\": it names no tutorial section, homework, or \"Beyond the tutorial\"");
        }
        SketchRun.Result<Gallery> r = SketchRun.of(picture).frames(3).run();
        for (Catalog.SketchInfo info : catalog.sketches()) {
            int[] c = picture.thumbnailCentre(info.name());
            assertTrue(c[1] + 64 < r.lastFrame().height, info.name() + " is inside the picture, not scrolled away");
            assertTrue(r.lastFrame().get(c[0], c[1]) != BACKGROUND, info.name() + "'s thumbnail is drawn");
        }
    }

    /** Whether any pixel of the rectangle [x0, x1) x [y0, y1) has exactly this colour. */
    private static boolean colourIn(PImage frame, int x0, int y0, int x1, int y1, int argb) {
        for (int y = Math.max(0, y0); y < Math.min(frame.height, y1); y++) {
            for (int x = Math.max(0, x0); x < Math.min(frame.width, x1); x++) {
                if (frame.get(x, y) == argb) {
                    return true;
                }
            }
        }
        return false;
    }
}
