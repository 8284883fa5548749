// Separating axes (tutorial section 10: convex polygons and turned rectangles need "the right
// math"): two convex shapes are apart exactly when a straight line fits between them. Shine a
// light across each edge and look at the two shadows on the axis along the edge's normal: if
// they do not overlap on some axis, that axis separates the shapes; if they overlap on every
// axis, the shapes overlap. The loop below is the theorem written out (ours: the tutorial gives
// no code) and colours the rectangle; Hitbox's shape.overlaps (polygon against polygon, exact,
// in double) runs beside it; press l and Hitbox decides. Shadows that only touch are a gap in
// both: touching is not colliding. The rectangle turns; the triangle follows the mouse.
// Keys: 3-6 the mouse shape's sides, space stops the turning, l who decides.
const cx = 300, cy = 200;
let angle = 0.35, turning = true, sides = 3, hitboxDecides = false;

// The corners of a w x h rectangle centred on (x, y), turned by a.
function turnedRect(x, y, w, h, a) {
  const c = Math.cos(a), s = Math.sin(a);
  return [[-w / 2, -h / 2], [w / 2, -h / 2], [w / 2, h / 2], [-w / 2, h / 2]]
      .map(([u, v]) => [x + u * c - v * s, y + u * s + v * c]);
}

// A regular polygon of n corners, radius r, the first one straight up.
function regular(x, y, r, n) {
  const out = [];
  for (let i = 0; i < n; i++) out.push([x + r * Math.cos(i * TWO_PI / n - HALF_PI), y + r * Math.sin(i * TWO_PI / n - HALF_PI)]);
  return out;
}

// A shape's shadow on the axis (nx, ny): each corner projected with the dot product, smallest to largest.
function shadow(p, nx, ny) {
  let lo = Infinity, hi = -Infinity;
  for (const [x, y] of p) {
    const along = x * nx + y * ny;
    lo = min(lo, along);
    hi = max(hi, along);
  }
  return [lo, hi];
}

// One axis per edge of p: the edge (dx, dy) turned a quarter, (dy, -dx), made length 1.
function axesOf(p) {
  const axes = [];
  for (let i = 0; i < p.length; i++) {
    const [ax, ay] = p[i], [bx, by] = p[(i + 1) % p.length];
    const dx = bx - ax, dy = by - ay, length = sqrt(dx * dx + dy * dy);
    if (length > 0) axes.push([dy / length, -dx / length]);
  }
  return axes;
}

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  if (turning && !window.scriptedRun) angle += 0.006;
  const box = turnedRect(cx, cy, 170, 90, angle);
  const mover = regular(mouseX, mouseY, 52, sides);

  // The theorem as a loop: a gap on any one axis means apart.
  let separating = null;
  const axes = axesOf(box).concat(axesOf(mover));
  for (const [nx, ny] of axes) {
    const [minA, maxA] = shadow(box, nx, ny), [minB, maxB] = shadow(mover, nx, ny);
    if (maxA <= minB || maxB <= minA) {
      separating = [nx, ny];
      break;
    }
  }
  const hitboxSays = hitbox.polygon(box).overlaps(hitbox.polygon(mover));
  const overlapping = hitboxDecides ? hitboxSays : separating === null;

  noStroke();
  fill(overlapping ? '#E8504A' : '#4CC36A');
  beginShape();
  for (const [x, y] of box) vertex(x, y);
  endShape(CLOSE);
  fill(255, 150);
  stroke(255);
  strokeWeight(2);
  beginShape();
  for (const [x, y] of mover) vertex(x, y);
  endShape(CLOSE);
  if (separating) {
    // the separating line: across the axis, halfway between the two shadows
    const [nx, ny] = separating;
    const [minA, maxA] = shadow(box, nx, ny), [minB, maxB] = shadow(mover, nx, ny);
    const at = maxA <= minB ? (maxA + minB) / 2 : (maxB + minA) / 2;
    stroke('#F2C14E');
    line(nx * at - ny * 1000, ny * at + nx * 1000, nx * at + ny * 1000, ny * at - nx * 1000);
  }
  noStroke();
  fill(255);
  text((separating ? 'an axis separates them: apart' : 'the shadows overlap on all ' + axes.length + ' axes: overlapping')
      + '    shape.overlaps: ' + hitboxSays, 10, 20);
  text((hitboxDecides ? 'l: Hitbox decides' : 'l: the loop decides') + '    3-6: sides    space: turning', 10, 390);
}

function keyPressed() {
  if (key === 'l') hitboxDecides = !hitboxDecides;
  else if (key >= '3' && key <= '6') sides = Number(key);
  else if (key === ' ') turning = !turning;
}
