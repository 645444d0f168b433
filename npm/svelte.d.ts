// `screwbender/svelte`: the `screwbender/viewer` entry (importing it defines <screw-bender>) plus
// the element in Svelte 5's svelte/elements, so that svelte-check knows its attributes,
// properties and handlers. Svelte 5 sets an attribute as a property when the element has one of
// that name and attaches `on<type>` as a listener of the event `<type>` (`ontime`,
// `oncamera-change`).
import type { HTMLAttributes } from 'svelte/elements';
import type { ScrewBenderAttributes, ScrewBenderElement, ScrewBenderEventProps, ScrewBenderProps } from './element-types.js';

export * from './viewer.js';
export type * from './element-types.js';

/** Attributes of <screw-bender> in markup: Svelte's HTML attributes (without those of the same names), then the element's. */
export type ScrewBenderSvelteProps = Omit<HTMLAttributes<ScrewBenderElement>, keyof ScrewBenderEventProps | keyof ScrewBenderAttributes> &
  ScrewBenderProps;

declare module 'svelte/elements' {
  interface SvelteHTMLElements {
    'screw-bender': ScrewBenderSvelteProps;
  }
}
