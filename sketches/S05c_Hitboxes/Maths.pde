// The tally, the hit box, and the "show the maths" overlay (key d).

// What the box and the rocket said about a rock this frame.
int NOTHING = 0, HIT = 1, FALSE_HIT = 2, MISS = 3;
color FALSE_HIT_COLOUR = #FFD23F;   // the box says hit, the rocket is untouched
color MISS_COLOUR = #B07CF0;        // the rocket is hit, the box says nothing
color CLEAR_COLOUR = #7A8290;

color colourOf(int verdict) {
  return verdict == HIT ? Palette.HIT : verdict == FALSE_HIT ? FALSE_HIT_COLOUR : verdict == MISS ? MISS_COLOUR : CLEAR_COLOUR;
}

/** Both said hit, or only one: counted in the tally. */
int judge(boolean boxHit, boolean shipHit) {
  if (boxHit && shipHit) {
    hits++;
    return HIT;
  } else if (boxHit) {
    falseHits++;
    return FALSE_HIT;
  } else if (shipHit) {
    misses++;
    return MISS;
  }
  return NOTHING;
}

/** A new box starts a new tally. */
void resize(float w, float h) {
  boxW = constrain(w, 4, 200);
  boxH = constrain(h, 4, 200);
  hits = 0;
  falseHits = 0;
  misses = 0;
}

void drawBox() {
  noFill();
  stroke(Palette.NEUTRAL);
  strokeWeight(1.5);
  rect(boxX(), boxY(), boxW, boxH);
  Overlay.labelBeside(g, boxX() + boxW, boxY(), 1, -1, "hit box " + (int) boxW + " x " + (int) boxH, Overlay.TEXT);
}

void drawTally() {
  int touching = hits + falseHits + misses;
  Overlay.label(g, 8, 8, "rock-frames touching the box or the rocket: " + touching
      + (touching > 0 ? "\nthe box was right in " + round(100.0 * hits / touching) + "%" : ""));
  Overlay.label(g, 8, 45, "both hit: " + hits, Palette.HIT);
  Overlay.label(g, 8, 67, "false hits (box only): " + falseHits, FALSE_HIT_COLOUR);
  Overlay.label(g, 8, 89, "misses (rocket only): " + misses, MISS_COLOUR);
}

/**
 * Where the mistakes come from: the box's area outside the rocket (a rock there is a false
 * hit) in yellow, the rocket's area outside the box (a rock there is missed) in purple, each
 * measured in pixels by testing every pixel's centre against both.
 */
void drawMaths() {
  // Inside the box: yellow, then the rocket over it. Outside the box: the rocket in purple.
  noStroke();
  fill(FALSE_HIT_COLOUR, 170);
  rect(boxX(), boxY(), boxW, boxH);
  ship.drawIn(MISS_COLOUR, MISS_COLOUR);
  clip(boxX(), boxY(), boxW, boxH);
  ship.draw();
  noClip();

  int shipArea = 0, boxOnly = 0, shipOnly = 0;
  for (int py = (int) ship.y - 110; py < ship.y + 110; py++) {
    for (int px = (int) ship.x - 110; px < ship.x + 110; px++) {
      boolean inShip = ship.contains(px + 0.5, py + 0.5);
      boolean inBox = Collide.rectPoint(boxX(), boxY(), boxW, boxH, px + 0.5, py + 0.5);
      shipArea += inShip ? 1 : 0;
      boxOnly += inBox && !inShip ? 1 : 0;
      shipOnly += inShip && !inBox ? 1 : 0;
    }
  }
  float lx = ship.x + 120;
  Overlay.label(g, lx, ship.y - 70, "rocket: " + shipArea + " px\u00B2\nhit box: " + (int) (boxW * boxH) + " px\u00B2");
  Overlay.label(g, lx, ship.y - 30, "box outside the rocket: " + boxOnly + " px\u00B2\nrocks here are false hits", FALSE_HIT_COLOUR);
  Overlay.label(g, lx, ship.y + 10, "rocket outside the box: " + shipOnly + " px\u00B2\nrocks here are missed", MISS_COLOUR);
  Overlay.label(g, lx, ship.y + 50, "box: Collide.rectRect(rock, box)\nrocket: body, leftFin or rightFin\n  .overlaps(rock)", Overlay.TEXT);
}
