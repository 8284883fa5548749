// Lines (tutorial section 10: "rectangle line intersection" and the like): a line runs from
// the start to the mouse; three segments, a rectangle and a circle turn red while it hits
// them. The tutorial leaves the maths to a search; it is written out below (ours), and decides
// the colours; the add-on's collideLineLine, collideLineRect and collideLineCircle (Hitbox's
// Collide.lineLine, lineRect, lineCircle) run beside it, and the top line counts the targets
// where they disagree. Press l and Hitbox's calls decide. They differ where the written-out
// maths is loose: a line through two corners of the rectangle crosses no side properly and
// has no end inside, so lineRect below misses it; Hitbox does not. Segments are closed
// (touching an end counts); shapes with area are open (running along an edge does not hit).
// Click moves the start.
let startX = 40, startY = 340;
const segments = [[60, 190, 170, 80], [300, 80, 300, 200], [430, 110, 570, 170]];
const box = { x: 400, y: 250, w: 140, h: 90 };    // its bottom edge is level with the start
const ball = { x: 220, y: 280, r: 42 };
let hitboxDecides = false, disagreements = 0;

// Which side of the line through a and b is p? The sign of a cross product, 0 on the line.
function side(ax, ay, bx, by, px, py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Is p, already on the line through a and b, between them?
function between(ax, ay, bx, by, px, py) {
  return px >= min(ax, bx) && px <= max(ax, bx) && py >= min(ay, by) && py <= max(ay, by);
}

// Do the segments cross properly: each one's ends strictly on opposite sides of the other's line?
function crosses(x1, y1, x2, y2, x3, y3, x4, y4) {
  const d1 = side(x3, y3, x4, y4, x1, y1), d2 = side(x3, y3, x4, y4, x2, y2);
  const d3 = side(x1, y1, x2, y2, x3, y3), d4 = side(x1, y1, x2, y2, x4, y4);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// line/line: they cross, or an end of one lies on the other.
function lineLine(x1, y1, x2, y2, x3, y3, x4, y4) {
  return crosses(x1, y1, x2, y2, x3, y3, x4, y4)
      || (side(x3, y3, x4, y4, x1, y1) === 0 && between(x3, y3, x4, y4, x1, y1))
      || (side(x3, y3, x4, y4, x2, y2) === 0 && between(x3, y3, x4, y4, x2, y2))
      || (side(x1, y1, x2, y2, x3, y3) === 0 && between(x1, y1, x2, y2, x3, y3))
      || (side(x1, y1, x2, y2, x4, y4) === 0 && between(x1, y1, x2, y2, x4, y4));
}

// line/rectangle: an end inside it (section 4's if), or the line crosses one of its sides.
function lineRect(x1, y1, x2, y2, rx, ry, rw, rh) {
  if (x1 > rx && x1 < rx + rw && y1 > ry && y1 < ry + rh) return true;
  if (x2 > rx && x2 < rx + rw && y2 > ry && y2 < ry + rh) return true;
  return crosses(x1, y1, x2, y2, rx, ry, rx + rw, ry)
      || crosses(x1, y1, x2, y2, rx, ry + rh, rx + rw, ry + rh)
      || crosses(x1, y1, x2, y2, rx, ry, rx, ry + rh)
      || crosses(x1, y1, x2, y2, rx + rw, ry, rx + rw, ry + rh);
}

// line/circle: the segment's point nearest the centre, then section 2's dist() < radius.
function lineCircle(x1, y1, x2, y2, cx, cy, r) {
  const dx = x2 - x1, dy = y2 - y1;
  let t = 0;
  if (dx !== 0 || dy !== 0) t = constrain(((cx - x1) * dx + (cy - y1) * dy) / (dx * dx + dy * dy), 0, 1);
  return dist(x1 + t * dx, y1 + t * dy, cx, cy) < r;
}

// One target's answer: the written-out maths, or Hitbox's (l); counted if they differ.
function decide(writtenOut, hitboxSays) {
  if (writtenOut !== hitboxSays) disagreements++;
  return hitboxDecides ? hitboxSays : writtenOut;
}

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  disagreements = 0;
  const segmentHit = segments.map(([x3, y3, x4, y4]) => decide(lineLine(startX, startY, mouseX, mouseY, x3, y3, x4, y4),
      collideLineLine(startX, startY, mouseX, mouseY, x3, y3, x4, y4)));
  const boxHit = decide(lineRect(startX, startY, mouseX, mouseY, box.x, box.y, box.w, box.h),
      collideLineRect(startX, startY, mouseX, mouseY, box.x, box.y, box.w, box.h));
  const ballHit = decide(lineCircle(startX, startY, mouseX, mouseY, ball.x, ball.y, ball.r),
      collideLineCircle(startX, startY, mouseX, mouseY, ball.x, ball.y, ball.r * 2));
  noStroke();
  fill(boxHit ? '#E8504A' : '#4CC36A');
  rect(box.x, box.y, box.w, box.h);
  fill(ballHit ? '#E8504A' : '#4CC36A');
  circle(ball.x, ball.y, ball.r * 2);
  strokeWeight(5);
  segments.forEach(([x1, y1, x2, y2], i) => {
    stroke(segmentHit[i] ? '#E8504A' : '#4CC36A');
    line(x1, y1, x2, y2);
  });
  stroke('#F2C14E');
  strokeWeight(3);
  line(startX, startY, mouseX, mouseY);
  noStroke();
  fill('#F2C14E');
  circle(startX, startY, 10);
  fill(255);
  text((hitboxDecides ? "Hitbox's calls decide (l: the maths)" : "the written-out maths decides (l: Hitbox's calls)")
      + ';  they disagree on ' + disagreements + ' targets', 10, 20);
}

function mousePressed() {
  startX = mouseX;
  startY = mouseY;
}

function keyPressed() {
  if (key === 'l') hitboxDecides = !hitboxDecides;
}
