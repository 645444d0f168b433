// The <screw-bender> element's attributes, properties and events, written once: what the
// framework typings (react.d.ts, vue.d.ts, svelte.d.ts) build their element entries from, and what
// custom-elements.json describes for IDEs and documentation tools. Names follow HTMLMediaElement
// where they apply (currentTime, duration, paused, playbackRate, loop; play, pause, ended,
// timeupdate, seeked). Every member is optional here: a framework may set any of them.
import type { MotionDocumentInput, SubdivisionOptions } from './screwbender.js';
import type { CameraState, ScrewBenderElement } from './viewer.js';

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
  /** A preset id, e.g. `'l_cycle_rotated'`. */
  preset?: string;
  /** @deprecated Renamed to `preset`. */
  scene?: string;
  /** URL of a motion `.json` document or a `.glb` / `.gltf` / `.csv` file. */
  src?: string;
  /** A playground share-link payload (the part after `#s=`, or the whole link). */
  share?: string;
  scheme?: SubdivisionOptions['scheme'];
  /** Subdivision levels, 0 to 19. */
  levels?: NumberAttribute;
  /** The J_s parameter `s`, -4 to 4 (implies scheme `'j'`). */
  s?: NumberAttribute;
  /** @deprecated Renamed to `s`. */
  j?: NumberAttribute;
  rules?: SubdivisionOptions['rules'];
  /** Copies of the object drawn along the motion, 0 to 20000. */
  strobe?: NumberAttribute;
  /** Layers shown, space separated: strobe control trajectories polyscrew polygon triads grid. */
  show?: string;
  autoplay?: BooleanAttribute;
  /** Loop an open motion while playing (default true). */
  loop?: BooleanAttribute;
  /** Control poses per second while playing, 0 to 100 (default 1). */
  speed?: NumberAttribute;
  /** Select and drag poses with the gizmo (default off: orbit, play and scrub only). */
  editable?: BooleanAttribute;
  /** The figure's chrome: none, minimal (default) or full. */
  controls?: 'none' | 'minimal' | 'full';
  /**
   * `iso`, `front`, `side`, `top`, `"yaw pitch [distance]"` or `"yaw pitch distance tx ty tz"`
   * (degrees, scene units; the last three the point looked at) as an attribute; as a property,
   * the camera as state (radians, scene units).
   */
  camera?: string | Partial<CameraState>;
  theme?: 'light' | 'dark';
  /** A localStorage key: the figure saves its edits there and restores them (never without it). */
  persist?: string;
  /** The figure's accessible name (a text alternative for screen readers). */
  alt?: string;
  /** `lazy` (default): start when the figure nears the viewport; `eager`: at once. */
  loading?: 'lazy' | 'eager';
  /** URL of an image shown until the figure starts. */
  poster?: string;
  /** Which touch gestures the page keeps (CSS touch-action over the figure's canvas). */
  'touch-action'?: string;
}

/** Options of play(): how many times an open motion plays before it ends. */
export interface PlayOptions {
  repetitions?: number;
}


/**
 * The properties a framework sets on the element (besides the attributes): the motion
 * document, a partial options object, and the playback state in the names of HTMLMediaElement.
 */
export interface ScrewBenderProperties {
  /** The motion document shown; set to show another. */
  document?: MotionDocumentInput | object | null;
  /** A partial options object (the attributes' names), applied in place. */
  options?: Partial<Record<keyof ScrewBenderAttributes, unknown>> & Partial<SubdivisionOptions>;
  /** The playhead in seconds (settable, also while paused). */
  currentTime?: number;
  /** Playback speed factor; negative plays backwards. */
  playbackRate?: number;
}

/** The detail of `time`: seconds `t` in [start, end] and the motion's parameter `u`. */
export interface TimeDetail {
  t: number;
  u: number;
  start: number;
  end: number;
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
/** The detail of `error`: the attribute and value at fault (null when none) and the message. */
export interface ErrorDetail {
  attribute: string | null;
  value: unknown;
  message: string;
}
/** The detail of `camera-change`: who moved the camera, and where it is now. */
export interface CameraChangeDetail {
  source: 'user' | 'api';
  camera?: CameraState;
}

/** The events of <screw-bender>, by type (none of them bubbles out of the figure as an exception). */
export interface ScrewBenderEvents {
  change: CustomEvent<ChangeDetail>;
  select: CustomEvent<SelectDetail>;
  time: CustomEvent<TimeDetail>;
  error: CustomEvent<ErrorDetail>;
  play: Event;
  pause: Event;
  ended: Event;
  timeupdate: Event;
  seeked: Event;
  'camera-change': CustomEvent<CameraChangeDetail>;
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

/** Everything a framework may set on <screw-bender>: attributes, properties and handlers. */
export type ScrewBenderProps = ScrewBenderAttributes & ScrewBenderProperties & ScrewBenderEventProps;

export type { ScrewBenderElement };
