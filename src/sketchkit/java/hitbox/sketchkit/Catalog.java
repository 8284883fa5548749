package hitbox.sketchkit;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;

import processing.core.PApplet;

/**
 * The sketches there are: every folder {@code sketches/<Name>/} that holds {@code <Name>.pde},
 * in tutorial order: sections by folder name (their numbers are zero-padded), then homework.
 *
 * <p>Found from the folders, never from a list, so a new sketch appears by being added.
 */
public final class Catalog {
    /** The system property that names the sketches folder; the build sets it. */
    public static final String SKETCHES_PROPERTY = "hitbox.sketches";

    /**
     * Tutorial order: the sections ({@code S01_...}, {@code S03b_...}) by name, then the
     * homework ({@code H01_...}), which comes after the tutorial.
     */
    private static final Comparator<File> TUTORIAL_ORDER = Comparator
            .comparing((File f) -> f.getName().startsWith("H"))
            .thenComparing(File::getName);

    private final File root;
    private final List<SketchInfo> sketches;

    private Catalog(File root, List<SketchInfo> sketches) {
        this.root = root;
        this.sketches = sketches;
    }

    /**
     * Reads the sketches folder named by the {@value #SKETCHES_PROPERTY} system property, or
     * {@code sketches} in the working directory.
     *
     * @return the catalog
     * @throws IllegalStateException if the folder does not exist
     */
    public static Catalog load() {
        return load(new File(System.getProperty(SKETCHES_PROPERTY, "sketches")));
    }

    /**
     * Reads a sketches folder whose sketches the build compiled onto this program's class path.
     *
     * @param root the folder that holds one folder per sketch
     * @return the catalog
     * @throws IllegalStateException if the folder does not exist
     */
    public static Catalog load(File root) {
        return load(root, Catalog.class.getClassLoader());
    }

    /**
     * Reads a sketches folder whose sketches {@link SketchBuild} compiled elsewhere.
     *
     * @param root    the folder that holds one folder per sketch
     * @param classes where the compiled sketches, their problems and line maps are found
     * @return the catalog
     * @throws IllegalStateException if the folder does not exist
     */
    public static Catalog load(File root, ClassLoader classes) {
        File[] folders = root.listFiles(File::isDirectory);
        if (folders == null) {
            throw new IllegalStateException("No sketches folder at " + root.getAbsolutePath()
                    + ": run from the project folder, or set -D" + SKETCHES_PROPERTY + "=<folder>");
        }
        List<SketchInfo> found = new ArrayList<>();
        Arrays.sort(folders, TUTORIAL_ORDER);
        for (File folder : folders) {
            File main = new File(folder, folder.getName() + ".pde");
            if (main.isFile()) {
                found.add(SketchInfo.read(folder, main, classes));
            }
        }
        return new Catalog(root, List.copyOf(found));
    }

    /** @return every sketch, in tutorial order */
    public List<SketchInfo> sketches() {
        return sketches;
    }

    /** @return the sketches folder */
    public File root() {
        return root;
    }

    /**
     * @param name a sketch's folder name, e.g. {@code S01_EdgeBounce}
     * @return that sketch, if there is one
     */
    public Optional<SketchInfo> find(String name) {
        return sketches.stream().filter(s -> s.name().equals(name)).findFirst();
    }

    /** @return the sketch names, comma-separated, for messages */
    public String names() {
        return sketches.stream().map(SketchInfo::name).collect(Collectors.joining(", "));
    }

    /**
     * Where a sketch belongs, from the second line of its header: the gallery shows each group
     * under its own heading, in this order.
     */
    public enum Group {
        /** "Tutorial section N: ...": a section of the tutorial (or the video beside it). */
        TUTORIAL("Tutorial section", "The tutorial, section by section"),
        /** "Homework N: ...": the tutorial's homework. */
        HOMEWORK("Homework", "The tutorial's homework"),
        /** "Beyond the tutorial: ...": an idea the tutorial does not have. */
        BEYOND("Beyond the tutorial", "Beyond the tutorial"),
        /**
         * "Beyond the tutorial: the world, ...": bodies in a {@code World}, moved with
         * reactions, layers, sensors and events; a row of its own after {@link #BEYOND}.
         */
        WORLD("Beyond the tutorial: the world", "Beyond the tutorial: a world of bodies"),
        /** No such line: a sketch of your own, say. */
        OTHER("", "Other sketches");

        private final String prefix;
        private final String heading;

        Group(String prefix, String heading) {
            this.prefix = prefix;
            this.heading = heading;
        }

        /** @return the words a header's second line starts with, "" for {@link #OTHER} */
        public String prefix() {
            return prefix;
        }

        /** @return the heading the gallery shows above the group */
        public String heading() {
            return heading;
        }

        /**
         * The group a header's second line names: the group with the longest words it starts
         * with ("Beyond the tutorial: the world, ..." is {@link #WORLD}, not {@link #BEYOND}).
         *
         * @param line the line after the title, e.g. "Beyond the tutorial: fast objects"
         * @return its group, {@link #OTHER} when it starts with no group's words
         */
        public static Group of(String line) {
            Group found = OTHER;
            for (Group g : values()) {
                if (!g.prefix.isEmpty() && line.startsWith(g.prefix) && g.prefix.length() > found.prefix.length()) {
                    found = g;
                }
            }
            return found;
        }
    }

    /**
     * A sketch folder and what its header comment says about it.
     *
     * @param name    the folder name, which is also the class name
     * @param folder  the sketch folder
     * @param title   the header's first line, e.g. "Circle/Point"
     * @param section the header's second line when it starts "Tutorial section", "Homework" or
     *                "Beyond the tutorial" (see {@link Group}), or "" if it does not
     * @param classes where its compiled class, problems and line map are found
     */
    public record SketchInfo(String name, File folder, String title, String section, ClassLoader classes) {

        static SketchInfo read(File folder, File mainTab, ClassLoader classes) {
            String title = folder.getName();
            String section = "";
            boolean titleSeen = false;
            for (String line : header(mainTab)) {
                String text = line.trim();
                if (text.isEmpty()) {
                    continue;
                }
                if (!titleSeen) {
                    title = text;
                    titleSeen = true;
                } else {
                    // Only the line after the title: later prose may start with the same words.
                    section = Group.of(text) == Group.OTHER ? "" : text;
                    break;
                }
            }
            return new SketchInfo(folder.getName(), folder, title, section, classes);
        }

        /**
         * The header comment of a main tab, the comment that must come first in it: its lines
         * between the opening and the closing line, each without the comment's margin
         * ({@code " * "}), blank lines kept, and indentation after the margin kept.
         */
        private static List<String> header(File mainTab) {
            List<String> lines;
            try {
                lines = Files.readAllLines(mainTab.toPath(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read " + mainTab, e);
            }
            List<String> header = new ArrayList<>();
            boolean inHeader = false;
            for (String raw : lines) {
                String line = raw.trim();
                if (!inHeader) {
                    if (line.startsWith("/**") || line.startsWith("/*")) {
                        inHeader = true;
                    } else if (!line.isEmpty()) {
                        break;  // the header comment must come first
                    }
                    continue;
                }
                if (line.startsWith("*/")) {
                    break;
                }
                header.add(line.replaceFirst("^\\* ?", "").stripTrailing());
            }
            return List.copyOf(header);
        }

        /**
         * Its header comment as written, for pages made from it (the title and section lines
         * first, then the prose).
         *
         * @return the header's lines without the comment's margin ({@code " * "}), blank lines
         *         and indentation after the margin kept; empty when the main tab has no header
         */
        public List<String> header() {
            return header(new File(folder, name + ".pde"));
        }

        /** @return the group its header's second line names, {@link Group#OTHER} for none */
        public Group group() {
            return Group.of(section);
        }

        /** @return the sketch's name, as test reports and messages show it */
        @Override
        public String toString() {
            return name;
        }

        /** @return the sketch's screenshot, which may not exist yet */
        public File screenshot() {
            return new File(folder, "screenshot.png");
        }

        /** @return the scripted input for its screenshot, which may not exist */
        public File screenshotScript() {
            return new File(folder, "screenshot.txt");
        }

        /**
         * Reads the scripted input for its screenshot.
         *
         * @return what {@code screenshot.txt} says, or no input for 120 frames if there is none
         * @throws IllegalArgumentException naming the line and column of a mistake in the file
         */
        public Script readScript() {
            return screenshotScript().isFile() ? Script.read(screenshotScript()) : new Script();
        }

        /**
         * What stopped this sketch from building, as the build reported it.
         *
         * @return its problems, one {@code sketches/<Name>/<Tab>.pde:<line>: <message>} a line,
         *         or "" when it built (or was not built at all)
         */
        public String errors() {
            String resource = SketchBuild.PACKAGE + "/" + name + SketchBuild.ERRORS_SUFFIX;
            try (var in = classes.getResourceAsStream(resource)) {
                return in == null ? "" : new String(in.readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read " + resource, e);
            }
        }

        /**
         * Where in the sketch's tabs an exception was thrown: the innermost place in the
         * sketch's own code, through the line map the build wrote beside its class.
         *
         * @param thrown an exception from a running sketch
         * @return {@code sketches/<Name>/<Tab>.pde:<line>}, or "" if no frame is the sketch's
         */
        public String locate(Throwable thrown) {
            String className = SketchBuild.PACKAGE + "." + name;
            String resource = SketchBuild.PACKAGE + "/" + name + SketchBuild.LINES_SUFFIX;
            List<String> lines;
            try (var in = classes.getResourceAsStream(resource)) {
                if (in == null) {
                    return "";
                }
                lines = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
            } catch (IOException e) {
                return "";
            }
            for (Throwable t = thrown; t != null; t = t.getCause()) {
                for (StackTraceElement e : t.getStackTrace()) {
                    boolean ours = e.getClassName().equals(className) || e.getClassName().startsWith(className + "$");
                    if (ours && e.getLineNumber() >= 1 && e.getLineNumber() <= lines.size()) {
                        return folder.getPath().replace(File.separatorChar, '/') + "/" + lines.get(e.getLineNumber() - 1);
                    }
                }
            }
            return "";
        }

        /**
         * Makes a fresh instance of the compiled sketch.
         *
         * @return the sketch, not yet running
         * @throws IllegalStateException if the sketch did not build (the message names each
         *         problem by tab and line) or was not built
         */
        public PApplet newInstance() {
            String errors = errors();
            if (!errors.isEmpty()) {
                throw new IllegalStateException(name + " does not build:\n" + errors);
            }
            try {
                return (PApplet) Class.forName(SketchBuild.PACKAGE + "." + name, true, classes).getDeclaredConstructor().newInstance();
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException("sketch " + name + " is not compiled: run it through gradle", e);
            }
        }
    }
}
