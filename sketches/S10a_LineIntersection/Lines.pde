// The maths for lines, written out: line/line, line/rectangle, line/circle. The sources give
// no code for these; this is ours, in plain floats, one small step at a time.

// Which side of the line through (ax, ay) and (bx, by) is the point (px, py)? The sign of a
// cross product: positive on one side, negative on the other, 0 on the line.
float side(float ax, float ay, float bx, float by, float px, float py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Is (px, py), already known to be on the line through a and b, between them?
boolean between(float ax, float ay, float bx, float by, float px, float py) {
  return px >= min(ax, bx) && px <= max(ax, bx) && py >= min(ay, by) && py <= max(ay, by);
}

// Do the segments (x1, y1)-(x2, y2) and (x3, y3)-(x4, y4) cross properly: each one's ends
// strictly on opposite sides of the other's line?
boolean crosses(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
  float d1 = side(x3, y3, x4, y4, x1, y1);
  float d2 = side(x3, y3, x4, y4, x2, y2);
  float d3 = side(x1, y1, x2, y2, x3, y3);
  float d4 = side(x1, y1, x2, y2, x4, y4);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// line/line: they cross, or an end of one lies on the other (segments are closed).
boolean lineLine(float x1, float y1, float x2, float y2, float x3, float y3, float x4, float y4) {
  if (crosses(x1, y1, x2, y2, x3, y3, x4, y4)) {
    return true;
  }
  return (side(x3, y3, x4, y4, x1, y1) == 0 && between(x3, y3, x4, y4, x1, y1))
      || (side(x3, y3, x4, y4, x2, y2) == 0 && between(x3, y3, x4, y4, x2, y2))
      || (side(x1, y1, x2, y2, x3, y3) == 0 && between(x1, y1, x2, y2, x3, y3))
      || (side(x1, y1, x2, y2, x4, y4) == 0 && between(x1, y1, x2, y2, x4, y4));
}

// line/rectangle: an end inside it (section 4's if), or the line crosses one of its sides.
boolean lineRect(float x1, float y1, float x2, float y2, float rx, float ry, float rw, float rh) {
  if (x1 > rx && x1 < rx + rw && y1 > ry && y1 < ry + rh) {
    return true;
  }
  if (x2 > rx && x2 < rx + rw && y2 > ry && y2 < ry + rh) {
    return true;
  }
  return crosses(x1, y1, x2, y2, rx, ry, rx + rw, ry)                 // top
      || crosses(x1, y1, x2, y2, rx, ry + rh, rx + rw, ry + rh)       // bottom
      || crosses(x1, y1, x2, y2, rx, ry, rx, ry + rh)                 // left
      || crosses(x1, y1, x2, y2, rx + rw, ry, rx + rw, ry + rh);      // right
}

// line/circle: the segment's point nearest the centre, then section 2's dist() < radius.
boolean lineCircle(float x1, float y1, float x2, float y2, float cx, float cy, float r) {
  float dx = x2 - x1;
  float dy = y2 - y1;
  float t = 0;   // how far along the segment the nearest point is, 0 at (x1, y1), 1 at (x2, y2)
  if (dx != 0 || dy != 0) {
    t = constrain(((cx - x1) * dx + (cy - y1) * dy) / (dx * dx + dy * dy), 0, 1);
  }
  return dist(x1 + t * dx, y1 + t * dy, cx, cy) < r;
}
