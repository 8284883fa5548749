package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * The npm package: {@code npm pack} on the build's web folder makes a tarball; a fresh
 * project installs it (no registry needed: it has no dependencies) and a page there imports it
 * by its name through an import map and asks it a question in headless Chromium.
 */
class BrowserPackageTest {
    @Test
    void tarball_installsAndAnswersInAFreshProject() throws Exception {
        Path web = Path.of(System.getProperty("hitbox.web", "build/web")).toAbsolutePath();
        Assumptions.assumeTrue(Browser.chromium() != null, "No Chromium on this machine: skipped");
        Assumptions.assumeTrue(Files.isRegularFile(web.resolve("hitbox.wasm")), "No browser build: skipped");
        Assumptions.assumeTrue(onPath("npm"), "No npm on this machine: the package test is skipped");
        Path project = web.resolveSibling("web-consumer");
        deleteTree(project);
        Files.createDirectories(project);
        String packed = run(web.resolveSibling("web").toFile(), "npm", "pack", "--pack-destination", project.toString());
        String tarball = packed.strip().lines().reduce((a, b) -> b).orElseThrow();
        assertTrue(tarball.endsWith(".tgz"), packed);
        long size = Files.size(project.resolve(tarball));
        Files.writeString(project.resolve("package.json"), "{\"name\": \"fresh\", \"private\": true, \"type\": \"module\"}\n");
        run(project.toFile(), "npm", "install", "--no-audit", "--no-fund", "--offline", "./" + tarball);
        Path installed = project.resolve("node_modules/hitbox-collide");
        for (String f : List.of("hitbox.js", "hitbox.wasm", "teavm-runtime.js", "hitbox.d.ts", "p5.hitbox.js", "package.json")) {
            assertTrue(Files.isRegularFile(installed.resolve(f)), f + " installed");
        }
        Files.writeString(project.resolve("index.html"), String.join("\n",
                "<!doctype html><meta charset=\"utf-8\">",
                "<script type=\"importmap\">{\"imports\": {\"hitbox-collide\": \"./node_modules/hitbox-collide/hitbox.js\"}}</script>",
                "<script type=\"module\">",
                "import { Collide, circle, rect } from 'hitbox-collide';",
                "const c = circle(0, 0, 10).contact(rect(5, -3, 20, 6));",
                "await fetch('/report/answer', {method: 'POST', body: JSON.stringify({hit: Collide.circleCircle(0, 0, 10, 15, 0, 10), depth: c.depth})});",
                "</script>"));
        try (Browser browser = Browser.start(project)) {
            String answer = new String(browser.run("index.html", "answer", Duration.ofSeconds(60)), StandardCharsets.UTF_8);
            float depth = new hitbox.Circle(0, 0, 10).contact(new hitbox.Rect(5, -3, 20, 6)).depth();
            assertTrue(answer.startsWith("{\"hit\":true,"), answer);
            assertEquals((double) depth, Double.parseDouble(answer.replaceAll(".*\"depth\":([^}]*)}.*", "$1")), answer);
        }
        System.out.println("  npm package: " + tarball + ", " + size / 1024 + " KiB packed, installed and answering in a fresh project");
    }

    private static boolean onPath(String name) {
        for (String dir : System.getenv("PATH").split(File.pathSeparator)) {
            if (new File(dir, name).canExecute()) {
                return true;
            }
        }
        return false;
    }

    private static String run(File dir, String... command) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(command).directory(dir).redirectErrorStream(true);
        pb.environment().put("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1");
        Process p = pb.start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), String.join(" ", command) + " timed out");
        String text = new String(out, StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), String.join(" ", command) + ": " + text);
        return text;
    }

    private static void deleteTree(Path p) throws Exception {
        if (Files.exists(p)) {
            try (var files = Files.walk(p)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
            }
        }
    }
}
