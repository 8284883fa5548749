// The drawing, and the "show the maths" overlay (key d): the next-position boxes.

void drawScene() {
  background(Palette.BACKGROUND);
  // The block glows red for a moment after each bounce off it.
  fill(Palette.OBSTACLE);
  if (flash > 0) {
    stroke(Palette.HIT);
    strokeWeight(4);
  } else {
    noStroke();
  }
  rect(blockX, blockY, blockW, blockH);
  noStroke();
  if (showMaths) {
    // See-through, so the next-position boxes show around and under it.
    fill(Palette.PLAYER, 110);
    stroke(Palette.NEUTRAL);
    strokeWeight(1);
  } else {
    fill(Palette.PLAYER);
  }
  rect(x, y, w, h);

  // Inside the block: what the checks were there to prevent. It is less than a step deep,
  // so a magnifier shows it 6 times bigger.
  PImage zoom = null;
  float ix = max(x, blockX), iy = max(y, blockY);
  if (Collide.rectRect(x, y, w, h, blockX, blockY, blockW, blockH)) {
    noStroke();
    fill(Palette.HIT);
    rect(ix, iy, min(x + w, blockX + blockW) - ix, min(y + h, blockY + blockH) - iy);
    zoom = get((int) ix - 10, (int) iy - 10, 20, 20);
  }

  if (showMaths) {
    drawMaths();
  }
  if (zoom != null) {
    float zx = width - 140, zy = 60;
    stroke(Overlay.HIT);
    strokeWeight(1.5);
    line(ix, iy, zx, zy + 60);
    image(magnified(zoom, 6), zx, zy);
    noFill();
    rect(zx, zy, 120, 120);
    Overlay.label(g, zx, zy + 126, "inside the block!\n(6 times bigger)", Overlay.HIT);
  }
  String way = tutorialWay ? "the tutorial's code" : "Motion.rectBlocked: " + Motion.describe(blocked);
  Overlay.label(g, 8, 8, (paused ? "paused: n steps one frame, p goes on   " : "") + way);
  Overlay.label(g, 8, 30, "frames the box ended inside the block: " + framesInside, framesInside > 0 ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "t: " + (tutorialWay ? "Motion.rectBlocked" : "the tutorial's code")
      + "   c: aim at the corner   p: pause   n: one frame   d: show the maths");
}

// The boxes the next frame's checks test, drawn where they are, each with its answer.
void drawMaths() {
  boolean hitX = Collide.rectRect(x + vx, y, w, h, blockX, blockY, blockW, blockH);
  boolean hitY = Collide.rectRect(x, y + vy, w, h, blockX, blockY, blockW, blockH);
  boolean hitBoth = Collide.rectRect(x + vx, y + vy, w, h, blockX, blockY, blockW, blockH);
  nextBox(x + vx, y, hitX);
  nextBox(x, y + vy, hitY);
  if (hitBoth && !hitX && !hitY) {
    // The corner case: neither axis alone hits, the diagonal move does.
    nextBox(x + vx, y + vy, true);
    Overlay.label(g, x + vx + w + 6, y + vy + h + 6, tutorialWay
        ? "next x and y (corner): colliding,\nbut the tutorial's code never tests it"
        : "next x and y (corner): colliding,\nMotion.rectBlocked reverses both", Overlay.HIT);
  }
  stroke(Palette.NEUTRAL);
  Draw.arrow(g, x + w / 2, y + h / 2, vx * 8, vy * 8);

  // "next x" on the side the box is moving to across, "next y" on the side it moves to down.
  String sx = "next x: (x + vx, y) = (" + Overlay.number(x + vx) + ", " + Overlay.number(y) + ")\n"
      + (hitX ? "colliding: reverse vx" : "not colliding");
  String sy = "next y: (x, y + vy) = (" + Overlay.number(x) + ", " + Overlay.number(y + vy) + ")\n"
      + (hitY ? "colliding: reverse vy" : "not colliding");
  float lx = vx > 0 ? x + w + 10 : x - 200;
  float ly = vy > 0 ? y + h + 10 : y - 44;
  Overlay.label(g, lx, y, sx, hitX ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, x - 40, ly, sy, hitY ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, 8, 52, "vx = " + Overlay.number(vx) + "   vy = " + Overlay.number(vy)
      + "\nwindow: Edges.rectCrossed(next) = " + Edges.describe(Edges.rectCrossed(x + vx, y + vy, w, h, width, height)));
}

void nextBox(float bx, float by, boolean colliding) {
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  pushStyle();
  fill(colour, 60);
  strokeWeight(2);
  stroke(colour);
  rect(bx, by, w, h);
  popStyle();
}

/** An image made n times bigger, each pixel a sharp n x n square. */
PImage magnified(PImage small, int n) {
  PImage big = createImage(small.width * n, small.height * n, RGB);
  small.loadPixels();
  big.loadPixels();
  for (int i = 0; i < big.pixels.length; i++) {
    int bx = i % big.width, by = i / big.width;
    big.pixels[i] = small.pixels[(by / n) * small.width + bx / n];
  }
  big.updatePixels();
  return big;
}
