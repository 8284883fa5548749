// detect-collisions' row of the world scene's table (gradle worldTable, docs/world-benchmark.md).
//
// The scene is Java's WorldScene: WorldSceneNode writes its bodies as they start (kind, size, the
// polygon's corners, pose, velocity, spin, standing) to a file of little-endian 32-bit numbers,
// and this script moves them frame by frame with WorldScene.step()'s float arithmetic
// (Math.fround after every operation Java does in float), so both see the same poses bit for bit;
// the poses after the checked frames go back to Java, which compares them with its own.
//
// Each frame is what a user of detect-collisions writes, as its stress demo (src/demo/stress.js)
// does: every moving body teleported (setAngle(a, false) for the turning ones, then setPosition,
// which updates the body's box in the system's tree when it left its padding), then
// system.checkAll(callback), which hands over each colliding pair (a pair of moving bodies from
// both sides; one side counts). Bodies are detect-collisions' own types: Circle, Ellipse (a
// polygon of at least 8 points on the ellipse, step 2 as the stress demo makes them), Box,
// Line, Polygon; the standing ones isStatic. Padding (min + max size) * 0.2, as the demo's.
//
// Usage: node world-scene.mjs <scene file> <answer file> <check frames> <rounds> <budget ms>
// Writes the pairs of the first frame and of the frame after <check frames> more, the poses
// then, and the timing: <rounds> rounds (after two to warm up) of frames until <budget ms> of
// CPU time, the CPU time a frame of the main thread (/proc/thread-self/schedstat, as Java's
// thread CPU time) and of the whole process (process.cpuUsage(), V8's garbage collector and
// compiler threads included), and the bytes allocated a frame (below; -1 where Node cannot tell).
import { readFileSync, writeFileSync } from 'node:fs';
import v8 from 'node:v8';
import { System } from 'detect-collisions';

const [sceneFile, answerFile, checkFramesArg, roundsArg, budgetArg] = process.argv.slice(2);
const checkFrames = Number(checkFramesArg), rounds = Number(roundsArg), budgetMs = Number(budgetArg);
// detect-collisions' release, and that of check2d, the package it now re-exports (its code).
const versions = ['detect-collisions', 'check2d'].map((name) =>
  JSON.parse(readFileSync(new URL(`./node_modules/${name}/package.json`, import.meta.url), 'utf8')).version);

// ---------------------------------------------------------------- the scene, as Java wrote it

const CIRCLE = 0, ELLIPSE = 1, BOX = 2, LINE = 3;
const WIDTH = 1024, HEIGHT = 768;
const raw = readFileSync(sceneFile);
const view = new DataView(raw.buffer, raw.byteOffset, raw.byteLength);
const n = view.getInt32(0, true);
const size = view.getFloat32(4, true);
let at = 8;
function ints(count) {
  const out = new Int32Array(count);
  for (let k = 0; k < count; k++, at += 4) out[k] = view.getInt32(at, true);
  return out;
}
function floats(count) {
  const out = new Float32Array(count);
  for (let k = 0; k < count; k++, at += 4) out[k] = view.getFloat32(at, true);
  return out;
}
const kind = ints(n), p = floats(n), q = floats(n), corners = floats(8 * n);
const x = floats(n), y = floats(n), angle = floats(n), vx = floats(n), vy = floats(n), spin = floats(n);
const standing = ints(n);
if (at !== raw.byteLength) throw new Error(`scene file: ${raw.byteLength} bytes, read ${at}`);

// WorldScene.step(), float for float: a Float32Array rounds each stored value to float, and
// fround rounds each sum before it is compared, as Java's float arithmetic does.
const fround = Math.fround, PI_F = fround(Math.PI), TWO_PI_F = fround(2 * Math.PI);
function step() {
  for (let i = 0; i < n; i++) {
    const nx = fround(x[i] + vx[i]), ny = fround(y[i] + vy[i]);
    if (nx < 0 || nx > WIDTH) vx[i] = -vx[i]; else x[i] = nx;
    if (ny < 0 || ny > HEIGHT) vy[i] = -vy[i]; else y[i] = ny;
    const a = fround(angle[i] + spin[i]);
    angle[i] = a > PI_F ? fround(a - TWO_PI_F) : a < -PI_F ? fround(a + TWO_PI_F) : a;
  }
}

// ---------------------------------------------------------------- detect-collisions' world

const system = new System();
const padding = (size + 1.25 * size) * 0.2;
const bodies = new Array(n);
for (let i = 0; i < n; i++) {
  const options = { isStatic: standing[i] === 1, padding, userData: i };
  const pos = { x: x[i], y: y[i] };
  let body;
  switch (kind[i]) {
    case CIRCLE:
      body = system.createCircle(pos, p[i], options);
      break;
    case ELLIPSE:
      body = system.createEllipse(pos, p[i], q[i], 2, options);   // always centred on pos
      break;
    case BOX:
      body = system.createBox(pos, p[i], q[i], { ...options, isCentered: true });
      break;
    case LINE:
      // From (-p, -q) to (p, q) about pos: centred, as the stress demo makes its lines.
      body = system.createLine(pos, { x: x[i] + 2 * p[i], y: y[i] + 2 * q[i] }, { ...options, isCentered: true });
      break;
    default: {
      // The corners are already about the body's origin (their mean); isCentered would move them
      // to the area's centroid, which would turn the polygon about another point than Java's.
      const c = [];
      for (let k = 0; k < 8; k += 2) c.push({ x: corners[8 * i + k], y: corners[8 * i + k + 1] });
      body = system.createPolygon(pos, c, options);
    }
  }
  body.setAngle(angle[i]);
  bodies[i] = body;
}

let count = 0, kept = null;
function collided({ a, b }) {
  // A pair of moving bodies comes from both sides, a moving and a standing one from the moving
  // side only (checkAll skips the standing bodies): each counted once.
  if (a.userData < b.userData || b.isStatic) {
    count++;
    if (kept) kept.push(Math.min(a.userData, b.userData), Math.max(a.userData, b.userData));
  }
  // Nothing returned: a true would stop checkAll.
}

function frame() {
  for (let i = 0; i < n; i++) {
    if (standing[i] === 1) continue;
    const body = bodies[i];
    if (spin[i] !== 0) body.setAngle(angle[i], false);
    body.setPosition(x[i], y[i]);
  }
  count = 0;
  system.checkAll(collided);
  return count;
}

function framePairs() {
  kept = [];
  frame();
  const out = kept;
  kept = null;
  return out;
}

// ---------------------------------------------------------------- the answers

const lines = [`versions ${versions.join(' ')}`];
lines.push(`pairs0 ${framePairs().join(' ')}`);
for (let f = 0; f < checkFrames; f++) {
  step();
  frame();
}
const poses = new Float32Array(3 * n);
for (let i = 0; i < n; i++) {
  poses[3 * i] = x[i];
  poses[3 * i + 1] = y[i];
  poses[3 * i + 2] = angle[i];
}
lines.push(`poses ${Array.from(new Int32Array(poses.buffer)).join(' ')}`);
lines.push(`pairsF ${framePairs().join(' ')}`);

// ---------------------------------------------------------------- the time, and the bytes

/** This thread's CPU time in ns (Linux: the first number of its schedstat), or -1 where there is none. */
function threadNanos() {
  try {
    return Number(readFileSync('/proc/thread-self/schedstat', 'latin1').split(' ')[0]);
  } catch {
    return -1;
  }
}
function processMicros() {
  const u = process.cpuUsage();
  return u.user + u.system;
}

// Bytes allocated: V8 keeps no running total, so they are read from its garbage collector: the
// used heap's growth from one collection to the next (what was allocated in between; objects
// only go away inside a collection), summed over the round, v8.GCProfiler giving the used heap
// before and after each collection. Memory that concurrent sweeping frees between
// collections would make it read low; in a steady state of short-lived objects (scavenges) that
// is little.
function usedHeap() {
  return v8.getHeapStatistics().used_heap_size;
}
function allocatedSince(start, end, statistics) {
  let total = 0, prev = start;
  for (const s of statistics) {
    total += Math.max(0, s.beforeGC.heapStatistics.usedHeapSize - prev);
    prev = s.afterGC.heapStatistics.usedHeapSize;
  }
  return total + Math.max(0, end - prev);
}

const threadMs = [], processMs = [], bytes = [];
const budgetMicros = budgetMs * 1000;
for (let r = -2; r < rounds; r++) {   // two rounds of warming up
  const profiler = v8.GCProfiler ? new v8.GCProfiler() : null;   // Node 18.15 and later
  profiler?.start();
  const heap0 = usedHeap(), t0 = threadNanos(), c0 = processMicros();
  let frames = 0, c;
  do {
    step();
    frame();
    frames++;
    c = processMicros() - c0;
  } while (c < budgetMicros);
  const t = threadNanos() - t0, heap1 = usedHeap();
  const gc = profiler?.stop();
  if (r >= 0) {
    threadMs.push(t0 < 0 ? -1 : t / 1e6 / frames);
    processMs.push(c / 1e3 / frames);
    bytes.push(gc ? allocatedSince(heap0, heap1, gc.statistics) / frames : -1);
  }
}
lines.push(`threadMs ${threadMs.join(' ')}`);
lines.push(`processMs ${processMs.join(' ')}`);
lines.push(`bytes ${bytes.join(' ')}`);
writeFileSync(answerFile, lines.join('\n') + '\n');
