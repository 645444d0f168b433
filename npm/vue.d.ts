// `screwbender/vue`: the `screwbender/viewer` entry (importing it defines <screw-bender>) plus the
// element in Vue 3's GlobalComponents, so that templates type-check its props and `@event`
// handlers (vue-tsc). Vue must be told the tag is a custom element, in the Vite plugin:
//   vue({ template: { compilerOptions: { isCustomElement: (tag) => tag === 'screw-bender' } } })
// Vue sets a bound prop as a property when the element
// has one of that name and as an attribute otherwise; `@time` listens to the event `time`.
import type { AllowedComponentProps, ComponentCustomProps, EmitFn, HTMLAttributes, VNodeProps } from 'vue';
import type { ScrewBenderAttributes, ScrewBenderElement, ScrewBenderEvents, ScrewBenderProperties } from './element-types.js';

export * from './viewer.js';
export type * from './element-types.js';

/** `on<Type>` props for the events, as Vue spells a listener `@type` in a template. */
export type ScrewBenderVueListeners = {
  [K in keyof ScrewBenderEvents as `on${Capitalize<K>}`]?: (event: ScrewBenderEvents[K]) => void;
};

/** Props of <screw-bender> in a template: Vue's HTML attributes (without those of the same names), then the element's. */
export type ScrewBenderVueProps = Omit<HTMLAttributes, keyof ScrewBenderVueListeners | keyof ScrewBenderAttributes> &
  ScrewBenderAttributes & ScrewBenderProperties & ScrewBenderVueListeners & AllowedComponentProps & VNodeProps & ComponentCustomProps;

/** The element as a component type (what GlobalComponents holds). */
export type ScrewBenderVueComponent = new () => ScrewBenderElement & {
  /** For template prop types only: not a property of the element. */
  $props: ScrewBenderVueProps;
  /** For template event types only: not a property of the element. */
  $emit: EmitFn<{ [K in keyof ScrewBenderEvents]: (event: ScrewBenderEvents[K]) => void }>;
};

declare module 'vue' {
  interface GlobalComponents {
    'screw-bender': ScrewBenderVueComponent;
  }
}
