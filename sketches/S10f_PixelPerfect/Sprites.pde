// The sprites, drawn in code on transparent squares, and their pixel masks.

PixelMask mask(PGraphics sprite) {
  sprite.loadPixels();
  return PixelMask.fromPixels(sprite.pixels, sprite.width, sprite.height, 127);
}

// A five-pointed star in white on a transparent square.
PGraphics starSprite(int size, float outer, float inner) {
  PGraphics s = createGraphics(size, size);
  s.beginDraw();
  s.clear();
  s.noStroke();
  s.fill(255);
  s.beginShape();
  for (int i = 0; i < 10; i++) {
    float a = -HALF_PI + i * PI / 5;
    float rr = i % 2 == 0 ? outer : inner;
    s.vertex(size / 2.0 + rr * cos(a), size / 2.0 + 3 + rr * sin(a));
  }
  s.endShape(CLOSE);
  s.endDraw();
  return s;
}

// A ring (a thick circle outline) in white on a transparent square.
PGraphics ringSprite(int size, float radius, float thickness) {
  PGraphics s = createGraphics(size, size);
  s.beginDraw();
  s.clear();
  s.noFill();
  s.stroke(255);
  s.strokeWeight(thickness);
  s.circle(size / 2.0, size / 2.0, 2 * radius);
  s.endDraw();
  return s;
}

// The crowd: small stars spread over the window on a jittered grid (seeded: the same
// every run).
void placeCrowd() {
  randomSeed(3);
  for (int i = 0; i < crowdX.length; i++) {
    crowdX[i] = 20 + (i % 8) * 72 + (int) random(0, 30);
    crowdY[i] = 60 + (i / 8) * 44 + (int) random(0, 14);
  }
}

// A white sprite drawn in a colour.
void sprite(PGraphics s, int x, int y, color colour, int alpha) {
  tint(colour, alpha);
  image(s, x, y);
  noTint();
}
