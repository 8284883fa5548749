package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The p5.js add-on in headless Chromium, with p5 2.x and p5 1.x: every p5.collide2D function
 * (and its Vector form) on a hit, a miss and a touch; then a sketch written for p5.collide2D
 * (web/sketches/collide2d_style) runs unchanged with scripted mouse moves, and its picture is
 * saved to build/web-shots/ and checked for the red of a hit.
 */
class BrowserAddonTest {
    @ParameterizedTest
    @ValueSource(strings = {"p5", "p5v1"})
    void addon_answersEveryFunction(String p5) throws Exception {
        try (Browser browser = Browser.start()) {
            Assumptions.assumeTrue(Files.exists(Path.of(System.getProperty("hitbox.web", "build/web"), "vendor", p5)),
                    "No " + p5 + " in build/web/vendor (npm missing?): skipped");
            String json = new String(browser.run("test/addon.html?p5=" + p5, "addon", Duration.ofSeconds(60)),
                    StandardCharsets.UTF_8);
            assertTrue(json.contains("\"failures\":[]"), json);
            assertTrue(json.contains("\"inSketch\":true"), json);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"collide2d_style"})
    void collide2dSketch_runsUnchanged(String sketch) throws Exception {
        try (Browser browser = Browser.start()) {
            Assumptions.assumeTrue(Files.exists(Path.of(System.getProperty("hitbox.web", "build/web"), "vendor", "p5")),
                    "No p5 in build/web/vendor (npm missing?): skipped");
            // The mouse ends over the still rectangle and the circle at (200, 220): both turn red.
            Map<String, byte[]> got = browser.run("sketches/" + sketch + "/index.html?test=1&path=10,10;60,60;120,180",
                    List.of("png", "done"), Duration.ofSeconds(60));
            Path shots = Path.of("build", "web-shots");
            Files.createDirectories(shots);
            Files.write(shots.resolve(sketch + ".png"), got.get("png"));
            java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(got.get("png")));
            assertEquals(400, img.getWidth());
            int red = 0;
            for (int y = 0; y < img.getHeight(); y++) {
                for (int x = 0; x < img.getWidth(); x++) {
                    int rgb = img.getRGB(x, y);
                    if ((rgb >> 16 & 0xff) > 150 && (rgb >> 8 & 0xff) < 120 && (rgb & 0xff) < 120) {
                        red++;
                    }
                }
            }
            assertTrue(red > 100, "the shapes the mouse hits are drawn red: " + red + " red pixels");
        }
    }
}
