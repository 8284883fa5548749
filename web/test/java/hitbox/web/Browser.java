package hitbox.web;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;

/**
 * Headless Chromium for the browser tests: the build's web folder served on the loopback
 * address by the JDK's own HTTP server, a page opened in Debian's Chromium (never a
 * downloaded one), and what the page reports back with {@code fetch('/report/NAME', {method:
 * 'POST', body})} handed to the test. A page that fails reports to {@code /report/error}.
 *
 * <p>With no Chromium on the machine the tests are skipped with a message that says so, as
 * the sketch tests are without a display. {@code -Dhitbox.chromium=/path} or the environment's
 * {@code HITBOX_CHROMIUM} names another binary.
 */
final class Browser implements AutoCloseable {
    private static final String[] CANDIDATES = {"/usr/bin/chromium", "/usr/bin/chromium-browser",
        "/usr/bin/google-chrome", "/usr/bin/google-chrome-stable"};

    private final HttpServer server;
    private final Path root;
    private final Map<String, CompletableFuture<byte[]>> reports = new ConcurrentHashMap<>();

    private Browser(Path root) throws IOException {
        this.root = root;
        server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        server.createContext("/", this::handle);
        server.start();
    }

    /**
     * The folder the build wrote the pages to (gradle webBuild), and Chromium to open them in;
     * skips the calling test, with the reason, when either is missing.
     *
     * @return a server on the loopback address, to close after use
     * @throws IOException if the server cannot start
     */
    static Browser start() throws IOException {
        String web = System.getProperty("hitbox.web", "build/web");
        Path root = Path.of(web);
        Assumptions.assumeTrue(Files.isRegularFile(root.resolve("hitbox.wasm")),
                "No browser build at " + root.toAbsolutePath() + ": run gradle webBuild (gradle test does)");
        Assumptions.assumeTrue(chromium() != null,
                "No Chromium on this machine: the browser tests are skipped (on Debian: apt-get install chromium)");
        return new Browser(root);
    }

    /**
     * A server for another folder (a page outside the build's web folder); skips the calling
     * test when the machine has no Chromium.
     *
     * @param root the folder to serve
     * @return a server on the loopback address, to close after use
     * @throws IOException if the server cannot start
     */
    static Browser start(Path root) throws IOException {
        Assumptions.assumeTrue(chromium() != null,
                "No Chromium on this machine: the browser tests are skipped (on Debian: apt-get install chromium)");
        return new Browser(root);
    }

    /**
     * Chromium's binary, or null when the machine has none.
     *
     * @return the path of the binary, or null
     */
    static String chromium() {
        String named = System.getProperty("hitbox.chromium", System.getenv("HITBOX_CHROMIUM"));
        if (named != null && !named.isEmpty()) {
            return new File(named).canExecute() ? named : null;
        }
        for (String c : CANDIDATES) {
            if (new File(c).canExecute()) {
                return c;
            }
        }
        return null;
    }

    /**
     * Opens a page and waits for what it reports under {@code name}.
     *
     * @param page    the page's path under the web folder, with its query
     * @param name    the report to wait for
     * @param timeout how long to wait
     * @return the report's bytes
     * @throws Exception if the page reports an error, or nothing comes in time
     */
    byte[] run(String page, String name, Duration timeout) throws Exception {
        return run(page, List.of(name), timeout).get(name);
    }

    /**
     * Opens a page and waits for all the reports named.
     *
     * @param page    the page's path under the web folder, with its query
     * @param names   the reports to wait for
     * @param timeout how long to wait for them all
     * @return the reports by name
     * @throws Exception if the page reports an error, or the reports do not all come in time
     */
    Map<String, byte[]> run(String page, List<String> names, Duration timeout) throws Exception {
        reports.clear();
        CompletableFuture<byte[]> error = future("error");
        List<CompletableFuture<byte[]>> wanted = new ArrayList<>();
        for (String n : names) {
            wanted.add(future(n));
        }
        Path profile = Files.createTempDirectory("hitbox-chromium");
        String url = "http://127.0.0.1:" + server.getAddress().getPort() + "/" + page;
        Process chromium = new ProcessBuilder(chromium(), "--headless", "--no-sandbox", "--disable-gpu",
                "--no-first-run", "--no-default-browser-check", "--disable-extensions", "--mute-audio",
                "--hide-scrollbars", "--window-size=800,600", "--user-data-dir=" + profile, url)
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        try {
            CompletableFuture<Object> all = CompletableFuture.allOf(wanted.toArray(new CompletableFuture<?>[0]))
                    .thenApply(v -> (Object) v);
            Object first = CompletableFuture.anyOf(all, error).get(timeout.toMillis(), TimeUnit.MILLISECONDS);
            if (error.isDone()) {
                throw new AssertionError(page + " reported an error: " + new String(error.get(), StandardCharsets.UTF_8));
            }
            Map<String, byte[]> out = new java.util.LinkedHashMap<>();
            for (int i = 0; i < names.size(); i++) {
                out.put(names.get(i), wanted.get(i).get());
            }
            return first == null ? out : out;
        } catch (TimeoutException e) {
            List<String> missing = new ArrayList<>();
            for (int i = 0; i < names.size(); i++) {
                if (!wanted.get(i).isDone()) {
                    missing.add(names.get(i));
                }
            }
            throw new AssertionError(page + " did not report " + missing + " within " + timeout.toSeconds() + " s");
        } finally {
            chromium.descendants().forEach(ProcessHandle::destroy);
            chromium.destroy();
            if (!chromium.waitFor(10, TimeUnit.SECONDS)) {
                chromium.destroyForcibly();
            }
            try (Stream<Path> files = Files.walk(profile)) {
                files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            } catch (IOException ignored) {
                // a temporary profile left behind is harmless
            }
        }
    }

    private CompletableFuture<byte[]> future(String name) {
        return reports.computeIfAbsent(name, n -> new CompletableFuture<>());
    }

    private void handle(HttpExchange ex) throws IOException {
        try (ex) {
            String path = ex.getRequestURI().getPath();
            if ("POST".equals(ex.getRequestMethod()) && path.startsWith("/report/")) {
                byte[] body;
                try (InputStream in = ex.getRequestBody()) {
                    body = in.readAllBytes();
                }
                future(path.substring("/report/".length())).complete(body);
                ex.sendResponseHeaders(204, -1);
                return;
            }
            Path file = root.resolve(path.substring(1)).normalize();
            if (!file.startsWith(root.normalize()) || !Files.isRegularFile(file)) {
                ex.sendResponseHeaders(404, -1);
                return;
            }
            byte[] bytes = Files.readAllBytes(file);
            ex.getResponseHeaders().set("Content-Type", contentType(file.toString()));
            ex.getResponseHeaders().set("Cache-Control", "no-store");
            ex.sendResponseHeaders(200, bytes.length);
            try (OutputStream out = ex.getResponseBody()) {
                out.write(bytes);
            }
        }
    }

    private static String contentType(String name) {
        if (name.endsWith(".wasm")) {
            return "application/wasm";
        } else if (name.endsWith(".js") || name.endsWith(".mjs")) {
            return "text/javascript; charset=utf-8";
        } else if (name.endsWith(".html")) {
            return "text/html; charset=utf-8";
        } else if (name.endsWith(".json")) {
            return "application/json";
        } else if (name.endsWith(".png")) {
            return "image/png";
        } else if (name.endsWith(".css")) {
            return "text/css";
        }
        return "application/octet-stream";
    }

    @Override
    public void close() {
        server.stop(0);
    }
}
