package hitbox;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * No tunnelling, against the pair sweeps: for every ordered pair of shape kinds (so both
 * roles), a small mover thrown at a thin body at up to 10,000 px a frame meets it exactly when
 * {@link Sweep#timeOfImpact(Shape, float, float, Shape)} says, at the same t, and ends on the
 * near side, overlapping it nowhere, whether it touches or slides.
 */
class WorldTunnellingTest {

    /** A small mover of each kind, around (0, 0). */
    static Shape mover(String kind) {
        return switch (kind) {
            case "Rect" -> new Rect(-3, -2, 6, 4);
            case "Circle" -> new Circle(0, 0, 2.5f);
            case "Segment" -> new Segment(-2, -3, 2, 3);
            case "Polygon" -> Polygon.of(-3, -2, 3, -1, 0, 3);
            case "Ellipse" -> new Ellipse(0, 0, 3, 1.5f, 0.4f);
            case "Capsule" -> new Capsule(-2, 0, 2, 1, 1.5f);
            default -> throw new IllegalArgumentException(kind);
        };
    }

    /** A thin wall of each kind, one pixel or so across, along x = 0. */
    static Shape wall(String kind) {
        return switch (kind) {
            case "Rect" -> new Rect(0, -300, 1, 600);
            case "Circle" -> new Circle(0, 0, 1);
            case "Segment" -> new Segment(0, -300, 0.5f, 300);
            case "Polygon" -> Polygon.of(0, -300, 1, -300, 0.5f, 300);
            case "Ellipse" -> new Ellipse(0, 0, 0.75f, 300);
            case "Capsule" -> new Capsule(0, -300, 0, 300, 0.5f);
            default -> throw new IllegalArgumentException(kind);
        };
    }

    static final List<String> KINDS = List.of("Rect", "Circle", "Segment", "Polygon", "Ellipse", "Capsule");

    @TestFactory
    List<DynamicTest> everyPairOfKinds_bothRoles_upTo10000PxAFrame() {
        return KINDS.stream().flatMap(m -> KINDS.stream().map(o -> DynamicTest.dynamicTest(m + " into " + o,
                () -> throwAt(m, o)))).toList();
    }

    private static void throwAt(String moverKind, String wallKind) {
        SplittableRandom rnd = new SplittableRandom(moverKind.hashCode() * 31L + wallKind.hashCode());
        int met = 0;
        for (int i = 0; i < 400; i++) {
            World w = new World();
            Body wall = w.add(wall(wallKind));
            float speed = (float) Math.pow(10, 1 + 3 * rnd.nextDouble());  // 10 to 10,000 px a frame
            double dir = (rnd.nextDouble() - 0.5) * 2.4;  // mostly across the wall
            float dx = (float) (speed * Math.cos(dir)), dy = (float) (speed * Math.sin(dir));
            float side = rnd.nextBoolean() ? 1 : -1;
            dx *= side;
            float sx = -side * (5 + (float) rnd.nextDouble() * Math.abs(dx) * 0.9f);
            // Aimed to cross x = 0 near y = 0, give or take a few pixels.
            float sy = (float) (-dy * (-sx / dx) + rnd.nextDouble() * 16 - 8);
            Body b = w.add(mover(moverKind), sx, sy, (float) rnd.nextDouble() * 6);
            Shape start = b.shape();
            if (start.overlaps(wall.shape())) {
                continue;
            }
            Hit pair = Sweep.timeOfImpact(start, dx, dy, wall.shape());
            Reaction reaction = rnd.nextBoolean() ? Reaction.TOUCH : Reaction.SLIDE;
            List<Collision> got = w.move(b, dx, dy, (m, o) -> reaction);
            String what = moverKind + " at " + start + " by (" + dx + ", " + dy + ") into " + wall.shape() + ", " + reaction;
            assertFalse(b.shape().overlaps(wall.shape()), what + ": ended inside, at " + b.shape());
            if (pair == null) {
                assertTrue(got.isEmpty(), what + ": met " + got);
                assertEquals(start.translated(dx, dy), b.shape(), what);
                continue;
            }
            met++;
            assertTrue(!got.isEmpty(), what + ": the pair sweep meets it at " + pair);
            Collision first = got.get(0);
            assertEquals(wall, first.other());
            assertEquals(pair.t(), first.hit().t(), what);
            assertEquals(pair.side(), first.hit().side(), what);
            // Never through the wall: along each leg of the path (start, each stop, the end),
            // the mover held a hundredth of a pixel off the surface it last met overlaps nothing.
            float px = sx, py = sy, nx = first.nx(), ny = first.ny();
            for (int k = 0; k <= got.size(); k++) {
                float qx = k < got.size() ? got.get(k).x() : b.pivotX(), qy = k < got.size() ? got.get(k).y() : b.pivotY();
                if (k > 0) {
                    nx = got.get(k - 1).nx();
                    ny = got.get(k - 1).ny();
                }
                for (int j = 0; j <= 50; j++) {
                    float fx = px + (qx - px) * j / 50f - sx - 0.01f * nx, fy = py + (qy - py) * j / 50f - sy - 0.01f * ny;
                    assertFalse(start.translated(fx, fy).overlaps(wall.shape()), what + ": went through on leg " + k
                            + " to " + b.shape() + ", " + got);
                }
                px = qx;
                py = qy;
            }
            if (reaction == Reaction.TOUCH) {
                assertEquals(start.translated(pair.t() * dx, pair.t() * dy), b.shape(), what);
            }
        }
        assertTrue(met > 100, "only " + met + " throws met the wall");
    }
}
