// The whole exported API of hitbox.js and p5.hitbox.js, used once each, so that the hand-written
// .d.ts files are checked by tsc --strict --noEmit (gradle webTypes, within gradle test). Never
// run: it only has to compile.
import * as H from '../../js/hitbox.js';
import { functions, hitboxAddon, addTo, ready } from '../../js/p5.hitbox.js';
import type { Body, BodyEvent, BodyHit, Box, Character, CharacterSettings, Collision, Contact, Grid, Hit, Points, RayHit,
  Reaction, Separation, Shape } from '../../js/hitbox.js';

const points: Points[] = [[0, 0, 10, 0, 0, 10], [[0, 0], [10, 0], [0, 10]], [{ x: 0, y: 0 }, { x: 10, y: 0 }, { x: 0, y: 10 }]];
const shapes: Shape[] = [H.circle(0, 0, 1), H.rect(0, 0, 2, 3), H.segment(0, 0, 1, 1), H.polygon(points[1]),
  H.ellipse(0, 0, 2, 1), H.ellipse(0, 0, 2, 1, 0.5), H.capsule(0, 0, 5, 0, 1)];
const flat: number[] = H.flat(points[2]);
const a: Shape = shapes[0], b: Shape = shapes[1];
const kind: 'Circle' | 'Rect' | 'Segment' | 'Polygon' | 'Ellipse' | 'Capsule' = a.kind;
const box: Box = a.bounds;
const overlap: boolean = a.overlaps(b) && a.contains(0, 0) && a.containsShape(b);
const contact: Contact | null = a.contact(b);
const gap: Separation = a.separation(b);
const hit: Hit | null = a.sweep(10, 0, b);
const side: string | undefined = hit?.side;
const ray: RayHit | null = a.raycast(0, 0, 1, 0, Infinity);
const moved: Shape = a.translated(1, 2).rotated(0.5, 0, 0);
const described: string = moved.toString();
const numbers: number[] = [H.separationCircleCircle(0, 0, 1, 3, 0, 1), H.sweepRectRect(0, 0, 1, 1, 5, 0, 3, 0, 1, 1), H.loadMillis,
  H.Snap.standY(10, 100), H.Snap.landY(95, 10, 100), gap.distance + gap.ax + gap.ay + gap.bx + gap.by, box.x + box.y + box.w + box.h,
  contact ? contact.nx + contact.ny + contact.depth : 0, ray ? ray.distance + ray.x + ray.y + ray.nx + ray.ny : 0, flat.length];
const tests: boolean[] = [H.Snap.onGround(90, 10, 100), H.Collide.circlePoint(0, 0, 1, 0, 0), H.Collide.circleCircle(0, 0, 1, 1, 0, 1),
  H.Collide.rectPoint(0, 0, 1, 1, 0, 0), H.Collide.rectRect(0, 0, 1, 1, 0, 0, 1, 1), H.Collide.circleRect(0, 0, 1, 0, 0, 1, 1),
  H.Collide.rectCircle(0, 0, 1, 1, 0, 0, 1), H.Collide.rectContainsRect(0, 0, 1, 1, 0, 0, 1, 1),
  H.Collide.circleContainsCircle(0, 0, 1, 0, 0, 1), H.Collide.circleContainsRect(0, 0, 1, 0, 0, 1, 1),
  H.Collide.rectContainsCircle(0, 0, 1, 1, 0, 0, 1), H.Collide.polygonPoint(flat, 0, 0), H.Collide.rayCrossesEdge(0, 0, 1, 1, 0, 0),
  H.Collide.lineSide(0, 0, 1, 1, 0, 0) > 0, H.Collide.lineLine(0, 0, 1, 1, 0, 1, 1, 0), H.Collide.lineCircle(0, 0, 1, 1, 0, 0, 1),
  H.Collide.lineRect(0, 0, 1, 1, 0, 0, 1, 1), H.Collide.polygonCircle(flat, 0, 0, 1), H.Collide.polygonRect(flat, 0, 0, 1, 1),
  H.Collide.polygonLine(flat, 0, 0, 1, 1), H.Collide.polygonPolygon(flat, flat), H.Collide.trianglePoint(0, 0, 1, 0, 0, 1, 0, 0),
  H.Collide.ellipsePoint(0, 0, 1, 1, 0, 0), H.Collide.ellipseCircle(0, 0, 1, 1, 0, 0, 1), H.Collide.ellipseRect(0, 0, 1, 1, 0, 0, 1, 1),
  H.Collide.ellipseLine(0, 0, 1, 1, 0, 0, 1, 1), H.Collide.ellipseEllipse(0, 0, 1, 1, 0, 0, 1, 1), H.Collide.polygonEllipse(flat, 0, 0, 1, 1),
  H.Collide.ellipseCapsule(0, 0, 1, 1, 0, 0, 1, 1, 1), H.Collide.capsulePoint(0, 0, 1, 1, 1, 0, 0),
  H.Collide.capsuleCircle(0, 0, 1, 1, 1, 0, 0, 1), H.Collide.capsuleRect(0, 0, 1, 1, 1, 0, 0, 1, 1),
  H.Collide.capsuleLine(0, 0, 1, 1, 1, 0, 0, 1, 1), H.Collide.capsuleCapsule(0, 0, 1, 1, 1, 0, 0, 1, 1, 1),
  H.Collide.polygonCapsule(flat, 0, 0, 1, 1, 1), H.Collide.arcPoint(0, 0, 1, 1, 0, 1, 0, 0, 0)];

// The world, its bodies and a character.
const world = new H.World();
const wall: Body = world.add(H.rect(100, 0, 10, 100)).sensor(false).oneWay('NONE').moveTo(100, 0).turnTo(0);
const grid: Grid = H.Grid.parse('..#\n...', 10);
const gridBody: Body = world.addGrid(grid);
const hero: Character = world.addCharacter(H.rect(0, 0, 10, 20)).maxSlope(50).stepHeight(6).snap(4).up(0, -1);
const reaction: Reaction = 'SLIDE';
const met: Collision[] = hero.move(3, 1, reaction).concat(world.move(wall, 1, 0, null), world.move(gridBody, 0, 0, 'BOUNCE'));
for (const c of met) {
  const other: Body = c.other;
  const landed: boolean = c.landed;
  console.log(other.id, other.pivotX, other.pivotY, other.angle, other.shape.kind, other.isSensor, c.reaction, c.t, c.nx, c.ny, c.side, c.x, c.y, landed);
}
const state: boolean = hero.onGround || hero.onWall || hero.onCeiling;
const ground: Body | null = hero.ground;
const normal: { x: number; y: number } | null = hero.groundNormal;
const settings: CharacterSettings = hero.settings;
const heroBody: Body = hero.body;
const events: BodyEvent[] = world.step();
for (const e of events) console.log(e.kind, e.a.id, e.b.id);
const found: Body[] = world.queryPoint(0, 0).concat(world.overlapping(heroBody));
const seen: BodyHit | null = world.raycast(0, 0, 1, 0, 100);
world.remove(wall);
const count: number = world.size() + (seen ? seen.body.id + seen.distance + seen.x + seen.y + seen.nx + seen.ny : 0);

// The grid.
const g2: Grid = new H.Grid(4, 3, 10);
g2.set(1, 1, 1);
const cells: number = g2.cols + g2.rows + g2.cellWidth + g2.cellHeight + g2.get(0, 0) + g2.colAt(5) + g2.rowAt(5);
const gridAnswers: boolean = g2.isSolid(1, 1) && g2.rectOverlapsSolid(0, 0, 5, 5) && g2.circleOverlapsSolid(5, 5, 2) && g2.lineOfSight(0, 0, 30, 20);
const route: Int32Array = g2.path(0, 0, 3, 2);
const slid: { x: number; y: number; vx: number; vy: number; sides: number } = g2.move(0, 0, 5, 5, 10, 0);

// The p5.js add-on.
const v = { x: 1, y: 2 };
const polyV = [{ x: 0, y: 0 }, { x: 10, y: 0 }, { x: 0, y: 10 }];
const f = functions;
const addonAnswers: boolean[] = [f.collideRectRect(0, 0, 1, 1, 0, 0, 1, 1), f.collideCircleCircle(0, 0, 2, 1, 0, 2),
  f.collideRectCircle(0, 0, 1, 1, 0, 0, 2), f.collidePointCircle(0, 0, 0, 0, 2), f.collidePointEllipse(0, 0, 0, 0, 2, 1),
  f.collidePointRect(0, 0, 0, 0, 1, 1), f.collidePointLine(0, 0, 0, 0, 1, 1), f.collidePointLine(0, 0, 0, 0, 1, 1, 0.5),
  f.collideLineCircle(0, 0, 1, 1, 0, 0, 2), f.collidePointPoly(1, 1, polyV), f.collideCirclePoly(1, 1, 2, polyV),
  f.collideCirclePoly(1, 1, 2, polyV, true), f.collideRectPoly(0, 0, 1, 1, polyV, false), f.collideLinePoly(0, 0, 1, 1, polyV),
  f.collidePolyPoly(polyV, polyV), f.collidePolyPoly(polyV, polyV, true), f.collidePointTriangle(0, 0, 0, 0, 1, 0, 0, 1),
  f.collidePointArc(0, 0, 0, 0, 10, 0, 1), f.collidePointArc(0, 0, 0, 0, 10, 0, 1, 0.1),
  f.collideRectRectVector(v, v, v, v), f.collideCircleCircleVector(v, 1, v, 1), f.collideRectCircleVector(v, v, v, 1),
  f.collidePointCircleVector(v, v, 1), f.collidePointEllipseVector(v, v, v), f.collidePointRectVector(v, v, v),
  f.collidePointLineVector(v, v, v), f.collidePointLineVector(v, v, v, 0.1), f.collideLineCircleVector(v, v, v, 1),
  f.collidePointPolyVector(v, polyV), f.collideCirclePolyVector(v, 1, polyV), f.collideRectPolyVector(v, v, polyV, true),
  f.collideLinePolyVector(v, v, polyV), f.collidePolyPolyVector(polyV, polyV, false), f.collidePointTriangleVector(v, v, v, v),
  f.collidePointArcVector(v, v, 10, 0, 1, 0.1)];
const crossing: boolean | { x: number | false; y: number | false } = f.collideLineLine(0, 0, 1, 1, 0, 1, 1, 0, true);
const crossingV: boolean | { x: number | false; y: number | false } = f.collideLineLineVector(v, v, v, v, true);
const sides: boolean | object = f.collideLineRect(0, 0, 1, 1, 0, 0, 1, 1, true);
const sidesV: boolean | object = f.collideLineRectVector(v, v, v, v, false);
f.collideDebug(true);
hitboxAddon({}, {});
addTo({});
ready.then((m: typeof H) => m.Collide.circleCircle(0, 0, 1, 1, 0, 1));

export const used = [kind, overlap, side, described, numbers, tests, state, ground, normal, settings, found, count, cells,
  gridAnswers, route, slid, addonAnswers, crossing, crossingV, sides, sidesV];
