// The tutorial's if statements again, with the numbers changed to a box's edges (key e): "Just
// change the numbers in the if statements to change where the edges are!"

/** The tutorial's two ifs, the centre against 150..450 across and 100..300 down. */
void boxIfs() {
  if (x < 150 || x > 450) {
    xSpeed *= -1;
    bounced = true;
  }
  if (y < 100 || y > 300) {
    ySpeed *= -1;
    bounced = true;
  }
}
