// Homework 2: "Create an animation that shows 100 randomly placed obstacles, and 100 random
// rectangles that bounce off of them. When a bouncer hits an obstacle, change their color."
// Section 8's program twice over: a loop over the bouncers, and inside it section 8's loop over
// the obstacles with its two ifs on the next position (X, then Y); an obstacle glows red for a
// few frames when hit. Beside each if, the add-on's collideRectRect on the same next position
// (Hitbox's Collide.rectRect); the bottom line counts where they disagree (never: it is the
// same question) and l lets Hitbox's answer decide. Random obstacles overlap and leave gaps
// narrower than one move, where a flip inside the loop can send a bouncer into an obstacle:
// the count of bouncers caught inside one says how many are stuck now.
// 100 x 100 = 10,000 pairs a frame, a few comparisons each: no grid is needed.
const obstacleCount = 100, bouncerCount = 100, size = 8;
const obstacles = [], bouncers = [];
let hitboxDecides = false, disagreements = 0;

function randomSpeed() {
  return random(1, 2.5) * (random(1) < 0.5 ? -1 : 1);
}

// A bright random colour, never the one it had, never red ("hit" here).
function changeColour(b) {
  const old = b.hue;
  while (b.hue === old) b.hue = Math.floor(random(30, 330));
}

function setup() {
  createCanvas(600, 400);
  randomSeed(2);
  for (let i = 0; i < obstacleCount; i++) {
    const w = random(10, 26), h = random(10, 26);
    obstacles.push({ x: random(0, width - w), y: random(0, height - h), w, h, glow: 0 });
  }
  while (bouncers.length < bouncerCount) {
    const x = random(0, width - size), y = random(0, height - size);
    if (!obstacles.some((o) => collideRectRect(x, y, size, size, o.x, o.y, o.w, o.h))) {   // start in a free spot
      const b = { x, y, vx: randomSpeed(), vy: randomSpeed(), hue: -1 };
      changeColour(b);
      bouncers.push(b);
    }
  }
}

function draw() {
  background(32);
  for (const b of bouncers) {
    let hit = false;
    //iterate over the obstacles: section 8's loop, for this bouncer
    for (const o of obstacles) {
      //check X movement bounce
      const ifX = b.x + size + b.vx > o.x && b.x + b.vx < o.x + o.w && b.y + size > o.y && b.y < o.y + o.h;
      const hitboxX = collideRectRect(b.x + b.vx, b.y, size, size, o.x, o.y, o.w, o.h);
      if (ifX !== hitboxX) disagreements++;
      if (hitboxDecides ? hitboxX : ifX) {
        b.vx *= -1;
        o.glow = 10;
        hit = true;
      }
      //check Y movement bounce
      const ifY = b.x + size > o.x && b.x < o.x + o.w && b.y + size + b.vy > o.y && b.y + b.vy < o.y + o.h;
      const hitboxY = collideRectRect(b.x, b.y + b.vy, size, size, o.x, o.y, o.w, o.h);
      if (ifY !== hitboxY) disagreements++;
      if (hitboxDecides ? hitboxY : ifY) {
        b.vy *= -1;
        o.glow = 10;
        hit = true;
      }
    }
    //bounce off the edges of the window, where the bouncer is now, as section 6 does
    if (b.x < 0 || b.x + size > width) b.vx *= -1;
    if (b.y < 0 || b.y + size > height) b.vy *= -1;
    if (hit) changeColour(b);   // the homework: a hit changes its colour
    b.x += b.vx;
    b.y += b.vy;
  }
  noStroke();
  for (const o of obstacles) {
    fill(o.glow > 0 ? '#E8504A' : '#4C7CC3');
    rect(o.x, o.y, o.w, o.h);
    o.glow = Math.max(0, o.glow - 1);
  }
  colorMode(HSB, 360, 100, 100);
  for (const b of bouncers) {
    fill(b.hue, 70, 100);
    rect(b.x, b.y, size, size);
  }
  colorMode(RGB, 255);
  const caught = bouncers.filter((b) => obstacles.some((o) => collideRectRect(b.x, b.y, size, size, o.x, o.y, o.w, o.h))).length;
  fill(0, 180);
  rect(0, 382, width, 18);
  fill(255);
  text((hitboxDecides ? "l: Hitbox's collideRectRect decides" : "l: section 8's ifs decide") + ';  caught inside an obstacle: '
      + caught + ';  disagreements so far: ' + disagreements, 6, 396);
}

function keyPressed() {
  if (key === 'l') hitboxDecides = !hitboxDecides;
}
