package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import processing.core.PApplet;

/**
 * Sketches written as the Processing IDE writes them (the fixtures in
 * {@code src/test/fixtures/sketches}) build through Processing's own preprocessor and run, and
 * broken ones are reported by tab and line, without harming the others.
 */
class SketchBuildTest {
    static final File FIXTURES = new File("src/test/fixtures/sketches");
    static final String PREFIX = "src/test/fixtures/sketches/";

    @TempDir
    static Path out;
    static File classes;
    static final Map<String, SketchBuild.Outcome> OUTCOMES = new HashMap<>();
    static Catalog catalog;

    @BeforeAll
    static void buildEveryFixture() throws IOException {
        classes = out.resolve("classes").toFile();
        for (File folder : FIXTURES.listFiles(File::isDirectory)) {
            OUTCOMES.put(folder.getName(), SketchBuild.build(folder, SketchBuild.PACKAGE, TestClassPath.get(), classes));
        }
        URLClassLoader loader = new URLClassLoader(new URL[] {classes.toURI().toURL()}, SketchBuildTest.class.getClassLoader());
        catalog = Catalog.load(FIXTURES, loader);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"StaticMode", "ActiveTabs", "ThrowsInSetup"})
    void ideStyleSketch_builds(String name) {
        SketchBuild.Outcome outcome = OUTCOMES.get(name);
        assertTrue(outcome.ok(), outcome.report());
        assertTrue(new File(classes, "sketches/" + name + ".class").isFile(), "class file");
        assertEquals("", catalog.find(name).orElseThrow().errors());
    }

    @Test
    void generatedJava_isWhatProcessingsPreprocessorWrites() {
        String java = OUTCOMES.get("ActiveTabs").java();
        assertTrue(java.contains("public class ActiveTabs extends PApplet"), java);
        assertTrue(java.contains("int background = 0xFF203040;"), "color and #hex become int and 0xFF...");
        assertTrue(java.contains("public void setup()"), "public added");
        assertTrue(java.contains("public void settings() { size(300, 200); }"), "size() moved into settings()");
        assertTrue(java.contains("random(1) < .2f") && java.contains("strokeWeight(1.5f)"), "float literals get their f");
        assertTrue(java.indexOf("class Ball") > java.indexOf("void draw()"), "tabs joined: the main tab first");
        assertTrue(java.indexOf("class Ball") < java.indexOf("hitColour() {"), "then the others by name");
        assertTrue(OUTCOMES.get("StaticMode").java().contains("noLoop();"), "static mode is wrapped in setup()");
    }

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource({
            "BrokenSyntax,      BrokenSyntax/BrokenSyntax.pde:5,     ''",
            "BrokenSyntaxInTab, BrokenSyntaxInTab/Helper.pde:4,      ''",
            "BrokenType,        BrokenType/BrokenType.pde:4,         incompatible types",
            "BrokenTypeInTab,   BrokenTypeInTab/Ball.pde:3,          cannot find symbol",
    })
    void brokenSketch_isReportedByTabAndLine(String name, String where, String message) {
        SketchBuild.Outcome outcome = OUTCOMES.get(name);
        assertFalse(outcome.ok(), name + " should not build");
        String first = outcome.problems().get(0).toString();
        assertTrue(first.startsWith(PREFIX + where + ": " + message), first);
        assertEquals(outcome.report(), catalog.find(name).orElseThrow().errors(), "the catalog reads what the build wrote");
        assertFalse(new File(classes, "sketches/" + name + ".class").exists(), "no class for a broken sketch");
    }

    @Test
    void activeModeSketch_withTabsAndData_runs() throws ReflectiveOperationException {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
        PApplet sketch = catalog.find("ActiveTabs").orElseThrow().newInstance();
        SketchRun.Result<PApplet> r = SketchRun.of(sketch).folder(new File(FIXTURES, "ActiveTabs"))
                .script(new Script().frames(5).mouse(1, 10, 190)).run();
        var field = sketch.getClass().getDeclaredField("words");
        field.setAccessible(true);  // a sketch's fields are package-private, as the IDE writes them
        String[] words = (String[]) field.get(r.sketch());  // the instance that ran
        assertEquals(List.of("first", "second", "third"), List.of(words), "loadStrings reads data/");
        assertEquals(0xFFFFFF00, r.lastFrame().get(3, 3), "loadImage reads data/");
        assertEquals(0xFF4CC36A, r.lastFrame().get(150, 100), "the ball, #4CC36A while the mouse is outside");
        assertEquals(0xFF203040, r.lastFrame().get(290, 10), "the background, a color variable");
    }

    @Test
    void staticModeSketch_drawsOnce() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
        PApplet sketch = catalog.find("StaticMode").orElseThrow().newInstance();
        SketchRun.Result<PApplet> r = SketchRun.of(sketch).frames(1).run();
        assertEquals(200, r.sketch().width);
        assertEquals(0xFF336699, r.lastFrame().get(50, 50));
        assertEquals(0xFFE8504A, r.lastFrame().get(150, 50));
    }

    @Test
    void gallery_showsABrokenSketchWithItsError_andOpensOnlyTheOthers() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
        List<String> opened = new ArrayList<>();
        Gallery gallery = new Gallery(catalog, info -> opened.add(info.name()));
        int[] b = gallery.thumbnailCentre("BrokenTypeInTab");
        int[] g = gallery.thumbnailCentre("StaticMode");
        SketchRun.Result<Gallery> r = SketchRun.of(gallery)
                .script(new Script().frames(12).click(3, b[0], b[1]).click(7, g[0], g[1])).run();
        assertEquals(List.of("StaticMode"), opened, "a click on a broken sketch opens nothing");
        assertEquals(0xFF5A1E22, r.lastFrame().get(b[0] - 90, b[1] + 60), "the broken sketch's card is red");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "ThrowsInSetup,   ThrowsInSetup stopped at " + PREFIX + "ThrowsInSetup/ThrowsInSetup.pde:6",
            "BrokenTypeInTab, " + PREFIX + "BrokenTypeInTab/Ball.pde:3: cannot find symbol",
    })
    void launcher_endsWithTheTabAndLine_neverHangs(String name, String expected) throws IOException, InterruptedException {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        File err = out.resolve(name + ".err").toFile();
        Process p = new ProcessBuilder(java, "-cp", TestClassPath.get() + File.pathSeparator + classes,
                "-D" + Catalog.SKETCHES_PROPERTY + "=" + FIXTURES.getPath(), Launcher.class.getName(), name)
                .redirectErrorStream(true).redirectOutput(err).start();
        boolean ended = p.waitFor(60, TimeUnit.SECONDS);
        if (!ended) {
            p.destroyForcibly();
        }
        String output = Files.readString(err.toPath(), StandardCharsets.UTF_8);
        assertTrue(ended, "the launcher still runs after 60 s: " + output);
        assertEquals(1, p.exitValue(), output);
        assertTrue(output.contains(expected), output);
    }
}
