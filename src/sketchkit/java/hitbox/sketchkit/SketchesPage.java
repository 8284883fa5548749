package hitbox.sketchkit;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Writes {@code docs/sketches.md}, every sketch with its screenshot, from the sketches' own
 * headers as {@link Catalog} reads them, so the page cannot say what the headers do not.
 *
 * <p>Groups, in order: each tutorial section ("Section N: ...", named by the section line of its
 * first sketch, up to the first comma or bracket), the homework, what goes beyond the tutorial,
 * the world's sketches, then any sketch of your own. Each entry: the screenshot, the title and the folder name, the
 * header's first prose paragraph, its paragraph on where Hitbox differs from the tutorial if it
 * has one (one that starts "Where Hitbox differs" or "Hitbox and the tutorial", else a later one
 * that says "Hitbox differs"), quoted as written, and the run command. The "Try this" and
 * "Keys" paragraphs stay in the header. {@code gradle sketchesPage} runs it; a test fails while
 * the committed page differs from what it makes.
 */
public final class SketchesPage {
    /** Where the page lives, from the project folder. */
    public static final String PAGE = "docs/sketches.md";

    /** What to run to remake the page, for messages. */
    public static final String TASK = "gradle sketchesPage";

    private static final Pattern SECTION = Pattern.compile("Tutorial section (\\d+): (.*)");
    private static final String[] LEAD_INS = {"Where Hitbox differs", "Hitbox and the tutorial"};

    private static final String INTRO = """
            # The sketches, one by one

            Every sketch with its screenshot, by tutorial section, then the homework, then the ideas that
            go beyond the tutorial; `gradle run` opens all of them from the gallery, and
            [sketches/README.md](../sketches/README.md) lists them one line each. Each entry quotes the
            sketch's own header: its first paragraph and, where the header has one, its paragraph on
            where Hitbox differs from the tutorial. The header says more (what to try, every key); where
            a sketch can run the tutorial's own code beside Hitbox's, to show what goes wrong with it,
            its header names the key that switches.

            This page is made from the headers by `gradle sketchesPage`: change a header, not this page,
            then run it (a test fails while the two disagree).
            """;

    private static final String OUTRO = """
            Every sketch: `d` shows the maths (the numbers the test compares, where they live, with the
            comparison written out); the header comment says what to try. How to write one:
            [sketch-style.md](sketch-style.md).
            """;

    private SketchesPage() {
    }

    /**
     * Writes the page: {@code SketchesPage [sketches folder] [page]}, by default
     * {@code sketches} and {@value #PAGE} in the working directory.
     *
     * @param args the sketches folder and the page to write, both optional
     * @throws IOException if the page cannot be written
     */
    public static void main(String[] args) throws IOException {
        File root = new File(args.length > 0 ? args[0] : "sketches");
        File page = new File(args.length > 1 ? args[1] : PAGE);
        Catalog catalog = Catalog.load(root);
        Files.writeString(page.toPath(), render(catalog), StandardCharsets.UTF_8);
        System.out.println("Wrote " + page.getPath() + ": " + catalog.sketches().size() + " sketches, from their headers.");
    }

    /**
     * Compares a page with what the headers make now.
     *
     * @param catalog the sketches
     * @param page    the committed page
     * @return "" when they are the same (line endings aside), else what differs first and
     *         "run gradle sketchesPage"
     */
    public static String check(Catalog catalog, File page) {
        String made = render(catalog);
        if (!page.isFile()) {
            return page.getPath() + " does not exist: run " + TASK;
        }
        String committed;
        try {
            committed = Files.readString(page.toPath(), StandardCharsets.UTF_8).replace("\r\n", "\n");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + page, e);
        }
        if (made.equals(committed)) {
            return "";
        }
        String[] a = made.split("\n", -1);
        String[] b = committed.split("\n", -1);
        int i = 0;
        while (i < a.length && i < b.length && a[i].equals(b[i])) {
            i++;
        }
        return page.getPath() + " is not what the sketches' headers make: run " + TASK
                + "\nfirst difference, line " + (i + 1) + ":\n  the headers make: " + (i < a.length ? a[i] : "(end of page)")
                + "\n  the page has:     " + (i < b.length ? b[i] : "(end of page)");
    }

    /**
     * Makes the page.
     *
     * @param catalog the sketches
     * @return the page's Markdown, lines ending in {@code \n}
     * @throws IllegalStateException if a tutorial sketch's section line has no section number
     */
    public static String render(Catalog catalog) {
        Map<Integer, List<Catalog.SketchInfo>> sections = new TreeMap<>();
        Map<Catalog.Group, List<Catalog.SketchInfo>> others = new LinkedHashMap<>();
        for (Catalog.Group g : Catalog.Group.values()) {
            if (g != Catalog.Group.TUTORIAL) {
                others.put(g, new ArrayList<>());
            }
        }
        for (Catalog.SketchInfo s : catalog.sketches()) {
            if (s.group() == Catalog.Group.TUTORIAL) {
                sections.computeIfAbsent(sectionNumber(s), n -> new ArrayList<>()).add(s);
            } else {
                others.get(s.group()).add(s);
            }
        }
        StringBuilder out = new StringBuilder(INTRO);
        for (Map.Entry<Integer, List<Catalog.SketchInfo>> e : sections.entrySet()) {
            group(out, "Section " + e.getKey() + ": " + sectionTitle(e.getValue().get(0)), null, e.getValue());
        }
        for (Map.Entry<Catalog.Group, List<Catalog.SketchInfo>> e : others.entrySet()) {
            List<Catalog.SketchInfo> list = e.getValue();
            if (list.isEmpty()) {
                continue;
            }
            switch (e.getKey()) {
                case HOMEWORK -> group(out, "Homework", null, list);
                case BEYOND -> group(out, e.getKey().heading(),
                        list.stream().allMatch(s -> s.name().startsWith("S10"))
                                ? "Ideas neither source has, in section 10's folders because they build on it."
                                : "Ideas neither source has.",
                        list);
                case WORLD -> group(out, e.getKey().heading(),
                        "Many bodies in a `World`: moved each frame with a reaction per pair, layers, sensors and events.",
                        list);
                default -> group(out, e.getKey().heading(), null, list);
            }
        }
        out.append('\n').append(OUTRO);
        return out.toString();
    }

    private static void group(StringBuilder out, String heading, String intro, List<Catalog.SketchInfo> sketches) {
        out.append("\n## ").append(heading).append("\n\n");
        if (intro != null) {
            out.append(intro).append("\n\n");
        }
        for (Catalog.SketchInfo s : sketches) {
            entry(out, s);
        }
    }

    private static void entry(StringBuilder out, Catalog.SketchInfo s) {
        if (s.screenshot().isFile()) {
            out.append("<img src=\"../sketches/").append(s.name()).append("/screenshot.png\" width=\"300\" alt=\"")
                    .append(attribute(s.title())).append("\" align=\"left\">\n\n");
        }
        List<List<String>> prose = prose(s);
        out.append("**").append(markdown(s.title())).append("** (`").append(s.name()).append("`).");
        if (!prose.isEmpty()) {
            out.append(' ').append(paragraph(prose.get(0)));
        }
        out.append("\n\n");
        List<String> differs = differs(prose);
        if (differs != null) {
            String text = paragraph(differs);
            for (String lead : LEAD_INS) {
                if (text.startsWith(lead) && text.indexOf(':') > 0) {
                    int colon = text.indexOf(':');
                    text = "*" + text.substring(0, colon + 1) + "*" + text.substring(colon + 1);
                    break;
                }
            }
            out.append(text).append("\n\n");
        }
        out.append("`gradle run -Psketch=").append(s.name()).append("`\n\n");
        out.append("<br clear=\"left\">\n\n");
    }

    /** The header's paragraphs after the title and section lines, without "Try this" and "Keys". */
    private static List<List<String>> prose(Catalog.SketchInfo s) {
        List<List<String>> paragraphs = new ArrayList<>();
        List<String> current = new ArrayList<>();
        int skip = s.section().isEmpty() ? 1 : 2;  // the title and section lines
        for (String line : s.header()) {
            if (line.isBlank()) {
                if (!current.isEmpty()) {
                    paragraphs.add(current);
                    current = new ArrayList<>();
                }
            } else if (skip > 0) {
                skip--;
            } else {
                current.add(line);
            }
        }
        if (!current.isEmpty()) {
            paragraphs.add(current);
        }
        paragraphs.removeIf(p -> p.get(0).startsWith("Try this") || p.get(0).startsWith("Keys:"));
        return paragraphs;
    }

    /** The paragraph after the first on where Hitbox differs, or null if there is none. */
    private static List<String> differs(List<List<String>> prose) {
        for (List<String> p : prose.subList(Math.min(1, prose.size()), prose.size())) {
            for (String lead : LEAD_INS) {
                if (p.get(0).startsWith(lead)) {
                    return p;
                }
            }
        }
        for (List<String> p : prose.subList(Math.min(1, prose.size()), prose.size())) {
            if (String.join(" ", p).contains("Hitbox differs")) {
                return p;
            }
        }
        return null;
    }

    /**
     * A paragraph's lines as one Markdown line. Lines indented past the margin are a list in
     * the header: each item at the least indentation starts on a line of its own.
     */
    private static String paragraph(List<String> lines) {
        int minIndent = Integer.MAX_VALUE;
        for (String line : lines.subList(1, lines.size())) {
            int indent = line.length() - line.stripLeading().length();
            if (indent > 0) {
                minIndent = Math.min(minIndent, indent);
            }
        }
        StringBuilder text = new StringBuilder(markdown(lines.get(0).strip()));
        for (String line : lines.subList(1, lines.size())) {
            int indent = line.length() - line.stripLeading().length();
            text.append(indent == minIndent ? "<br>" : " ").append(markdown(line.strip()));
        }
        return text.toString();
    }

    private static int sectionNumber(Catalog.SketchInfo s) {
        Matcher m = SECTION.matcher(s.section());
        if (!m.matches()) {
            throw new IllegalStateException(s.name() + ": the header's second line should read \"Tutorial section N: <title>\", not \""
                    + s.section() + "\"");
        }
        return Integer.parseInt(m.group(1));
    }

    /** "Circle/Point, for ellipses (beyond the tutorial)" is section "Circle/Point". */
    private static String sectionTitle(Catalog.SketchInfo s) {
        Matcher m = SECTION.matcher(s.section());
        m.matches();
        return m.group(2).split(",| \\(", 2)[0].strip();
    }

    /** Header text as Markdown that shows it as written. */
    static String markdown(String text) {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            char prev = i > 0 ? text.charAt(i - 1) : ' ';
            char next = i + 1 < text.length() ? text.charAt(i + 1) : ' ';
            switch (c) {
                case '\\', '`' -> out.append('\\').append(c);
                case '*' -> out.append(prev == ' ' && next == ' ' ? "*" : "\\*");
                case '_' -> out.append(Character.isLetterOrDigit(prev) && Character.isLetterOrDigit(next) ? "_" : "\\_");
                case '<' -> out.append(Character.isLetter(next) || next == '/' || next == '!' || next == '?' ? "&lt;" : "<");
                case '&' -> out.append(Character.isLetter(next) || next == '#' ? "&amp;" : "&");
                default -> out.append(c);
            }
        }
        return out.toString();
    }

    private static String attribute(String text) {
        return text.replace("&", "&amp;").replace("\"", "&quot;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
