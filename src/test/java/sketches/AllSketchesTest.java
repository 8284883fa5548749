package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import hitbox.sketchkit.Catalog;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/**
 * What every sketch must do, found from the sketch folders so a new sketch is covered
 * without editing this file: run 300 frames with its screenshot's scripted input and the
 * overlay key pressed twice (shown, then hidden) without an exception, and have a screenshot.
 */
class AllSketchesTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    static Stream<Catalog.SketchInfo> sketches() {
        return Catalog.load().sketches().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sketches")
    void runs300FramesWithItsScript_andTogglesTheOverlay(Catalog.SketchInfo info) {
        Script script = info.readScript();
        script.frames(300).key(100, 'd').key(200, 'd');
        SketchRun.Result<?> result = SketchRun.of(info.newInstance()).script(script).run();
        assertEquals(300, result.framesDrawn(), "frames drawn");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sketches")
    void hasAScreenshotAndItsScript(Catalog.SketchInfo info) {
        assertTrue(info.screenshot().isFile(), info.name() + " has no screenshot.png: run xvfb-run -a gradle screenshots -Psketch=" + info.name());
        assertTrue(info.screenshotScript().isFile(), info.name() + " has no screenshot.txt (its scripted input)");
    }
}
