package hitbox.internal;

import hitbox.*;

/**
 * The maths of {@link Shape#transformed}: each kind's image under an affine transform, and
 * which kind that image is. Every point is transformed in double and rounded once to float.
 *
 * <ul>
 *   <li>Circle: a circle when the image's two radii round to the same float (every
 *       similarity: turn, mirror, uniform scale, move), else a turned {@link Ellipse}.</li>
 *   <li>Rect: a rect when the transform keeps the axes ({@link Affine#keepsAxes}: an axis
 *       scale, a mirror, a quarter turn, a move), else a {@link Polygon} of its four
 *       corners.</li>
 *   <li>Segment: a segment. Polygon: a polygon. Ellipse: an ellipse (radii and angle from the
 *       2x2 singular value decomposition).</li>
 *   <li>Capsule: a capsule when the image of its radius is one float (a similarity), else
 *       refused: a capsule stretched one way is no capsule.</li>
 * </ul>
 */
public final class Transforms {
    private Transforms() {
    }

    /**
     * The relative rounding allowed in the least stretch of a transform's linear part (the
     * smaller singular value, found in double): the image check takes the stretch as at least
     * this much smaller, so rounding never makes a valid polygon's image look collapsed.
     */
    private static final double STRETCH_ROUNDING = 1e-12;

    /**
     * The shape's image, by its kind: for a caller that holds a {@link Shape} and an
     * {@link Affine} (each kind's own {@code transformed} calls its case directly).
     *
     * @param s the shape, not null
     * @param a the transform
     * @return the image, never null
     * @throws IllegalArgumentException as the kind's {@code transformed} documents
     */
    public static Shape apply(Shape s, Affine a) {
        return switch (ShapeKind.of(s)) {
            case ELLIPSE -> ellipse((Ellipse) s, a);
            case CAPSULE -> capsule((Capsule) s, a);
            case CIRCLE -> circle((Circle) s, a);
            case RECT -> rect((Rect) s, a);
            case SEGMENT -> segment((Segment) s, a);
            case POLYGON -> polygon((Polygon) s, a);
        };
    }

    /**
     * The shape's image under a transform, by its kind: {@link #apply(Shape, Affine)} with the
     * transform's entries.
     *
     * @param s the shape, not null
     * @param t the transform, not null
     * @return the image, never null
     * @throws IllegalArgumentException as the kind's {@code transformed} documents, or if
     *                                  {@code t} is null
     */
    public static Shape apply(Shape s, Transform t) {
        return apply(s, affine(t));
    }

    /**
     * @param t the transform, not null
     * @return its entries in double, as it keeps them
     * @throws IllegalArgumentException if {@code t} is null
     */
    public static Affine affine(Transform t) {
        return HiddenParts.affine(Check.notNull("t", t));
    }

    /** A transformed coordinate rounded to float, refused if it leaves the float range. */
    private static float coordinate(String name, double v) {
        float f = (float) v;
        if (!Float.isFinite(f)) {
            throw new IllegalArgumentException("the transform takes " + name + " to " + v
                    + ", beyond the float range");
        }
        return f;
    }

    /**
     * {@link #coordinate(String, double)} for the {@code index}th vertex, its name (prefix,
     * index, suffix) built only when refused: a turned body's shape is made every frame, and
     * a name built up front would be most of its cost.
     */
    private static float coordinate(String prefix, int index, String suffix, double v) {
        float f = (float) v;
        if (!Float.isFinite(f)) {
            return coordinate(prefix + index + suffix, v);
        }
        return f;
    }

    /** A transformed size rounded to float, refused if it leaves the float range. */
    private static float size(String name, double v) {
        return coordinate(name, v);
    }

    // ---- the singular values of a 2x2 matrix ------------------------------------------

    /**
     * The image of the unit circle under the linear map [[a, b], [c, d]]: an ellipse with
     * radii {@code out[0] >= out[1] >= 0}, the first along the angle {@code out[2]} (radians,
     * clockwise on screen). That is the 2x2 singular value decomposition
     * {@code M = R(phi) diag(s1, s2) R(theta)}, in closed form (J. Blinn, "Consider the
     * lowly 2x2 matrix", 1996): with {@code E = (a + d) / 2, F = (a - d) / 2,
     * G = (c + b) / 2, H = (c - b) / 2}, {@code s1 = hypot(E, H) + hypot(F, G)},
     * {@code phi = (atan2(G, F) + atan2(H, E)) / 2}; the second radius is
     * {@code |det| / s1}, which does not cancel for a thin image.
     */
    static double[] unitCircleImage(double a, double b, double c, double d) {
        double s1 = largestStretch(a, b, c, d);
        if (s1 == 0) {
            return new double[] {0, 0, 0};
        }
        double e = (a + d) / 2, f = (a - d) / 2, g = (c + b) / 2, h = (c - b) / 2;
        double phi = (Math.atan2(g, f) + Math.atan2(h, e)) / 2;
        return new double[] {s1, secondStretch(s1, a, b, c, d), phi};
    }

    /**
     * The smaller radius of {@link #unitCircleImage}, the same number, without its angle: a
     * turned body's polygon is placed every frame, and the angle's two arc tangents were a
     * third of that.
     */
    static double leastStretch(double a, double b, double c, double d) {
        double s1 = largestStretch(a, b, c, d);
        return s1 == 0 ? 0 : secondStretch(s1, a, b, c, d);
    }

    /** {@link #unitCircleImage}'s first radius, {@code s1 = hypot(E, H) + hypot(F, G)}. */
    private static double largestStretch(double a, double b, double c, double d) {
        double e = (a + d) / 2, f = (a - d) / 2, g = (c + b) / 2, h = (c - b) / 2;
        return Math.hypot(e, h) + Math.hypot(f, g);
    }

    /** {@link #unitCircleImage}'s second radius from its first (not 0): {@code |det| / s1}, at most s1. */
    private static double secondStretch(double s1, double a, double b, double c, double d) {
        return Math.min(s1, Math.abs(a * d - b * c) / s1);
    }

    // ---- the kinds --------------------------------------------------------------------

    /**
     * A circle's image: its centre transformed; a circle whose radius is the old one times the
     * scale when both radii of the image round to the same float, else a turned ellipse (an
     * aligned one when the transform keeps the axes), flat when the transform is singular.
     */
    public static Shape circle(Circle c, Affine a) {
        float x = coordinate("the centre's x", a.x(c.x(), c.y()));
        float y = coordinate("the centre's y", a.y(c.x(), c.y()));
        double r = c.r();
        if (a.isSimilarity()) {
            return new Circle(x, y, size("the radius", r * Math.hypot(a.m00(), a.m10())));
        }
        if (a.m01() == 0 && a.m10() == 0) {
            return roundOrEllipse(x, y, r * Math.abs(a.m00()), r * Math.abs(a.m11()), 0);
        }
        if (a.m00() == 0 && a.m11() == 0) {
            return roundOrEllipse(x, y, r * Math.abs(a.m01()), r * Math.abs(a.m10()), 0);
        }
        double[] svd = unitCircleImage(a.m00(), a.m01(), a.m10(), a.m11());
        return roundOrEllipse(x, y, r * svd[0], r * svd[1], svd[2]);
    }

    private static Shape roundOrEllipse(float x, float y, double rx, double ry, double angle) {
        float fx = size("the ellipse's radius rx", rx);
        float fy = size("the ellipse's radius ry", ry);
        if (fx == fy) {
            return new Circle(x, y, fx);
        }
        return new Ellipse(x, y, fx, fy, (float) angle);
    }

    /**
     * A rectangle's image: a rectangle when the transform keeps the axes (its two corners
     * transformed, each edge rounded to float), else the polygon of its four corners, refused
     * when that has no area (a singular transform, or a rectangle of width or height 0).
     */
    public static Shape rect(Rect r, Affine a) {
        double x0 = r.x(), y0 = r.y(), x1 = (double) r.x() + r.w(), y1 = (double) r.y() + r.h();
        if (a.keepsAxes()) {
            double ax = a.x(x0, y0), bx = a.x(x1, y1), ay = a.y(x0, y0), by = a.y(x1, y1);
            float left = coordinate("the left edge", Math.min(ax, bx));
            float top = coordinate("the top edge", Math.min(ay, by));
            float right = coordinate("the right edge", Math.max(ax, bx));
            float bottom = coordinate("the bottom edge", Math.max(ay, by));
            return new Rect(left, top, size("the width", (double) right - left), size("the height", (double) bottom - top));
        }
        if (r.w() == 0 || r.h() == 0) {
            throw new IllegalArgumentException("a rectangle of width or height 0 (" + r + ") turned or sheared off the"
                    + " axes is a segment without its ends, which no shape kind is: transform a Segment instead");
        }
        if (a.det() == 0) {
            throw singular("rectangle", a);
        }
        return polygonOf(x0, y0, x1, y1, a, r);
    }

    /** A segment's image: its two ends transformed. */
    public static Segment segment(Segment s, Affine a) {
        return new Segment(coordinate("x1", a.x(s.x1(), s.y1())), coordinate("y1", a.y(s.x1(), s.y1())),
                coordinate("x2", a.x(s.x2(), s.y2())), coordinate("y2", a.y(s.x2(), s.y2())));
    }

    /**
     * A polygon's image: every vertex transformed (a mirror reverses the winding, which either
     * winding allows), checked only as far as rounding could have changed it (see
     * {@code Polygon.translated}); refused when the transform is singular.
     */
    public static Polygon polygon(Polygon p, Affine a) {
        if (a.det() == 0) {
            throw singular("polygon", a);
        }
        float[] xy = HiddenParts.raw(p);
        float[] out = new float[xy.length];
        double err = 0;
        double big = 0;
        for (int i = 0; i < xy.length; i += 2) {
            double x = a.x(xy[i], xy[i + 1]);
            double y = a.y(xy[i], xy[i + 1]);
            out[i] = coordinate("x", i / 2, "", x);
            out[i + 1] = coordinate("y", i / 2, "", y);
            // how far the double sum can be off: a few units of 2^-53 of its terms
            err = Math.max(err, Math.abs(a.m00() * xy[i]) + Math.abs(a.m01() * xy[i + 1]) + Math.abs(a.m02())
                    + Math.abs(a.m10() * xy[i]) + Math.abs(a.m11() * xy[i + 1]) + Math.abs(a.m12()));
            big = Math.max(big, Math.max(Math.abs(out[i]), Math.abs(out[i + 1])));
        }
        // each vertex moves from its exact image by at most half a float step per coordinate
        // (the rounding to float) plus the double sum's error
        double delta = Math.ulp((float) big) + 4 * Math.ulp(err);
        double least = leastStretch(a.m00(), a.m01(), a.m10(), a.m11());
        return HiddenParts.image(p, out, least * (1 - STRETCH_ROUNDING), delta, () -> "transforming by " + a);
    }

    /**
     * An ellipse's image: an ellipse, its radii and angle the singular values and direction of
     * the transform times the ellipse's own axes, exact (the radii times the factors, the
     * angle 0) when the transform keeps the axes of an aligned ellipse, the radii kept and the
     * angles added when it is a turn or a mirror. Flat when the transform is singular.
     */
    public static Ellipse ellipse(Ellipse e, Affine a) {
        float x = coordinate("the centre's x", a.x(e.x(), e.y()));
        float y = coordinate("the centre's y", a.y(e.x(), e.y()));
        double rx = e.rx(), ry = e.ry();
        boolean aligned = e.angle() == 0 || rx == ry;
        if (aligned && a.m01() == 0 && a.m10() == 0) {
            return new Ellipse(x, y, size("the radius rx", rx * Math.abs(a.m00())), size("the radius ry", ry * Math.abs(a.m11())), 0);
        }
        if (aligned && a.m00() == 0 && a.m11() == 0) {
            // x goes to y and y to x: the horizontal radius comes from ry
            return new Ellipse(x, y, size("the radius rx", ry * Math.abs(a.m01())), size("the radius ry", rx * Math.abs(a.m10())), 0);
        }
        if (a.isSimilarity()) {
            double k = Math.hypot(a.m00(), a.m10());
            double turn = Math.atan2(a.m10(), a.m00());
            double angle = a.det() >= 0 ? e.angle() + turn : turn - e.angle();
            return new Ellipse(x, y, size("the radius rx", rx * k), size("the radius ry", ry * k), (float) angle);
        }
        // M = L R(angle) diag(rx, ry): the image of the unit circle under M
        double cos = StrictMath.cos(e.angle()), sin = StrictMath.sin(e.angle());
        double b00 = cos * rx, b01 = -sin * ry, b10 = sin * rx, b11 = cos * ry;
        double m00 = a.m00() * b00 + a.m01() * b10, m01 = a.m00() * b01 + a.m01() * b11;
        double m10 = a.m10() * b00 + a.m11() * b10, m11 = a.m10() * b01 + a.m11() * b11;
        double[] svd = unitCircleImage(m00, m01, m10, m11);
        return new Ellipse(x, y, size("the radius rx", svd[0]), size("the radius ry", svd[1]), (float) svd[2]);
    }

    /**
     * A capsule's image: its segment's ends transformed and its radius scaled, when the
     * transform scales every direction by the same float (a similarity), or the radius is 0;
     * otherwise refused, as a capsule stretched one way has elliptical ends and is no capsule.
     */
    public static Capsule capsule(Capsule c, Affine a) {
        double r = c.r();
        float radius;
        if (r == 0) {
            radius = 0;
        } else if (a.isSimilarity()) {
            radius = size("the radius", r * Math.hypot(a.m00(), a.m10()));
        } else {
            double[] svd = unitCircleImage(a.m00(), a.m01(), a.m10(), a.m11());
            float big = size("the radius", r * svd[0]);
            float small = size("the radius", r * svd[1]);
            if (big != small) {
                throw new IllegalArgumentException("a capsule under a non-uniform scale or a shear has no exact"
                        + " result: its round ends would become elliptical (the transform scales its radius " + c.r()
                        + " to between " + small + " and " + big + "). Scale it the same both ways,"
                        + " or build the shape you need from its transformed segment() and radius");
            }
            radius = big;
        }
        return new Capsule(coordinate("x1", a.x(c.x1(), c.y1())), coordinate("y1", a.y(c.x1(), c.y1())),
                coordinate("x2", a.x(c.x2(), c.y2())), coordinate("y2", a.y(c.x2(), c.y2())), radius);
    }

    /**
     * The polygon of the rectangle from (x0, y0) to (x1, y1) (its edges in double)
     * transformed, checked as Polygon.of checks.
     */
    private static Polygon polygonOf(double x0, double y0, double x1, double y1, Affine a, Rect rect) {
        // The corners top-left, top-right, bottom-right, bottom-left, each transformed in
        // double and rounded once; the array is the polygon's own (a turned body's rectangle
        // is made every frame: no corner array and no copy besides).
        float[] xy = new float[8];
        for (int i = 0; i < 4; i++) {
            double x = i == 1 || i == 2 ? x1 : x0, y = i >= 2 ? y1 : y0;
            xy[2 * i] = coordinate("corner ", i, "'s x", a.x(x, y));
            xy[2 * i + 1] = coordinate("corner ", i, "'s y", a.y(x, y));
        }
        try {
            // A rectangle is convex: its image is checked in full only if rounding bent it.
            return HiddenParts.convexImage(xy);
        } catch (IllegalArgumentException ex) {
            throw new IllegalArgumentException("the corners of the rectangle " + rect + " transformed round to an outline a"
                    + " polygon cannot have: " + ex.getMessage(), ex);
        }
    }

    private static IllegalArgumentException singular(String kind, Affine a) {
        return new IllegalArgumentException("the transform is singular (determinant 0: a scale by 0, or a"
                + " squash onto a line), so the " + kind + " would have no area, which a " + kind
                + " must have; a transform with a determinant that is not 0 is needed (entries " + a + ")");
    }
}
