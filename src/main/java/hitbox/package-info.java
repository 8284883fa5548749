/**
 * Hitbox: collision detection for Processing sketches and Java 2D games, one idea at a time.
 *
 * <h2>Three ways in</h2>
 * <ul>
 *   <li>{@link hitbox.Collide}: static tests on plain {@code float}s, written the way the
 *       tutorial writes its {@code if} statements, for example
 *       {@code Collide.circleCircle(x1, y1, r1, x2, y2, r2)}. They allocate nothing and check
 *       nothing, so they are safe to call thousands of times a frame.</li>
 *   <li>Shapes ({@link hitbox.Circle}, {@link hitbox.Rect}, and the rest of the sealed
 *       {@link hitbox.Shape} family): immutable values whose constructors reject bad input
 *       with a message that names the parameter. {@code a.overlaps(b)} answers for every
 *       pair of shapes, in either order, through the same code as {@code Collide}. A shape
 *       moves with {@code translated} and turns with {@code rotated} or
 *       {@code transformed(}{@link hitbox.Transform}{@code )}, the way Processing's
 *       {@code translate}, {@code rotate} and {@code scale} draw it.</li>
 *   <li>A {@link hitbox.World} of {@link hitbox.Body bodies}, for a game: each body keeps its
 *       shape and a pose, and {@code world.move(body, dx, dy, filter)} moves it through the
 *       others with the reaction each pair needs, never tunnelling.</li>
 * </ul>
 *
 * <h2>Units and conventions</h2>
 * Pixels, with Processing's axes: x grows to the right and y grows <em>down</em>. A
 * {@link hitbox.Circle} is its centre and its <em>radius</em> (Processing's {@code ellipse}
 * takes a diameter: draw it with {@code circle(x, y, 2 * r)}). A {@link hitbox.Rect} is its
 * top-left corner and its size, Processing's {@code CORNER} mode.
 *
 * <h2 id="touching">The touching rule</h2>
 * One rule for every pair, the one the tutorial's {@code &&} tests keep: <strong>touching is
 * not colliding.</strong> (Its flipped {@code ||} form, with the same strict comparisons, calls
 * touching rectangles colliding.)
 * <ul>
 *   <li>Shapes with area (circles, rectangles, polygons, ellipses, capsules) are open sets:
 *       their outline is not part of them. Two circles whose distance equals the sum of their radii, two
 *       rectangles side by side, a point exactly on an edge: none of them collide. In the
 *       tutorial's form this is {@code dist < r1 + r2} and
 *       {@code px > rx && px < rx + rw && py > ry && py < ry + rh}, strict inequalities.</li>
 *   <li>Segments and points are closed: a segment collides with what it touches, so two
 *       segments meeting at an end point intersect, and so does a segment that reaches the
 *       inside of a shape. A segment lying along a rectangle's edge does not collide with
 *       it, because it never reaches the inside.</li>
 *   <li>A zero-size shape has no inside of its own: a circle of radius 0 behaves as a
 *       point, a rectangle of width or height 0 as a segment without its end points, an
 *       ellipse with a radius of 0 as its flat box, a capsule of radius 0 as its segment. It
 *       collides with a shape that has area only by reaching into that shape's inside.
 *       Between two zero-size shapes the same formulas give: a point never collides with a
 *       point or a flat rectangle, and two flat rectangles collide only when they cross
 *       (like a plus sign), never when they lie along each other or meet at an end.</li>
 * </ul>
 * A segment of length 0 is a point, and closed like every segment: it meets a segment through
 * it. Segments and points have no inside, so a segment never collides with a zero-size shape
 * (a circle of radius 0, a rectangle of width or height 0).
 * Comparisons are exact, with no hidden epsilon in any yes-or-no answer: for whole-number
 * coordinates of modest size (up to about a million) every answer, touching cases included,
 * is exact. The tolerances that do exist are named and listed <a href="#tolerances">below</a>.
 *
 * <h2 id="polygons">Polygons</h2>
 * A {@link hitbox.Polygon} is its vertices in order, {@code x0, y0, x1, y1, ...}; edge i runs
 * from vertex i to vertex i + 1 and the last edge closes the outline back to vertex 0, so the
 * first vertex is not repeated at the end. Either winding works (clockwise or anticlockwise on
 * screen), and so does any <em>simple</em> polygon, convex or concave: one whose outline never
 * crosses or touches itself, edges meeting only at the corner two neighbours share.
 * {@link hitbox.Polygon#of} checks that and says which vertices or edges are wrong. Like
 * circles and rectangles, a polygon is open: polygons that share an edge or a corner do not
 * overlap, one wholly inside another does, and so do two with the same outline. The
 * {@code Collide.polygon...} methods take the raw {@code float[]} and check nothing: fewer than
 * 3 vertices never collide, an odd last coordinate is ignored, a repeated vertex (the first one
 * written again at the end, say) changes nothing, and an outline that crosses
 * itself is read even-odd by {@code polygonPoint} and gives unspecified answers elsewhere (but
 * never an exception). The tests work on concave
 * polygons without splitting them into triangles, and answer exactly, by orientation signs.
 *
 * <h2 id="contract">One contract for every answer</h2>
 * <ul>
 *   <li><b>Normals.</b> Every normal a result carries points <em>from the first shape to
 *       the second</em>, or, for a motion, <em>from the mover into what it hit</em> (dyn4j's
 *       convention): {@link hitbox.Contact} from a to b, {@link hitbox.Hit} from the moving
 *       shape into the obstacle, {@link hitbox.RayHit} from the ray into the shape. Landing on
 *       a floor gives (0, 1) (y grows down). Every method of {@link hitbox.Response} takes
 *       that normal as it comes: {@code Response.bounce(vx, vy, hit.nx(), hit.ny(), 1)}
 *       bounces the mover off what it hit. The one exception is drawing data, not a result:
 *       {@link hitbox.SeparatingAxis.Axis} is an edge's outward normal.</li>
 *   <li><b>Sides.</b> Every "which side" answer is a {@link hitbox.Side}, named from the
 *       obstacle (or the window): {@code TOP} is landed on, {@code BOTTOM} hit from below. A
 *       normal gives its side by one rule, {@link hitbox.Side#ofNormal}. Answers that name
 *       several sides at once ({@link hitbox.Edges#crossed}, {@link hitbox.Motion#blocked},
 *       {@link hitbox.Sweep.Move#sides()}) are unmodifiable {@code Set<Side>}s, empty when
 *       there are none, never holding {@code NONE}. A result that names one side gives it as {@code side()}
 *       ({@link hitbox.Hit}, {@link hitbox.RayHit}, {@link hitbox.Contact},
 *       {@link hitbox.Snap.Push}).</li>
 *   <li><b>No result.</b> An answer that is an object is {@code null} when there is none (no
 *       contact or manifold, no hit, no ray hit, no {@link hitbox.Separation} for shapes that
 *       overlap, no bounds for an empty mask); a {@code float} time or
 *       distance is {@link java.lang.Float#POSITIVE_INFINITY}, so {@code t <= 1} reads "hits
 *       this frame"; an index is -1, as in {@link java.util.List#indexOf}; a boolean is
 *       false; a set of sides is 0 ({@code NONE}); an array of answers is empty, never
 *       null ({@link hitbox.Grid#path} when there is no route). {@link hitbox.Side#NONE} is never "no
 *       result" on its own: it is the side of a result that has no side (a hit that started
 *       overlapping, a {@link hitbox.Snap.Push} that did not push).</li>
 *   <li><b>Exact, and conservative where it rounds.</b> Decisions are exact for floats; a
 *       float box that must hold a shape ({@link hitbox.Shape#bounds()}) is rounded
 *       outwards; sums that could cancel or overflow in float (a polygon's area and centroid,
 *       orientations of points far apart) are done in double or exactly.</li>
 * </ul>
 *
 * <h2 id="bad-input">Bad input: the NaN rule</h2>
 * <ul>
 *   <li>A method whose arguments are all plain numbers ({@code Collide}, the raw-float
 *       methods of {@code Contact}, {@code Sweep}, {@code Ray}, {@code Edges},
 *       {@code Motion}, {@code Snap}, {@code Response}, {@code Grid}'s pixel tests) never
 *       throws: a NaN anywhere, and likewise a negative size, answers "no result" for that
 *       kind of answer (false, {@code NONE}, null, {@code +Infinity}), or hands the value
 *       back unchanged where the answer is a position or a velocity. Infinite values either
 *       take part in the comparisons as they are (for the {@code boolean} tests) or give "no
 *       result" (for answers that would have to carry them); each method's documentation
 *       says which.</li>
 *   <li>Constructors and methods that take objects (shapes, contacts, lists) check what
 *       they are given: they throw {@link java.lang.IllegalArgumentException} for null, NaN,
 *       infinite values, negative sizes and out-of-range counts, with a message that names
 *       the parameter and the value, for example {@code "radius must be >= 0, was -1.0"}.</li>
 *   <li>One exception per kind of mistake: a bad value (null, NaN, infinite, negative, out
 *       of its range) is an {@link java.lang.IllegalArgumentException}; an index that must
 *       name an existing element and does not (a grid cell outside the grid, given to
 *       {@link hitbox.Grid#get}, {@link hitbox.Grid#set}, {@link hitbox.Grid#path} or
 *       {@link hitbox.Grid#fillRandom(float, long, int, int)}, or a contact point that a
 *       {@link hitbox.Manifold} does not have, given to {@link hitbox.Manifold#x(int)} and
 *       its kin) is an
 *       {@link java.lang.IndexOutOfBoundsException}, like a list's, its message naming the
 *       cell or the parameter; changing a {@link hitbox.BroadPhase} from inside its own
 *       callback is an {@link java.lang.IllegalStateException}. Nothing throws anything else
 *       ({@code NullPointerException}, {@code NegativeArraySizeException},
 *       {@code ArithmeticException}) for any input. (Until issue 19, {@code Grid.path} threw
 *       an {@code IllegalArgumentException} for a cell outside the grid.)</li>
 * </ul>
 *
 * <h2 id="tolerances">Tolerances</h2>
 * Two yes-or-no answers depend on a tolerance: {@link hitbox.Shape#contains(hitbox.Shape)},
 * only for curved pairs whose exact answer is a root of a quartic (see the stopping rules
 * below), and whether a sweep found by conservative advancement (ellipses, capsules, a
 * polygon with anything but a convex polygon) hits at all: a path entering the obstacle
 * less than 2^-40 of the shapes' size deep is a graze, no hit (see
 * <a href="Sweep.html#t">what t promises</a>); no other does. The ones Hitbox has are named, and each says
 * why in the source:
 * <ul>
 *   <li>Public: {@link hitbox.Contact#UNIT_TOLERANCE} (how far from 1 a hand-made contact's
 *       normal may be), {@link hitbox.Contact#TIE} (when two contact depths are equally
 *       short for the tie rule), {@link hitbox.Hybrid#CIRCLE_SLACK} (the bounding-circle
 *       stage's margin, so rounding never rejects a touching pair).</li>
 *   <li>Guard bands, inside the exact tests: a double comparison is trusted only outside a
 *       band a little wider than its proven rounding; inside it, an exact test decides. They
 *       change speed, never an answer.</li>
 *   <li>Paddings of a broad phase's query box (1e-9 of the coordinates): a candidate too
 *       many, which the exact test drops, never one too few.</li>
 *   <li>Stopping rules of the searches behind curved and turning shapes: contacts of
 *       ellipses and capsules, the {@link hitbox.Separation} of an ellipse (to about 1e-9 of
 *       the shapes' size), and {@link hitbox.Sweep#turningTimeOfImpact} and the curved
 *       sweeps, answer to within those rules (each method's documentation says how
 *       closely); so does {@link hitbox.Shape#contains(hitbox.Shape)} for the curved pairs
 *       it searches (an ellipse holding a circle, capsule or ellipse, an ellipse in a circle
 *       or capsule, anything and a turned ellipse): held within 1e-9 of the container's size
 *       of touching from inside.</li>
 *   <li>The world's slide: a body that meets a slanted surface and slides on stops a
 *       <em>skin</em> short of it (1/64 pixel near the origin, four float steps of its
 *       coordinates far out; an axis-aligned face is met touching exactly), so that the float
 *       positions of the slide never round into it; a character's ground is what faces up
 *       within its {@code maxSlope}, to 1e-6 of the angle's cosine
 *       (the project's docs/character.md has the whole design).
 *       They decide where a body stops, never whether two shapes overlap.</li>
 * </ul>
 *
 * <h2 id="push-out">Which push-out to use</h2>
 * <ul>
 *   <li>{@link hitbox.Response#separate}: a shape must end up clear of another, exactly
 *       ({@code overlaps} is false afterwards), for any pair with area. The default.</li>
 *   <li>{@link hitbox.Response#pushOut(hitbox.Shape, hitbox.Contact, float)}: you already
 *       have the {@link hitbox.Contact} and move by its depth, one shape or both (a
 *       {@code share} each, the other with {@code contact.flipped()}); may leave a rounding
 *       hair of overlap.</li>
 *   <li>{@link hitbox.Snap#pushOut}: two boxes, on plain floats, pushed along one axis, with the
 *       {@link hitbox.Side} the mover was pushed to (landed, hit a wall): a platformer's
 *       tiles.</li>
 * </ul>
 *
 * <h2 id="words">Words</h2>
 * A {@link hitbox.Segment} is a segment everywhere in these docs; the {@code Collide.line...}
 * methods keep the tutorial's word "line" in their names, but take segments, two closed end
 * points ({@code Collide.lineSide} alone reads the whole line through them). A rectangle's corner and size are
 * {@code x, y, w, h}, or {@code rectX, rectY, rectW, rectH} beside another shape's
 * coordinates; an ellipse's {@code rx} and {@code ry} are its radii. The verb says what comes
 * back: {@code overlaps}, {@code contains} and the {@code Collide} tests a boolean,
 * {@code contact} a {@link hitbox.Contact} or null, {@code manifold} a
 * {@link hitbox.Manifold} (the contact with its one or two points) or null, {@code separation} a
 * {@link hitbox.Separation} (how far apart, and the closest points) or null when the shapes
 * overlap, {@code timeOfImpact} a
 * {@link hitbox.Hit} or null (its time in [0, 1]), {@code distance...} a length or
 * {@code +Infinity}; {@link hitbox.Hits#first} an index.
 */
package hitbox;
