// Hitbox in the browser: the Java library compiled to WebAssembly GC by TeaVM, loaded once.
//
//   import { Collide, circle, rect, World } from 'hitbox-collide';
//   Collide.circleCircle(x1, y1, r1, x2, y2, r2);        // the tutorial's tests, radii
//   circle(100, 100, 40).contact(rect(120, 90, 50, 30)); // {nx, ny, depth} or null
//
// Every answer is the JVM's, bit for bit (docs/browser.md): floats are float32, as in Java, and
// touching is not overlapping. Needs a browser with WebAssembly GC (Chrome 119, Firefox 120,
// Safari 18.2 and later).
import { load } from './teavm-runtime.js';
import { flat } from './points.js';

const started = performance.now();
const teavm = await load(new URL('./hitbox.wasm', import.meta.url).href);
const x = teavm.exports;

/** How long loading and compiling the module took, in milliseconds. */
export const loadMillis = performance.now() - started;

/** The tutorial's tests as calls on numbers: Collide.circleCircle(x1, y1, r1, x2, y2, r2), ... */
export const Collide = x.Collide;
/** A world of bodies: add, move (slide, touch, cross, bounce), step, queries, rays. */
export const World = x.World;
/** A grid of cells: terrain, moves that slide along solid cells, line of sight, paths. */
export const Grid = x.Grid;
/** Snapping to a ground line (tutorial section 7): Snap.onGround(y, h, groundY), Snap.standY(h, groundY), Snap.landY(y, h, groundY). */
export const Snap = x.Snap;

export { flat };

/** A circle from its centre and radius. */
export const circle = (cx, cy, r) => x.circle(cx, cy, r);
/** A rectangle from its top-left corner, width and height (p5's rectMode(CORNER)). */
export const rect = (left, top, w, h) => x.rect(left, top, w, h);
/** A segment between two points. */
export const segment = (x1, y1, x2, y2) => x.segment(x1, y1, x2, y2);
/** A polygon from its corners (any of the forms flat() takes), convex or not. */
export const polygon = (points) => x.polygon(flat(points));
/** An ellipse from its centre and radii, turned by an angle in radians (default 0). */
export const ellipse = (cx, cy, rx, ry, angle = 0) => x.ellipse(cx, cy, rx, ry, angle);
/** A capsule: the points within r of the segment (x1, y1)-(x2, y2). */
export const capsule = (x1, y1, x2, y2, r) => x.capsule(x1, y1, x2, y2, r);

/** The gap between two circles' edges (negative when they overlap). */
export const separationCircleCircle = (x1, y1, r1, x2, y2, r2) => x.separationCircleCircle(x1, y1, r1, x2, y2, r2);
/** When a rectangle moved by (vx, vy) first touches another: t in [0, 1], or Infinity. */
export const sweepRectRect = (x0, y0, w, h, vx, vy, ox, oy, ow, oh) => x.sweepRectRect(x0, y0, w, h, vx, vy, ox, oy, ow, oh);

/** The module's own exports, for tests. */
export const raw = x;
