// The "show the maths" overlay (d): the tests this frame, and a look at the structure.

float lensW = 200;
float lensH = 150;

void drawMaths() {
  BroadPhase world = structures[current];
  // The structure's own cells (grid cells, quadtree squares, the dynamic tree's boxes) in a
  // box around the mouse: all of them at once would cover the window.
  float lx = mouseX - lensW / 2;
  float ly = mouseY - lensH / 2;
  noFill();
  stroke(Palette.ACCENT);
  world.cells((depth, cx, cy, cw, ch) -> {
    if (Collide.rectRect(cx, cy, cw, ch, lx, ly, lensW, lensH)) {
      float x0 = max(cx, lx), y0 = max(cy, ly);
      rect(x0, y0, min(cx + cw, lx + lensW) - x0, min(cy + ch, ly + lensH) - y0);
    }
  });
  strokeWeight(2);
  rect(lx, ly, lensW, lensH);
  strokeWeight(1);
  long boxes = active + obstacleCount;
  long allPairs = boxes * (boxes - 1) / 2;
  String text = "boxes: " + nfc(active) + " bouncers + " + obstacleCount + " obstacles = " + nfc((int) boxes)
      + "\nan all-pairs loop: n(n-1)/2 = " + nfc(allPairs) + " tests"
      + "\n" + world + ": " + nfc(world.checks()) + " tests (" + nf(100.0 * world.checks() / allPairs, 0, 3) + "%)"
      + "\noverlapping pairs: " + nfc(pairsThisFrame) + ", of them bounces: " + nfc(hitsThisFrame);
  Overlay.label(g, 8, 60, text);
}

String nfc(long v) {
  return String.format("%,d", v);
}
