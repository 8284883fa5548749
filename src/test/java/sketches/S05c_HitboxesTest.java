package sketches;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import hitbox.Collide;
import hitbox.Rect;
import hitbox.sketchkit.Script;
import hitbox.sketchkit.SketchRun;
import processing.core.PImage;

/**
 * S05c_Hitboxes: rocks rain on a rocket; each frame every rock is tested against the hit box
 * (centred on the rocket) and against the rocket's outline, and the tally counts where they
 * agree and where the box is wrong.
 */
class S05c_HitboxesTest {

    @BeforeAll
    static void needsDisplay() {
        assumeTrue(SketchRun.displayAvailable(), SketchRun.NO_DISPLAY);
    }

    private static S05c_Hitboxes rain(Script script) {
        return SketchRun.of(new S05c_Hitboxes()).script(script).everyFrame(s -> {
            // Every rock's colour is what the two tests say about it this frame: the box as the
            // sketch's shape is, the rocket's outline exactly.
            for (S05c_Hitboxes.Rock rock : s.rocks) {
                boolean box = switch (s.boxShape) {
                    case "rectangle" -> Collide.rectRect(rock.x, rock.y, rock.size, rock.size, s.ship.x - s.boxW / 2, s.ship.y - s.boxH / 2, s.boxW, s.boxH);
                    case "circle" -> Collide.circleRect(s.ship.x, s.ship.y, s.boxH / 2, rock.x, rock.y, rock.size, rock.size);
                    default -> s.hitBox().overlaps(new Rect(rock.x, rock.y, rock.size, rock.size));
                };
                boolean ship = s.ship.touches(new Rect(rock.x, rock.y, rock.size, rock.size));
                int expected = box && ship ? s.HIT : box ? s.FALSE_HIT : ship ? s.MISS : s.NOTHING;
                assertEquals(expected, rock.verdict, "the rock at (" + rock.x + ", " + rock.y + ")");
            }
            // Boxes first: the exact test ran once for every box hit, and never otherwise.
            assertEquals(s.hits + s.falseHits, s.exactTests, "exact tests only after a box hit");
        }).run().sketch();
    }

    @Test
    void byDefault_theWrittenOutRectangleIf_andWithL_CollideRectRect_giveTheSameTally() {
        S05c_Hitboxes ifs = rain(new Script().frames(600));
        S05c_Hitboxes library = rain(new Script().frames(600).key(1, 'l'));
        assertTrue(library.hitboxDecides && !ifs.hitboxDecides);
        assertEquals(ifs.hits, library.hits);
        assertEquals(ifs.falseHits, library.falseHits);
        assertEquals(ifs.misses, library.misses);
        assertTrue(ifs.exactTests < ifs.rockTests / 4, "most rocks never reach the exact test: "
                + ifs.exactTests + " of " + ifs.rockTests);
    }

    @Test
    void circleAndPolygonBoxes_theVideos_countTheirOwnMistakes_andLAgreesOnTheCircle() {
        S05c_Hitboxes circle = rain(new Script().frames(900).key(1, 'b'));
        assertEquals("circle", circle.boxShape);
        assertTrue(circle.hits > 50 && circle.falseHits > 20, "hits " + circle.hits + ", false hits " + circle.falseHits);
        S05c_Hitboxes circleLibrary = rain(new Script().frames(900).key(1, 'b').key(1, 'l'));
        assertEquals(circle.hits, circleLibrary.hits, "dist() to the nearest point and Collide.circleRect agree");
        assertEquals(circle.falseHits, circleLibrary.falseHits);
        S05c_Hitboxes polygon = rain(new Script().frames(900).key(1, 'b').key(2, 'b'));
        assertEquals("polygon", polygon.boxShape);
        assertTrue(polygon.hits > 50, "hits " + polygon.hits);
        assertTrue(polygon.falseHits < circle.falseHits, "the rocket-shaped polygon hits falsely less often than the circle: "
                + polygon.falseHits + " and " + circle.falseHits);
    }

    @Test
    void boxAroundEverything_neverMisses_butHitsFalsely() {
        S05c_Hitboxes s = rain(new Script().frames(1200).key(1, '3'));
        assertEquals(84, s.boxW);
        assertEquals(108, s.boxH);
        assertEquals(0, s.misses, "the rocket is inside its bounding box: a rock on the rocket is on the box");
        assertTrue(s.falseHits > 100, "rocks in the box's empty corners: " + s.falseHits);
        assertTrue(s.hits > 100, "real hits: " + s.hits);
    }

    @Test
    void boxInsideTheBody_neverHitsFalsely_butMisses() {
        S05c_Hitboxes s = rain(new Script().frames(1200).key(1, '1'));
        assertEquals(0, s.falseHits, "the box is inside the body: a rock on the box is on the rocket");
        assertTrue(s.misses > 100, "rocks on the nose and the fins: " + s.misses);
        assertTrue(s.hits > 100, "real hits: " + s.hits);
    }

    @Test
    void fittedBox_makesBothMistakes() {
        S05c_Hitboxes s = rain(new Script().frames(1200).key(1, '2'));
        assertTrue(s.falseHits > 20 && s.misses > 20 && s.hits > s.falseHits + s.misses,
                "hits " + s.hits + ", false hits " + s.falseHits + ", misses " + s.misses);
    }

    @Test
    void arrowKeys_resizeTheBox_andStartANewTally() {
        // Inside the body (1) until frame 600: misses pile up; then three times wider, taller
        // and then the bounding box (3): a new tally, with no miss in it.
        Script script = new Script().frames(1000).key(1, '1')
                .hold(300, "RIGHT", 1).hold(303, "RIGHT", 1).hold(306, "UP", 1).key(600, '3');
        S05c_Hitboxes[] seen = new S05c_Hitboxes[1];
        int[] at = new int[3];
        SketchRun.of(new S05c_Hitboxes()).script(script).everyFrame(s -> {
            if (s.frameCount == 310) {
                at[0] = (int) s.boxW;
                at[1] = (int) s.boxH;
            }
            if (s.frameCount == 599) {
                at[2] = s.misses;
            }
            seen[0] = s;
        }).run();
        assertEquals(24 + 8, at[0], "RIGHT twice: 8 px wider");
        assertEquals(56 + 4, at[1], "UP once: 4 px taller");
        assertTrue(at[2] > 0, "the small box missed rocks");
        assertEquals(0, seen[0].misses, "the new tally, for the bounding box, has none");
        assertTrue(seen[0].hits > 0);
    }

    @Test
    void theDrawnRocket_isTheOutlineTheExactTestUses() {
        // Frame 1: no rock has come down yet.
        SketchRun.Result<S05c_Hitboxes> r = SketchRun.of(new S05c_Hitboxes()).script(new Script().frames(1)).run();
        S05c_Hitboxes s = r.sketch();
        PImage frame = r.lastFrame();
        int[] rocketColours = {0xFFD8DCE4, 0xFFE8504A, 0xFF5AA9F0};
        float left = s.ship.x - s.boxW / 2, right = left + s.boxW, top = s.ship.y - s.boxH / 2, bottom = top + s.boxH;
        int inside = 0;
        for (int y = (int) s.ship.y - 60; y <= s.ship.y + 60; y++) {
            for (int x = (int) s.ship.x - 50; x <= s.ship.x + 50; x++) {
                if (near(x, left) || near(x, right) || near(y, top) || near(y, bottom)) {
                    continue;   // the hit box's outline is drawn over the rocket
                }
                if (Math.abs(Math.hypot(x + 0.5 - s.ship.x, y + 0.5 - (s.ship.y - 6)) - 8) < 1.5) {
                    continue;   // the window's rim: body and window colours blend
                }
                int around = 0;
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        around += s.ship.contains(x + dx + 0.5f, y + dy + 0.5f) ? 1 : 0;
                    }
                }
                boolean drawnAsRocket = false;
                for (int c : rocketColours) {
                    drawnAsRocket |= frame.get(x, y) == c;
                }
                if (around == 9) {
                    assertTrue(drawnAsRocket, "inside the outline, (" + x + ", " + y + ") is drawn as the rocket");
                    inside++;
                } else if (around == 0) {
                    assertTrue(!drawnAsRocket, "outside the outline, (" + x + ", " + y + ") is not drawn as the rocket");
                }
            }
        }
        assertTrue(inside > 2500, "the rocket's inside: " + inside + " px");
    }

    private static boolean near(int pixel, float line) {
        return Math.abs(pixel + 0.5f - line) < 2.5f;
    }

    @Test
    void overlayKey_changesWhatIsDrawn_andPressingAgainHidesIt() {
        Script script = new Script().frames(12).key(3, 'd').key(8, 'd');
        SketchRun.Result<S05c_Hitboxes> r = SketchRun.of(new S05c_Hitboxes()).script(script)
                .capture(2).capture(6).run();
        // The rocket and the labels beside it (the rocks have not come down yet).
        assertTrue(SketchPixels.differing(r.frame(2), r.frame(6), 200, 180, 599, 370) > 2000, "the overlay shades the areas and writes them");
        assertEquals(0, SketchPixels.differing(r.frame(2), r.lastFrame(), 200, 180, 599, 370), "pressing d again hides it");
    }
}
