/**
 * Ball in a Circle
 * Tutorial section 3: Circle/Circle
 *
 * The tutorial's "try this" at the end of section 3: a ball that bounces off the edges of
 * the screen and also turns red when it is inside a circle at the center of the window. The
 * tutorial leaves the program to you; here it is, with two tests each frame, both the
 * tutorial's own and running by default: section 1's centre against the edges with the speed
 * multiplied by -1 (the ball goes half out of the window before it turns), and section 3's
 * circles, dist(x, y, circleCenterX, circleCenterY) < r + circleRadius. Red here means
 * "overlapping": the ball turns red as soon as it reaches in.
 *
 * Where Hitbox differs: at the edges. Press l for Hitbox's tests: it tests the ball's edge
 * against the window's (Edges, as in S01), sets the speed's sign and puts the ball back at
 * the edge; the circles are Collide.circleCircle, the same test compared squared.
 *
 * Try this: make it red only when wholly inside (dist + r < circleRadius); make the ball
 * bigger than the circle; add a second ball and test the two balls against each other.
 * Keys: l Hitbox's tests / the tutorial's, d shows the maths (distance, both radii,
 * dist < r + circleRadius, the edges crossed), space pauses, click puts the ball at the mouse.
 */
import hitbox.*;
import java.util.Set;
import hitbox.processing.*;

// The circle in the middle.
float circleCenterX = 300;
float circleCenterY = 200;
float circleRadius = 90;

// The ball: position, radius and speed (pixels a frame).
float x = 110;
float y = 90;
float r = 22;
float xSpeed = 3.3;
float ySpeed = 2.1;

boolean inside;      // does the ball overlap the circle? It is drawn red while it does
boolean hitboxDecides;  // l: Hitbox's tests instead of the tutorial's
boolean paused;      // space
boolean showMaths;   // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
  startTrail();
}

void draw() {
  background(Palette.BACKGROUND);
  if (!paused) {
    x += xSpeed;
    y += ySpeed;
    Set<Side> crossed;
    if (!hitboxDecides) {
      // Section 1 as the tutorial writes it: the centre past an edge, the speed flipped.
      if (x < 0 || x > width) {
        xSpeed *= -1;
      }
      if (y < 0 || y > height) {
        ySpeed *= -1;
      }
      crossed = Edges.crossed(new Circle(x, y, 0), width, height);   // only for the edge that lights up
    } else {
      // Hitbox's (S01): the ball's edge, the speed's sign set, then put back at the edge.
      crossed = Edges.crossed(new Circle(x, y, r), width, height);
      xSpeed = Edges.bounceX(crossed, xSpeed);
      ySpeed = Edges.bounceY(crossed, ySpeed);
      x = Edges.circleClampX(x, r, width);
      y = Edges.circleClampY(y, r, height);
    }
    addToTrail(crossed);
  }

  // Section 3: does the ball overlap the circle?
  if (!hitboxDecides) {
    inside = dist(x, y, circleCenterX, circleCenterY) < r + circleRadius;
  } else {
    inside = Collide.circleCircle(x, y, r, circleCenterX, circleCenterY, circleRadius);
  }

  // The circle: an obstacle the ball passes through.
  stroke(Palette.OBSTACLE);
  strokeWeight(2);
  fill(Palette.OBSTACLE, 50);
  circle(circleCenterX, circleCenterY, 2 * circleRadius);

  color ballColour = inside ? Palette.HIT : Palette.MISS;
  drawTrail(ballColour);
  noStroke();
  fill(ballColour);
  circle(x, y, 2 * r);

  if (showMaths) {
    drawMaths();
  }
  Overlay.hint(g, (hitboxDecides ? "Hitbox's tests (l: the tutorial's)" : "the tutorial's tests (l: Hitbox's)")
      + "     d: show the maths     space: pause     click: put the ball there");
  drawBounce();
}

void mousePressed() {
  x = Edges.circleClampX(mouseX, r, width);
  y = Edges.circleClampY(mouseY, r, height);
}

void keyPressed() {
  if (key == 'd') {
    showMaths = !showMaths;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == ' ') {
    paused = !paused;
  }
}
