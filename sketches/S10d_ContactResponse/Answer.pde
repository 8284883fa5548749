/**
 * One contact and what was done about it: which shape (its index: the shapes, then the
 * window's edges), the contact and its contact point (the manifold), where the ball was before the push out and after it, and the
 * velocity just before and just after the response.
 */
class Answer {
  int shape;
  Contact contact;
  Manifold touch;
  float ghostX, ghostY;
  float x, y;
  Vec before, after;

  Answer(int shape, Contact contact, Manifold touch, float ghostX, float ghostY, float x, float y, Vec before, Vec after) {
    this.shape = shape;
    this.contact = contact;
    this.touch = touch;
    this.ghostX = ghostX;
    this.ghostY = ghostY;
    this.x = x;
    this.y = y;
    this.before = before;
    this.after = after;
  }
}
