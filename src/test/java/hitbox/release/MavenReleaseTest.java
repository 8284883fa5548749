package hitbox.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.module.ModuleDescriptor;
import java.lang.module.ModuleFinder;
import java.lang.module.ModuleReference;
import java.lang.reflect.Modifier;
import java.net.URI;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * What Maven Central would be sent ({@code gradle publish}): the POM the build generates and
 * the main, sources and javadoc jars beside it. Central refuses a POM without name,
 * description, url, licence, developers or scm, and a group outside a verified namespace; a
 * reader of the javadoc must find every class it documents in the jar.
 */
class MavenReleaseTest {
    static Document pom;
    static String artifact;
    static Map<String, byte[]> main;
    static Map<String, byte[]> sources;
    static Map<String, byte[]> javadoc;
    static Path mainJar;

    @BeforeAll
    static void readThePomAndTheJars() throws Exception {
        Path pomFile = Archives.BUILD.resolve("publications/hitbox/pom-default.xml");
        assertTrue(Files.isRegularFile(pomFile), pomFile + ": run gradle generatePomFileForHitboxPublication");
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        pom = f.newDocumentBuilder().parse(pomFile.toFile());
        artifact = text("artifactId") + "-" + text("version");
        mainJar = Archives.BUILD.resolve("libs/" + artifact + ".jar");
        main = Archives.entries(mainJar);
        sources = Archives.entries(Archives.BUILD.resolve("libs/" + artifact + "-sources.jar"));
        javadoc = Archives.entries(Archives.BUILD.resolve("libs/" + artifact + "-javadoc.jar"));
    }

    /** The home page the build was given (-Phitbox.url), or none when run outside it. */
    static String configuredUrl() {
        return System.getProperty("hitbox.url", "");
    }

    @Test
    void pom_hasEveryFieldCentralAsksFor() {
        for (String path : List.of("groupId", "artifactId", "version", "name", "description", "url",
                "licenses/license/name", "licenses/license/url", "developers/developer/name",
                "scm/url", "scm/connection")) {
            assertFalse(text(path).isBlank(), "the POM's " + path + " is empty or missing");
        }
    }

    @Test
    void pom_hasNoEmptyElementAndNoLeftover() {
        List<String> problems = new ArrayList<>();
        walk(pom.getDocumentElement(), "", problems);
        assertTrue(problems.isEmpty(), "the POM has: " + problems);
    }

    @Test
    void pom_groupIsAReverseDomainNamespace() {
        String group = text("groupId");
        assertTrue(group.matches("[a-z][a-z0-9-]*(\\.[a-z0-9_][a-z0-9_-]*)+"),
                "group " + group + " is not a reverse-domain namespace (com.example, io.github.<owner>)");
    }

    @Test
    void pom_urlsAreTheConfiguredHomePage() throws Exception {
        String url = text("url");
        assertTrue(url.startsWith("https://"), "url " + url);
        new URI(url).toURL();
        if (!configuredUrl().isEmpty()) {
            assertEquals(configuredUrl(), url, "the POM's url is hitbox.url");
        }
        assertEquals(url, text("scm/url"));
        assertEquals(url, text("developers/developer/url"));
        assertEquals("scm:git:" + url + ".git", text("scm/connection"));
    }

    @Test
    void pom_declaresNoDependency() {
        // The library is pure Java: a consumer gets nothing else with it.
        assertEquals(0, pom.getElementsByTagNameNS("*", "dependency").getLength());
    }

    @Test
    void aModuleRequiringHitbox_seesTheApi_andIsRefusedTheInternals(@TempDir Path dir) throws IOException {
        Path app = Files.createDirectories(dir.resolve("app"));
        Files.writeString(app.resolve("module-info.java"), "module app { requires hitbox; }");
        Path pkg = Files.createDirectories(app.resolve("app"));
        Files.writeString(pkg.resolve("Api.java"),
                "package app; class Api { boolean hit = new hitbox.Circle(0, 0, 5).contains(1, 1); }");
        assertEquals(0, javac(dir, app, pkg.resolve("Api.java")), "the API compiles from a module requiring hitbox");
        Files.writeString(pkg.resolve("Internal.java"), "package app; class Internal { hitbox.internal.Tolerance t; }");
        assertEquals(1, javac(dir, app, pkg.resolve("Api.java"), pkg.resolve("Internal.java")),
                "hitbox.internal is not exported, so a module cannot use it");
    }

    private int javac(Path dir, Path app, Path... sources) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        List<String> args = new ArrayList<>(List.of("-d", dir.resolve("out").toString(),
                "--module-path", mainJar.toString(), "-Xlint:none", app.resolve("module-info.java").toString()));
        for (Path source : sources) {
            args.add(source.toString());
        }
        return javac.run(null, null, new java.io.ByteArrayOutputStream(), args.toArray(new String[0]));
    }

    @Test
    void mainJar_isTheModuleHitbox_exportingTheApiOnly() {
        Set<ModuleReference> found = ModuleFinder.of(mainJar).findAll();
        assertEquals(1, found.size());
        ModuleDescriptor module = found.iterator().next().descriptor();
        assertEquals("hitbox", module.name());
        assertFalse(module.isAutomatic(), "a module-info, not a manifest name: an automatic module exports everything");
        assertEquals(Set.of("hitbox"), module.exports().stream().map(ModuleDescriptor.Exports::source).collect(Collectors.toSet()),
                "exported packages");
        assertTrue(module.packages().contains("hitbox.internal"), "the internals are in the jar, unexported");
        for (String pkg : module.packages()) {
            assertTrue(pkg.equals("hitbox") || pkg.startsWith("hitbox."), "package " + pkg + " outside module hitbox");
        }
        assertEquals(Set.of("java.base"), module.requires().stream().map(ModuleDescriptor.Requires::name).collect(Collectors.toSet()),
                "pure Java: the module needs java.base only");
    }

    @Test
    void javadocJar_documentsOnlyClassesTheJarHolds() {
        Set<String> documented = Archives.documentedClasses(javadoc, "");
        assertTrue(documented.contains("hitbox/Collide.class"), "the javadoc jar documents hitbox.Collide");
        Set<String> missing = new TreeSet<>(documented);
        missing.removeAll(main.keySet());
        assertTrue(missing.isEmpty(), "documented but not in " + artifact + ".jar: " + missing);
        for (String pkg : Archives.documentedPackages(javadoc, "")) {
            assertFalse(pkg.contains(".internal"), "the javadoc documents the internal package " + pkg);
        }
    }

    @Test
    void javadocJar_documentsEveryPublicClassOfTheApi() throws Exception {
        Set<String> packages = Archives.documentedPackages(javadoc, "");
        Set<String> documented = Archives.documentedClasses(javadoc, "");
        List<String> undocumented = new ArrayList<>();
        try (URLClassLoader jar = new URLClassLoader(new URL[] {mainJar.toUri().toURL()}, null)) {
            for (String entry : main.keySet()) {
                if (!entry.endsWith(".class") || entry.endsWith("package-info.class") || entry.equals("module-info.class")) {
                    continue;
                }
                String name = entry.substring(0, entry.length() - ".class".length()).replace('/', '.');
                String pkg = name.substring(0, name.lastIndexOf('.'));
                Class<?> c = Class.forName(name, false, jar);
                boolean visible = Modifier.isPublic(c.getModifiers())
                        && (c.getEnclosingClass() == null || Modifier.isPublic(c.getEnclosingClass().getModifiers()))
                        && !c.isAnonymousClass() && !c.isSynthetic();
                if (visible && !pkg.contains(".internal") && !documented.contains(entry)) {
                    undocumented.add(name + (packages.contains(pkg) ? "" : " (package " + pkg + " not documented)"));
                }
            }
        }
        assertTrue(undocumented.isEmpty(), "public but not in the javadoc jar: " + undocumented);
    }

    @Test
    void sourcesJar_holdsTheSourceOfEveryClassInTheJar_andNoOther() {
        Set<String> fromClasses = main.keySet().stream().filter(e -> e.endsWith(".class"))
                .map(e -> e.substring(0, e.length() - ".class".length()).replaceAll("\\$.*", "") + ".java").collect(Collectors.toCollection(TreeSet::new));
        Set<String> fromSources = sources.keySet().stream().filter(e -> e.endsWith(".java"))
                .collect(Collectors.toCollection(TreeSet::new));
        // A source file may hold more than one top-level class; every class needs its file, and
        // every file of the sources jar must compile into this jar (none of hitbox.processing).
        fromClasses.removeIf(fromSources::contains);
        assertTrue(fromClasses.isEmpty(), "classes without their source: " + fromClasses);
        for (String source : fromSources) {
            String stem = source.substring(0, source.length() - ".java".length());
            if (stem.endsWith("/package-info")) {
                String dir = stem.substring(0, stem.lastIndexOf('/') + 1);
                assertTrue(main.keySet().stream().anyMatch(e -> e.startsWith(dir) && e.endsWith(".class")),
                        source + " in the sources jar, but the jar has no class in its package");
                continue;
            }
            assertTrue(main.containsKey(stem + ".class"), source + " in the sources jar, but no " + stem + ".class in the jar");
        }
    }

    private static String text(String path) {
        Element at = pom.getDocumentElement();
        for (String step : path.split("/")) {
            Element next = null;
            for (Node n = at.getFirstChild(); n != null; n = n.getNextSibling()) {
                if (n instanceof Element && n.getLocalName().equals(step)) {
                    next = (Element) n;
                    break;
                }
            }
            if (next == null) {
                return "";
            }
            at = next;
        }
        return at.getTextContent().strip();
    }

    /** Every leaf must say something, and nothing may be a placeholder or a Groovy leftover. */
    private static void walk(Element e, String path, List<String> problems) {
        String here = path + "/" + e.getLocalName();
        NodeList children = e.getChildNodes();
        boolean leaf = true;
        for (int i = 0; i < children.getLength(); i++) {
            if (children.item(i) instanceof Element) {
                leaf = false;
                walk((Element) children.item(i), here, problems);
            }
        }
        if (!leaf) {
            return;
        }
        String text = e.getTextContent().strip();
        if (text.isEmpty()) {
            problems.add(here + " empty");
        }
        for (String leftover : List.of("[]", "null", "${", "TODO", "example.com")) {
            if (text.contains(leftover)) {
                problems.add(here + " contains " + leftover + ": " + text);
            }
        }
        // The reserved .invalid domain is the documented placeholder of hitbox.url: it may
        // stand only where that url goes, and only while the build is given it (checkRelease
        // refuses it for a release).
        if (text.contains(".invalid") && (configuredUrl().isEmpty() || !text.contains(configuredUrl()))) {
            problems.add(here + " has a placeholder: " + text);
        }
    }
}
