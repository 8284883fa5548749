// Snapping to an edge (tutorial section 7): the player falls (gravity: playerSpeedY++ every
// frame in the air) and a key makes it jump unless it is already jumping. The frame it reaches
// the ground it is already a little inside; the tutorial's code snaps its bottom onto the
// ground: playerY = groundY - playerHeight. Keys: 1 stop where it is (a little inside),
// 2 check the next position first (stops short, floating), 3 the tutorial's snap (the
// default), 4 or l Hitbox's Snap.onGround and Snap.standY in the same places; any other key
// jumps. Where Hitbox differs: Snap.onGround counts standing exactly on the ground as on it
// (>=, the tutorial's test is >), so a standing player's speed stays 0.
let groundY = 350;
let playerX = 290;
let playerY = 100;
let playerWidth = 20;
let playerHeight = 50;
let playerSpeedY = 0;
//only allow jumping if the player is not already jumping
let jumping = false;
let way = 3;
const names = { 1: 'stop where it is: a little inside', 2: 'check the next position: floating above',
  3: "the tutorial's snap", 4: "Hitbox's Snap.onGround / Snap.standY" };

function setup() {
  createCanvas(600, 400);
}

function draw() {
  background(32);
  if (way === 1) {
    playerY += playerSpeedY;
    if (playerY + playerHeight > groundY) {
      playerSpeedY = 0;          // no snap: it stays where the move left it
      jumping = false;
    } else {
      playerSpeedY++;
    }
  } else if (way === 2) {
    playerSpeedY++;
    if (playerY + playerSpeedY + playerHeight > groundY) {
      playerSpeedY = 0;          // the next position is in the ground: stop short
      jumping = false;
    }
    playerY += playerSpeedY;
  } else if (way === 3) {
    //move the player
    playerY += playerSpeedY;
    //is the player colliding with the ground?
    if (playerY + playerHeight > groundY) {
      //snap the player's bottom to the ground's position
      playerY = groundY - playerHeight;
      //stop the player falling
      playerSpeedY = 0;
      //allow jumping again
      jumping = false;
    }
    //player is not colliding with the ground
    else {
      //gravity accelerates the movement speed
      playerSpeedY++;
    }
  } else {
    playerY += playerSpeedY;
    if (hitbox.Snap.onGround(playerY, playerHeight, groundY)) {
      playerY = hitbox.Snap.standY(playerHeight, groundY);
      playerSpeedY = 0;
      jumping = false;
    } else {
      playerSpeedY++;
    }
  }
  // under test: jump now and then, and try every way in turn
  if (window.scriptedRun && frameCount % 45 === 0) {
    way = way % 4 + 1;
    if (!jumping) {
      playerSpeedY = -15;
      jumping = true;
    }
  }

  //draw the ground
  stroke(255);
  line(0, groundY, width, groundY);
  noStroke();
  fill('#4CC36A');
  //draw the player rectangle
  rect(playerX, playerY, playerWidth, playerHeight);
  // the earth under the line, drawn over the player: what is inside the ground is hidden
  fill('#6B4F3F');
  rect(0, groundY + 1, width, height - groundY);
  fill(255);
  const gap = groundY - (playerY + playerHeight);
  text(way + ': ' + names[way], 10, 20);
  text('bottom - groundY: ' + nf(-gap, 1, 1) + (gap > 0 ? '  (above the ground)' : gap < 0 ? '  (inside it)' : '  (on it)')
      + '    Snap.onGround: ' + hitbox.Snap.onGround(playerY, playerHeight, groundY), 10, 40);
}

function keyPressed() {
  if ('1234l'.includes(key)) {
    way = key === 'l' ? 4 : Number(key);
    playerY = 100;
    playerSpeedY = 0;
  }
  //you can only jump if you aren't already jumping
  else if (!jumping) {
    //going up
    playerSpeedY = -15;
    //disallow jumping while already jumping
    jumping = true;
  }
}
