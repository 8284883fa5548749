package hitbox.release;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

/** Reading the release files: the entries of a zip or jar, and what a javadoc tree documents. */
final class Archives {
    private Archives() {
    }

    /** Where the build writes what it releases, from the project folder the tests run in. */
    static final Path BUILD = Path.of("build");

    /**
     * @param zip a zip or jar
     * @return every file entry's name and bytes, in the zip's order
     */
    static Map<String, byte[]> entries(Path zip) throws IOException {
        Map<String, byte[]> out = new LinkedHashMap<>();
        try (InputStream raw = Files.newInputStream(zip); ZipInputStream in = new ZipInputStream(raw)) {
            for (ZipEntry e; (e = in.getNextEntry()) != null; ) {
                if (!e.isDirectory()) {
                    out.put(e.getName(), in.readAllBytes());
                }
            }
        }
        return out;
    }

    /**
     * The classes a javadoc tree has a page for, as class-file names ({@code hitbox/Sweep$Move.class}).
     *
     * @param entries the tree's files, by path
     * @param prefix  the tree's folder within them ("" for a javadoc jar)
     * @return the class files those pages describe
     */
    static Set<String> documentedClasses(Map<String, byte[]> entries, String prefix) {
        Set<String> packages = documentedPackages(entries, prefix);
        Set<String> classes = new TreeSet<>();
        for (String name : entries.keySet()) {
            if (!name.startsWith(prefix) || !name.endsWith(".html")) {
                continue;
            }
            String path = name.substring(prefix.length());
            int slash = path.lastIndexOf('/');
            if (slash < 0) {
                continue;
            }
            String pkg = path.substring(0, slash).replace('/', '.');
            String page = path.substring(slash + 1, path.length() - ".html".length());
            if (packages.contains(pkg) && Character.isUpperCase(page.charAt(0))) {
                classes.add(path.substring(0, slash) + "/" + page.replace('.', '$') + ".class");
            }
        }
        return classes;
    }

    /**
     * @param entries a javadoc tree's files, by path
     * @param prefix  the tree's folder within them
     * @return the packages its element-list names
     */
    static Set<String> documentedPackages(Map<String, byte[]> entries, String prefix) {
        byte[] list = entries.get(prefix + "element-list");
        if (list == null) {
            throw new AssertionError("no " + prefix + "element-list: not a javadoc tree");
        }
        Set<String> packages = new TreeSet<>();
        for (String line : new String(list, StandardCharsets.UTF_8).split("\n")) {
            if (!line.isBlank()) {
                packages.add(line.strip());
            }
        }
        return packages;
    }

    /**
     * @param markdown a Markdown text
     * @return the targets of its links and images that are not absolute URLs
     */
    static List<String> relativeLinks(String markdown) {
        List<String> out = new ArrayList<>();
        Matcher m = Pattern.compile("\\]\\(([^)\\s]+)\\)").matcher(markdown);
        while (m.find()) {
            String target = m.group(1);
            if (!target.matches("(?i)[a-z][a-z0-9+.-]*:.*") && !target.startsWith("#")) {
                out.add(target.replaceAll("#.*", ""));
            }
        }
        return out;
    }

    /**
     * @param classFile a class file's bytes
     * @return its major version (61 for Java 17)
     */
    static int majorVersion(byte[] classFile) {
        return ((classFile[6] & 0xff) << 8) | (classFile[7] & 0xff);
    }
}
