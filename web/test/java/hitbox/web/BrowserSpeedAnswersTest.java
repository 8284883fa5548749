package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * The speed page (web/pages/test/speed.html, timed by gradle webSpeed) with small counts and no
 * timing: every row's forms (the tutorial's ifs in plain JavaScript, Hitbox, detect-collisions)
 * count the same hits, and in the stress scene every pair Hitbox's world reports,
 * detect-collisions' System reports too, and every pair only detect-collisions reports is one
 * that touches (it counts touching as a hit; Hitbox does not).
 */
class BrowserSpeedAnswersTest {
    @Test
    void speedPage_everyFormAnswersAlike() throws Exception {
        try (Browser browser = Browser.start()) {
            Assumptions.assumeTrue(Files.exists(Path.of(System.getProperty("hitbox.web", "build/web"), "vendor", "detect-collisions")),
                    "No detect-collisions in build/web/vendor (npm missing?): skipped");
            String json = new String(browser.run("test/speed.html?quick", "speed", Duration.ofSeconds(120)), StandardCharsets.UTF_8);
            assertTrue(json.contains("\"alike\":true"), json);
            assertFalse(json.contains("\"alike\":false"), "a form counts other hits: " + json);
            assertTrue(json.contains("\"onlyDcOther\":0,"), "detect-collisions finds pairs Hitbox does not, not touching: " + json);
            assertTrue(json.contains("\"onlyHitbox\":0,"), "Hitbox finds pairs detect-collisions does not: " + json);
            assertFalse(json.contains("\"hbPairs\":0,"), "the scene has overlapping pairs to compare: " + json);
            System.out.println("  browser speed page answers: " + json.substring(json.indexOf("\"scene\"")));
        }
    }
}
