package hitbox.web;

import hitbox.Body;
import hitbox.Capsule;
import hitbox.Circle;
import hitbox.Collide;
import hitbox.Collision;
import hitbox.Contact;
import hitbox.Ellipse;
import hitbox.Grid;
import hitbox.Hit;
import hitbox.Polygon;
import hitbox.Ray;
import hitbox.RayHit;
import hitbox.Rect;
import hitbox.Segment;
import hitbox.Separation;
import hitbox.Shape;
import hitbox.Sweep;
import hitbox.World;
import hitbox.internal.Extents;
import hitbox.internal.Fdlibm;
import hitbox.internal.RawTests;
import java.util.List;

/**
 * The test vectors that the JVM and the browser both answer, to be compared bit for bit
 * (docs/browser.md): cases made from a seed by a generator of its own (SplitMix64, long
 * arithmetic only, so both platforms make the same cases), each run through the library and
 * its answers written as ints: floats by their bits (every NaN as the one canonical NaN),
 * booleans as 0 or 1, no answer as a mark, an exception as a mark and its kind.
 *
 * <p>The cases go over every ordered pair of the six shape kinds for {@code overlaps},
 * {@code contact}, {@code separation}, {@code contains} and the sweep, a ray at each kind,
 * the tutorial's raw-float tests ({@link Collide}), the grid, and moves in a world of bodies.
 * Coordinates are drawn from half-integers (touching cases are common), nearby floats one ulp
 * off them, plain random floats and, rarely, values the library refuses (NaN, infinity, a
 * negative size), whose exceptions are compared by kind.
 */
public final class Vectors {
    /** Before a record of an answer that may be absent: the answer is null. */
    static final int NONE = 0x6e6f6e65;
    /** Before an exception's kind. */
    static final int THROWN = 0x7468726f;
    /** How many kinds of case {@link #runCase} cycles through. */
    static final int CASE_KINDS = 12;

    private long state;
    private int[] out = new int[1 << 16];
    private int size;
    private int[] ends;
    /** Does the case being made reach sine or cosine (a turned ellipse, a sweep, a world move)? */
    private boolean turning;
    private boolean[] turned;

    private Vectors(long seed) {
        this.state = seed;
    }

    /**
     * Runs {@code count} cases made from {@code seed} and returns every answer's record.
     *
     * @param seed  the generator's seed
     * @param count how many cases
     * @return the records, case after case
     */
    public static int[] run(long seed, int count) {
        Vectors v = new Vectors(seed);
        v.ends = new int[count];
        for (int i = 0; i < count; i++) {
            v.runCase(i);
            v.ends[i] = v.size;
        }
        int[] result = new int[v.size];
        System.arraycopy(v.out, 0, result, 0, v.size);
        return result;
    }

    /**
     * Where each case's records end in {@link #run}'s answer (for naming the case of a difference).
     *
     * @param seed  the generator's seed
     * @param count how many cases
     * @return for each case, the index just past its last record
     */
    public static int[] caseEnds(long seed, int count) {
        return layout(seed, count).ends;
    }

    /**
     * Which cases reach sine and cosine: those with a turned ellipse, and the sweeps and world
     * moves (the curved sweeps search directions by angle). The library calls
     * {@code StrictMath}'s, fdlibm's on every JVM and {@link Fdlibm} on the browser build,
     * so these must be alike too; the test counts them, to say how many there were.
     *
     * @param seed  the generator's seed
     * @param count how many cases
     * @return for each case, whether it drew one
     */
    public static boolean[] turnedCases(long seed, int count) {
        return layout(seed, count).turned;
    }

    private static Vectors layout(long seed, int count) {
        Vectors v = new Vectors(seed);
        v.ends = new int[count];
        v.turned = new boolean[count];
        for (int i = 0; i < count; i++) {
            v.turning = i % CASE_KINDS == 5 || i % CASE_KINDS == 10;
            v.runCase(i);
            v.ends[i] = v.size;
            v.turned[i] = v.turning;
        }
        return v;
    }

    /**
     * What case {@code index} of a seed asks, in words, for a failure message.
     *
     * @param seed  the generator's seed
     * @param index the case
     * @return its kind and shapes
     */
    public static String describe(long seed, int index) {
        Vectors v = new Vectors(seed);
        for (int i = 0; i < index; i++) {
            v.runCase(i);
        }
        long before = v.state;
        v.describing = new StringBuilder();
        v.runCase(index);
        v.state = before;
        return "case " + index + " (" + kindName(index % CASE_KINDS) + "): " + v.describing;
    }

    private StringBuilder describing;

    private static String kindName(int kind) {
        String[] names = {"overlaps", "contact", "separation", "contains shape", "contains point", "sweep",
            "ray", "Collide", "Collide polygons", "grid", "world move", "bounds"};
        return names[kind];
    }

    // ---------------------------------------------------------------- the generator

    /** SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014). */
    private long next() {
        long z = state += 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    private int below(int n) {
        return (int) ((next() >>> 33) % n);
    }

    /** A float in [0, 1) from 24 random bits: exact, the same on every platform. */
    private float unit() {
        return (next() >>> 40) * 0x1p-24f;
    }

    private float coord() {
        int r = below(64);
        float lattice = (below(33) - 16) * 0.5f;
        if (r < 32) {
            return lattice;
        } else if (r < 40) {
            return (r & 1) == 0 ? Math.nextUp(lattice) : Math.nextDown(lattice);
        } else if (r < 63) {
            return unit() * 32 - 16;
        }
        float[] odd = {Float.NaN, Float.POSITIVE_INFINITY, -0.0f, 1e-30f, 3e30f};
        return odd[below(odd.length)];
    }

    private float size() {
        int r = below(64);
        if (r < 36) {
            return (below(16) + 1) * 0.5f;
        } else if (r < 62) {
            return unit() * 8 + 0x1p-10f;
        }
        float[] odd = {0f, -1f, Float.NaN, 0x1p-20f};
        return odd[below(odd.length)];
    }

    private Shape shape(int kind) {
        float x = coord(), y = coord();
        Shape s;
        switch (kind) {
            case 0:
                s = new Circle(x, y, size());
                break;
            case 1:
                s = new Rect(x, y, size(), size());
                break;
            case 2:
                s = new Segment(x, y, coord(), coord());
                break;
            case 3:
                s = polygon(x, y);
                break;
            case 4:
                float angle = below(2) == 0 ? 0 : unit() * 7 - 3.5f;
                turning |= angle != 0;
                s = new Ellipse(x, y, size(), size(), angle);
                break;
            default:
                s = new Capsule(x, y, coord(), coord(), size());
                break;
        }
        if (describing != null) {
            describing.append(s).append(' ');
        }
        return s;
    }

    private Polygon polygon(float x, float y) {
        switch (below(4)) {
            case 0:
                return Polygon.of(x, y, coord(), coord(), coord(), coord());
            case 1:
                return Polygon.regular(x, y, size(), 3 + below(6), unit() * 6);
            case 2:
                return Polygon.of(Rect.centered(x, y, size(), size())).rotated(unit() * 6, x, y);
            default:
                int n = 3 + below(5);
                float[] xy = new float[2 * n];
                for (int i = 0; i < n; i++) {
                    float r = size();
                    // Any vertices: a self-crossing polygon is refused by kind on both platforms.
                    xy[2 * i] = x + r * (below(3) - 1);
                    xy[2 * i + 1] = y + r * (below(3) - 1) + i * 0.25f;
                }
                return Polygon.of(xy);
        }
    }

    // ---------------------------------------------------------------- the records

    private void put(int value) {
        if (size == out.length) {
            int[] grown = new int[out.length * 2];
            System.arraycopy(out, 0, grown, 0, size);
            out = grown;
        }
        out[size++] = value;
    }

    private void put(float value) {
        put(Float.floatToIntBits(value));
    }

    private void put(double value) {
        long bits = Double.doubleToLongBits(value);
        put((int) (bits >>> 32));
        put((int) bits);
    }

    private void put(boolean value) {
        put(value ? 1 : 0);
    }

    private void thrown(RuntimeException e) {
        put(THROWN);
        put(kindOf(e));
    }

    /**
     * An exception's kind as a number: compared by kind, not by message.
     *
     * @param e the exception
     * @return its kind
     */
    static int kindOf(RuntimeException e) {
        if (e instanceof IllegalArgumentException) {
            return 1;
        } else if (e instanceof NullPointerException) {
            return 2;
        } else if (e instanceof IndexOutOfBoundsException) {
            return 3;
        } else if (e instanceof ArithmeticException) {
            return 4;
        } else if (e instanceof IllegalStateException) {
            return 5;
        } else if (e instanceof UnsupportedOperationException) {
            return 6;
        }
        return 9;
    }

    private void contact(Contact c) {
        if (c == null) {
            put(NONE);
        } else {
            put(c.nx());
            put(c.ny());
            put(c.depth());
        }
    }

    private void hit(Hit h) {
        if (h == null) {
            put(NONE);
        } else {
            put(h.t());
            put(h.nx());
            put(h.ny());
            put(h.side().ordinal());
        }
    }

    // ---------------------------------------------------------------- the cases

    private void runCase(int index) {
        int kind = index % CASE_KINDS;
        int pair = (index / CASE_KINDS) % 36;
        int ka = pair / 6, kb = pair % 6;
        // A refused shape or question ends the case with its exception's kind: the draws
        // made so far are the same on both platforms, so the next case starts alike.
        try {
            switch (kind) {
                case 0: {
                    Shape a = shape(ka), b = shape(kb);
                    put(a.overlaps(b));
                    put(b.overlaps(a));
                    break;
                }
                case 1: {
                    Shape a = shape(ka), b = shape(kb);
                    contact(a.contact(b));
                    break;
                }
                case 2: {
                    Shape a = shape(ka), b = shape(kb);
                    Separation s = Separation.between(a, b);
                    put(s.distance());
                    put(s.ax());
                    put(s.ay());
                    put(s.bx());
                    put(s.by());
                    break;
                }
                case 3: {
                    Shape a = shape(ka), b = shape(kb);
                    put(a.contains(b));
                    break;
                }
                case 4: {
                    Shape a = shape(ka);
                    float px = coord(), py = coord();
                    if (describing != null) {
                        describing.append("point ").append(px).append(", ").append(py);
                    }
                    put(a.contains(px, py));
                    break;
                }
                case 5: {
                    Shape a = shape(ka), b = shape(kb);
                    float vx = coord() * 2, vy = coord() * 2;
                    if (describing != null) {
                        describing.append("velocity ").append(vx).append(", ").append(vy);
                    }
                    hit(Sweep.timeOfImpact(a, vx, vy, b));
                    break;
                }
                case 6: {
                    Shape a = shape(ka);
                    float ox = coord(), oy = coord(), dx = coord(), dy = coord();
                    float max = below(2) == 0 ? Float.POSITIVE_INFINITY : size() * 4;
                    if (describing != null) {
                        describing.append("ray ").append(ox).append(", ").append(oy).append(" dir ")
                                .append(dx).append(", ").append(dy).append(" max ").append(max);
                    }
                    RayHit h = new Ray(ox, oy, dx, dy, max).cast(a);
                    if (h == null) {
                        put(NONE);
                    } else {
                        put(h.distance());
                        put(h.x());
                        put(h.y());
                        put(h.nx());
                        put(h.ny());
                    }
                    break;
                }
                case 7:
                    collide();
                    break;
                case 8:
                    collidePolygons();
                    break;
                case 9:
                    grid();
                    break;
                case 10:
                    world();
                    break;
                default: {
                    Shape a = shape(ka);
                    put(Extents.minX(a));
                    put(Extents.minY(a));
                    put(Extents.maxX(a));
                    put(Extents.maxY(a));
                    Rect r = a.bounds();
                    put(r.x());
                    put(r.y());
                    put(r.w());
                    put(r.h());
                    break;
                }
            }
        } catch (RuntimeException e) {
            thrown(e);
        }
    }

    private void collide() {
        float x1 = coord(), y1 = coord(), a = size(), b = size();
        float x2 = coord(), y2 = coord(), c = size(), d = size();
        float x3 = coord(), y3 = coord();
        if (describing != null) {
            describing.append(x1).append(' ').append(y1).append(' ').append(a).append(' ').append(b).append(' ')
                    .append(x2).append(' ').append(y2).append(' ').append(c).append(' ').append(d).append(' ')
                    .append(x3).append(' ').append(y3);
        }
        int which = below(12);
        try {
            switch (which) {
                case 0 -> put(Collide.circlePoint(x1, y1, a, x2, y2));
                case 1 -> put(Collide.circleCircle(x1, y1, a, x2, y2, c));
                case 2 -> put(Collide.rectPoint(x1, y1, a, b, x2, y2));
                case 3 -> put(Collide.rectRect(x1, y1, a, b, x2, y2, c, d));
                case 4 -> put(Collide.circleRect(x1, y1, a, x2, y2, c, d));
                case 5 -> put(Collide.lineLine(x1, y1, x2, y2, x3, y3, a, b));
                case 6 -> put(Collide.lineCircle(x1, y1, x2, y2, x3, y3, a));
                case 7 -> put(Collide.lineRect(x1, y1, x2, y2, x3, y3, a, b));
                case 8 -> put(RawTests.ellipsePoint(x1, y1, a, b, x2, y2));
                case 9 -> put(Collide.trianglePoint(x1, y1, x2, y2, x3, y3, a, b));
                case 10 -> put(Collide.lineSide(x1, y1, x2, y2, x3, y3));
                default -> put(RawTests.ellipseEllipse(x1, y1, a, b, x2, y2, c, d));
            }
        } finally {
            put(which);
        }
    }

    private void collidePolygons() {
        int n = 3 + below(4);
        float[] p = new float[2 * n];
        float[] q = new float[2 * n];
        for (int i = 0; i < 2 * n; i++) {
            p[i] = coord();
            q[i] = coord();
        }
        float x = coord(), y = coord(), r = size();
        if (describing != null) {
            describing.append(java.util.Arrays.toString(p)).append(' ').append(java.util.Arrays.toString(q))
                    .append(' ').append(x).append(' ').append(y).append(' ').append(r);
        }
        put(Collide.polygonPoint(p, x, y));
        put(Collide.polygonCircle(p, x, y, r));
        put(Collide.polygonRect(p, x, y, r, r));
        put(Collide.polygonLine(p, x, y, q[0], q[1]));
        put(Collide.polygonPolygon(p, q));
    }

    private void grid() {
        int cols = 2 + below(10), rows = 2 + below(10);
        float cell = size();
        Grid g = new Grid(cols, rows, cell).fillRandom(unit(), next(), 0, 0);
        float x = coord() + 8, y = coord() + 8, w = size(), h = size(), vx = coord(), vy = coord();
        if (describing != null) {
            describing.append(g.toMap().replace('\n', '/')).append(" cell ").append(cell).append(" rect ")
                    .append(x).append(' ').append(y).append(' ').append(w).append(' ').append(h)
                    .append(" velocity ").append(vx).append(' ').append(vy);
        }
        int solid = 0;
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                solid += g.isSolid(col, row) ? 1 : 0;
            }
        }
        put(solid);
        // a NaN or negative size is refused by the shape: marked, and the case goes on
        try {
            put(g.overlapsSolid(new Rect(x, y, w, h)));
        } catch (RuntimeException e) {
            thrown(e);
        }
        try {
            put(g.overlapsSolid(new Circle(x, y, w)));
        } catch (RuntimeException e) {
            thrown(e);
        }
        put(g.lineOfSight(x, y, vx + 8, vy + 8));
        Sweep.Move m = g.move(new Rect(x, y, w, h), vx, vy);
        put(m.x());
        put(m.y());
        int[] path = g.path(0, 0, cols - 1, rows - 1);
        put(path == null ? -1 : path.length);
        if (path != null) {
            for (int p : path) {
                put(p);
            }
        }
    }

    private void world() {
        World world = new World();
        int n = 3 + below(8);
        Body[] bodies = new Body[n];
        for (int i = 0; i < n; i++) {
            bodies[i] = world.add(shape(below(6)));
            bodies[i].data(i);
        }
        for (int step = 0; step < 4; step++) {
            Body mover = bodies[below(n)];
            float dx = coord(), dy = coord();
            if (describing != null) {
                describing.append("move ").append(mover.data()).append(" by ").append(dx).append(", ").append(dy)
                        .append("; ");
            }
            try {
                List<Collision> met = world.move(mover, dx, dy);
                put(met.size());
                for (Collision c : met) {
                    put((Integer) c.other().data());
                    put(c.reaction().ordinal());
                    hit(c.hit());
                    put(c.x());
                    put(c.y());
                }
            } catch (RuntimeException e) {
                thrown(e);
            }
            put(mover.pivotX());
            put(mover.pivotY());
        }
        put(world.step().size());
        for (Body b : bodies) {
            put(world.overlapping(b).size());
        }
    }

    /**
     * Exact products and sums (the cases of {@link ExactFma}): {@code count} triples made from
     * {@code seed}, each answered by {@code Math.fma}, as the bits of the answers.
     *
     * @param seed  the generator's seed
     * @param count how many triples
     * @return two ints per triple, the high and low halves of the answer's bits
     */
    public static int[] fmaCases(long seed, int count) {
        Vectors v = new Vectors(seed);
        for (int i = 0; i < count; i++) {
            double a = v.fmaOperand(), b = v.fmaOperand();
            double c = v.below(2) == 0 ? -(a * b) : v.fmaOperand();
            v.put(Math.fma(a, b, c));
        }
        int[] result = new int[v.size];
        System.arraycopy(v.out, 0, result, 0, v.size);
        return result;
    }

    /**
     * {@code StrictMath.sin} and {@code cos} of angles from a seed: small, medium, huge, near
     * multiples of pi/2 (where the reduction cancels), and any double. On the browser build
     * these calls go to {@link Fdlibm}; on the JVM, to its fdlibm.
     *
     * @param seed  the generator's seed
     * @param count how many angles
     * @return the bits of three doubles for each angle: it, its sine, its cosine
     */
    public static int[] trigCases(long seed, int count) {
        Vectors v = new Vectors(seed);
        for (int i = 0; i < count; i++) {
            double x = v.trigOperand();
            v.put(x);
            v.put(StrictMath.sin(x));
            v.put(StrictMath.cos(x));
        }
        int[] result = new int[v.size];
        System.arraycopy(v.out, 0, result, 0, v.size);
        return result;
    }

    /**
     * The platform methods the library calls, by {@link #mathCases}' numbers (all but
     * {@code Math.tan}, which only CharacterBody's step-up height reaches: docs/browser.md).
     */
    static final String[] MATH_OPS = {
        "Math.min(double, double)", "Math.max(double, double)", "Math.min(float, float)", "Math.max(float, float)",
        "Math.abs(double)", "Math.abs(float)", "Math.sqrt", "Math.nextUp(double)", "Math.nextDown(double)",
        "Math.nextUp(float)", "Math.nextDown(float)", "Math.ulp(double)", "Math.ulp(float)", "Math.atan2",
        "Math.signum(double)", "Math.signum(float)", "Math.floor", "Math.copySign(double, double)", "Math.scalb",
        "(int) double", "(long) double", "(int) float", "(float) double", "Math.floorMod(int, int)",
        "Math.floorDiv(int, int)", "Math.ceil", "Math.copySign(float, float)",
    };

    /**
     * The platform's own methods that the library calls, on awkward arguments (zeros of both
     * signs, NaN, infinities, the smallest and largest numbers, near-ties, and the library's
     * usual magnitudes): TeaVM's class library answers some of them otherwise than the JVM.
     *
     * @param seed  the generator's seed
     * @param count how many calls
     * @return for each call seven ints: which method ({@link #MATH_OPS}), its two arguments'
     *         bits as doubles, and its answer's bits as a double
     */
    public static int[] mathCases(long seed, int count) {
        Vectors v = new Vectors(seed);
        for (int i = 0; i < count; i++) {
            int op = i % MATH_OPS.length;
            double a = v.mathOperand(), b = v.mathOperand();
            float fa = (float) a, fb = (float) b;
            int ia = (int) v.next(), ib = v.below(3) == 0 ? v.below(7) - 3 : (int) v.next();
            if (ib == 0) {
                ib = 1;
            }
            double r;
            switch (op) {
                case 0: r = Math.min(a, b); break;
                case 1: r = Math.max(a, b); break;
                case 2: r = Math.min(fa, fb); break;
                case 3: r = Math.max(fa, fb); break;
                case 4: r = Math.abs(a); break;
                case 5: r = Math.abs(fa); break;
                case 6: r = Math.sqrt(a); break;
                case 7: r = Math.nextUp(a); break;
                case 8: r = Math.nextDown(a); break;
                case 9: r = Math.nextUp(fa); break;
                case 10: r = Math.nextDown(fa); break;
                case 11: r = Math.ulp(a); break;
                case 12: r = Math.ulp(fa); break;
                case 13: r = Math.atan2(a, b); break;
                case 14: r = Math.signum(a); break;
                case 15: r = Math.signum(fa); break;
                case 16: r = Math.floor(a); break;
                case 17: r = Math.copySign(a, b); break;
                case 18: r = Math.scalb(a, ib % 2200); b = ib % 2200; break;
                case 19: r = (int) a; break;
                case 20: r = (long) a; break;
                case 21: r = (int) fa; break;
                case 22: r = fa; break;
                case 23: r = Math.floorMod(ia, ib); a = ia; b = ib; break;
                case 24: r = Math.floorDiv(ia, ib); a = ia; b = ib; break;
                case 25: r = Math.ceil(a); break;
                default: r = Math.copySign(fa, fb); break;
            }
            v.put(op);
            v.put(a);
            v.put(b);
            v.put(r);
        }
        int[] result = new int[v.size];
        System.arraycopy(v.out, 0, result, 0, v.size);
        return result;
    }

    private double mathOperand() {
        int r = below(8);
        if (r == 0) {
            double[] odd = {0.0, -0.0, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.MIN_VALUE,
                -Double.MIN_VALUE, Double.MAX_VALUE, Double.MIN_NORMAL, 1.0, -1.0, 0.5, -0.5, 2.5, Float.MIN_VALUE,
                Float.MAX_VALUE, Float.MIN_NORMAL, 0x1p31, -0x1p31, 0x1p63, 1e300, -1e-300};
            return odd[below(odd.length)];
        }
        double unit = (next() >>> 11) * 0x1p-53;
        if (r < 5) {
            return (float) ((unit - 0.5) * 64);           // the library's floats
        }
        if (r < 7) {
            return (unit - 0.5) * 64;                     // doubles of the same size
        }
        return fmaOperand();                              // any double
    }

    /**
     * The angle {@link #trigCases} asks about at an index, for a failure message.
     *
     * @param seed  the generator's seed
     * @param index which angle
     * @return the angle
     */
    public static double trigAngle(long seed, int index) {
        Vectors v = new Vectors(seed);
        double x = 0;
        for (int i = 0; i <= index; i++) {
            x = v.trigOperand();
        }
        return x;
    }

    private double trigOperand() {
        double unit = (next() >>> 11) * 0x1p-53;
        switch (below(6)) {
            case 0:
                return (unit - 0.5) * 16;                                  // the library's angles
            case 1:
                return (float) ((unit - 0.5) * 4000);                      // a float angle
            case 2:
                return (unit - 0.5) * 0x1p21;                              // medium: the reduction's 33-bit pi/2
            case 3:
                // near n * pi/2: the reduction cancels most bits
                return Math.nextAfter((1 + below(100_000)) * (Math.PI / 2), below(2) == 0 ? 0 : 1e9) + (below(4) - 2) * Math.ulp(1.0);
            case 4:
                return Math.scalb(unit - 0.5, below(1100) - 60);            // up to 2^1039: the long reduction
            default:
                return fmaOperand();                                       // any double, NaN and infinities too
        }
    }

    private double fmaOperand() {
        int r = below(16);
        if (r == 0) {
            double[] odd = {0.0, -0.0, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                Double.MIN_VALUE, Double.MAX_VALUE, 0x1p-1022, 1.0};
            return odd[below(odd.length)];
        }
        long bits = next();
        if (r < 8) {
            // exponents near 0 (the library's sizes), any mantissa, either sign
            bits = (bits & 0x800FFFFFFFFFFFFFL) | ((long) (1023 - 40 + below(80)) << 52);
        } else if (r < 10) {
            // few mantissa bits: exact products and ties
            bits &= 0xFFFFFF0000000000L;
        }
        double d = Double.longBitsToDouble(bits);
        return Double.isNaN(d) ? 1.5 : d;
    }
}
