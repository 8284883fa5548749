package hitbox.sketchkit;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import processing.mode.java.preproc.PdePreprocessIssue;
import processing.mode.java.preproc.PdePreprocessor;
import processing.mode.java.preproc.PreprocessorResult;
import processing.mode.java.preproc.TextTransform;
import processing.utils.SketchException;

/**
 * Turns a sketch folder into a compiled {@code PApplet} subclass exactly as the Processing IDE
 * does: its {@code .pde} tabs joined in the IDE's order (the main tab, then the others by file
 * name), Processing's own preprocessor ({@code PdePreprocessor}, which turns {@code color},
 * {@code #RRGGBB}, {@code 0.5} and static-mode sketches into Java and moves {@code size()} into
 * {@code settings()}), then the JDK's compiler.
 *
 * <p>Every problem is reported where the learner wrote it, as
 * {@code sketches/<Name>/<Tab>.pde:<line>: <message>}: the preprocessor's syntax errors by their
 * line in the joined tabs, the compiler's through the preprocessor's own edit list, which maps
 * every place in the generated Java back to a place in the tabs.
 *
 * <p>Each sketch is built on its own, so a broken one harms no other. {@code gradle} runs
 * {@link #main} over the whole sketches folder; the display tests, the fixtures and the IDE-path
 * test call {@link #build} directly.
 */
public final class SketchBuild {
    /** The package the build puts sketches in (the IDE uses none; tests need to name them). */
    public static final String PACKAGE = "sketches";
    /** Beside {@code <Name>.class}: the sketch's problems, one a line, when it did not build. */
    public static final String ERRORS_SUFFIX = ".errors";
    /** Beside {@code <Name>.class}: for each line of the generated Java, its {@code Tab.pde:line}. */
    public static final String LINES_SUFFIX = ".lines";
    /** The IDE's default tab size, set so the preprocessor never reads a preferences file. */
    private static final int TAB_SIZE = 2;

    private SketchBuild() {
    }

    /**
     * One thing wrong with a sketch, where the learner wrote it.
     *
     * @param file    the tab, as the user names it, e.g. {@code sketches/S01_EdgeBounce/Maths.pde}
     * @param line    the line in that tab, from 1
     * @param message what is wrong
     */
    public record Problem(String file, int line, String message) {
        /** @return {@code file:line: message}, the form editors and terminals link to */
        @Override
        public String toString() {
            return file + ":" + line + ": " + message;
        }
    }

    /**
     * What building one sketch gave.
     *
     * @param name     the sketch's name, which is also its class name
     * @param java     the generated Java source, or "" when the preprocessor refused the tabs
     * @param problems what is wrong, in the order found; empty when it built
     */
    public record Outcome(String name, String java, List<Problem> problems) {
        /** @return true when the sketch compiled */
        public boolean ok() {
            return problems.isEmpty();
        }

        /** @return the problems, one a line, or "" */
        public String report() {
            StringBuilder out = new StringBuilder();
            for (Problem p : problems) {
                out.append(p).append('\n');
            }
            return out.toString();
        }
    }

    /**
     * Builds every sketch of a folder; a broken sketch is reported and the others still built.
     *
     * <p>Arguments: the sketches folder, the output folder (its {@code classes/} and
     * {@code java/} are made anew), and the class path to compile against (the library, its
     * Processing helpers and {@code processing-core}).
     *
     * @param args {@code <sketches folder> <output folder> <class path>}
     * @throws IOException if a file cannot be read or written
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 3) {
            throw new IllegalArgumentException("usage: SketchBuild <sketches folder> <output folder> <class path>");
        }
        File root = new File(args[0]);
        File out = new File(args[1]);
        File classes = new File(out, "classes");
        File java = new File(out, "java");
        deleteTree(out);
        List<Catalog.SketchInfo> sketches = Catalog.load(root).sketches();
        int broken = 0;
        for (Catalog.SketchInfo info : sketches) {
            Outcome outcome = build(info.folder(), PACKAGE, args[2], classes);
            write(new File(java, PACKAGE + "/" + info.name() + ".java"), outcome.java());
            if (!outcome.ok()) {
                broken++;
                System.err.print(outcome.report());
            }
        }
        System.out.println("sketches: " + (sketches.size() - broken) + " built, " + broken + " broken");
    }

    /**
     * Preprocesses and compiles one sketch folder.
     *
     * @param folder      the sketch folder, holding {@code <Name>.pde} and any other tabs
     * @param packageName the package to put the class in, or "" for none (as the IDE does)
     * @param classPath   what to compile against
     * @param classes     where the class files go; beside them, the line map of a sketch that
     *                    built, or the problems of one that did not ({@link #ERRORS_SUFFIX})
     * @return the generated Java and any problems, each named by tab and line
     * @throws IOException if a tab cannot be read or a file written
     */
    public static Outcome build(File folder, String packageName, String classPath, File classes) throws IOException {
        Outcome outcome = preprocessAndCompile(folder, packageName, classPath, classes);
        String base = (packageName.isEmpty() ? "" : packageName.replace('.', '/') + "/") + outcome.name();
        if (!outcome.ok()) {
            write(new File(classes, base + ERRORS_SUFFIX), outcome.report());
        }
        return outcome;
    }

    private static Outcome preprocessAndCompile(File folder, String packageName, String classPath, File classes) throws IOException {
        String name = folder.getName();
        Tabs tabs = Tabs.read(folder);
        PdePreprocessor.PdePreprocessorBuilder builder = PdePreprocessor.builderFor(name).setTabSize(TAB_SIZE);
        if (!packageName.isEmpty()) {
            builder.setDestinationPackage(packageName);
        }
        StringWriter generated = new StringWriter();
        PreprocessorResult result;
        try {
            result = builder.build().write(generated, tabs.program());
        } catch (SketchException | RuntimeException e) {
            return new Outcome(name, "", List.of(new Problem(tabs.file(0), 1, "the preprocessor failed: " + e)));
        }
        List<Problem> problems = new ArrayList<>();
        for (PdePreprocessIssue issue : result.getPreprocessIssues()) {
            problems.add(tabs.problemAtLine(issue.getLine(), issue.getMsg()));
        }
        if (!problems.isEmpty()) {
            return new Outcome(name, "", problems);
        }
        String java = generated.toString();
        TextTransform edits = new TextTransform(tabs.program());
        edits.addAll(result.getEdits());
        TextTransform.OffsetMapper mapper = edits.getMapper();

        String qualified = packageName.isEmpty() ? name : packageName + "." + name;
        problems.addAll(compile(qualified, java, classPath, classes, tabs, mapper));
        if (problems.isEmpty()) {
            write(new File(classes, qualified.replace('.', '/') + LINES_SUFFIX), lineMap(java, tabs, mapper));
        }
        return new Outcome(name, java, problems);
    }

    /** Compiles the generated source; each error is mapped back to its tab and line. */
    private static List<Problem> compile(String qualified, String java, String classPath, File classes,
                                         Tabs tabs, TextTransform.OffsetMapper mapper) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IllegalStateException("no Java compiler: sketches need a JDK, not only a JRE");
        }
        Files.createDirectories(classes.toPath());
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        JavaFileObject source = new SimpleJavaFileObject(
                URI.create("string:///" + qualified.replace('.', '/') + ".java"), JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return java;
            }
        };
        List<String> options = List.of("-d", classes.getPath(), "-classpath", classPath,
                "--release", "17", "-g", "-nowarn", "-proc:none", "-implicit:none", "-encoding", "UTF-8");
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ENGLISH, StandardCharsets.UTF_8)) {
            javac.getTask(null, files, diagnostics, options, null, List.of(source)).call();
        }
        List<Problem> problems = new ArrayList<>();
        for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
            if (d.getKind() != Diagnostic.Kind.ERROR) {
                continue;
            }
            // javac's first line says what is wrong; the others ("symbol: ...") go in brackets.
            List<String> lines = Arrays.stream(d.getMessage(Locale.ENGLISH).split("\n"))
                    .map(s -> s.trim().replaceAll("\\s+", " ")).filter(s -> !s.isEmpty()).toList();
            String message = lines.isEmpty() ? "error" : lines.size() == 1 ? lines.get(0)
                    : lines.get(0) + " (" + String.join(", ", lines.subList(1, lines.size())) + ")";
            long position = d.getPosition();
            problems.add(position == Diagnostic.NOPOS
                    ? new Problem(tabs.file(0), 1, message)
                    : tabs.problemAt(mapper.getInputOffset((int) position), message));
        }
        return problems;
    }

    /** For each line of the generated Java, the tab and line it came from: "Tab.pde:12". */
    private static String lineMap(String java, Tabs tabs, TextTransform.OffsetMapper mapper) {
        StringBuilder map = new StringBuilder();
        int start = 0;
        while (start <= java.length()) {
            Problem where = tabs.problemAt(mapper.getInputOffset(start), "");
            map.append(new File(where.file()).getName()).append(':').append(where.line()).append('\n');
            int next = java.indexOf('\n', start);
            if (next < 0) {
                break;
            }
            start = next + 1;
        }
        return map.toString();
    }

    /**
     * The tabs of a sketch, joined as the IDE joins them: the main tab, then the other
     * {@code .pde} files by name, each followed by a newline.
     */
    record Tabs(String folderPath, List<String> names, int[] starts, String program) {

        static Tabs read(File folder) throws IOException {
            String main = folder.getName() + ".pde";
            File[] found = folder.listFiles((dir, n) -> n.endsWith(".pde") && !n.equals(main));
            List<String> names = new ArrayList<>();
            names.add(main);
            if (found != null) {
                // The IDE's order: the main tab, then the others by file name.
                names.addAll(Arrays.stream(found).map(File::getName).sorted().toList());
            }
            StringBuilder program = new StringBuilder();
            int[] starts = new int[names.size()];
            for (int i = 0; i < names.size(); i++) {
                starts[i] = program.length();
                String text = Files.readString(new File(folder, names.get(i)).toPath(), StandardCharsets.UTF_8);
                program.append(text.replace("\r\n", "\n").replace('\r', '\n')).append('\n');
            }
            String path = folder.getPath().replace(File.separatorChar, '/');
            return new Tabs(path, List.copyOf(names), starts, program.toString());
        }

        /** @return the tab's path as the user names it, e.g. {@code sketches/S01/S01.pde} */
        String file(int tab) {
            return folderPath + "/" + names.get(tab);
        }

        /** A problem at a character offset of the joined program. */
        Problem problemAt(int offset, String message) {
            int at = Math.max(0, Math.min(offset, program.length() - 1));
            int tab = names.size() - 1;
            while (tab > 0 && starts[tab] > at) {
                tab--;
            }
            int line = 1;
            for (int i = starts[tab]; i < at; i++) {
                if (program.charAt(i) == '\n') {
                    line++;
                }
            }
            return new Problem(file(tab), line, message);
        }

        /** A problem at a line (from 1) of the joined program. */
        Problem problemAtLine(int line, String message) {
            int offset = 0;
            for (int l = 1; l < line && offset >= 0; l++) {
                offset = program.indexOf('\n', offset) + 1;
                if (offset == 0) {
                    offset = program.length();
                    break;
                }
            }
            return problemAt(offset, message);
        }
    }

    private static void write(File file, String text) throws IOException {
        Files.createDirectories(file.getAbsoluteFile().getParentFile().toPath());
        Files.writeString(file.toPath(), text, StandardCharsets.UTF_8);
    }

    private static void deleteTree(File dir) {
        File[] children = dir.listFiles();
        if (children != null) {
            for (File child : children) {
                deleteTree(child);
            }
        }
        if (dir.exists() && !dir.delete()) {
            throw new UncheckedIOException(new IOException("cannot delete " + dir));
        }
    }
}
