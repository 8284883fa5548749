// The tally: what the box and the rocket said about each rock, counted.

// What the box and the rocket said about a rock this frame.
int NOTHING = 0, HIT = 1, FALSE_HIT = 2, MISS = 3;
color FALSE_HIT_COLOUR = #FFD23F;   // the box says hit, the rocket is untouched
color MISS_COLOUR = #B07CF0;        // the rocket is hit, the box says nothing
color CLEAR_COLOUR = #7A8290;

color colourOf(int verdict) {
  return verdict == HIT ? Palette.HIT : verdict == FALSE_HIT ? FALSE_HIT_COLOUR : verdict == MISS ? MISS_COLOUR : CLEAR_COLOUR;
}

/**
 * What the two tests said, counted in the tally. A rock the box let through was never tested
 * against the rocket; to count the misses, the tally tests it here, an exact test a game
 * would not run.
 */
int judge(boolean boxHit, boolean shipHit, Rock rock) {
  if (boxHit && shipHit) {
    hits++;
    return HIT;
  } else if (boxHit) {
    falseHits++;
    return FALSE_HIT;
  } else if (ship.touches(new Rect(rock.x, rock.y, rock.size, rock.size))) {
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
  rockTests = 0;
  exactTests = 0;
}

void drawTally() {
  int touching = hits + falseHits + misses;
  Overlay.label(g, 8, 8, "rock-frames touching the box or the rocket: " + touching
      + (touching > 0 ? "\nthe box was right in " + round(100.0 * hits / touching) + "%" : ""));
  Overlay.label(g, 8, 45, "both hit: " + hits, Palette.HIT);
  Overlay.label(g, 8, 67, "false hits (box only): " + falseHits, FALSE_HIT_COLOUR);
  Overlay.label(g, 8, 89, "misses (rocket only): " + misses, MISS_COLOUR);
  Overlay.label(g, 8, 111, "box tests: " + rockTests + ", exact tests after a box hit: " + exactTests);
}
