// p5.hitbox: p5.collide2D's functions, answered by Hitbox (docs/browser.md).
//
// A sketch written for p5.collide2D runs unchanged: the same names and the same arguments
// (circles by diameter, as p5's circle() takes them; polygons as arrays of p5.Vector). What
// differs is written on each function below; the two differences that matter everywhere:
//
//   * Touching is not a hit. p5.collide2D counts shapes that only touch (an edge on an edge,
//     a point on a border) as colliding; Hitbox, like the tutorial's own ifs with < and >,
//     does not. Move one pixel in and both say yes.
//   * Exact answers. p5.collide2D computes in JavaScript doubles with rounding on the way
//     (distances through sqrt, sums of lengths for points on lines); Hitbox takes the numbers
//     as float32 (as a Java sketch would) and answers exactly for them.
//
// Load it after p5 and before the sketch, as a module:
//   <script src="p5.min.js"></script>
//   <script type="module" src="p5.hitbox.js"></script>
//   <script type="module" src="sketch.js"></script>      (or a classic script: see below)
// p5 2.x: it registers itself with p5.registerAddon; p5 1.x: it adds to p5.prototype; and it
// sets each function on window for a global sketch given as a classic script. It registers at
// once and loads the WebAssembly module beside it; until that is ready it holds the sketch's
// start (p5 2.x: an async presetup hook; p5 1.x: a preload count), so setup() may call it.
// `hitbox` (the whole module: hitbox.Collide, hitbox.circle, hitbox.World, ...) is set on
// window once loaded.
import { flat } from './points.js';

let H = null;
let C = null;
/** Resolves to the module (hitbox.js) once it has loaded. */
export const ready = import('./hitbox.js').then((m) => {
  H = m;
  C = m.Collide;
  if (typeof window !== 'undefined') window.hitbox = m;
  return m;
});
const PIE = 3;

const polyXY = flat;

/** Where the lines (x1, y1)-(x2, y2) and (x3, y3)-(x4, y4) cross, in doubles, as p5.collide2D returns it. */
function crossing(x1, y1, x2, y2, x3, y3, x4, y4) {
  const den = (y4 - y3) * (x2 - x1) - (x4 - x3) * (y2 - y1);
  const uA = ((x4 - x3) * (y1 - y3) - (y4 - y3) * (x1 - x3)) / den;
  return { x: x1 + uA * (x2 - x1), y: y1 + uA * (y2 - y1) };
}

/**
 * The functions, by p5.collide2D's names. Each returns true when the shapes overlap (touching
 * is not overlapping), as Hitbox's Collide does.
 */
export const functions = {
  /** collideRectRect(x, y, w, h, x2, y2, w2, h2): Collide.rectRect. Rectangles that only share an edge do not collide. */
  collideRectRect(x, y, w, h, x2, y2, w2, h2) {
    return C.rectRect(x, y, w, h, x2, y2, w2, h2);
  },
  /** collideCircleCircle(cx, cy, d, cx2, cy2, d2), diameters: Collide.circleCircle with the radii. Circles that only touch do not collide. */
  collideCircleCircle(cx, cy, d, cx2, cy2, d2) {
    return C.circleCircle(cx, cy, d / 2, cx2, cy2, d2 / 2);
  },
  /** collideRectCircle(rx, ry, rw, rh, cx, cy, d), a diameter: Collide.rectCircle. A circle touching an edge does not collide. */
  collideRectCircle(rx, ry, rw, rh, cx, cy, d) {
    return C.rectCircle(rx, ry, rw, rh, cx, cy, d / 2);
  },
  /** collidePointCircle(x, y, cx, cy, d), a diameter: Collide.circlePoint. A point on the circle is not inside (p5.collide2D: it is). */
  collidePointCircle(x, y, cx, cy, d) {
    return C.circlePoint(cx, cy, d / 2, x, y);
  },
  /** collidePointEllipse(x, y, cx, cy, dx, dy), diameters: Collide.ellipsePoint (Java's Ellipse.contains). A point on the ellipse is not inside. */
  collidePointEllipse(x, y, cx, cy, dx, dy) {
    return C.ellipsePoint(cx, cy, dx / 2, dy / 2, x, y);
  },
  /** collidePointRect(px, py, x, y, w, h): Collide.rectPoint. A point on an edge is not inside (p5.collide2D: it is). */
  collidePointRect(px, py, x, y, w, h) {
    return C.rectPoint(x, y, w, h, px, py);
  },
  /**
   * collidePointLine(px, py, x1, y1, x2, y2, buffer = 0.1): is the point within buffer of the
   * segment (Collide.capsulePoint, Java's Capsule.contains: a capsule of radius buffer)? p5.collide2D compares the sum of
   * the point's distances to the ends with the length, within buffer: a band that narrows at
   * the ends; Hitbox's band has the same width all along and round ends. A buffer of 0 asks for
   * a point exactly on the segment (Collide.lineSide and the segment's box).
   */
  collidePointLine(px, py, x1, y1, x2, y2, buffer = 0.1) {
    if (buffer > 0) return C.capsulePoint(x1, y1, x2, y2, buffer, px, py);
    return C.lineSide(x1, y1, x2, y2, px, py) === 0
      && px >= Math.min(x1, x2) && px <= Math.max(x1, x2) && py >= Math.min(y1, y2) && py <= Math.max(y1, y2);
  },
  /** collideLineCircle(x1, y1, x2, y2, cx, cy, d), a diameter: Collide.lineCircle. A segment tangent to the circle does not collide. */
  collideLineCircle(x1, y1, x2, y2, cx, cy, d) {
    return C.lineCircle(x1, y1, x2, y2, cx, cy, d / 2);
  },
  /**
   * collideLineLine(x1, y1, x2, y2, x3, y3, x4, y4, calcIntersection = false): Collide.lineLine,
   * exact (segments that cross at an end count, as in the tutorial). With calcIntersection,
   * {x, y} where they cross (in doubles, as p5.collide2D computes it), or {x: false, y: false}.
   */
  collideLineLine(x1, y1, x2, y2, x3, y3, x4, y4, calcIntersection = false) {
    const hit = C.lineLine(x1, y1, x2, y2, x3, y3, x4, y4);
    if (!calcIntersection) return hit;
    return hit ? crossing(x1, y1, x2, y2, x3, y3, x4, y4) : { x: false, y: false };
  },
  /**
   * collideLineRect(x1, y1, x2, y2, rx, ry, rw, rh, calcIntersection = false): Collide.lineRect,
   * which also answers true for a segment wholly inside the rectangle (p5.collide2D tests the
   * four edges only, so it answers false there). With calcIntersection, {left, right, top,
   * bottom}, each as collideLineLine gives it.
   */
  collideLineRect(x1, y1, x2, y2, rx, ry, rw, rh, calcIntersection = false) {
    const hit = C.lineRect(x1, y1, x2, y2, rx, ry, rw, rh);
    if (!calcIntersection) return hit;
    const f = functions.collideLineLine;
    return {
      left: f(x1, y1, x2, y2, rx, ry, rx, ry + rh, true),
      right: f(x1, y1, x2, y2, rx + rw, ry, rx + rw, ry + rh, true),
      top: f(x1, y1, x2, y2, rx, ry, rx + rw, ry, true),
      bottom: f(x1, y1, x2, y2, rx, ry + rh, rx + rw, ry + rh, true),
    };
  },
  /** collidePointPoly(px, py, vertices): Collide.polygonPoint, by counting crossings as the tutorial does. */
  collidePointPoly(px, py, vertices) {
    return C.polygonPoint(polyXY(vertices), px, py);
  },
  /**
   * collideCirclePoly(cx, cy, d, vertices, interior = false), a diameter: Collide.polygonCircle.
   * A circle wholly inside the polygon collides whatever interior says (p5.collide2D: only with
   * interior true); one touching an edge does not.
   */
  collideCirclePoly(cx, cy, d, vertices, interior = false) {
    return C.polygonCircle(polyXY(vertices), cx, cy, d / 2);
  },
  /** collideRectPoly(rx, ry, rw, rh, vertices, interior = false): Collide.polygonRect; inside counts, as for circles. */
  collideRectPoly(rx, ry, rw, rh, vertices, interior = false) {
    return C.polygonRect(polyXY(vertices), rx, ry, rw, rh);
  },
  /** collideLinePoly(x1, y1, x2, y2, vertices): Collide.polygonLine; a segment wholly inside collides (p5.collide2D: no). */
  collideLinePoly(x1, y1, x2, y2, vertices) {
    return C.polygonLine(polyXY(vertices), x1, y1, x2, y2);
  },
  /** collidePolyPoly(p1, p2, interior = false): Collide.polygonPolygon; one inside the other collides whatever interior says. */
  collidePolyPoly(p1, p2, interior = false) {
    return C.polygonPolygon(polyXY(p1), polyXY(p2));
  },
  /** collidePointTriangle(px, py, x1, y1, x2, y2, x3, y3): Collide.trianglePoint. A point on an edge is not inside. */
  collidePointTriangle(px, py, x1, y1, x2, y2, x3, y3) {
    return C.trianglePoint(x1, y1, x2, y2, x3, y3, px, py);
  },
  /**
   * collidePointArc(px, py, ax, ay, arcRadius, arcHeading, arcAngle, buffer = 0): is the point in
   * the pie slice of that radius, centred on the heading, arcAngle wide (radians)?
   * Collide.arcPoint in PIE mode, the radius grown by buffer. A point on the rim or on a
   * straight edge is not inside.
   */
  collidePointArc(px, py, ax, ay, arcRadius, arcHeading, arcAngle, buffer = 0) {
    const r = arcRadius + buffer;
    return C.arcPoint(ax, ay, r, r, arcHeading - arcAngle / 2, arcHeading + arcAngle / 2, PIE, px, py);
  },
  /** p5.collide2D draws its tests when debugging is on; Hitbox keeps drawing apart from the maths, so this does nothing. */
  collideDebug() {},
};

// The Vector forms: points as p5.Vector (or anything with x and y), sizes as vectors (x: width, y: height).
Object.assign(functions, {
  collideRectRectVector: (p, sz, p2, sz2) => functions.collideRectRect(p.x, p.y, sz.x, sz.y, p2.x, p2.y, sz2.x, sz2.y),
  collideCircleCircleVector: (p1, d1, p2, d2) => functions.collideCircleCircle(p1.x, p1.y, d1, p2.x, p2.y, d2),
  collideRectCircleVector: (r, sz, c, d) => functions.collideRectCircle(r.x, r.y, sz.x, sz.y, c.x, c.y, d),
  collidePointCircleVector: (p, c, d) => functions.collidePointCircle(p.x, p.y, c.x, c.y, d),
  collidePointEllipseVector: (p, c, sz) => functions.collidePointEllipse(p.x, p.y, c.x, c.y, sz.x, sz.y),
  collidePointRectVector: (p, r, sz) => functions.collidePointRect(p.x, p.y, r.x, r.y, sz.x, sz.y),
  collidePointLineVector: (p, a, b, buffer) => functions.collidePointLine(p.x, p.y, a.x, a.y, b.x, b.y, buffer),
  collideLineCircleVector: (a, b, c, d) => functions.collideLineCircle(a.x, a.y, b.x, b.y, c.x, c.y, d),
  collideLineLineVector: (a, b, c, d, calc) => functions.collideLineLine(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y, calc),
  collideLineRectVector: (a, b, r, sz, calc) => functions.collideLineRect(a.x, a.y, b.x, b.y, r.x, r.y, sz.x, sz.y, calc),
  collidePointPolyVector: (p, vertices) => functions.collidePointPoly(p.x, p.y, vertices),
  collideCirclePolyVector: (c, d, vertices, interior) => functions.collideCirclePoly(c.x, c.y, d, vertices, interior),
  collideRectPolyVector: (r, sz, vertices, interior) => functions.collideRectPoly(r.x, r.y, sz.x, sz.y, vertices, interior),
  collideLinePolyVector: (a, b, vertices) => functions.collideLinePoly(a.x, a.y, b.x, b.y, vertices),
  collidePolyPolyVector: (p1, p2, interior) => functions.collidePolyPoly(p1, p2, interior),
  collidePointTriangleVector: (p, a, b, c) => functions.collidePointTriangle(p.x, p.y, a.x, a.y, b.x, b.y, c.x, c.y),
  collidePointArcVector: (p, a, r, heading, angle, buffer) =>
    functions.collidePointArc(p.x, p.y, a.x, a.y, r, heading, angle, buffer),
});

/** The add-on for p5 2.x: p5.registerAddon(hitboxAddon). Setup waits for the module. */
export function hitboxAddon(p5, fn, lifecycles) {
  Object.assign(fn, functions);
  lifecycles.presetup = async function () {
    await ready;
  };
}

/** Adds the functions to a p5 1.x prototype (or any object). */
export function addTo(target) {
  Object.assign(target, functions);
}

const P5 = globalThis.p5;
if (P5) {
  if (typeof P5.registerAddon === 'function') {
    P5.registerAddon(hitboxAddon);
  } else {
    addTo(P5.prototype);
    // p5 1.x waits for preload() calls before setup: hold it with one more until the module is in.
    P5.prototype.registerMethod('init', function () {
      if (H) return;
      const context = this._isGlobal ? window : this;
      if (typeof context.preload !== 'function') context.preload = function () {};
      this._incrementPreload();
      ready.then(() => this._decrementPreload());
    });
  }
}
// A global sketch given as a classic script may already be running: give it the functions too.
if (typeof window !== 'undefined') {
  for (const [name, f] of Object.entries(functions)) {
    if (!(name in window)) window[name] = f;
  }

}
