// Corners as Hitbox takes them, shared by hitbox.js and the p5.js add-on (no WebAssembly here,
// so the add-on can import it without waiting for the module).

/** Corners as [x0, y0, x1, y1, ...], [[x, y], ...] or [{x, y}, ...] (p5.Vector), as a flat array. */
export function flat(points) {
  if (points.length === 0 || typeof points[0] === 'number') return Array.from(points);
  const out = [];
  for (const p of points) {
    if (Array.isArray(p)) out.push(p[0], p[1]);
    else out.push(p.x, p.y);
  }
  return out;
}
