package hitbox.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import hitbox.Body;
import hitbox.CharacterBody;
import hitbox.Collisions;
import hitbox.Polygon;
import hitbox.Rect;
import hitbox.Vec;
import hitbox.World;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The character body from JavaScript (web/pages/test/character.html): a character walks right
 * over a floor, up a 27-degree ramp and onto a plateau, under gravity. Checked against the
 * ramp's geometry (its foot on the ramp's line, the ramp's normal, three pixels a frame
 * sideways up the slope, standing on the plateau, then at the wall), and frame by frame
 * against the same walk on the JVM, bit for bit.
 */
class BrowserCharacterTest {
    private static final float RAMP_LEFT = 260;
    private static final float RAMP_RIGHT = 400;
    private static final float FLOOR = 360;
    private static final float PLATEAU = 290;

    @Test
    void character_walksUpTheRampAndStands_asOnTheJvm() throws Exception {
        String json;
        try (Browser browser = Browser.start()) {
            json = new String(browser.run("test/character.html", "character", Duration.ofSeconds(60)), StandardCharsets.UTF_8);
        }
        assertTrue(json.contains("\"settings\":{\"maxSlope\":45,\"stepHeight\":6,\"snap\":4,\"upX\":0,\"upY\":-1}"), json);
        List<int[]> browser = frames(json);
        assertEquals(200, browser.size(), "frames reported");

        // The geometry of the walk, from the browser's numbers alone.
        double rampNx = -70 / Math.hypot(70, 140);
        double rampNy = -140 / Math.hypot(70, 140);
        int onRamp = 0;
        int onPlateau = 0;
        float lastLeft = Float.NaN;
        for (int i = 0; i < browser.size(); i++) {
            int[] f = browser.get(i);
            float left = Float.intBitsToFloat(f[2]);
            float bottom = Float.intBitsToFloat(f[3]) + 36;
            float foot = left + 24;   // the bottom-right corner is the one on the slope
            boolean ground = f[4] == 1;
            float nx = Float.intBitsToFloat(f[7]);
            float ny = Float.intBitsToFloat(f[8]);
            if (ground && foot > RAMP_LEFT + 1 && foot < RAMP_RIGHT - 1) {
                onRamp++;
                float rampY = FLOOR - (foot - RAMP_LEFT) / 2;
                assertEquals(rampY, bottom, 0.5f, "frame " + i + ": its foot on the ramp at x " + foot);
                assertEquals(rampNx, nx, 1e-4, "frame " + i + ": the ramp's normal, x");
                assertEquals(rampNy, ny, 1e-4, "frame " + i + ": the ramp's normal, y");
                if (!Float.isNaN(lastLeft) && foot > RAMP_LEFT + 4) {
                    assertEquals(3f, left - lastLeft, 1e-3f, "frame " + i + ": up the slope at the speed given, 3 a frame sideways");
                }
            }
            if (left >= RAMP_RIGHT) {
                assertTrue(ground, "frame " + i + ": standing on the plateau");
                assertEquals(PLATEAU, bottom, 0.5f, "frame " + i + ": on the plateau's top");
                assertEquals(0f, nx, 1e-6f, "frame " + i + ": the plateau faces up");
                assertEquals(-1f, ny, 1e-6f, "frame " + i + ": the plateau faces up");
                onPlateau++;
            }
            lastLeft = left;
        }
        assertTrue(onRamp >= 30, "frames walking up the ramp: " + onRamp);
        assertTrue(onPlateau >= 20, "frames on the plateau: " + onPlateau);
        int[] last = browser.get(browser.size() - 1);
        assertEquals(580 - 24, Float.intBitsToFloat(last[2]), 0.5f, "at the end it stands against the wall");
        assertEquals(1, last[5], "at the end it is at a wall");

        // The same walk on the JVM, frame by frame, bit for bit.
        List<int[]> jvm = jvmWalk();
        for (int i = 0; i < jvm.size(); i++) {
            assertEquals(java.util.Arrays.toString(jvm.get(i)), java.util.Arrays.toString(browser.get(i)), "frame " + i);
        }
        System.out.println("  browser character: " + onRamp + " frames on the ramp, " + onPlateau + " on the plateau, 200 frames as the JVM's");
    }

    private static List<int[]> jvmWalk() {
        World world = new World();
        List<Body> added = List.of(world.add(new Rect(0, 360, 600, 40)), world.add(new Rect(580, 0, 20, 360)),
                world.add(Polygon.of(260, 360, 400, 290, 400, 360)), world.add(new Rect(400, 290, 180, 70)));
        CharacterBody hero = world.addCharacter(new Rect(60, 300, 24, 36)).maxSlope(45).stepHeight(6).snap(4).up(0, -1);
        List<int[]> out = new ArrayList<>();
        float vy = 0;
        for (int i = 0; i < 200; i++) {
            vy = Math.min(vy + 0.6f, 12);
            Collisions met = hero.move(3, vy);
            if (hero.onGround()) {
                vy = 0;
            }
            Vec n = hero.groundNormal();
            Rect b = hero.body().shape().bounds();
            out.add(new int[] {bits(hero.body().pivotX()), bits(hero.body().pivotY()), bits(b.x()), bits(b.y()),
                hero.onGround() ? 1 : 0, hero.onWall() ? 1 : 0, hero.onCeiling() ? 1 : 0,
                n == null ? 0 : bits(n.x()), n == null ? 0 : bits(n.y()),
                hero.ground() == null ? -1 : added.indexOf(hero.ground()), met.size()});
        }
        return out;
    }

    private static int bits(float v) {
        return Float.floatToIntBits(v);
    }

    private static List<int[]> frames(String json) {
        String body = json.substring(json.indexOf("\"frames\":[") + 10, json.lastIndexOf("]]") + 1);
        List<int[]> out = new ArrayList<>();
        for (String f : body.split("\\],\\[")) {
            String[] parts = f.replace("[", "").replace("]", "").split(",");
            int[] v = new int[parts.length];
            for (int i = 0; i < parts.length; i++) {
                v[i] = Integer.parseInt(parts[i].trim());
            }
            out.add(v);
        }
        return out;
    }
}
