// The drawing, and the "show the maths" overlay (key d): the next-position boxes.

void drawScene() {
  background(Palette.BACKGROUND);
  //draw the center rectangle: a white outline, as the tutorial draws it
  noFill();
  stroke(255);
  strokeWeight(2);
  rect(centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  //draw the bouncing rectangle: blue, as in the tutorial's picture
  noStroke();
  if (showMaths) {
    // See-through, so the next-position boxes show around and under it.
    fill(Palette.PLAYER, 110);
    stroke(Palette.NEUTRAL);
    strokeWeight(1);
  } else {
    fill(Palette.PLAYER);
  }
  rect(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight);

  // Inside the center rectangle: what the checks were there to prevent. It is less than a
  // step deep, so a magnifier shows it 6 times bigger.
  PImage zoom = null;
  float ix = max(bouncingRectX, centerRectX), iy = max(bouncingRectY, centerRectY);
  if (Collide.rectRect(bouncingRectX, bouncingRectY, bouncingRectWidth, bouncingRectHeight,
      centerRectX, centerRectY, centerRectWidth, centerRectHeight)) {
    noStroke();
    fill(Palette.HIT);
    rect(ix, iy, min(bouncingRectX + bouncingRectWidth, centerRectX + centerRectWidth) - ix,
        min(bouncingRectY + bouncingRectHeight, centerRectY + centerRectHeight) - iy);
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
    Overlay.label(g, zx, zy + 126, "inside!\n(6 times bigger)", Overlay.HIT);
  }
  String way = library ? "Motion.blocked" : "the tutorial's code";
  Overlay.label(g, 8, 8, (paused ? "paused: n steps one frame, p goes on   " : "") + way);
  Overlay.label(g, 8, 30, "frames it ended inside the center rectangle: " + framesInside, framesInside > 0 ? Overlay.HIT : Overlay.MISS);
  Overlay.hint(g, "l: " + (library ? "the tutorial's code" : "Motion.blocked")
      + "   c: aim at the corner   p: pause   n: one frame   d: show the maths");
}

// The boxes the next frame's checks test, drawn where they are, each with its answer.
void drawMaths() {
  float nextX = bouncingRectX + bouncingRectSpeedX;
  float nextY = bouncingRectY + bouncingRectSpeedY;
  float w = bouncingRectWidth;
  float h = bouncingRectHeight;
  boolean hitX = Collide.rectRect(nextX, bouncingRectY, w, h, centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  boolean hitY = Collide.rectRect(bouncingRectX, nextY, w, h, centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  boolean hitBoth = Collide.rectRect(nextX, nextY, w, h, centerRectX, centerRectY, centerRectWidth, centerRectHeight);
  nextBox(nextX, bouncingRectY, hitX);
  nextBox(bouncingRectX, nextY, hitY);
  if (hitBoth && !hitX && !hitY) {
    // The corner case: neither axis alone hits, the diagonal move does.
    nextBox(nextX, nextY, true);
    Overlay.label(g, nextX + w + 6, nextY + h + 6, library
        ? "next across and down (corner): colliding,\nMotion.blocked reverses both"
        : "next across and down (corner): colliding,\nbut the tutorial's code never tests it", Overlay.HIT);
  }
  stroke(Palette.NEUTRAL);
  Draw.arrow(g, bouncingRectX + w / 2, bouncingRectY + h / 2, bouncingRectSpeedX * 8, bouncingRectSpeedY * 8);

  // The across check beside the side it moves to, the down check above or below.
  String sx = "nextBouncingLeft, nextBouncingRight = " + Overlay.number(nextX) + ", " + Overlay.number(nextX + w)
      + "\nwith the current top and bottom: " + (hitX ? "colliding: bouncingRectSpeedX *= -1" : "not colliding");
  String sy = "nextBouncingTop, nextBouncingBottom = " + Overlay.number(nextY) + ", " + Overlay.number(nextY + h)
      + "\nwith the current left and right: " + (hitY ? "colliding: bouncingRectSpeedY *= -1" : "not colliding");
  float lx = bouncingRectSpeedX > 0 ? bouncingRectX + w + 10 : bouncingRectX - 330;
  float ly = bouncingRectSpeedY > 0 ? bouncingRectY + h + 10 : bouncingRectY - 44;
  Overlay.label(g, constrain(lx, 4, width - 330), bouncingRectY, sx, hitX ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, constrain(bouncingRectX - 40, 4, width - 330), ly, sy, hitY ? Overlay.HIT : Overlay.MISS);
  Overlay.label(g, 8, 52, "bouncingRectSpeedX = " + Overlay.number(bouncingRectSpeedX)
      + "   bouncingRectSpeedY = " + Overlay.number(bouncingRectSpeedY));
}

void nextBox(float bx, float by, boolean colliding) {
  color colour = colliding ? Overlay.HIT : Overlay.MISS;
  pushStyle();
  fill(colour, 60);
  strokeWeight(2);
  stroke(colour);
  rect(bx, by, bouncingRectWidth, bouncingRectHeight);
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
