// Types of the `screwbender/viewer` entry (browsers only: it defines a custom element).
import type { MotionDocumentInput, SubdivisionOptions } from './screwbender.js';

/** Layers a figure can show (the `show` option: a space-separated list). */
export type Layer = 'strobe' | 'control' | 'trajectories' | 'polyscrew' | 'polygon' | 'triads' | 'grid';

/**
 * Options of a figure: the attributes of <screw-bender>, by the same names. Numbers and
 * booleans may be given as such (attributes are strings: `levels="4"`, `autoplay`).
 */
export interface ViewerOptions {
  /** A preset id (see `presets()` of the math module), e.g. `'l_cycle_rotated'`. */
  preset?: string;
  /** @deprecated Renamed to `preset`. */
  scene?: string;
  /** URL of a motion `.json` document or a `.glb` / `.gltf` / `.csv` file. */
  src?: string;
  /** A share-link payload of the playground (the part after `#s=`, or the whole link). */
  share?: string;
  /** A motion document (mount only; the element reads an inline `<script type="application/json">` child). */
  document?: MotionDocumentInput;
  scheme?: SubdivisionOptions['scheme'];
  /** Subdivision levels, 0 to 19 (and within the module's refined-pose limit). */
  levels?: number | string;
  /** The J_s parameter `s`, -4 to 4 (implies scheme `'j'` unless a scheme is given). */
  s?: number | string;
  /** @deprecated Renamed to `s`. */
  j?: number | string;
  rules?: SubdivisionOptions['rules'];
  /** Copies of the object drawn along the motion, 0 to 20000. */
  strobe?: number | string;
  /** Layers shown, space separated (default: strobe control trajectories polygon triads grid). */
  show?: string;
  autoplay?: boolean | string;
  /** Loop an open motion while playing (default true). */
  loop?: boolean | string;
  /** Control poses per second while playing, 0 to 100 (default 1). */
  speed?: number | string;
  /** Off (default): orbit, play and scrub only. On: select and drag poses with the gizmo. */
  editable?: boolean | string;
  /** The figure's chrome: none, minimal (play, scrub, time; default) or full (plus scheme, levels, frame). */
  controls?: 'none' | 'minimal' | 'full';
  /** `iso`, `front`, `side`, `top`, `"yaw pitch [distance]"` or `"yaw pitch distance tx ty tz"` (degrees, scene units; the last three the point looked at). */
  camera?: string;
  /** The figure's chrome, frame and 3-D view (background and line colours). */
  theme?: 'light' | 'dark';
  /** A localStorage key: the figure saves its edits there and restores them (never without it). */
  persist?: string;
  /** The figure's accessible name (default "3-D figure of a rigid motion"). */
  alt?: string;
  /** `lazy` (default): start when near the viewport; `eager`: start at once. */
  loading?: 'lazy' | 'eager';
  /** URL of an image shown until the first frame is drawn. */
  poster?: string;
  /**
   * What a touch on the unfocused figure leaves to the page: `pan-y` (default: a vertical swipe
   * scrolls the page, a sideways one orbits), `pan-x`, or `none` (the figure takes every touch).
   * Once focused, the figure takes every touch. The attribute is `touch-action`.
   */
  touchAction?: 'pan-y' | 'pan-x' | 'none';
  'touch-action'?: 'pan-y' | 'pan-x' | 'none';
}

/** The camera as state: angles in radians, lengths in scene units (z up). */
export interface CameraState {
  /** Around z from +x. */
  yaw: number;
  /** Elevation, −π/2 to π/2. */
  pitch: number;
  /** From the target to the eye, > 0. */
  distance: number;
  /** The point the camera orbits and looks at. */
  target: [number, number, number];
  projection: 'perspective' | 'orthographic';
}

/** Options of toBlob and toDataURL. */
export interface PictureOptions {
  /** `image/png` (default), `image/jpeg` or `image/webp`. */
  type?: 'image/png' | 'image/jpeg' | 'image/webp';
  /** 0 to 1, for JPEG and WebP. */
  quality?: number;
  /** Times the drawing buffer (CSS size × devicePixelRatio), up to 8: drawn at that size, not scaled. Default 1. */
  scale?: number;
  /** A transparent background (PNG and WebP). Default false. */
  transparent?: boolean;
  /** Keep the selected pose's gizmo and the hover highlight in the picture. Default false. */
  gizmo?: boolean;
}

/**
 * A figure's script API: what mount() returns (the element has the same members but
 * `destroy`). Playback follows HTMLMediaElement: times are seconds of the motion's own timing
 * (pose i at `times[i]`, else at i s), over [start, start + duration].
 */
export interface ViewerHandle {
  /** Resolves when the figure is drawn (a lazy one: once near the viewport) or has shown its error; never rejects. */
  readonly ready: Promise<void>;
  /** The motion document now shown (null before it loads); set to show another. */
  document: object | null;
  /** The options given, with the motion's subdivision options; set a partial object to change some. */
  options: ViewerOptions & Partial<SubdivisionOptions>;
  /** `'WebGPU'`, `'WebGL2'`, or null before the start (or without graphics). */
  readonly backend: string | null;
  /** The playhead in seconds; set it to seek (works while paused; fires `seeked`). */
  currentTime: number;
  /** The playback interval's length in seconds (NaN before the motion loads). */
  readonly duration: number;
  readonly paused: boolean;
  /** Motion seconds per real second, −100 to 100 (negative plays backwards); starts as `speed`. */
  playbackRate: number;
  /** An open motion wraps at its end while playing (a cycle always does). */
  loop: boolean;
  /** The camera; set any of its fields (fires `camera-change` with source `'api'`). Null before the start. */
  camera: CameraState | null;
  /** Plays; with `repetitions` (a whole number ≥ 1), that many passes and then `ended`. */
  play(options?: { repetitions?: number }): void;
  pause(): void;
  /** Shows the moving object at time t in seconds (the `currentTime` setter). */
  seek(t: number): void;
  /** A picture of the current view; rejects with a RangeError naming a bad option or before the start. */
  toBlob(options?: PictureOptions): Promise<Blob>;
  /** The same picture as a `data:` URL; throws a RangeError as toBlob rejects. */
  toDataURL(options?: PictureOptions): string;
  /** Frees the figure's GPU data and listeners (mount only; the element does it on removal). */
  destroy(): void;
}

/** The playhead of `time` and `timeupdate`: t in seconds, u the motion parameter, the interval in seconds. */
export interface PlayheadDetail {
  t: number;
  u: number;
  start: number;
  end: number;
}

/** Event details (none of the events bubble). */
export interface ViewerEventMap {
  change: CustomEvent<{ poses: Float64Array; index: number }>;
  select: CustomEvent<{ index: number }>;
  time: CustomEvent<PlayheadDetail>;
  timeupdate: CustomEvent<PlayheadDetail>;
  play: CustomEvent<Record<string, never>>;
  pause: CustomEvent<Record<string, never>>;
  /** Playback reached an end by itself (an open motion without loop, or the last repetition). */
  ended: CustomEvent<Record<string, never>>;
  seeked: CustomEvent<Record<string, never>>;
  ratechange: CustomEvent<Record<string, never>>;
  /** The camera moved: `user` for the reader's gestures and keys, `api` for code. */
  'camera-change': CustomEvent<{ source: 'user' | 'api'; camera: CameraState }>;
  error: CustomEvent<{ attribute: string | null; value: unknown; message: string }>;
}

/** Mounts a figure into `element` (its content becomes the caption); failures show in the figure. */
export function mount(element: HTMLElement, options?: ViewerOptions): ViewerHandle;

/** The element's members are the handle's, but `destroy` (it frees itself when removed). */
export interface ScrewBenderElement extends Omit<ViewerHandle, 'destroy'> {}

/**
 * The class of <screw-bender> (defined when this module is imported). Children with
 * `slot="pose-3"` (or `slot="pose"` and `data-pose="3"`) label pose 3; the rest is the caption.
 */
export class ScrewBenderElement extends HTMLElement {
  addEventListener<K extends keyof ViewerEventMap>(type: K, listener: (this: ScrewBenderElement, ev: ViewerEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  removeEventListener<K extends keyof ViewerEventMap>(type: K, listener: (this: ScrewBenderElement, ev: ViewerEventMap[K]) => unknown, options?: boolean | EventListenerOptions): void;
  removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
}

/** The attribute names the element watches. */
export const ATTRIBUTES: readonly string[];
/** The layer names of `show`. */
export const LAYERS: readonly Layer[];

/** Where a figure finds its assets, for a build that moves or inlines them (each optional). */
export interface AssetConfig {
  /** Functions that import the wasm-bindgen modules: the renderer module, the WebGL2 one (null: none), one that reads glTF and CSV. */
  modules?: { main: () => Promise<unknown>; gl: (() => Promise<unknown>) | null; files: () => Promise<unknown> };
  /** The stylesheet's URL (a `data:` URL works). */
  stylesheet?: string;
  /** The stylesheet's text, put in a `<style>` instead. */
  css?: string;
  /** The bunny6 preset's mesh (OBJ) URL; null: none (a wedge stands in). */
  bunny?: string | null;
}
/**
 * Tells every figure where its assets are, before the first one starts. This entry already
 * names its own modules; a bundle that inlines them calls it from a module imported first.
 */
export function configure(assets: AssetConfig): void;

declare global {
  interface HTMLElementTagNameMap {
    'screw-bender': ScrewBenderElement;
  }
}
