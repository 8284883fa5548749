package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.Body;
import hitbox.Circle;
import hitbox.Collision;
import hitbox.Contact;
import hitbox.Ellipse;
import hitbox.Grid;
import hitbox.Hit;
import hitbox.Ray;
import hitbox.RayHit;
import hitbox.Rect;
import hitbox.Separation;
import hitbox.Sweep;
import hitbox.World;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The ES module's JavaScript API in headless Chromium (web/pages/test/module.html): the same
 * questions asked here of the library, the answers compared by their bits; and the module's
 * load time and first answer, printed for docs/browser.md.
 */
class BrowserModuleTest {
    @Test
    void module_answersAsTheJvm() throws Exception {
        String json;
        try (Browser browser = Browser.start()) {
            json = new String(browser.run("test/module.html", "module", Duration.ofSeconds(60)), StandardCharsets.UTF_8);
        }
        Contact c = new Circle(0, 0, 10).contact(new Rect(5, -3, 20, 6));
        assertTrue(json.contains("\"contact\":" + bits(c.nx(), c.ny(), c.depth())), json);
        assertTrue(json.contains("\"kind\":\"Circle\""), json);
        assertTrue(json.contains("\"overlaps\":true"), json);
        assertTrue(json.contains("\"separation\":" + Float.floatToIntBits(Separation.between(new Circle(0, 0, 1), new Circle(10, 0, 2)).distance())), json);
        Hit h = Sweep.timeOfImpact(new Rect(0, 0, 10, 10), 100, 0, new Rect(50, 0, 10, 10));
        assertTrue(json.contains("\"sweep\":[" + Float.floatToIntBits(h.t()) + "," + Float.floatToIntBits(h.nx()) + ",\"" + h.side() + "\"]"), json);
        RayHit r = new Ray(0, 0, 1, 0).cast(new Ellipse(50, 0, 10, 5, 0.5f));
        assertTrue(json.contains("\"ray\":" + bits(r.distance(), r.x(), r.y())), json);
        World w = new World();
        Body player = w.add(new Rect(0, 0, 10, 10));
        w.add(new Rect(30, -50, 10, 100));
        List<Collision> met = w.move(player, 50, 5);
        assertTrue(json.contains("\"moved\":[" + Float.floatToIntBits(player.pivotX()) + "," + Float.floatToIntBits(player.pivotY()) + ","
                + met.size() + ",1,\"" + met.get(0).reaction() + "\"]"), json);
        int[] path = Grid.parse("....\n.##.\n....", 10).path(0, 0, 3, 2);
        assertTrue(json.contains("\"path\":" + Arrays.toString(path).replace(" ", "")), json);
        assertTrue(json.contains("\"thrown\":\"") && !json.contains("\"thrown\":null"), "a refused shape throws: " + json);
        assertEquals(-1, json.indexOf("NaN"), json);
        System.out.println("  browser module: " + json.replaceAll(",\"contact.*", "}"));
    }

    private static String bits(float... v) {
        StringBuilder sb = new StringBuilder("[");
        for (int i = 0; i < v.length; i++) {
            sb.append(i > 0 ? "," : "").append(Float.floatToIntBits(v[i]));
        }
        return sb.append(']').toString();
    }
}
