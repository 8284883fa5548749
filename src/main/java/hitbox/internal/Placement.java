package hitbox.internal;

import hitbox.*;

/**
 * A body's shape where it stands, kept as numbers in storage the body owns, so that a world's
 * pair tests read a moved or turned body without a new {@link Shape} each frame (Box2D tests
 * its shapes by value in the same way). The numbers are exactly those of the shape
 * {@link Poses#place} would make for the same pose: the same double arithmetic, rounded to
 * float once. {@link PlacedOverlaps} answers a pair of them.
 *
 * <p>Only the common cases are kept as numbers: a circle, a rectangle, a segment, a capsule,
 * an ellipse with both radii above 0, and a convex polygon (a turned rectangle is one), at
 * angle 0 or at an angle whose cosine and sine are both non-zero. Everything else (a concave
 * polygon, a quarter or half turn, a flat shape turned, a coordinate beyond the float range, an
 * outline that rounding bent) is left to the shape itself: {@link #place} answers false, and
 * the caller makes the shape, which also throws where the pose has no float shape.
 *
 * <p>Mutable and owned by one body; never handed out.
 */
public final class Placement {
    /** The kind the numbers are, or null when only the shape can answer. */
    ShapeKind kind;
    /**
     * Circle: x, y, r. Rectangle: x, y, w, h. Segment: x1, y1, x2, y2. Capsule: x1, y1, x2,
     * y2, r. Ellipse: x, y, rx, ry, angle.
     */
    float a, b, c, d, e;
    /** A convex polygon's vertices: the body's own buffer, or a placed shape's own array. */
    float[] xy;
    /** The convex polygon's winding (never 0 when the kind is a polygon). */
    int winding;
    /**
     * The buffer a turned or moved polygon is placed into: made with the placement, at the
     * home's size (a rectangle's four corners), so placing never allocates.
     */
    private final float[] own;

    /**
     * Storage for shapes taken as they are ({@link #of}) and never placed: a query's own
     * shape, say.
     */
    public Placement() {
        own = null;
    }

    /**
     * Storage for the body whose home shape this is.
     *
     * @param home the shape in the body's own frame
     */
    public Placement(Shape home) {
        own = switch (ShapeKind.of(home)) {
            case RECT -> new float[8];
            case POLYGON -> new float[HiddenParts.raw((Polygon) home).length];
            case ELLIPSE, CAPSULE, CIRCLE, SEGMENT -> null;
        };
    }

    /** @return the kind the numbers are, or null if the body's shape must answer */
    public ShapeKind kind() {
        return kind;
    }

    /** @return the first number (x, or x1), as the kind reads it (see the fields) */
    public float a() {
        return a;
    }

    /** @return the second number (y, or y1) */
    public float b() {
        return b;
    }

    /** @return the third number (a circle's r, a rectangle's w, x2) */
    public float c() {
        return c;
    }

    /** @return the fourth number (a rectangle's h, y2) */
    public float d() {
        return d;
    }

    /**
     * Sets a rectangle's numbers: where a walk left a box, which then has no shape until one
     * is asked for ({@link #shape()}).
     */
    public void rect(float x, float y, float w, float h) {
        set(ShapeKind.RECT, x, y, w, h, 0);
    }

    /** Sets a circle's numbers: where a walk left it, with no shape made. */
    public void circle(float x, float y, float r) {
        set(ShapeKind.CIRCLE, x, y, r, 0, 0);
    }

    /**
     * A new shape of these numbers, equal to the one they were taken from or placed as.
     *
     * @throws IllegalStateException for a polygon (its shape is kept, not remade) or no kind
     */
    public Shape shape() {
        if (kind == null) {
            throw new IllegalStateException("no numbers to remake a shape from");
        }
        return switch (kind) {
            case RECT -> new Rect(a, b, c, d);
            case CIRCLE -> new Circle(a, b, c);
            case SEGMENT -> new Segment(a, b, c, d);
            case CAPSULE -> new Capsule(a, b, c, d, e);
            case ELLIPSE -> new Ellipse(a, b, c, d, e);
            case POLYGON -> throw new IllegalStateException("a placed polygon's shape is kept, not remade");
        };
    }

    /**
     * Takes a shape's numbers as they are (a polygon's array is read, not copied).
     *
     * @return false if only the shape itself can answer for it (see the class doc)
     */
    public boolean of(Shape s) {
        kind = null;
        switch (ShapeKind.of(s)) {
            case CIRCLE -> {
                Circle k = (Circle) s;
                set(ShapeKind.CIRCLE, k.x(), k.y(), k.r(), 0, 0);
            }
            case RECT -> {
                Rect r = (Rect) s;
                set(ShapeKind.RECT, r.x(), r.y(), r.w(), r.h(), 0);
            }
            case SEGMENT -> {
                Segment g = (Segment) s;
                set(ShapeKind.SEGMENT, g.x1(), g.y1(), g.x2(), g.y2(), 0);
            }
            case ELLIPSE -> {
                Ellipse l = (Ellipse) s;
                if (l.rx() > 0 && l.ry() > 0) {
                    set(ShapeKind.ELLIPSE, l.x(), l.y(), l.rx(), l.ry(), l.angle());
                }
            }
            case POLYGON -> {
                Polygon p = (Polygon) s;
                int w = HiddenParts.convexWinding(p);
                if (w != 0) {
                    xy = HiddenParts.raw(p);
                    winding = w;
                    kind = ShapeKind.POLYGON;
                }
            }
            case CAPSULE -> {
                Capsule k = (Capsule) s;
                set(ShapeKind.CAPSULE, k.x1(), k.y1(), k.x2(), k.y2(), k.r());
            }
        }
        return kind != null;
    }

    /**
     * Places a body's home shape by its pose, as {@link Poses#place} would (same arguments),
     * into these numbers.
     *
     * @return false if only the placed shape itself can answer (see the class doc): nothing is
     *         kept then, and the caller makes the shape
     */
    public boolean place(Shape home, double px, double py, double tx, double ty, float angle, double cos, double sin) {
        kind = null;
        if (angle == 0) {
            return translate(home, tx, ty);
        }
        if (cos == 0 || sin == 0) {
            return false;  // a quarter or half turn keeps the axes: Transforms' own cases
        }
        // Poses.place's matrix, p -> R (p - pivot) + pivot + t, always a similarity here
        // (its columns are (cos, sin) and (-sin, cos), so Transforms takes the same branches).
        double m02 = px + tx - (cos * px - sin * py), m12 = py + ty - (sin * px + cos * py);
        switch (ShapeKind.of(home)) {
            case CIRCLE -> {
                Circle k = (Circle) home;
                float x = (float) (cos * k.x() + -sin * k.y() + m02), y = (float) (sin * k.x() + cos * k.y() + m12);
                set(ShapeKind.CIRCLE, x, y, (float) (k.r() * Math.hypot(cos, sin)), 0, 0);
            }
            case SEGMENT -> {
                Segment g = (Segment) home;
                set(ShapeKind.SEGMENT, (float) (cos * g.x1() + -sin * g.y1() + m02), (float) (sin * g.x1() + cos * g.y1() + m12),
                        (float) (cos * g.x2() + -sin * g.y2() + m02), (float) (sin * g.x2() + cos * g.y2() + m12), 0);
            }
            case ELLIPSE -> {
                Ellipse l = (Ellipse) home;
                if (!(l.rx() > 0 && l.ry() > 0)) {
                    return false;  // a flat ellipse: no ellipse here
                }
                // Transforms.ellipse's similarity: the radii scaled, the turn's angle added
                double k = Math.hypot(cos, sin);
                set(ShapeKind.ELLIPSE, (float) (cos * l.x() + -sin * l.y() + m02), (float) (sin * l.x() + cos * l.y() + m12),
                        (float) (l.rx() * k), (float) (l.ry() * k), (float) (l.angle() + Math.atan2(sin, cos)));
            }
            case RECT -> {
                Rect r = (Rect) home;
                if (r.w() == 0 || r.h() == 0) {
                    return false;
                }
                // Transforms.polygonOf's corners: top-left, top-right, bottom-right, bottom-left
                double x0 = r.x(), y0 = r.y(), x1 = (double) r.x() + r.w(), y1 = (double) r.y() + r.h();
                float[] out = buffer(8);
                for (int i = 0; i < 4; i++) {
                    double x = i == 1 || i == 2 ? x1 : x0, y = i >= 2 ? y1 : y0;
                    out[2 * i] = (float) (cos * x + -sin * y + m02);
                    out[2 * i + 1] = (float) (sin * x + cos * y + m12);
                }
                return convex(out);
            }
            case POLYGON -> {
                Polygon p = (Polygon) home;
                if (HiddenParts.convexWinding(p) == 0) {
                    return false;
                }
                float[] in = HiddenParts.raw(p), out = buffer(in.length);
                for (int i = 0; i < in.length; i += 2) {
                    out[i] = (float) (cos * in[i] + -sin * in[i + 1] + m02);
                    out[i + 1] = (float) (sin * in[i] + cos * in[i + 1] + m12);
                }
                return convex(out);
            }
            case CAPSULE -> {
                // Transforms.capsule's similarity: the ends turned, the radius scaled (0 stays 0)
                Capsule k = (Capsule) home;
                set(ShapeKind.CAPSULE, (float) (cos * k.x1() + -sin * k.y1() + m02), (float) (sin * k.x1() + cos * k.y1() + m12),
                        (float) (cos * k.x2() + -sin * k.y2() + m02), (float) (sin * k.x2() + cos * k.y2() + m12),
                        k.r() == 0 ? 0 : (float) (k.r() * Math.hypot(cos, sin)));
            }
        }
        return finite();
    }

    /** Poses.place at angle 0: each coordinate moved by the translation, rounded once. */
    private boolean translate(Shape home, double tx, double ty) {
        switch (ShapeKind.of(home)) {
            case CIRCLE -> {
                Circle k = (Circle) home;
                set(ShapeKind.CIRCLE, (float) (k.x() + tx), (float) (k.y() + ty), k.r(), 0, 0);
            }
            case RECT -> {
                Rect r = (Rect) home;
                set(ShapeKind.RECT, (float) (r.x() + tx), (float) (r.y() + ty), r.w(), r.h(), 0);
            }
            case SEGMENT -> {
                Segment g = (Segment) home;
                set(ShapeKind.SEGMENT, (float) (g.x1() + tx), (float) (g.y1() + ty), (float) (g.x2() + tx), (float) (g.y2() + ty), 0);
            }
            case ELLIPSE -> {
                Ellipse l = (Ellipse) home;
                if (!(l.rx() > 0 && l.ry() > 0)) {
                    return false;
                }
                set(ShapeKind.ELLIPSE, (float) (l.x() + tx), (float) (l.y() + ty), l.rx(), l.ry(), l.angle());
            }
            case POLYGON -> {
                Polygon p = (Polygon) home;
                if (HiddenParts.convexWinding(p) == 0) {
                    return false;
                }
                // Poses.place: Polygon.translated adds a translation that is a float in float,
                // Transforms any other in double (a double sum rounded to float could round
                // twice, so the two are kept apart).
                float[] in = HiddenParts.raw(p), out = buffer(in.length);
                float fx = (float) tx, fy = (float) ty;
                boolean inFloat = fx == tx && fy == ty;
                for (int i = 0; i < in.length; i += 2) {
                    out[i] = inFloat ? in[i] + fx : (float) (in[i] + tx);
                    out[i + 1] = inFloat ? in[i + 1] + fy : (float) (in[i + 1] + ty);
                }
                return convex(out);
            }
            case CAPSULE -> {
                Capsule k = (Capsule) home;
                set(ShapeKind.CAPSULE, (float) (k.x1() + tx), (float) (k.y1() + ty), (float) (k.x2() + tx), (float) (k.y2() + ty), k.r());
            }
        }
        return finite();
    }

    private void set(ShapeKind k, float a, float b, float c, float d, float e) {
        kind = k;
        this.a = a;
        this.b = b;
        this.c = c;
        this.d = d;
        this.e = e;
    }

    /** Every number within the float range (else the shape must be made, and it throws). */
    private boolean finite() {
        if (Float.isFinite(a) && Float.isFinite(b) && Float.isFinite(c) && Float.isFinite(d) && Float.isFinite(e)) {
            return true;
        }
        kind = null;
        return false;
    }

    private float[] buffer(int length) {
        if (own == null || own.length != length) {
            throw new IllegalArgumentException("this placement is for a home shape of another kind or size");
        }
        return own;
    }

    /**
     * The placed outline kept if it is convex with no vertex repeated, as {@code Polygon}'s
     * image and convexImage keep it (else the shape is made, checked in full, and refused if
     * rounding bent it).
     */
    private boolean convex(float[] out) {
        for (float v : out) {
            if (!Float.isFinite(v)) {
                return false;
            }
        }
        int w = Polygons.convexWinding(out);
        if (w == 0 || Polygons.repeatsNeighbour(out)) {
            return false;
        }
        xy = out;
        winding = w;
        kind = ShapeKind.POLYGON;
        return true;
    }
}
