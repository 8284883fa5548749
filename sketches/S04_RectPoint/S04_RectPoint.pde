/**
 * Rectangle/Point
 * Tutorial section 4: Rectangle/Point
 *
 * A button: the mouse is over it when it is right of the left edge, left of the right edge,
 * below the top edge and above the bottom edge. The tutorial writes that two ways, as two
 * nested ifs (across, then down) and combined into one if with &&; n switches between
 * them, and the one chosen colours the button. They are the same test, even in the work they
 * do: && stops at the first comparison that is false, as the nested if does. Hitbox's
 * Collide.rectPoint is the combined if (it adds rectX + rectWidth in double, so the sum never
 * rounds); it runs beside them, both answers are written at the top, and l lets it colour the
 * button instead. The tutorial's "another if statement that also checks whether the mouse is
 * pressed" is written out too: pressed and over the button, the button is drawn pressed, and
 * a press there counts as a click.
 *
 * Try this: make several buttons from an array of rectangles; make the button move away
 * when hovered; change rectMode to CENTER and see which numbers have to change.
 * Keys: n nested if / combined if, l Collide.rectPoint decides / the tutorial's if, d shows
 * the maths (each comparison at its edge, the ones never reached greyed). Click the button.
 */
import hitbox.*;
import hitbox.processing.*;

// The button: top-left corner and size, Processing's rectMode(CORNER).
float rectX = 200;
float rectY = 150;
float rectWidth = 200;
float rectHeight = 100;

boolean nestedIf;       // n: the tutorial's nested ifs, or its combined if
boolean hitboxDecides;  // l: Collide.rectPoint decides instead of the tutorial's if
boolean hovered;        // the mouse is over the button, this frame
int clicks;             // clicks that landed on the button
boolean showMaths;      // d

void setup() {
  size(600, 400);
  textFont(createFont("SansSerif", 14));
}

void draw() {
  background(Palette.BACKGROUND);

  boolean tutorialSays = false;
  if (nestedIf) {
    //the tutorial's nested ifs: the second is reached only when the first holds
    if (mouseX > rectX && mouseX < rectX + rectWidth) {
      if (mouseY > rectY && mouseY < rectY + rectHeight) {
        tutorialSays = true;
      }
    }
  } else {
    //the tutorial's combined if
    if (mouseX > rectX && mouseX < rectX + rectWidth && mouseY > rectY && mouseY < rectY + rectHeight) {
      tutorialSays = true;
    }
  }
  //Hitbox's call, beside them: the combined if
  boolean hitboxSays = Collide.rectPoint(rectX, rectY, rectWidth, rectHeight, mouseX, mouseY);
  hovered = hitboxDecides ? hitboxSays : tutorialSays;

  noStroke();
  fill(hovered ? Palette.HIT : Palette.MISS);
  //the tutorial's other if: the mouse is pressed, and inside the rectangle
  if (mousePressed && hovered) {
    fill(Palette.ACCENT);   // drawn pressed
  }
  rect(rectX, rectY, rectWidth, rectHeight);
  fill(Palette.BACKGROUND);
  textAlign(CENTER, CENTER);
  textSize(24);
  text(clicks == 1 ? "1 click" : clicks + " clicks", rectX + rectWidth / 2, rectY + rectHeight / 2 - 3);
  drawLastClick();

  // The point: the mouse.
  stroke(Palette.BACKGROUND);
  strokeWeight(2);
  fill(Palette.NEUTRAL);
  circle(mouseX, mouseY, 9);

  if (showMaths) {
    drawMaths(hovered);
  } else {
    answer(8, 8, (nestedIf ? "the tutorial's nested ifs" : "the tutorial's combined if") + (hitboxDecides ? "" : " (decides)"), tutorialSays);
    answer(8, 30, "Collide.rectPoint" + (hitboxDecides ? " (decides)" : "") + (tutorialSays == hitboxSays ? ", agrees" : ", DISAGREES"), hitboxSays);
  }
  Overlay.hint(g, "hover over the button and click it     n: nested if / combined if     l: who decides     d: show the maths");
}

void mousePressed() {
  // The mouse was just pressed: a click, if it is inside the rectangle (the same if as the hover).
  if (hovered) {
    clicks++;
  }
  rememberClick(hovered);
}

void keyPressed() {
  if (key == 'n') {
    nestedIf = !nestedIf;
  } else if (key == 'l') {
    hitboxDecides = !hitboxDecides;
  } else if (key == 'd') {
    showMaths = !showMaths;
  }
}
