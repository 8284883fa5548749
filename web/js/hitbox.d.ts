// Types of the Hitbox browser module (hitbox.js). Numbers are taken as float32, as in Java.

/** How to push the first shape out of the second: the normal points from the first to the second. */
export interface Contact { nx: number; ny: number; depth: number; }
/** The gap between two shapes and their nearest points (distance negative when they overlap). */
export interface Separation { distance: number; ax: number; ay: number; bx: number; by: number; }
/** A swept hit: t in [0, 1] along the move, the normal, and the side hit. */
export interface Hit { t: number; nx: number; ny: number; side: 'NONE' | 'TOP' | 'BOTTOM' | 'LEFT' | 'RIGHT'; }
/** Where a ray first meets a shape. */
export interface RayHit { distance: number; x: number; y: number; nx: number; ny: number; }
export interface Box { x: number; y: number; w: number; h: number; }
/** Corners as [x0, y0, x1, y1, ...], [[x, y], ...] or [{x, y}, ...]. */
export type Points = number[] | [number, number][] | { x: number; y: number }[];

/** One of the six shapes: immutable; every question in either order of a pair. */
export interface Shape {
  readonly kind: 'Circle' | 'Rect' | 'Segment' | 'Polygon' | 'Ellipse' | 'Capsule';
  readonly bounds: Box;
  overlaps(other: Shape): boolean;
  contact(other: Shape): Contact | null;
  separation(other: Shape): Separation;
  contains(x: number, y: number): boolean;
  containsShape(other: Shape): boolean;
  sweep(vx: number, vy: number, obstacle: Shape): Hit | null;
  raycast(ox: number, oy: number, dx: number, dy: number, maxDistance: number): RayHit | null;
  translated(dx: number, dy: number): Shape;
  rotated(angle: number, pivotX: number, pivotY: number): Shape;
  toString(): string;
}

export function circle(cx: number, cy: number, r: number): Shape;
export function rect(left: number, top: number, w: number, h: number): Shape;
export function segment(x1: number, y1: number, x2: number, y2: number): Shape;
export function polygon(points: Points): Shape;
export function ellipse(cx: number, cy: number, rx: number, ry: number, angle?: number): Shape;
export function capsule(x1: number, y1: number, x2: number, y2: number, r: number): Shape;
export function flat(points: Points): number[];
export function separationCircleCircle(x1: number, y1: number, r1: number, x2: number, y2: number, r2: number): number;
export function sweepRectRect(x: number, y: number, w: number, h: number, vx: number, vy: number,
                              ox: number, oy: number, ow: number, oh: number): number;
/** The WebAssembly module's own exports, for the tests; not part of the API. */
export const raw: unknown;
/** Milliseconds the module took to load and compile. */
export const loadMillis: number;

/** The tutorial's tests as calls on numbers; polygons as flat arrays [x0, y0, x1, y1, ...]. */
export const Collide: {
  circlePoint(cx: number, cy: number, r: number, px: number, py: number): boolean;
  circleCircle(x1: number, y1: number, r1: number, x2: number, y2: number, r2: number): boolean;
  rectPoint(rectX: number, rectY: number, rectW: number, rectH: number, px: number, py: number): boolean;
  rectRect(x1: number, y1: number, w1: number, h1: number, x2: number, y2: number, w2: number, h2: number): boolean;
  circleRect(cx: number, cy: number, r: number, rectX: number, rectY: number, rectW: number, rectH: number): boolean;
  rectCircle(x: number, y: number, w: number, h: number, cx: number, cy: number, r: number): boolean;
  rectContainsRect(x1: number, y1: number, w1: number, h1: number, x2: number, y2: number, w2: number, h2: number): boolean;
  circleContainsCircle(x1: number, y1: number, r1: number, x2: number, y2: number, r2: number): boolean;
  circleContainsRect(cx: number, cy: number, r: number, rectX: number, rectY: number, rectW: number, rectH: number): boolean;
  rectContainsCircle(x: number, y: number, w: number, h: number, cx: number, cy: number, r: number): boolean;
  polygonPoint(xy: number[], px: number, py: number): boolean;
  rayCrossesEdge(ax: number, ay: number, bx: number, by: number, px: number, py: number): boolean;
  lineSide(x1: number, y1: number, x2: number, y2: number, px: number, py: number): number;
  lineLine(x1: number, y1: number, x2: number, y2: number, x3: number, y3: number, x4: number, y4: number): boolean;
  lineCircle(x1: number, y1: number, x2: number, y2: number, cx: number, cy: number, r: number): boolean;
  lineRect(x1: number, y1: number, x2: number, y2: number, rectX: number, rectY: number, rectW: number, rectH: number): boolean;
  polygonCircle(xy: number[], cx: number, cy: number, r: number): boolean;
  polygonRect(xy: number[], rectX: number, rectY: number, rectW: number, rectH: number): boolean;
  polygonLine(xy: number[], x1: number, y1: number, x2: number, y2: number): boolean;
  polygonPolygon(a: number[], b: number[]): boolean;
  trianglePoint(x1: number, y1: number, x2: number, y2: number, x3: number, y3: number, px: number, py: number): boolean;
  ellipsePoint(x: number, y: number, radiusX: number, radiusY: number, px: number, py: number): boolean;
  ellipseCircle(x: number, y: number, radiusX: number, radiusY: number, cx: number, cy: number, r: number): boolean;
  ellipseRect(x: number, y: number, radiusX: number, radiusY: number, rectX: number, rectY: number, rectW: number, rectH: number): boolean;
  ellipseLine(x: number, y: number, radiusX: number, radiusY: number, x1: number, y1: number, x2: number, y2: number): boolean;
  ellipseEllipse(x1: number, y1: number, radiusX1: number, radiusY1: number, x2: number, y2: number, radiusX2: number, radiusY2: number): boolean;
  polygonEllipse(xy: number[], x: number, y: number, radiusX: number, radiusY: number): boolean;
  ellipseCapsule(x: number, y: number, radiusX: number, radiusY: number, x1: number, y1: number, x2: number, y2: number, r: number): boolean;
  capsulePoint(x1: number, y1: number, x2: number, y2: number, r: number, px: number, py: number): boolean;
  capsuleCircle(x1: number, y1: number, x2: number, y2: number, r1: number, cx: number, cy: number, r2: number): boolean;
  capsuleRect(x1: number, y1: number, x2: number, y2: number, r: number, rectX: number, rectY: number, rectW: number, rectH: number): boolean;
  capsuleLine(x1: number, y1: number, x2: number, y2: number, r: number, x3: number, y3: number, x4: number, y4: number): boolean;
  capsuleCapsule(x1: number, y1: number, x2: number, y2: number, r1: number, x3: number, y3: number, x4: number, y4: number, r2: number): boolean;
  polygonCapsule(xy: number[], x1: number, y1: number, x2: number, y2: number, r: number): boolean;
  arcPoint(x: number, y: number, radiusX: number, radiusY: number, start: number, stop: number, mode: number, px: number, py: number): boolean;
};

export interface Body {
  readonly id: number;
  /** Where its pivot stands (Java's Body.pivotX/pivotY): for world.add(shape), the centre of the shape's bounds. */
  readonly pivotX: number;
  readonly pivotY: number;
  readonly angle: number;
  readonly shape: Shape;
  readonly isSensor: boolean;
  moveTo(x: number, y: number): Body;
  turnTo(angle: number): Body;
  sensor(sensor: boolean): Body;
  oneWay(side: 'NONE' | 'TOP' | 'BOTTOM' | 'LEFT' | 'RIGHT'): Body;
}
export type Reaction = 'SLIDE' | 'TOUCH' | 'CROSS' | 'BOUNCE';
export interface Collision { other: Body; reaction: Reaction; t: number; nx: number; ny: number; side: string; x: number; y: number; landed: boolean; }
export interface BodyEvent { kind: 'ENTER' | 'STAY' | 'EXIT'; a: Body; b: Body; }
export interface BodyHit { body: Body; distance: number; x: number; y: number; nx: number; ny: number; }

export class World {
  constructor();
  add(shape: Shape): Body;
  /** A body that walks: stands on ground, walks slopes, climbs steps (Java's CharacterBody). */
  addCharacter(shape: Shape): Character;
  addGrid(grid: Grid): Body;
  remove(body: Body): void;
  size(): number;
  move(body: Body, dx: number, dy: number, reaction: Reaction | null): Collision[];
  step(): BodyEvent[];
  queryPoint(x: number, y: number): Body[];
  overlapping(body: Body): Body[];
  raycast(ox: number, oy: number, dx: number, dy: number, maxDistance: number): BodyHit | null;
}

/** The values a Character's setters set. */
export interface CharacterSettings { maxSlope: number; stepHeight: number; snap: number; upX: number; upY: number; }

/** A body that walks (world.addCharacter): move every frame, then read onGround, onWall, onCeiling. */
export interface Character {
  readonly body: Body;
  readonly onGround: boolean;
  readonly onWall: boolean;
  readonly onCeiling: boolean;
  /** The body it stands on, or null. */
  readonly ground: Body | null;
  /** The normal of the ground it stands on, pointing out of it, or null. */
  readonly groundNormal: { x: number; y: number } | null;
  readonly settings: CharacterSettings;
  move(dx: number, dy: number, reaction: Reaction | null): Collision[];
  /** Degrees, from 0 to less than 90 (45 by default): steeper surfaces are walls. */
  maxSlope(degrees: number): Character;
  /** Pixels (0 by default): how high a step it climbs. */
  stepHeight(px: number): Character;
  /** Pixels (0 by default): how far down it keeps to the ground walking down. */
  snap(px: number): Character;
  /** Which way is up ((0, -1) by default); (0, 0) for a top-down game. */
  up(x: number, y: number): Character;
}

/** Snapping to a ground line (tutorial section 7). */
export const Snap: {
  /** The top that stands a rectangle of height h on the ground line, never in it. */
  standY(h: number, groundY: number): number;
  /** Whether the rectangle's bottom is at or below the ground line (y + h >= groundY). */
  onGround(y: number, h: number, groundY: number): boolean;
  /** Its top after landing: standY when on the ground, else y. */
  landY(y: number, h: number, groundY: number): number;
};

export class Grid {
  constructor(cols: number, rows: number, cellSize: number);
  static parse(map: string, cellSize: number): Grid;
  readonly cols: number;
  readonly rows: number;
  readonly cellWidth: number;
  readonly cellHeight: number;
  get(col: number, row: number): number;
  set(col: number, row: number, terrain: number): void;
  isSolid(col: number, row: number): boolean;
  colAt(x: number): number;
  rowAt(y: number): number;
  rectOverlapsSolid(x: number, y: number, w: number, h: number): boolean;
  circleOverlapsSolid(cx: number, cy: number, r: number): boolean;
  lineOfSight(x0: number, y0: number, x1: number, y1: number): boolean;
  path(fromCol: number, fromRow: number, toCol: number, toRow: number): Int32Array;
  move(x: number, y: number, w: number, h: number, vx: number, vy: number): { x: number; y: number; vx: number; vy: number; sides: number };
}
