package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.sketchkit.Catalog;
import hitbox.sketchkit.Gallery;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/** The gallery shows every sketch found in the folders, and a click opens the one clicked. */
class GalleryTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @Test
    void click_opensTheClickedSketch() {
        Catalog catalog = Catalog.load();
        assumeTrue(catalog.sketches().size() >= 2, "needs two sketches");
        List<String> opened = new ArrayList<>();
        int last = catalog.sketches().size() - 1;
        int[] first = Gallery.thumbnailCentre(0);
        int[] other = Gallery.thumbnailCentre(Math.min(last, 5));
        SketchRun.of(new Gallery(catalog, info -> opened.add(info.name())))
                .script(new Script().frames(20).click(3, first[0], first[1]).click(8, other[0], other[1])
                        .click(13, 2, 2))  // the header: opens nothing
                .run();
        assertEquals(List.of(catalog.sketches().get(0).name(), catalog.sketches().get(Math.min(last, 5)).name()), opened);
    }

    @Test
    void draw_showsEveryThumbnail() {
        Catalog catalog = Catalog.load();
        assumeTrue(!catalog.sketches().isEmpty(), "needs a sketch");
        SketchRun.Result<Gallery> r = SketchRun.of(new Gallery(catalog, info -> { })).frames(3).run();
        int[] c = Gallery.thumbnailCentre(0);
        int background = 0xFF181A20;
        assertTrue(r.lastFrame().get(c[0], c[1]) != background, "the first thumbnail is drawn");
    }
}
