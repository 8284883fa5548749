package hitbox.web;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

/**
 * gradle webSpeed: runs the speed page (web/pages/test/speed.html) in headless Chromium with the
 * full counts, prints its table and writes it to build/web-speed.md, for docs/browser.md. A
 * benchmark: run it on a quiet machine (uptime) and say in the docs how quiet it was.
 */
public final class SpeedRun {
    private SpeedRun() {
    }

    /**
     * Runs the page.
     *
     * @param args unused
     * @throws Exception if the page fails or the machine has no Chromium
     */
    public static void main(String[] args) throws Exception {
        if (Browser.chromium() == null) {
            throw new IllegalStateException("No Chromium on this machine (on Debian: apt-get install chromium)");
        }
        try (Browser browser = Browser.start()) {
            String table = new String(browser.run("test/speed.html", java.util.List.of("speed", "table"), Duration.ofMinutes(15))
                    .get("table"), StandardCharsets.UTF_8);
            Path out = Path.of("build", "web-speed.md");
            Files.writeString(out, table);
            System.out.println(table);
            System.out.println("written to " + out.toAbsolutePath());
        }
    }
}
