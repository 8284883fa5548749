package sketches;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;

/** S10h_VisionCone: the guard sees the capsule player in its cone, not behind a wall, not outside the cone. */
class S10h_VisionConeTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private static SketchRun.Result<S10h_VisionCone> playerAt(int x, int y) {
        // Space stops the guard's sweep at facing 0 after frame 1 (a fixed cone from -0.55 to 0.55).
        return SketchRun.of(new S10h_VisionCone()).script(new Script().frames(6).mouse(1, x, y).key(1, ' ')).run();
    }

    @Test
    void inTheOpenInsideTheCone_isSeen() {
        assertTrue(playerAt(250, 200).sketch().seen);
    }

    @Test
    void behindTheWall_isHidden() {
        // Behind the upper wall (300..324, 60..170), in the cone's direction.
        assertFalse(playerAt(360, 110).sketch().seen);
    }

    @Test
    void outsideTheCone_isHidden() {
        assertFalse(playerAt(150, 360).sketch().seen);
        assertFalse(Collide.arcPoint(110, 200, 330, 330, -0.55f, 0.55f, 3, 150, 360));
    }

    @Test
    void theConeIsDrawnRedOnlyWhenSeen() {
        int seen = SketchPixels.count(playerAt(250, 200).lastFrame(), 0xFFE8504A);
        int hidden = SketchPixels.count(playerAt(150, 360).lastFrame(), 0xFFE8504A);
        assertTrue(seen > hidden, "the player drawn red when seen: " + seen + " vs " + hidden);
    }
}
