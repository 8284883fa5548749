package hitbox.sketchkit;

import java.io.File;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * The class path the tests run on, for compiling a sketch or starting a JVM like the build's.
 *
 * <p>Not simply {@code java.class.path}: on Gradle 4.4.1 the JUnit console launcher loads the
 * tests through a class loader of its own, and the JVM's class path holds only the launcher.
 */
final class TestClassPath {
    private TestClassPath() {
    }

    /** @return every entry the tests can see, joined with the platform's separator */
    static String get() {
        Set<String> entries = new LinkedHashSet<>();
        for (ClassLoader l = TestClassPath.class.getClassLoader(); l != null; l = l.getParent()) {
            if (l instanceof URLClassLoader urls) {
                for (URL url : urls.getURLs()) {
                    try {
                        entries.add(Path.of(url.toURI()).toString());
                    } catch (URISyntaxException | IllegalArgumentException e) {
                        entries.add(url.getPath());
                    }
                }
            }
        }
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            entries.add(entry);
        }
        return String.join(File.pathSeparator, entries);
    }
}
