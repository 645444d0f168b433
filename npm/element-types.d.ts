// The <screw-bender> element's attributes, properties and events: what the framework typings
// (react.d.ts, vue.d.ts, svelte.d.ts) build their element entries from. Written by
// scripts/element-api.mjs from the element's declarations (www/js/element/features.js and
// the files it names): edit those, not this file. Names follow HTMLMediaElement where they
// apply. Every member is optional here: a framework may set any of them.
import type { Motion, MotionDocumentInput, SubdivisionOptions } from './screwbender.js';
import type { CameraState, PictureOptions, ScrewBenderElement } from './viewer.js';

/** A boolean attribute: present (`true`, `''`, any string but `'false'`) or absent. */
export type BooleanAttribute = boolean | '' | 'true' | 'false';
/** A number attribute: a number, or its decimal text as attributes carry it. */
export type NumberAttribute = number | `${number}`;

/**
 * The attributes of <screw-bender> (strings in HTML; a framework may pass numbers and booleans,
 * which the element reads the same way). Sources: the first present of `src`, `share`, an inline
 * `<script type="application/json">` child, `preset`.
 */
export interface ScrewBenderAttributes {
  /** A preset id, e.g. `l_cycle_rotated` (the source when none of src, share or an inline JSON child is given). */
  preset?: string;
  /** @deprecated Renamed to `preset`. */
  scene?: string;
  /** URL of a motion `.json` document or a `.glb` / `.gltf` / `.csv` file. */
  src?: string;
  /** A playground share-link payload (the part after `#s=`, or the whole link). */
  share?: string;
  /** A localStorage key: the figure saves its edits there and restores them (never without it). */
  persist?: string;
  /** The subdivision scheme. */
  scheme?: SubdivisionOptions['scheme'];
  /** The J_s parameter `s`, -4 to 4 (implies scheme `j`). */
  s?: NumberAttribute;
  /** @deprecated Renamed to `s`. */
  j?: NumberAttribute;
  /** The rule set: `direct`, or the first version's split-then-tweak (`split`). */
  rules?: SubdivisionOptions['rules'];
  /** Subdivision levels, 0 to 19. */
  levels?: NumberAttribute;
  /** Copies of the object drawn along the motion, 0 to 20000. */
  strobe?: NumberAttribute;
  /** Layers shown, space separated: strobe control trajectories polyscrew polygon triads grid. */
  show?: string;
  /** The figure's chrome: none, minimal (play, scrub, time) or full (plus scheme, levels, frame). */
  controls?: 'none' | 'minimal' | 'full';
  /** Colours of the chrome, frame and 3-D view. */
  theme?: 'light' | 'dark';
  /** What a touch on the unfocused figure leaves to the page: `pan-y` (a vertical swipe scrolls the page, a sideways one orbits), `pan-x`, or `none` (the figure takes every touch). */
  'touch-action'?: 'pan-y' | 'pan-x' | 'none';
  /** The figure's accessible name (a text alternative for screen readers). */
  alt?: string;
  /** Select and drag poses with the gizmo (off: orbit, play and scrub only). */
  editable?: BooleanAttribute;
  /** `iso`, `front`, `side`, `top`, `"yaw pitch [distance]"` or `"yaw pitch distance tx ty tz"` (degrees, scene units; the last three the point looked at) as an attribute; as a property, the camera as state (radians, scene units). */
  camera?: string | Partial<CameraState>;
  /** Play from the start. */
  autoplay?: BooleanAttribute;
  /** Loop an open motion while playing. */
  loop?: BooleanAttribute;
  /** Control poses per second while playing, 0 to 100. */
  speed?: NumberAttribute;
  /** `lazy`: start when the figure nears the viewport; `eager`: at once. */
  loading?: 'lazy' | 'eager';
  /** URL of an image shown until the figure starts. */
  poster?: string;
}

/** Options of play(): how many times an open motion plays before it ends. */
export interface PlayOptions {
  repetitions?: number;
}

/**
 * The properties a framework sets on the element besides the attributes (those of an
 * attribute's name are typed there).
 */
export interface ScrewBenderProperties {
  /** The options given, with the motion's subdivision options; set a partial object to change some. */
  options?: Partial<Record<keyof ScrewBenderAttributes, unknown>> & Partial<SubdivisionOptions>;
  /** The motion document shown (null before it loads); set to show another. */
  document?: MotionDocumentInput | object | null;
  /** The playhead in seconds; set it to seek (works while paused; fires `seeked`). */
  currentTime?: number;
  /** Motion seconds per real second, −100 to 100 (negative plays backwards); starts as `speed`. */
  playbackRate?: number;
}
/** The detail of `error`: the attribute and value at fault (null when none) and the message. */
export interface ErrorDetail {
  attribute: string | null;
  value: unknown;
  message: string;
}
/** The detail of `change`: every control pose (7 numbers each) and the pose edited. */
export interface ChangeDetail {
  poses: Float64Array;
  index: number;
}
/** The detail of `select`: the selected control pose, -1 for none. */
export interface SelectDetail {
  index: number;
}
/** The detail of `camera-change`: who moved the camera, and where it is now. */
export interface CameraChangeDetail {
  source: 'user' | 'api';
  camera: CameraState;
}
/** The detail of `time`: seconds `t` in [start, end] and the motion's parameter `u`. */
export interface TimeDetail {
  t: number;
  u: number;
  start: number;
  end: number;
}

/** The events of <screw-bender>, by type (none of them bubbles out of the figure as an exception). */
export interface ScrewBenderEvents {
  /** An attribute, source or call failed; the figure shows the message. */
  error: CustomEvent<ErrorDetail>;
  /** A pose of an editable figure was moved: every control pose (7 numbers each) and the pose edited. */
  change: CustomEvent<ChangeDetail>;
  /** A control pose was selected (-1: none). */
  select: CustomEvent<SelectDetail>;
  /** The camera moved, by the reader (`user`) or by code (`api`). */
  'camera-change': CustomEvent<CameraChangeDetail>;
  /** The playhead moved: seconds t in [start, end] and the motion's parameter u. */
  time: CustomEvent<TimeDetail>;
  /** The playhead moved (as `time`, in HTMLMediaElement's name). */
  timeupdate: CustomEvent<TimeDetail>;
  /** Playback started. */
  play: Event;
  /** Playback stopped. */
  pause: Event;
  /** An open motion that does not loop reached its end. */
  ended: Event;
  /** A seek (or a set of currentTime) finished. */
  seeked: Event;
  /** playbackRate changed. */
  ratechange: Event;
}

/** An event's handler, `this` being the element. */
export type ScrewBenderHandler<K extends keyof ScrewBenderEvents> = (this: ScrewBenderElement, event: ScrewBenderEvents[K]) => void;

/**
 * The handlers as `on<type>` props, the spelling React 19 and Svelte 5 attach to a custom
 * element's event of that type (`ontime`, `oncamera-change`).
 */
export type ScrewBenderEventProps = {
  [K in keyof ScrewBenderEvents as `on${K}`]?: (event: ScrewBenderEvents[K]) => void;
};

/** The options of mount(): the attributes (by their names) and those a script alone gives. */
export interface ScrewBenderOptions extends ScrewBenderAttributes {
  /** `webgl2` skips WebGPU (mount() only; without it WebGPU where the browser has a usable adapter, else WebGL2). */
  backend?: 'webgl2';
}

/**
 * A figure's script API: what mount() returns and what <screw-bender> has (its properties and
 * methods). Playback follows HTMLMediaElement: times are seconds of the motion's own timing.
 */
export interface ScrewBenderHandle {
  /** The options given, with the motion's subdivision options; set a partial object to change some. */
  options: Partial<Record<keyof ScrewBenderAttributes, unknown>> & Partial<SubdivisionOptions>;
  /** The renderer's backend, null before the start or without graphics. */
  readonly backend: 'WebGPU' | 'WebGL2' | null;
  /** The viewer (for tests and advanced use): camera, picking, renderer. */
  readonly viewer: unknown;
  /** The motion document shown (null before it loads); set to show another. */
  document: MotionDocumentInput | object | null;
  /** The Motion handle of the math module (read-only). */
  readonly motion: Motion | null;
  /** The camera; set any of its fields (fires `camera-change` with source `'api'`). Null before the start. */
  camera: CameraState | null;
  /** The playhead in seconds; set it to seek (works while paused; fires `seeked`). */
  currentTime: number;
  /** The playback interval's length in seconds (NaN before the motion loads). */
  readonly duration: number;
  /** True unless playing. */
  readonly paused: boolean;
  /** Motion seconds per real second, −100 to 100 (negative plays backwards); starts as `speed`. */
  playbackRate: number;
  /** An open motion wraps at its end while playing (a cycle always does); the `loop` attribute. */
  loop: boolean;
  /** Resolves when the figure is drawn (a lazy one: once near the viewport) or has shown its error; never rejects. */
  readonly ready: Promise<void>;
  /** Plays; with `repetitions` (a whole number ≥ 1), that many passes and then `ended`. */
  play(options?: { repetitions?: number }): void;
  /** Stops playback. */
  pause(): void;
  /** Shows the moving object at time `t` in seconds (the `currentTime` setter). */
  seek(t: number): void;
  /** A picture of the figure, drawn at the asked size. */
  toBlob(options?: PictureOptions): Promise<Blob>;
  /** The same picture as a data: URL (synchronous). */
  toDataURL(options?: PictureOptions): string;
}

/** Everything a framework may set on <screw-bender>: attributes, properties and handlers. */
export type ScrewBenderProps = ScrewBenderAttributes & ScrewBenderProperties & ScrewBenderEventProps;

export type { ScrewBenderElement };
