package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** docs/sketches.md is made from the sketches' headers; no display needed. */
class SketchesPageTest {
    @TempDir
    Path root;

    private void sketch(String name, String mainTab) throws IOException {
        Path folder = Files.createDirectories(root.resolve(name));
        Files.writeString(folder.resolve(name + ".pde"), mainTab);
    }

    @Test
    void committedPage_isWhatTheSketchHeadersMake() {
        Catalog catalog = Catalog.load();
        File page = new File(catalog.root().getAbsoluteFile().getParentFile(), SketchesPage.PAGE);
        String difference = SketchesPage.check(catalog, page);
        assertTrue(difference.isEmpty(), difference);
        String made = SketchesPage.render(catalog);
        for (Catalog.SketchInfo s : catalog.sketches()) {
            assertTrue(made.contains("(`" + s.name() + "`)"), s.name() + " has an entry");
            assertTrue(made.contains("`gradle run -Psketch=" + s.name() + "`"), s.name() + " has its run command");
        }
    }

    @Test
    void check_namesTheTask_whenThePageDiffers() throws IOException {
        sketch("S01_EdgeBounce", "/**\n * Edges\n * Tutorial section 1: Edges\n *\n * Bounce.\n */\n");
        Catalog catalog = Catalog.load(root.toFile());
        File page = root.resolve("sketches.md").toFile();
        assertTrue(SketchesPage.check(catalog, page).contains("run gradle sketchesPage"), "no page at all");
        Files.writeString(page.toPath(), SketchesPage.render(catalog).replace("Bounce.", "Bounce twice."));
        String difference = SketchesPage.check(catalog, page);
        assertTrue(difference.contains("run gradle sketchesPage"), difference);
        assertTrue(difference.contains("Bounce twice."), difference);
        Files.writeString(page.toPath(), SketchesPage.render(catalog).replace("\n", "\r\n"));
        assertEquals("", SketchesPage.check(catalog, page), "line endings aside, the same page");
    }

    @Test
    void render_groupsBySection_andQuotesTheFirstParagraphAndWhereHitboxDiffers() throws IOException {
        sketch("S02_CirclePoint", """
                /**
                 * Circle/Point
                 * Tutorial section 2: Circle/Point
                 *
                 * The mouse is a point: dist(mouseX, mouseY, x, y) < r,
                 * compared as dx * dx < r * r.
                 *
                 * Press t for the tutorial's code.
                 *
                 * Where Hitbox differs: it does not. Collide.circlePoint
                 * is the same test.
                 *
                 * Try this: make the radius 0.
                 * Keys: d shows the maths.
                 */
                """);
        sketch("S02c_Ellipses", "/**\n * Ellipses\n * Tutorial section 2: Circle/Point, for ellipses (beyond the tutorial)\n *\n"
                + " * Four ways:\n *   1: a point;\n *   2: a circle, which\n *      is round.\n *\n * Try this: squash one.\n */\n");
        sketch("S01_EdgeBounce", "/**\n * Edges\n * Tutorial section 1: Edges\n *\n * Bounce.\n *\n"
                + " * Press t. Hitbox differs because of that: it waits.\n */\n");
        sketch("S10e_FastObjects", "/**\n * Fast objects\n * Beyond the tutorial: fast objects\n *\n * A_b, _b_ and A* and <b>.\n */\n");
        sketch("H02_Bouncers", "/**\n * Bouncers\n * Homework 2: 100 bouncers\n *\n * A hundred.\n */\n");
        Files.createFile(root.resolve("S01_EdgeBounce/screenshot.png"));

        String page = SketchesPage.render(Catalog.load(root.toFile()));

        int s1 = page.indexOf("\n## Section 1: Edges\n");
        int s2 = page.indexOf("\n## Section 2: Circle/Point\n");
        int hw = page.indexOf("\n## Homework\n");
        int beyond = page.indexOf("\n## Beyond the tutorial\n");
        assertTrue(0 < s1 && s1 < s2 && s2 < hw && hw < beyond, page);
        assertTrue(page.indexOf("(`S02_CirclePoint`)") < page.indexOf("(`S02c_Ellipses`)"), page);
        assertTrue(page.contains("<img src=\"../sketches/S01_EdgeBounce/screenshot.png\" width=\"300\" alt=\"Edges\" align=\"left\">"), page);
        assertFalse(page.contains("S02_CirclePoint/screenshot.png"), "no screenshot, no picture");
        assertTrue(page.contains("**Circle/Point** (`S02_CirclePoint`). The mouse is a point: dist(mouseX, mouseY, x, y) < r,"
                + " compared as dx * dx < r * r.\n\n*Where Hitbox differs:* it does not. Collide.circlePoint is the same test.\n\n"
                + "`gradle run -Psketch=S02_CirclePoint`\n\n<br clear=\"left\">\n"), page);
        assertTrue(page.contains("**Edges** (`S01_EdgeBounce`). Bounce.\n\nPress t. Hitbox differs because of that: it waits.\n\n"), page);
        assertTrue(page.contains("Four ways:<br>1: a point;<br>2: a circle, which is round.\n"), page);
        assertTrue(page.contains("A_b, \\_b\\_ and A\\* and &lt;b>."), page);
        assertFalse(page.contains("Try this") || page.contains("Keys:") || page.contains("tutorial's code"),
                "only the first paragraph and where Hitbox differs: " + page);
    }
}
