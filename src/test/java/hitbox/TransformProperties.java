package hitbox;

import hitbox.internal.Extents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/**
 * {@link Shape#transformed} on generated shapes and transforms, against
 * {@link TransformTest#oracle}'s inverse check: a point is in the image exactly when its
 * inverse image is in the shape, away from the outline.
 */
class TransformProperties {

    @Property(tries = 150)
    void image_agreesWithTheInverseOracle(@ForAll("shapes") Shape s, @ForAll("transforms") Transform t) {
        Shape image;
        try {
            image = s.transformed(t);
        } catch (IllegalArgumentException e) {
            // a capsule stretched one way: its two radii round apart
            assertTrue(s instanceof Capsule && e.getMessage().contains("capsule"), s + " under " + t + ": " + e.getMessage());
            return;
        }
        TransformTest.oracle(s, t, image, 30);
    }

    @Property(tries = 200)
    void rotated_keepsAreaAndDistanceFromThePivot(@ForAll("shapes") Shape s, @ForAll("angles") float angle,
                                                  @ForAll("coordinates") float px, @ForAll("coordinates") float py) {
        Shape turned = s.rotated(angle, px, py);
        if (s instanceof Polygon p) {
            assertEquals(p.area(), ((Polygon) turned).area(), 1e-3 * p.area() + 1e-2);
        }
        // the box's centre stays as far from the pivot (a box turns with its shape's centre
        // only for centred kinds: circles, ellipses, segments, capsules)
        if (s instanceof Circle c) {
            Circle d = (Circle) turned;
            assertEquals(c.r(), d.r());
            assertEquals(Math.hypot(c.x() - px, c.y() - py), Math.hypot(d.x() - px, d.y() - py), 1e-3);
        }
        // turning back takes every shape home, to within rounding
        Shape back = turned.rotated(-angle, px, py);
        assertEquals(Extents.minX(s), Extents.minX(back), 1e-2);
        assertEquals(Extents.maxY(s), Extents.maxY(back), 1e-2);
    }

    @Provide
    Arbitrary<Float> angles() {
        return Arbitraries.floats().between(-7, 7);
    }

    @Provide
    Arbitrary<Float> coordinates() {
        return Arbitraries.floats().between(-500, 500);
    }

    @Provide
    Arbitrary<Shape> shapes() {
        Arbitrary<Float> c = Arbitraries.floats().between(-200, 200);
        Arbitrary<Float> r = Arbitraries.floats().between(2, 60);
        Arbitrary<Float> a = Arbitraries.floats().between(-3.2f, 3.2f);
        return Arbitraries.oneOf(
                Combinators.combine(c, c, r).as(Circle::new),
                Combinators.combine(c, c, r, r).as(Rect::new),
                Combinators.combine(c, c, c, c).as(Segment::new),
                Combinators.combine(c, c, r, r, a).as(Ellipse::new),
                Combinators.combine(c, c, c, c, r).as(Capsule::new),
                Combinators.combine(c, c, r, Arbitraries.integers().between(3, 9), a).as(Polygon::regular),
                Combinators.combine(c, c, r).as((x, y, k) -> TransformTest.comb(4).transformed(
                        Transform.scaling(k / 40, k / 40).then(Transform.translation(x, y)))));
    }

    @Provide
    Arbitrary<Transform> transforms() {
        Arbitrary<Float> angle = Arbitraries.floats().between(-7, 7);
        Arbitrary<Float> scale = Arbitraries.floats().between(0.3f, 3).flatMap(v ->
                Arbitraries.of(v, -v));
        Arbitrary<Float> shear = Arbitraries.floats().between(-1, 1);
        Arbitrary<Float> move = Arbitraries.floats().between(-1000, 1000);
        return Combinators.combine(angle, scale, scale, shear, move, move).as((ang, sx, sy, sh, dx, dy) ->
                Transform.of(1, sh, 0, 0, 1, 0).then(Transform.scaling(sx, sy)).then(Transform.rotation(ang))
                        .then(Transform.translation(dx, dy)));
    }
}
