// Types of the `screwbender/viewer` entry (browsers only: it defines a custom element).
import type { MotionDocumentInput, SubdivisionOptions } from './screwbender.js';

/** Layers a figure can show (the `show` option: a space-separated list). */
export type Layer = 'strobe' | 'control' | 'trajectories' | 'polyscrew' | 'polygon' | 'triads' | 'grid';

/**
 * Options of a figure: the attributes of <screw-bender>, by the same names. Numbers and
 * booleans may be given as such (attributes are strings: `levels="4"`, `autoplay`).
 */
export interface ViewerOptions {
  /** A preset id (see `scenes()` of the math module), e.g. `'l_cycle_rotated'`. */
  scene?: string;
  /** URL of a motion `.json` document or a `.glb` / `.gltf` / `.csv` file. */
  src?: string;
  /** A share-link payload of the playground (the part after `#s=`, or the whole link). */
  share?: string;
  /** A motion document (mount only; the element reads an inline `<script type="application/json">` child). */
  document?: MotionDocumentInput;
  scheme?: SubdivisionOptions['scheme'];
  /** Subdivision levels, 0 to 12 (and within the module's refined-pose limit). */
  levels?: number | string;
  /** The J_s parameter, -4 to 4 (implies scheme `'j'` unless a scheme is given). */
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
  /** `iso`, `front`, `side`, `top` or `"yaw pitch [distance]"` (degrees, scene units). */
  camera?: string;
  /** The figure's chrome, frame and 3-D view (background and line colours). */
  theme?: 'light' | 'dark';
  /** A localStorage key: the figure saves its edits there and restores them (never without it). */
  persist?: string;
}

/** What mount() returns (the element has the same members). */
export interface ViewerHandle {
  /** Resolves when the figure is drawn (or has shown its error message); never rejects. */
  readonly ready: Promise<void>;
  /** The motion document now shown (null before it loads); set to show another. */
  document: object | null;
  /** The options given, with the motion's subdivision options; set a partial object to change some. */
  options: ViewerOptions & Partial<SubdivisionOptions>;
  /** `'WebGPU'`, `'WebGL2'`, or null before the start (or without graphics). */
  readonly backend: string | null;
  play(): void;
  pause(): void;
  /** Shows the moving object at parameter u (wrapped into the motion's domain). */
  seek(u: number): void;
  /** Frees the figure's GPU data and listeners (mount only; the element does it on removal). */
  destroy(): void;
}

/** Event details. */
export interface ViewerEventMap {
  change: CustomEvent<{ poses: Float64Array; index: number }>;
  select: CustomEvent<{ index: number }>;
  time: CustomEvent<{ u: number; start: number; end: number }>;
  error: CustomEvent<{ attribute: string | null; value: unknown; message: string }>;
}

/** Mounts a figure into `element` (its content becomes the caption); failures show in the figure. */
export function mount(element: HTMLElement, options?: ViewerOptions): ViewerHandle;

/** The class of <screw-bender> (defined when this module is imported). */
export class ScrewBenderElement extends HTMLElement {
  readonly ready: Promise<void>;
  document: object | null;
  options: ViewerOptions & Partial<SubdivisionOptions>;
  readonly backend: string | null;
  play(): void;
  pause(): void;
  seek(u: number): void;
  addEventListener<K extends keyof ViewerEventMap>(type: K, listener: (this: ScrewBenderElement, ev: ViewerEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
}

/** The attribute names the element watches. */
export const ATTRIBUTES: readonly string[];
/** The layer names of `show`. */
export const LAYERS: readonly Layer[];

declare global {
  interface HTMLElementTagNameMap {
    'screw-bender': ScrewBenderElement;
  }
}
