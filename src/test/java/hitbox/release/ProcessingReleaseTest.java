package hitbox.release;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The three files a Processing contributed library releases ({@code gradle processingLibrary}),
 * as the IDE and the contributions index read them: {@code Hitbox.zip} (unzipped into the
 * sketchbook's libraries folder), {@code Hitbox.pdex} (the same, installed by a double-click)
 * and {@code Hitbox.txt} (the library.properties that the contributions index reads).
 * {@code hitbox.sketchkit.ProcessingLibraryTest} builds and runs the zip's examples.
 */
class ProcessingReleaseTest {
    /** The revision of Processing 4.0 beta 3, the first Processing on Java 17. */
    static final int FIRST_ON_JAVA_17 = 1278;
    /** The categories the contributions index knows. */
    static final Set<String> CATEGORIES = Set.of("3D", "Animation", "Compilations", "Data", "Fabrication",
            "Geometry", "GUI", "Hardware", "I/O", "Language", "Math", "Simulation", "Sound", "Utilities",
            "Typography", "Video & Vision", "Other");

    static final Path DIR = Archives.BUILD.resolve("distributions");
    static Map<String, byte[]> zip;
    static Map<String, byte[]> pdex;
    static Properties txt;
    static byte[] txtBytes;

    @BeforeAll
    static void readTheThreeFiles() throws IOException {
        for (String name : List.of("Hitbox.zip", "Hitbox.pdex", "Hitbox.txt")) {
            assertTrue(Files.isRegularFile(DIR.resolve(name)), "build/distributions/" + name + ": run gradle processingLibrary");
        }
        zip = Archives.entries(DIR.resolve("Hitbox.zip"));
        pdex = Archives.entries(DIR.resolve("Hitbox.pdex"));
        txtBytes = Files.readAllBytes(DIR.resolve("Hitbox.txt"));
        txt = properties(txtBytes);
    }

    @Test
    void txt_hasWhatTheContributionsIndexReads() {
        for (String key : List.of("name", "authors", "url", "categories", "sentence", "paragraph", "version",
                "prettyVersion", "minRevision", "maxRevision")) {
            assertFalse(txt.getProperty(key, "").isBlank(), "Hitbox.txt has " + key);
        }
        assertEquals("Hitbox", txt.getProperty("name"));
        assertTrue(txt.getProperty("version").matches("\\d+"), "version is a whole number the IDE compares");
        assertTrue(txt.getProperty("url").matches("https?://\\S+"), "url " + txt.getProperty("url"));
        String url = System.getProperty("hitbox.url", "");
        if (!url.isEmpty()) {
            assertEquals(url, txt.getProperty("url"), "the url is hitbox.url");
        } else {
            assertFalse(txt.getProperty("url").contains(".invalid"), "a placeholder url");
        }
        for (String category : txt.getProperty("categories").split(",")) {
            assertTrue(CATEGORIES.contains(category.strip().replace("\"", "")), "unknown category " + category);
        }
        String[] v = txt.getProperty("prettyVersion").split("[.-]");
        assertEquals(Integer.parseInt(v[0]) * 10000 + Integer.parseInt(v[1]) * 100 + Integer.parseInt(v[2]),
                Integer.parseInt(txt.getProperty("version")), "version follows prettyVersion");
    }

    @Test
    void revisions_letInEveryProcessingThatRunsTheJar() throws IOException {
        int lowestMajor = Integer.MAX_VALUE;
        int highestMajor = 0;
        for (Map.Entry<String, byte[]> e : Archives.entries(jar()).entrySet()) {
            if (e.getKey().endsWith(".class")) {
                lowestMajor = Math.min(lowestMajor, Archives.majorVersion(e.getValue()));
                highestMajor = Math.max(highestMajor, Archives.majorVersion(e.getValue()));
            }
        }
        // Java 17's class files (major version 61) run on Processing 4.0 beta 3 (1278) and later.
        assertEquals(61, highestMajor, "Hitbox.jar holds Java 17 class files");
        assertEquals(61, lowestMajor);
        assertEquals(FIRST_ON_JAVA_17, Integer.parseInt(txt.getProperty("minRevision")),
                "minRevision: the first Processing on Java 17");
        assertEquals("0", txt.getProperty("maxRevision"), "no upper limit");
    }

    @Test
    void zipAndPdex_holdTheSameLibraryFolder() {
        assertEquals(zip.keySet(), pdex.keySet());
        for (String name : zip.keySet()) {
            assertArrayEquals(zip.get(name), pdex.get(name), name);
            assertTrue(name.startsWith("Hitbox/"), "one folder, Hitbox/, as the IDE installs it: " + name);
        }
        for (String path : List.of("library/Hitbox.jar", "library.properties", "reference/index.html",
                "README.md", "LICENSE", "examples/S03_CircleCircle/S03_CircleCircle.pde")) {
            assertTrue(zip.containsKey("Hitbox/" + path), "Hitbox/" + path);
        }
        assertArrayEquals(txtBytes, zip.get("Hitbox/library.properties"), "Hitbox.txt is the zip's library.properties");
    }

    @Test
    void readme_linksOnlyFilesInTheZip() {
        String readme = new String(zip.get("Hitbox/README.md"), StandardCharsets.UTF_8);
        List<String> links = Archives.relativeLinks(readme);
        assertFalse(links.isEmpty(), "the README points at the jar, the reference and the examples");
        List<String> broken = new ArrayList<>();
        for (String link : links) {
            String target = "Hitbox/" + link;
            boolean found = link.endsWith("/")
                    ? zip.keySet().stream().anyMatch(n -> n.startsWith(target))
                    : zip.containsKey(target);
            if (!found) {
                broken.add(link);
            }
        }
        assertTrue(broken.isEmpty(), "the zip's README links what the zip does not hold: " + broken);
    }

    @Test
    void reference_documentsTheApiPackages_andOnlyClassesTheJarHolds() throws IOException {
        Set<String> packages = Archives.documentedPackages(zip, "Hitbox/reference/");
        assertEquals(Set.of("hitbox", "hitbox.processing"), packages);
        Set<String> documented = Archives.documentedClasses(zip, "Hitbox/reference/");
        assertTrue(documented.contains("hitbox/processing/Overlay.class"));
        Set<String> missing = new TreeSet<>(documented);
        missing.removeAll(Archives.entries(jar()).keySet());
        assertTrue(missing.isEmpty(), "documented but not in Hitbox.jar: " + missing);
    }

    private static Path jar() {
        try {
            Path tmp = Files.createTempFile("Hitbox", ".jar");
            tmp.toFile().deleteOnExit();
            Files.write(tmp, zip.get("Hitbox/library/Hitbox.jar"));
            return tmp;
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    private static Properties properties(byte[] bytes) throws IOException {
        Properties p = new Properties();
        p.load(new InputStreamReader(new ByteArrayInputStream(bytes), StandardCharsets.UTF_8));
        return p;
    }
}
