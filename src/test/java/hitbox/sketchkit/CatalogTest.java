package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CatalogTest {
    @TempDir
    Path root;

    private void sketch(String name, String mainTab) throws IOException {
        Path folder = Files.createDirectories(root.resolve(name));
        Files.writeString(folder.resolve(name + ".pde"), mainTab);
    }

    @Test
    void load_findsSketchFoldersInTutorialOrder_andReadsTheirHeaders() throws IOException {
        sketch("S02_CirclePoint", """
                /**
                 * Circle/Point
                 * Tutorial section 2: Circle/Point
                 *
                 * Try this: move the mouse.
                 */
                import hitbox.*;
                """);
        sketch("H02_Bouncers", "/**\n * Bouncers\n * Homework 2: 100 bouncers\n */\n");
        sketch("S01_EdgeBounce", "// no header\nint x;\n");
        Files.createDirectories(root.resolve("notASketch"));  // no notASketch.pde inside
        Files.writeString(root.resolve("README.md"), "not a folder");

        Catalog catalog = Catalog.load(root.toFile());

        List<Catalog.SketchInfo> s = catalog.sketches();
        assertEquals(List.of("S01_EdgeBounce", "S02_CirclePoint", "H02_Bouncers"),
                s.stream().map(Catalog.SketchInfo::name).toList());
        assertEquals("Circle/Point", s.get(1).title());
        assertEquals("Tutorial section 2: Circle/Point", s.get(1).section());
        assertEquals("Homework 2: 100 bouncers", s.get(2).section());
        assertEquals("S01_EdgeBounce", s.get(0).title(), "no header: the folder name is the title");
        assertEquals("", s.get(0).section());
        assertEquals(new File(root.toFile(), "S02_CirclePoint/screenshot.png"), s.get(1).screenshot());
        assertTrue(catalog.find("S01_EdgeBounce").isPresent());
        assertTrue(catalog.find("S99_Nothing").isEmpty());
        assertEquals("S01_EdgeBounce, S02_CirclePoint, H02_Bouncers", catalog.names());
    }

    @Test
    void load_beyondTheTutorial_isASectionLineOfItsOwnGroup() throws IOException {
        sketch("S10e_FastObjects", "/**\n * Fast objects\n * Beyond the tutorial: fast objects\n */\n");
        sketch("S02_CirclePoint", "/**\n * Circle/Point\n * Tutorial section 2: Circle/Point\n */\n");

        Catalog catalog = Catalog.load(root.toFile());

        Catalog.SketchInfo beyond = catalog.find("S10e_FastObjects").orElseThrow();
        assertEquals("Beyond the tutorial: fast objects", beyond.section());
        assertEquals(Catalog.Group.BEYOND, beyond.group());
        assertEquals(Catalog.Group.TUTORIAL, catalog.find("S02_CirclePoint").orElseThrow().group());
        assertEquals(Catalog.Group.OTHER, Catalog.Group.of("Fast objects"));
    }

    @Test
    void groupOf_theWorldsLine_isTheWorldGroup_notPlainBeyond() {
        assertEquals(Catalog.Group.WORLD, Catalog.Group.of("Beyond the tutorial: the world, a platformer"));
        assertEquals(Catalog.Group.BEYOND, Catalog.Group.of("Beyond the tutorial: fast objects"));
    }

    @Test
    void load_missingFolder_saysWhereItLooked() {
        File missing = root.resolve("nope").toFile();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> Catalog.load(missing));
        assertTrue(e.getMessage().contains(missing.getAbsolutePath()), e.getMessage());
    }

    @Test
    void theRealSketchesFolder_everySketchHasATitleAndSection() {
        Catalog catalog = Catalog.load();
        for (Catalog.SketchInfo info : catalog.sketches()) {
            assertTrue(!info.title().equals(info.name()), info.name() + " has no header title");
            assertTrue(!info.section().isEmpty(), info.name()
                    + " has no \"Tutorial section\", \"Homework\" or \"Beyond the tutorial\" line after its title");
        }
    }

    @Test
    void theIndexes_linkEverySketchFolder() throws IOException {
        Catalog catalog = Catalog.load();
        File project = catalog.root().getAbsoluteFile().getParentFile();
        String readme = Files.readString(new File(project, "README.md").toPath());
        String index = Files.readString(new File(catalog.root(), "README.md").toPath());
        for (Catalog.SketchInfo info : catalog.sketches()) {
            assertTrue(readme.contains("](sketches/" + info.name() + ")"),
                    info.name() + " has no line in the README's table of sections");
            assertTrue(index.contains("- [" + info.name() + "](" + info.name() + "/)"),
                    info.name() + " has no line in sketches/README.md, the sketch index");
        }
    }
}
