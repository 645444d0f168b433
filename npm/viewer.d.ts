// Types of the `screwbender/viewer` entry (browsers only: it defines a custom element).
import type { MotionDocumentInput } from './screwbender.js';
import type { ScrewBenderAttributes, ScrewBenderEvents, ScrewBenderHandle, ScrewBenderOptions, TimeDetail } from './element-types.js';

/** Layers a figure can show (the `show` option: a space-separated list). */
export type Layer = 'strobe' | 'control' | 'trajectories' | 'polyscrew' | 'polygon' | 'triads' | 'grid';

/**
 * Options of mount(): the attributes of <screw-bender> by the same names (numbers and booleans
 * may be given as such), `backend`, and the motion document itself.
 */
export interface ViewerOptions extends ScrewBenderOptions {
  /** A motion document (the element reads an inline `<script type="application/json">` child instead). */
  document?: MotionDocumentInput;
  /** The `touch-action` attribute, in camelCase. */
  touchAction?: ScrewBenderAttributes['touch-action'];
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

/** What mount() returns: the element's properties and methods, and destroy(). */
export interface ViewerHandle extends ScrewBenderHandle {
  /** Frees the figure's GPU data and listeners (mount only; the element does it on removal). */
  destroy(): void;
}

/** The playhead of `time` and `timeupdate`. */
export type PlayheadDetail = TimeDetail;

/** Event details by event type (none of the events bubble but `change`). */
export type ViewerEventMap = ScrewBenderEvents;

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
