package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import hitbox.Collide;
import hitbox.Ray;
import hitbox.RayHit;
import hitbox.Segment;
import hitbox.processing.Palette;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S10a_LineIntersection: the line from the start (40, 340; a click moves it) to the mouse,
 * against s1 (60, 190)-(170, 80), s2 (300, 80)-(300, 200), s3 (430, 110)-(570, 170), the
 * rectangle (400, 250, 140 x 90, bottom edge level with the start) and the circle
 * (220, 280, r 42).
 */
class S10a_LineIntersectionTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    @ParameterizedTest(name = "start ({0}, {1}), mouse ({2}, {3}): s1 {4}, s2 {5}, s3 {6}, rect {7}, circle {8}")
    @CsvSource({
            // start x, y (-1: the default), mouse x, y, then what is hit
            "-1, -1, 430, 130, false, true,  false, false, true",    // across s2 and through the circle
            "-1, -1, 300, 200, false, true,  false, false, true",    // ending exactly on s2's end: closed, counts
            "-1, -1, 300, 201, false, false, false, false, true",    // a pixel below that end
            "-1, -1, 300, 150, false, true,  false, false, false",   // ending on s2's middle
            "-1, -1, 299, 150, false, false, false, false, false",   // a pixel short of it
            "-1, -1, 450, 340, false, false, false, false, false",   // along the rectangle's bottom edge: never inside
            "-1, -1, 450, 339, false, false, false, true,  false",   // tilted a pixel up: into the rectangle
            "-1, -1, 520, 290, false, false, false, true,  true",
            "-1, -1, 100, 380, false, false, false, false, false",   // away from everything
            "-1, -1, 170, 80,  true,  false, false, false, false",   // ending on s1's end
            "150, 238, 300, 238, false, false, false, false, false", // a tangent to the circle's top
            "150, 238, 300, 239, false, false, false, false, true",  // a pixel into it
            "470, 300, 480, 310, false, false, false, true,  false", // wholly inside the rectangle
            "430, 110, 570, 170, false, false, true,  false, false", // lying on s3: collinear, counts
    })
    void eachTarget_isRedOnlyWhileTheLineHitsIt(int sx, int sy, int mx, int my,
                                                boolean s1, boolean s2, boolean s3, boolean rect, boolean circle) {
        Script script = new Script().frames(5);
        if (sx >= 0) {
            script.click(1, sx, sy);
        }
        script.mouse(3, mx, my);
        SketchRun.Result<S10a_LineIntersection> r = SketchRun.of(new S10a_LineIntersection()).script(script).run();
        S10a_LineIntersection s = r.sketch();
        assertEquals(sx >= 0 ? sx : 40, s.startX, "start x");
        assertEquals(mx, s.mouseX, "the line ends at the mouse");
        boolean[] expected = {s1, s2, s3};
        for (int i = 0; i < 3; i++) {
            Segment g = s.segments[i];
            assertEquals(s.lineLine(s.startX, s.startY, s.mouseX, s.mouseY, g.x1(), g.y1(), g.x2(), g.y2()), s.segmentHit[i],
                    "the colour is the written-out lineLine's answer");
            assertEquals(Collide.lineLine(s.startX, s.startY, s.mouseX, s.mouseY, g.x1(), g.y1(), g.x2(), g.y2()), s.segmentHit[i],
                    "and the library agrees");
            assertEquals(expected[i], s.segmentHit[i], s.names[i]);
        }
        assertEquals(rect, s.boxHit, "rectangle");
        assertEquals(circle, s.ballHit, "circle");
        assertEquals(0, s.disagreements, "the written-out maths and Hitbox agree here");
        PImage frame = r.lastFrame();
        SketchPixels.assertColour(frame, 300, 90, s2 ? Palette.HIT : Palette.MISS, "s2");
        SketchPixels.assertColour(frame, 530, 262, rect ? Palette.HIT : Palette.MISS, "rectangle");
        SketchPixels.assertColour(frame, 250, 270, circle ? Palette.HIT : Palette.MISS, "circle");
    }

    @Test
    void throughTwoCorners_theWrittenOutLineRectMissesIt_CollideLineRectAfterLDoesNot() {
        // From (372, 232) to (568, 358): through the rectangle's corners (400, 250) and (540, 340).
        Script script = new Script().frames(5).click(1, 372, 232).mouse(3, 568, 358);
        SketchRun.Result<S10a_LineIntersection> r = SketchRun.of(new S10a_LineIntersection()).script(script).run();
        assertFalse(r.sketch().boxHit, "no end inside, no side crossed properly");
        assertEquals(1, r.sketch().disagreements, "Collide.lineRect says it goes inside");
        SketchPixels.assertColour(r.lastFrame(), 530, 262, Palette.MISS, "the rectangle, by the written-out maths");
        SketchRun.Result<S10a_LineIntersection> l = SketchRun.of(new S10a_LineIntersection())
                .script(new Script().frames(5).click(1, 372, 232).mouse(3, 568, 358).key(3, 'l')).run();
        assertTrue(l.sketch().hitboxDecides);
        assertTrue(l.sketch().boxHit, "Collide.lineRect: through the inside");
        SketchPixels.assertColour(l.lastFrame(), 530, 262, Palette.HIT, "the rectangle, by Hitbox's call");
    }

    @Test
    void crossingPoint_isMarkedWhereTheRayMeetsTheSegment() {
        SketchRun.Result<S10a_LineIntersection> r = SketchRun.of(new S10a_LineIntersection())
                .script(new Script().frames(4).mouse(1, 430, 130)).run();
        S10a_LineIntersection s = r.sketch();
        RayHit hit = Ray.between(s.startX, s.startY, s.mouseX, s.mouseY).cast(s.segments[1]);
        assertNotNull(hit);
        assertEquals(300, hit.x(), 1e-3f, "on s2");
        SketchPixels.assertColour(r.lastFrame(), Math.round(hit.x()) + 2, Math.round(hit.y()), Palette.ACCENT, "the crossing dot");
        // The circle: the line goes in and comes out, two dots.
        RayHit in = Ray.between(s.startX, s.startY, s.mouseX, s.mouseY).cast(s.ball);
        RayHit out = Ray.between(s.mouseX, s.mouseY, s.startX, s.startY).cast(s.ball);
        assertTrue(in.x() < out.x(), "entry before exit");
        SketchPixels.assertColour(r.lastFrame(), Math.round(in.x()), Math.round(in.y()) + 2, Palette.ACCENT, "entry dot");
        SketchPixels.assertColour(r.lastFrame(), Math.round(out.x()), Math.round(out.y()) + 2, Palette.ACCENT, "exit dot");
    }

    @Test
    void mouseOnTheStart_isAPoint_andNothingBreaks() {
        S10a_LineIntersection s = SketchRun.of(new S10a_LineIntersection())
                .script(new Script().frames(4).mouse(1, 40, 340).key(1, 'd')).run().sketch();
        for (boolean hit : s.segmentHit) {
            assertTrue(!hit);
        }
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).mouse(1, 430, 130).key(3, 'd').key(8, 'd');
        SketchRun.Result<S10a_LineIntersection> r = SketchRun.of(new S10a_LineIntersection()).script(script)
                .capture(2).capture(6).run();
        PImage off = r.frame(2);
        assertTrue(SketchPixels.differing(off, r.frame(6)) > 2000, "the overlay writes out each test");
        assertEquals(0, SketchPixels.differing(off, r.lastFrame()), "pressing d again hides the overlay");
    }
}
