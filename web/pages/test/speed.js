// Speed in the browser: Hitbox (WebAssembly GC) beside detect-collisions (its System, SAT and
// BVH, plain JavaScript) and plain-JavaScript forms of the tutorial's ifs. For each row the
// answers are compared first (counts of hits, and for the scene every pair); then it is timed.
// ?quick: small counts, for the test that checks the answers; nothing is reported as speed.
import { report, reportError } from './report.js';
import * as H from '../hitbox.js';
import { System, pointInPolygon } from '../vendor/detect-collisions/index.js';

const quick = new URLSearchParams(location.search).has('quick');
const out = document.getElementById('out');
const log = (s) => { out.textContent += '\n' + s; };

// A seeded generator (mulberry32), so every run meets the same cases.
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6D2B79F5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const f32 = Math.fround;

/** Median of the runs' milliseconds for a loop over all cases; the loop returns its hit count. */
function time(loop, runs) {
  const ms = [];
  let hits = 0;
  for (let r = 0; r < runs; r++) {
    const t0 = performance.now();
    hits = loop();
    ms.push(performance.now() - t0);
  }
  ms.sort((x, y) => x - y);
  return { ms: ms[Math.floor(runs / 2)], hits };
}

// ---------------------------------------------------------------- the small tests

function smallTests(cases, runs) {
  const rows = [];
  const system = new System();
  const R = rng(20261129);
  const coord = () => f32(R() * 400);

  // circle/circle: the tutorial's dist() < r1 + r2
  const cc = [];
  for (let i = 0; i < cases; i++) cc.push([coord(), coord(), f32(5 + R() * 40), coord(), coord(), f32(5 + R() * 40)]);
  const ccBodies = cc.map(([x1, y1, r1, x2, y2, r2]) => [system.createCircle({ x: x1, y: y1 }, r1), system.createCircle({ x: x2, y: y2 }, r2)]);
  rows.push(row('circle/circle', cases, runs, {
    'plain JS (the tutorial\'s if)': () => {
      let n = 0;
      for (const [x1, y1, r1, x2, y2, r2] of cc) if (Math.sqrt((x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1)) < r1 + r2) n++;
      return n;
    },
    'Hitbox Collide.circleCircle': () => {
      let n = 0;
      const C = H.Collide;
      for (const [x1, y1, r1, x2, y2, r2] of cc) if (C.circleCircle(x1, y1, r1, x2, y2, r2)) n++;
      return n;
    },
    'detect-collisions checkCollision': () => {
      let n = 0;
      for (const [a, b] of ccBodies) if (system.checkCollision(a, b)) n++;
      return n;
    },
  }));

  // rectangle/rectangle: the tutorial's four comparisons
  const rr = [];
  for (let i = 0; i < cases; i++) rr.push([coord(), coord(), f32(5 + R() * 80), f32(5 + R() * 80), coord(), coord(), f32(5 + R() * 80), f32(5 + R() * 80)]);
  const rrBodies = rr.map(([x1, y1, w1, h1, x2, y2, w2, h2]) => [system.createBox({ x: x1, y: y1 }, w1, h1), system.createBox({ x: x2, y: y2 }, w2, h2)]);
  rows.push(row('rectangle/rectangle', cases, runs, {
    'plain JS (the tutorial\'s if)': () => {
      let n = 0;
      for (const [x1, y1, w1, h1, x2, y2, w2, h2] of rr) if (x1 + w1 > x2 && x1 < x2 + w2 && y1 + h1 > y2 && y1 < y2 + h2) n++;
      return n;
    },
    'Hitbox Collide.rectRect': () => {
      let n = 0;
      const C = H.Collide;
      for (const [x1, y1, w1, h1, x2, y2, w2, h2] of rr) if (C.rectRect(x1, y1, w1, h1, x2, y2, w2, h2)) n++;
      return n;
    },
    'detect-collisions checkCollision': () => {
      let n = 0;
      for (const [a, b] of rrBodies) if (system.checkCollision(a, b)) n++;
      return n;
    },
  }));

  // A star-shaped polygon of 7 corners round (cx, cy): concave more often than not.
  const star = (cx, cy) => {
    const xy = [];
    const turn = R() * Math.PI * 2;
    for (let k = 0; k < 7; k++) {
      const a = turn + k * Math.PI * 2 / 7, r = 20 + R() * 40;
      xy.push(f32(cx + r * Math.cos(a)), f32(cy + r * Math.sin(a)));
    }
    return xy;
  };
  const toPoints = (xy) => { const p = []; for (let k = 0; k < xy.length; k += 2) p.push({ x: xy[k], y: xy[k + 1] }); return p; };

  // point in polygon: counting the edges a ray to the right crosses (S10b's crosses())
  const pp = [];
  for (let i = 0; i < cases; i++) pp.push([star(200, 200), f32(120 + R() * 160), f32(120 + R() * 160)]);
  const ppBodies = pp.map(([xy]) => system.createPolygon({ x: 0, y: 0 }, toPoints(xy)));
  const ppPoints = pp.map(([, px, py]) => ({ x: px, y: py }));
  rows.push(row('point in polygon (7 corners, concave)', cases, runs, {
    'plain JS (counting crossings)': () => {
      let n = 0;
      for (const [xy, px, py] of pp) {
        let inside = false;
        for (let k = 0, m = xy.length; k < m; k += 2) {
          const ax = xy[k], ay = xy[k + 1], bx = xy[(k + 2) % m], by = xy[(k + 3) % m];
          if ((ay > py) !== (by > py)) {
            const side = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
            if (by > ay ? side > 0 : side < 0) inside = !inside;
          }
        }
        if (inside) n++;
      }
      return n;
    },
    'Hitbox Collide.polygonPoint': () => {
      let n = 0;
      const C = H.Collide;
      for (const [xy, px, py] of pp) if (C.polygonPoint(xy, px, py)) n++;
      return n;
    },
    'detect-collisions pointInPolygon': () => {
      let n = 0;
      for (let i = 0; i < ppBodies.length; i++) if (pointInPolygon(ppPoints[i], ppBodies[i])) n++;
      return n;
    },
  }));

  // polygon/polygon, convex: separating axes (S10c's loop)
  const convex = (cx, cy) => {
    const xy = [];
    const turn = R() * Math.PI * 2, r = 10 + R() * 40;
    for (let k = 0; k < 5; k++) {
      const a = turn + k * Math.PI * 2 / 5;
      xy.push(f32(cx + r * Math.cos(a)), f32(cy + r * Math.sin(a)));
    }
    return xy;
  };
  const qq = [];
  for (let i = 0; i < cases; i++) qq.push([convex(200, 200), convex(f32(120 + R() * 160), f32(120 + R() * 160))]);
  const qqBodies = qq.map(([a, b]) => [system.createPolygon({ x: 0, y: 0 }, toPoints(a)), system.createPolygon({ x: 0, y: 0 }, toPoints(b))]);
  const qqShapes = qq.map(([a, b]) => [H.polygon(a), H.polygon(b)]);
  const gapOn = (a, b, nx, ny) => {
    let minA = Infinity, maxA = -Infinity, minB = Infinity, maxB = -Infinity;
    for (let k = 0; k < a.length; k += 2) { const d = a[k] * nx + a[k + 1] * ny; if (d < minA) minA = d; if (d > maxA) maxA = d; }
    for (let k = 0; k < b.length; k += 2) { const d = b[k] * nx + b[k + 1] * ny; if (d < minB) minB = d; if (d > maxB) maxB = d; }
    return maxA <= minB || maxB <= minA;
  };
  const separated = (p, a, b) => {
    for (let k = 0, m = p.length; k < m; k += 2) {
      const dx = p[(k + 2) % m] - p[k], dy = p[(k + 3) % m] - p[k + 1];
      if (gapOn(a, b, dy, -dx)) return true;
    }
    return false;
  };
  rows.push(row('polygon/polygon (5 corners, convex)', cases, runs, {
    'plain JS (separating axes)': () => {
      let n = 0;
      for (const [a, b] of qq) if (!separated(a, a, b) && !separated(b, a, b)) n++;
      return n;
    },
    'Hitbox Collide.polygonPolygon': () => {
      let n = 0;
      const C = H.Collide;
      for (const [a, b] of qq) if (C.polygonPolygon(a, b)) n++;
      return n;
    },
    'Hitbox shape.overlaps (shapes made before)': () => {
      let n = 0;
      for (const [a, b] of qqShapes) if (a.overlaps(b)) n++;
      return n;
    },
    'detect-collisions checkCollision': () => {
      let n = 0;
      for (const [a, b] of qqBodies) if (system.checkCollision(a, b)) n++;
      return n;
    },
  }));
  return rows;
}

/** One test: each form's hit count over the cases (all must agree), then each timed. */
function row(test, cases, runs, forms) {
  const counts = {};
  for (const [name, loop] of Object.entries(forms)) counts[name] = loop();
  const alike = new Set(Object.values(counts)).size === 1;
  const timed = [];
  for (const [name, loop] of Object.entries(forms)) {
    const t = runs > 0 ? time(loop, runs) : { ms: 0, hits: counts[name] };
    timed.push({ form: name, hits: counts[name], nsPerCase: t.ms * 1e6 / cases });
  }
  log(test + ': ' + JSON.stringify(counts) + (alike ? ' alike' : ' DIFFER'));
  return { test, cases, alike, forms: timed };
}

// ---------------------------------------------------------------- the stress scene

// detect-collisions' stress demo (src/demo/stress.js in its repository): as many bodies as its
// demo puts on a 1920 x 1080 screen (2000), each about sqrt(w * h / (count * 50)) pixels, one in
// twenty up to three times larger, circles, boxes, lines and four-cornered polygons in turn,
// each moving in its own direction and bouncing off the screen's edges. Unlike the demo, the
// bodies do not turn or change size, and there are no ellipses (its ellipse is a polygon of
// many corners, Hitbox's an ellipse): so both libraries answer for the same shapes. Positions
// and sizes are multiples of 1/16, exact in float32 and in double, so both see the same numbers.
function makeScene(count) {
  const W = 1920, Hh = 1080, R = rng(7);
  const size = Math.sqrt((W * Hh) / (count * 50));
  const q = (v) => Math.round(v * 16) / 16;
  const bodies = [];
  for (let i = 0; i < count; i++) {
    const large = R() < 0.05;
    const lo = size * (large ? R() + 1 : 1), hi = size * 1.25 * (large ? R() * 2 + 1 : 1);
    const s = () => q(lo + R() * (hi - lo));
    const x = q(R() * W), y = q(R() * Hh), dir = R() * Math.PI * 2;
    const b = { x, y, vx: q(Math.cos(dir)), vy: q(Math.sin(dir)), variant: i % 4 };
    if (b.variant === 0) b.r = q(s() / 2);
    else if (b.variant === 1) { b.w = s(); b.h = s(); }
    else if (b.variant === 2) { b.ex = s(); b.ey = s(); }
    else b.corners = [-s(), s(), s(), s(), s(), -s(), -s(), -s()];
    b.pad = (lo + hi) * 0.2;
    bodies.push(b);
  }
  return { W, H: Hh, bodies };
}

/** Moves every body of the scene one frame: the same numbers for both libraries. */
function stepScene(scene) {
  for (const b of scene.bodies) {
    b.x += b.vx;
    b.y += b.vy;
    if (b.x < 0 || b.x > scene.W) b.vx = -b.vx;
    if (b.y < 0 || b.y > scene.H) b.vy = -b.vy;
  }
}

function detectCollisionsScene(scene) {
  const system = new System();
  const made = scene.bodies.map((b, i) => {
    const opt = { padding: b.pad };
    let body;
    if (b.variant === 0) body = system.createCircle({ x: b.x, y: b.y }, b.r, opt);
    else if (b.variant === 1) body = system.createBox({ x: b.x - b.w / 2, y: b.y - b.h / 2 }, b.w, b.h, opt);
    else if (b.variant === 2) body = system.createLine({ x: b.x, y: b.y }, { x: b.x + b.ex, y: b.y + b.ey }, opt);
    else body = system.createPolygon({ x: b.x, y: b.y }, [0, 2, 4, 6].map((k) => ({ x: b.corners[k], y: b.corners[k + 1] })), opt);
    body.hid = i;
    body.dx = body.pos.x - b.x;
    body.dy = body.pos.y - b.y;
    return body;
  });
  return {
    frame(pairs) {
      for (let i = 0; i < made.length; i++) {
        const b = scene.bodies[i], body = made[i];
        body.setPosition(b.x + body.dx, b.y + body.dy);
      }
      let n = 0;
      system.checkAll(pairs ? (r) => { if (r.a.hid < r.b.hid) pairs.add(r.a.hid * 100000 + r.b.hid); n++; } : () => { n++; });
      return n / 2;   // checkAll reports each pair from both sides
    },
  };
}

function hitboxScene(scene) {
  const world = new H.World();
  const shapes = [];
  const made = scene.bodies.map((b) => {
    let shape;
    if (b.variant === 0) shape = H.circle(b.x, b.y, b.r);
    else if (b.variant === 1) shape = H.rect(b.x - b.w / 2, b.y - b.h / 2, b.w, b.h);
    else if (b.variant === 2) shape = H.segment(b.x, b.y, b.x + b.ex, b.y + b.ey);
    else shape = H.polygon([0, 2, 4, 6].flatMap((k) => [b.x + b.corners[k], b.y + b.corners[k + 1]]));
    shapes.push(shape);
    const body = world.add(shape);
    body.dx = body.pivotX - b.x;   // its pivot (the centre of its bounds) from the scene's point
    body.dy = body.pivotY - b.y;
    return body;
  });
  return {
    frame(pairs) {
      for (let i = 0; i < made.length; i++) {
        const b = scene.bodies[i], body = made[i];
        body.moveTo(b.x + body.dx, b.y + body.dy);
      }
      let n = 0;
      for (const e of world.step()) {
        if (e.kind === 'EXIT') continue;
        n++;
        if (pairs) pairs.add(Math.min(e.a.id, e.b.id) * 100000 + Math.max(e.a.id, e.b.id));
      }
      return n;
    },
    touching(key) {
      const a = made[Math.floor(key / 100000)].shape, b = made[key % 100000].shape;
      return !a.overlaps(b) && a.separation(b).distance === 0;
    },
  };
}

function stress(count, checkFrames, timedFrames) {
  // The answers: the same frames through both, every pair compared.
  const scene = makeScene(count);
  const dc = detectCollisionsScene(scene), hb = hitboxScene(scene);
  let dcPairs = 0, hbPairs = 0, onlyDcTouching = 0, onlyDcOther = 0, onlyHitbox = 0;
  for (let f = 0; f < checkFrames; f++) {
    stepScene(scene);
    const a = new Set(), b = new Set();
    dc.frame(a);
    hb.frame(b);
    dcPairs += a.size;
    hbPairs += b.size;
    for (const k of a) if (!b.has(k)) { if (hb.touching(k)) onlyDcTouching++; else onlyDcOther++; }
    for (const k of b) if (!a.has(k)) onlyHitbox++;
  }
  log('stress answers: ' + JSON.stringify({ dcPairs, hbPairs, onlyDcTouching, onlyDcOther, onlyHitbox }));
  // The time: a fresh scene each, a few frames to warm up, then the frames timed.
  const timed = {};
  for (const [name, make] of [['detect-collisions System (setPosition, checkAll)', detectCollisionsScene],
    ['Hitbox World (moveTo, step)', hitboxScene]]) {
    const s = makeScene(count), lib = make(s);
    for (let f = 0; f < 20; f++) { stepScene(s); lib.frame(null); }
    let pairs = 0;
    const t0 = performance.now();
    for (let f = 0; f < timedFrames; f++) { stepScene(s); pairs += lib.frame(null); }
    timed[name] = { msPerFrame: (performance.now() - t0) / Math.max(1, timedFrames), pairsPerFrame: pairs / Math.max(1, timedFrames) };
  }
  log('stress time: ' + JSON.stringify(timed));
  return { count, checkFrames, dcPairs, hbPairs, onlyDcTouching, onlyDcOther, onlyHitbox, timedFrames, timed };
}

/** The results as the Markdown table in docs/browser.md. */
function table(rows, scene) {
  const lines = ['| test | form | cases | hits | ns per case |', '|---|---|---:|---:|---:|'];
  for (const r of rows) {
    for (const f of r.forms) lines.push(`| ${r.test} | ${f.form} | ${r.cases} | ${f.hits} | ${f.nsPerCase.toFixed(1)} |`);
  }
  lines.push('', '| stress scene, ' + scene.count + ' bodies | pairs a frame | ms a frame |', '|---|---:|---:|');
  for (const [name, t] of Object.entries(scene.timed)) lines.push(`| ${name} | ${t.pairsPerFrame.toFixed(1)} | ${t.msPerFrame.toFixed(2)} |`);
  lines.push('', `Answers, ${scene.checkFrames} frames compared pair by pair: detect-collisions ${scene.dcPairs} pairs, Hitbox ${scene.hbPairs};`
      + ` only detect-collisions: ${scene.onlyDcTouching} touching (it counts touching as a hit) and ${scene.onlyDcOther} other;`
      + ` only Hitbox: ${scene.onlyHitbox}.`);
  return lines.join('\n') + '\n';
}

try {
  const rows = quick ? smallTests(2000, 0) : smallTests(50000, 7);
  const scene = quick ? stress(400, 10, 0) : stress(2000, 60, 300);
  await report('speed', JSON.stringify({ quick, userAgent: navigator.userAgent, cores: navigator.hardwareConcurrency, rows, scene }));
  if (!quick) await report('table', table(rows, scene));
} catch (e) {
  reportError(e);
}
