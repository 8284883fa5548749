// The two routes to the goal (click sets it): the shortest, the fewest steps, and the cheapest,
// where a step costs the time it takes to cross the cell it enters. Hitbox's grid.path; the
// section names no routes, this is beyond it.

PathCosts costs = PathCosts.byTerrain(1, Float.POSITIVE_INFINITY, 3);  // the time to cross a cell
boolean diagonals = false;
int goalCol = 28;
int goalRow = 3;
int[] shortest = new int[0];
int[] cheapest = new int[0];

void findRoutes() {
  PathCosts steps = diagonals ? PathCosts.steps().withDiagonals() : PathCosts.steps();
  shortest = grid.path(playerCol(), playerRow(), goalCol, goalRow, steps);
  cheapest = grid.path(playerCol(), playerRow(), goalCol, goalRow, diagonals ? costs.withDiagonals() : costs);
}
