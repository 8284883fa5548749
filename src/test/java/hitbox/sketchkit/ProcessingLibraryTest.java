package hitbox.sketchkit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.Reader;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import processing.core.PApplet;

/**
 * The path a Processing IDE user takes: the library zip ({@code gradle processingLibrary})
 * unpacked into a sketchbook as the Contribution Manager would, its examples preprocessed by
 * Processing's own preprocessor and compiled against {@code processing-core} and
 * {@code library/Hitbox.jar} only, and one of them run with the library's classes from that jar.
 */
class ProcessingLibraryTest {
    /** The keys the Contribution Manager reads from library.properties. */
    static final List<String> KEYS = List.of("name", "version", "prettyVersion", "authors", "url",
            "categories", "sentence", "paragraph", "minRevision", "maxRevision");

    @TempDir
    static Path sketchbook;
    static File library;

    @BeforeAll
    static void unpackTheZipIntoASketchbook() throws IOException {
        File[] zips = new File("build/distributions").listFiles((dir, n) -> n.equals("Hitbox.zip"));
        assertTrue(zips != null && zips.length == 1, "build/distributions/Hitbox.zip: run gradle processingLibrary");
        Path libraries = sketchbook.resolve("libraries");
        try (ZipInputStream zip = new ZipInputStream(new FileInputStream(zips[0]))) {
            for (ZipEntry e; (e = zip.getNextEntry()) != null; ) {
                Path target = libraries.resolve(e.getName()).normalize();
                assertTrue(target.startsWith(libraries), "an entry outside the folder: " + e.getName());
                if (e.isDirectory()) {
                    Files.createDirectories(target);
                } else {
                    Files.createDirectories(target.getParent());
                    Files.copy(zip, target);
                }
            }
        }
        library = libraries.resolve("Hitbox").toFile();
    }

    @Test
    void zip_hasTheContributionManagersLayout() throws IOException {
        for (String path : List.of("library/Hitbox.jar", "library.properties", "reference/index.html",
                "src/hitbox/Collide.java", "src/hitbox/processing/Overlay.java",
                "examples/S03_CircleCircle/S03_CircleCircle.pde")) {
            assertTrue(new File(library, path).isFile(), "Hitbox/" + path);
        }
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(new File(library, "library.properties").toPath(), StandardCharsets.UTF_8)) {
            p.load(in);
        }
        for (String key : KEYS) {
            assertTrue(p.getProperty(key, "").length() > 0, "library.properties has " + key);
        }
        assertTrue(p.getProperty("version").matches("\\d+"), "version is a whole number the IDE compares");
        assertEquals("Hitbox", p.getProperty("name"));
    }

    @Test
    void everyExample_buildsAgainstCoreAndHitboxJarOnly() throws IOException, URISyntaxException {
        String classPath = coreJar() + File.pathSeparator + new File(library, "library/Hitbox.jar");
        File[] examples = new File(library, "examples").listFiles(File::isDirectory);
        assertNotNull(examples);
        assertTrue(examples.length >= 17, "every sketch is an example");
        for (File example : examples) {
            SketchBuild.Outcome outcome = SketchBuild.build(example, "", classPath, sketchbook.resolve("classes").toFile());
            assertTrue(outcome.ok(), example.getName() + ":\n" + outcome.report());
        }
    }

    @Test
    void anExample_runsAFrame_withTheLibraryFromHitboxJar() throws Exception {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
        File example = new File(library, "examples/S03_CircleCircle");
        File classes = sketchbook.resolve("one").toFile();
        String classPath = coreJar() + File.pathSeparator + new File(library, "library/Hitbox.jar");
        SketchBuild.Outcome outcome = SketchBuild.build(example, "", classPath, classes);
        assertTrue(outcome.ok(), outcome.report());

        // Processing's classes come from the test's class path (the same core jar); hitbox's
        // only from Hitbox.jar, as in the IDE.
        ClassLoader withoutHitbox = new ClassLoader(getClass().getClassLoader()) {
            @Override
            protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
                if (name.startsWith("hitbox.")) {
                    throw new ClassNotFoundException(name);
                }
                return super.loadClass(name, resolve);
            }
        };
        try (URLClassLoader ide = new URLClassLoader(new URL[] {classes.toURI().toURL(),
                new File(library, "library/Hitbox.jar").toURI().toURL()}, withoutHitbox)) {
            PApplet sketch = (PApplet) ide.loadClass("S03_CircleCircle").getDeclaredConstructor().newInstance();
            String from = ide.loadClass("hitbox.Collide").getProtectionDomain().getCodeSource().getLocation().toString();
            assertTrue(from.endsWith("library/Hitbox.jar"), "hitbox.Collide comes from " + from);
            SketchRun.Result<PApplet> r = SketchRun.of(sketch).folder(example).frames(3).run();
            assertEquals(3, r.framesDrawn());
            assertEquals(600, r.sketch().width);
        }
    }

    private static String coreJar() throws URISyntaxException {
        return Path.of(PApplet.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
    }
}
