package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The p5.js sketches (web/sketches) in headless Chromium with a scripted mouse: each runs
 * without an error, its picture is saved to build/web-shots/NAME.png (to look at), and where
 * the mouse ends on a shape, the hit's red (#E8504A) is drawn. A fourth column is added to the
 * page's query (a sketch's other mode).
 */
class BrowserSketchesTest {
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "S01_EdgeBounce |       300,200 | false |",
        "S02_CirclePoint |      100,100;310,210 | true |",
        "S03_CircleCircle |     50,50;420,260 | true |",
        "S04_RectPoint |        50,50;300,200 | true |",
        "S05_RectRect |         50,50;320,220 | true |",
        "S06_MovingObjects |    300,200 | false |",
        "S08_ManyObjects |      50,50;300,200 | false |",
        "S09_Grid |             50,50;130,75 | true |",
        "S07_SnapToEdge |       300,200;300,200;300,200;300,200;300,200;300,200 | false |",
        "S10a_LineIntersection | 50,50;470,300 | true |",
        "S10b_PointInPolygon |  50,50;300,180 | true |",
        "S10b_PointInPolygon |  50,50;300,180 |   true | poly",
        "S10c_SeparatingAxis |  50,50;300,200 | true |",
        "S10d_ContactResponse | 50,50;230,190 | true |",
        "H01_Maze |             100,100;300,150;300,150;300,150;300,150;300,150;300,150;300,150 | false |",
        "H02_Bouncers |         300,200;300,200;300,200;300,200;300,200;300,200 | false |",
        "B02_Platformer |       300,200;300,200;300,200;300,200;300,200;300,200;300,200;300,200 | false |",
    })
    void sketch_runsWithScriptedInput(String sketch, String path, boolean hitAtTheEnd, String mode) throws Exception {
        String shot = mode == null ? sketch : sketch + "-" + mode;
        try (Browser browser = Browser.start()) {
            Assumptions.assumeTrue(Files.exists(Path.of(System.getProperty("hitbox.web", "build/web"), "vendor", "p5")),
                    "No p5 in build/web/vendor (npm missing?): skipped");
            Map<String, byte[]> got = browser.run("sketches/" + sketch + "/index.html?test=1&path=" + path
                    + (mode == null ? "" : "&" + mode),
                    List.of("png", "done"), Duration.ofSeconds(60));
            Path shots = Path.of("build", "web-shots");
            Files.createDirectories(shots);
            Files.write(shots.resolve(shot + ".png"), got.get("png"));
            BufferedImage img = ImageIO.read(new ByteArrayInputStream(got.get("png")));
            assertEquals(600, img.getWidth(), "canvas width");
            Set<Integer> colours = new HashSet<>();
            int hit = 0;
            for (int y = 0; y < img.getHeight(); y++) {
                for (int x = 0; x < img.getWidth(); x++) {
                    int rgb = img.getRGB(x, y) & 0xffffff;
                    colours.add(rgb);
                    if (rgb == 0xE8504A) {
                        hit++;
                    }
                }
            }
            assertTrue(colours.size() >= 3, shot + " drew something: " + colours.size() + " colours");
            if (hitAtTheEnd) {
                assertTrue(hit > 200, shot + ": the mouse ends on the shape, so it is drawn red: " + hit + " red pixels");
            }
        }
    }
}
