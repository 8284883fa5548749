// The 'd' overlay: the fan the blade's tips sweep this frame (the area the end-of-frame test
// never looks at), the blade where the frame started, and the hit's time and normal.

void drawMaths(Polygon startBlade) {
  float r = bladeLength / 2;
  noFill();
  stroke(Overlay.GUIDE);
  strokeWeight(1);
  float a0 = min(angle - (lastHit != null ? lastHit.t() * -spin : lastTurn), angle);
  float a1 = max(angle - (lastHit != null ? lastHit.t() * -spin : lastTurn), angle);
  arc(hubX, hubY, 2 * r, 2 * r, a0, a1, PIE);
  arc(hubX, hubY, 2 * r, 2 * r, a0 + PI, a1 + PI, PIE);
  stroke(Overlay.TEXT);
  Draw.shape(g, startBlade);
  String text = "turn this frame " + nf(lastTurn, 0, 2) + " rad: the tip moves " + Overlay.number(abs(lastTurn) * r) + " px";
  if (lastHit != null) {
    text += "\nhit at t = " + nf(lastHit.t(), 0, 2) + ", normal (" + Overlay.number(lastHit.nx()) + ", " + Overlay.number(lastHit.ny()) + ")";
  }
  Overlay.labelCentered(g, width / 2, 28, text, lastHit != null ? Overlay.HIT : Overlay.GUIDE);
}
