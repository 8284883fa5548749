// The coins: objects in the grid's cells, several to a cell in places.

class Coin {
  float x;
  float y;
  float radius = 3;

  Coin(float x, float y) {
    this.x = x;
    this.y = y;
  }
}

int collected = 0;   // coins picked up so far
int looked = 0;      // coins looked at this frame: only those in the cells under the player
int placed = 0;

// 24 cells of grass or forest get 1 to 3 coins each, the same ones every run.
void placeCoins() {
  randomSeed(9);
  int cells = 0;
  while (cells < 24) {
    int row = int(random(rows));
    int column = int(random(columns));
    if (terrain[row][column] == WATER || coins[row][column].size() > 0 || (row == 3 && column == 1)) {
      continue;   // not in the water, not twice in a cell, not under the player at the start
    }
    int n = 1 + int(random(3));
    for (int i = 0; i < n; i++) {
      coins[row][column].add(new Coin(column * cell + 4 + random(cell - 8), row * cell + 4 + random(cell - 8)));
      placed++;
    }
    cells++;
  }
}

void drawCoins() {
  pushStyle();
  stroke(0, 120);
  fill(#F2C94C);
  for (int row = 0; row < rows; row++) {
    for (int column = 0; column < columns; column++) {
      for (Coin coin : coins[row][column]) {
        circle(coin.x, coin.y, 2 * coin.radius);
      }
    }
  }
  popStyle();
  Overlay.label(g, 470, 8, "coins: " + collected + " of " + placed);
}
