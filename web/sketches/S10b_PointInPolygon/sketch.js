// Polygons (tutorial section 10: any shape works "once you find the right math"): is the mouse
// inside this concave crown? Project a line from the point, a ray to the right, and count the
// edges it crosses: odd means inside, even outside. crosses() below decides for one edge (ours:
// the tutorial gives no code); the count colours the crown, and the add-on's collidePointPoly
// (Hitbox's Collide.polygonPoint) runs beside it. Press l and Hitbox decides. Where they differ:
// Hitbox first asks whether the point is on the outline; there it is not inside (touching is
// not colliding), whatever the count says.
// Press p and the mouse carries a pentagon: polygon/polygon, written out as "an edge of one
// crosses an edge of the other, or a corner of one is inside the other" (the count again),
// beside collidePolyPoly (Collide.polygonPolygon).
const crown = [[120, 70], [220, 140], [300, 60], [380, 140], [480, 70], [520, 210],
  [430, 310], [330, 230], [250, 310], [140, 270], [90, 190]];
let hitboxDecides = false;
let polyMode = new URLSearchParams(location.search).has('poly');

// Does the ray from (px, py) to the right cross the edge from (ax, ay) to (bx, by)?
function crosses(ax, ay, bx, by, px, py) {
  // The edge must reach the ray's level: one end below it, the other at or above (y grows down).
  if ((ay > py) === (by > py)) return false;
  // Where it meets that level, is that right of the point? Multiplied out, exact for whole pixels.
  const side = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  return by > ay ? side > 0 : side < 0;
}

// How many edges of the polygon the ray from (px, py) crosses.
function crossings(poly, px, py) {
  let count = 0;
  for (let i = 0; i < poly.length; i++) {
    const [ax, ay] = poly[i], [bx, by] = poly[(i + 1) % poly.length];
    if (crosses(ax, ay, bx, by, px, py)) count++;
  }
  return count;
}

// Do two segments cross properly (each one's ends strictly on opposite sides of the other)?
function edgesCross([x1, y1], [x2, y2], [x3, y3], [x4, y4]) {
  const s = (ax, ay, bx, by, px, py) => Math.sign((bx - ax) * (py - ay) - (by - ay) * (px - ax));
  return s(x3, y3, x4, y4, x1, y1) * s(x3, y3, x4, y4, x2, y2) < 0
      && s(x1, y1, x2, y2, x3, y3) * s(x1, y1, x2, y2, x4, y4) < 0;
}

// polygon/polygon: an edge of one crosses an edge of the other, or a corner of one is inside the other.
function polyPoly(a, b) {
  for (let i = 0; i < a.length; i++) {
    for (let j = 0; j < b.length; j++) {
      if (edgesCross(a[i], a[(i + 1) % a.length], b[j], b[(j + 1) % b.length])) return true;
    }
  }
  return crossings(a, b[0][0], b[0][1]) % 2 === 1 || crossings(b, a[0][0], a[0][1]) % 2 === 1;
}

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  const vertices = crown.map(([x, y]) => createVector(x, y));
  let inside, hitboxSays, verdict;
  let pentagon = null;
  if (polyMode) {
    pentagon = [];
    for (let i = 0; i < 5; i++) pentagon.push([mouseX + 40 * Math.cos(i * TWO_PI / 5 - HALF_PI), mouseY + 40 * Math.sin(i * TWO_PI / 5 - HALF_PI)]);
    const counted = polyPoly(crown, pentagon);
    hitboxSays = collidePolyPoly(vertices, pentagon.map(([x, y]) => createVector(x, y)));
    inside = hitboxDecides ? hitboxSays : counted;
    verdict = 'edges crossing or a corner inside: ' + counted + '    collidePolyPoly: ' + hitboxSays;
  } else {
    const count = crossings(crown, mouseX, mouseY);
    hitboxSays = collidePointPoly(mouseX, mouseY, vertices);
    inside = hitboxDecides ? hitboxSays : count % 2 === 1;
    verdict = count + (count === 1 ? ' crossing: ' : ' crossings: ') + (count % 2 === 1 ? 'odd, inside' : 'even, outside')
        + '    collidePointPoly: ' + hitboxSays;
  }
  noStroke();
  fill(inside ? '#E8504A' : '#4CC36A');
  beginShape();
  for (const [x, y] of crown) vertex(x, y);
  endShape(CLOSE);
  if (pentagon) {
    fill(255, 170);
    beginShape();
    for (const [x, y] of pentagon) vertex(x, y);
    endShape(CLOSE);
  } else {
    // the ray, and where it crosses the edges
    stroke('#F2C14E');
    strokeWeight(2);
    line(mouseX, mouseY, width, mouseY);
    noStroke();
    fill('#F2C14E');
    for (let i = 0; i < crown.length; i++) {
      const [ax, ay] = crown[i], [bx, by] = crown[(i + 1) % crown.length];
      if (crosses(ax, ay, bx, by, mouseX, mouseY)) circle(ax + (mouseY - ay) / (by - ay) * (bx - ax), mouseY, 8);
    }
    fill(255);
    circle(mouseX, mouseY, 10);
  }
  fill(255);
  text(verdict, 10, 20);
  text((hitboxDecides ? 'l: Hitbox decides' : 'l: the written-out maths decides') + '    p: ' + (polyMode ? 'a point' : 'a pentagon'), 10, 390);
}

function keyPressed() {
  if (key === 'l') hitboxDecides = !hitboxDecides;
  else if (key === 'p') polyMode = !polyMode;
}
