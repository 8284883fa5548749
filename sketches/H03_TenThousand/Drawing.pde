// Drawing 10,000 bouncers (the maths overlay is in Maths.pde).

// 10,000 rect() calls are slow: each bouncer is written straight into the pixels.
void drawBouncers() {
  loadPixels();
  int calm = Palette.PLAYER;
  int hit = Palette.HIT;
  for (int i = 0; i < active; i++) {
    int c = flash[i] > 0 ? hit : calm;
    flash[i] = max(0, flash[i] - 1);
    int left = (int) x[i];
    int top = (int) y[i];
    for (int py = top; py < top + size && py < height; py++) {
      for (int px = left; px < left + size && px < width; px++) {
        pixels[py * width + px] = c;
      }
    }
  }
  updatePixels();
}
