package hitbox.internal;

import hitbox.*;

/**
 * A body's shape kept in its own frame and placed by a pose, behind {@link Body}: the shape as
 * it was added (its "home"), turned by an angle about a pivot and moved by a translation. A
 * point p of the home shape stands at {@code pivot + R(angle) (p - pivot) + t}, worked out in
 * double and rounded once to float; a turned shape is {@link Shape#transformed}'s image under
 * that matrix (a turned rectangle a polygon, or a rect for a quarter turn). At angle 0 this is a plain translation of each
 * coordinate, {@code (float) (p + t)}, so a body that only moves keeps its kind and its exact
 * size (a rectangle stays the rectangle {@code Sweep.move} would give).
 *
 * <p>The extents of the turned home shape about its pivot are worked out without making a
 * shape (no allocation, time linear in a polygon's vertices), so a teleport can update the
 * broad phase's box at once and leave the shape to be made when asked.
 */
public final class Poses {
    private Poses() {
    }

    /**
     * How much a turned ellipse's box is widened, relative to its larger radius: the box's
     * half-widths come from a cosine, a sine and a square root, each off by about 2^-53 of
     * the radius, and the placed ellipse's float angle is off the exact one by half a float
     * step (about 1.2e-7 radians for an angle near pi), which moves its extent by at most that
     * times the radius; the box is widened past both and never cuts the ellipse.
     */
    private static final double ELLIPSE_BOX_WIDEN = 1e-6;

    /**
     * The thread's matrix for {@link #place}: set for each pose and read only during the call
     * (Transforms keeps no reference to it), so placing a turned body each frame makes its
     * shape and no matrix.
     */
    private static final ThreadLocal<Affine> MATRIX = ThreadLocal.withInitial(() -> new Affine(1, 0, 0, 0, 1, 0));

    /**
     * The extents of the home shape turned by (cos, sin) about the pivot, relative to the
     * pivot: out[0..3] = min x, min y, max x, max y.
     */
    public static void extents(Shape home, double px, double py, double cos, double sin, double[] out) {
        if (sin == 0 && cos == 1) {
            out[0] = Extents.minX(home) - px;
            out[1] = Extents.minY(home) - py;
            out[2] = Extents.maxX(home) - px;
            out[3] = Extents.maxY(home) - py;
            return;
        }
        double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY;
        double grow = 0;
        switch (ShapeKind.of(home)) {
            case CIRCLE -> {
                Circle c = (Circle) home;
                double x = turnX(c.x() - px, c.y() - py, cos, sin), y = turnY(c.x() - px, c.y() - py, cos, sin);
                minX = x - c.r();
                maxX = x + c.r();
                minY = y - c.r();
                maxY = y + c.r();
            }
            case RECT -> {
                Rect r = (Rect) home;
                double x0 = r.x() - px, y0 = r.y() - py, x1 = (double) r.x() + r.w() - px, y1 = (double) r.y() + r.h() - py;
                for (int i = 0; i < 4; i++) {
                    double x = (i & 1) == 0 ? x0 : x1, y = (i & 2) == 0 ? y0 : y1;
                    double tx = turnX(x, y, cos, sin), ty = turnY(x, y, cos, sin);
                    minX = Math.min(minX, tx);
                    maxX = Math.max(maxX, tx);
                    minY = Math.min(minY, ty);
                    maxY = Math.max(maxY, ty);
                }
            }
            case SEGMENT, CAPSULE -> {
                double x1, y1, x2, y2;
                if (home instanceof Segment s) {
                    x1 = s.x1(); y1 = s.y1(); x2 = s.x2(); y2 = s.y2();
                } else {
                    Capsule c = (Capsule) home;
                    x1 = c.x1(); y1 = c.y1(); x2 = c.x2(); y2 = c.y2();
                    grow = c.r();
                }
                double ax = turnX(x1 - px, y1 - py, cos, sin), ay = turnY(x1 - px, y1 - py, cos, sin);
                double bx = turnX(x2 - px, y2 - py, cos, sin), by = turnY(x2 - px, y2 - py, cos, sin);
                minX = Math.min(ax, bx);
                maxX = Math.max(ax, bx);
                minY = Math.min(ay, by);
                maxY = Math.max(ay, by);
            }
            case ELLIPSE -> {
                Ellipse e = (Ellipse) home;
                double x = turnX(e.x() - px, e.y() - py, cos, sin), y = turnY(e.x() - px, e.y() - py, cos, sin);
                // The placed ellipse's angle is its own plus the pose's; an ellipse added
                // unturned (the usual home) has the pose's cosine and sine, no trigonometry
                // needed. Either way each half-width is off by a few units of 2^-53 of the
                // radius at most (a float radius squared neither overflows nor underflows in
                // double), far inside the widening below.
                double c = cos, s = sin;
                if (e.angle() != 0) {
                    double a = e.angle() + Math.atan2(sin, cos);
                    c = StrictMath.cos(a);
                    s = StrictMath.sin(a);
                }
                double rxc = e.rx() * c, rys = e.ry() * s, rxs = e.rx() * s, ryc = e.ry() * c;
                double hx = Math.sqrt(rxc * rxc + rys * rys), hy = Math.sqrt(rxs * rxs + ryc * ryc);
                minX = x - hx;
                maxX = x + hx;
                minY = y - hy;
                maxY = y + hy;
                grow = ELLIPSE_BOX_WIDEN * Math.max(e.rx(), e.ry());
            }
            case POLYGON -> {
                float[] xy = HiddenParts.raw((Polygon) home);
                for (int i = 0; i < xy.length; i += 2) {
                    double x = xy[i] - px, y = xy[i + 1] - py;
                    double tx = turnX(x, y, cos, sin), ty = turnY(x, y, cos, sin);
                    minX = Math.min(minX, tx);
                    maxX = Math.max(maxX, tx);
                    minY = Math.min(minY, ty);
                    maxY = Math.max(maxY, ty);
                }
            }
        }
        out[0] = minX - grow;
        out[1] = minY - grow;
        out[2] = maxX + grow;
        out[3] = maxY + grow;
    }

    private static double turnX(double x, double y, double cos, double sin) {
        return x * cos - y * sin;
    }

    private static double turnY(double x, double y, double cos, double sin) {
        return x * sin + y * cos;
    }

    /**
     * The home shape placed: turned by angle (given with its cos and sin) about the pivot,
     * then moved by (tx, ty). A turned rectangle is a polygon, a turned ellipse an ellipse with
     * its angle added; the other kinds keep their kind.
     *
     * @throws IllegalArgumentException if a coordinate leaves the float range, or rounding the
     *                                  turned polygon makes its outline touch itself
     */
    public static Shape place(Shape home, double px, double py, double tx, double ty, float angle,
                              double cos, double sin) {
        if (angle == 0) {
            return switch (ShapeKind.of(home)) {
                case RECT -> {
                    Rect r = (Rect) home;
                    yield new Rect(f(r.x() + tx), f(r.y() + ty), r.w(), r.h());
                }
                case CIRCLE -> {
                    Circle c = (Circle) home;
                    yield new Circle(f(c.x() + tx), f(c.y() + ty), c.r());
                }
                case SEGMENT -> {
                    Segment s = (Segment) home;
                    yield new Segment(f(s.x1() + tx), f(s.y1() + ty), f(s.x2() + tx), f(s.y2() + ty));
                }
                case CAPSULE -> {
                    Capsule c = (Capsule) home;
                    yield new Capsule(f(c.x1() + tx), f(c.y1() + ty), f(c.x2() + tx), f(c.y2() + ty), c.r());
                }
                case ELLIPSE -> {
                    Ellipse e = (Ellipse) home;
                    yield new Ellipse(f(e.x() + tx), f(e.y() + ty), e.rx(), e.ry(), e.angle());
                }
                case POLYGON -> {
                    Polygon p = (Polygon) home;
                    float fx = (float) tx, fy = (float) ty;
                    if (fx == tx && fy == ty) {
                        yield p.translated(fx, fy);  // checks again only where rounding moved a vertex
                    }
                    // Transforms checks the moved outline again only where rounding could have
                    // made it touch itself (a move smaller than its clearance never does).
                    yield Transforms.polygon(p, MATRIX.get().set(1, 0, tx, 0, 1, ty));
                }
            };
        }
        // Turned: Shape.transformed's own maths (one home for how each kind turns), on the
        // pose's matrix in double: p -> R (p - pivot) + pivot + t.
        Affine a = MATRIX.get().set(cos, -sin, px + tx - (cos * px - sin * py),
                sin, cos, py + ty - (sin * px + cos * py));
        try {
            return Transforms.apply(home, a);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("the body's shape placed at its pose (angle " + angle
                    + ") has no float shape: " + e.getMessage(), e);
        }
    }

    private static float f(double v) {
        float r = (float) v;
        if (Float.isInfinite(r) || Float.isNaN(r)) {
            throw new IllegalArgumentException("the body's pose puts its shape out of the float range (a coordinate of "
                    + v + ")");
        }
        return r;
    }

    /** A coordinate that moves with the shape exactly as its pose's translation: its first x. */
    public static double refX(Shape s) {
        return switch (ShapeKind.of(s)) {
            case RECT -> ((Rect) s).x();
            case CIRCLE -> ((Circle) s).x();
            case SEGMENT -> ((Segment) s).x1();
            case CAPSULE -> ((Capsule) s).x1();
            case ELLIPSE -> ((Ellipse) s).x();
            case POLYGON -> HiddenParts.raw((Polygon) s)[0];
        };
    }

    /** {@link #refX}'s y. */
    public static double refY(Shape s) {
        return switch (ShapeKind.of(s)) {
            case RECT -> ((Rect) s).y();
            case CIRCLE -> ((Circle) s).y();
            case SEGMENT -> ((Segment) s).y1();
            case CAPSULE -> ((Capsule) s).y1();
            case ELLIPSE -> ((Ellipse) s).y();
            case POLYGON -> HiddenParts.raw((Polygon) s)[1];
        };
    }
}
