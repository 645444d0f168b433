// `screwbender/react`: the `screwbender/viewer` entry (importing it defines <screw-bender>) plus
// the element's entry in React 19's JSX namespace. React 19 sets a prop as a property when the
// element has one of that name (document, options, currentTime, …) and as an attribute
// otherwise, and attaches a prop `on<type>` as a listener of the event `<type>`: the handlers are
// spelled in lower case (`ontime`, `onchange`, `oncamera-change`), which keeps React's own
// synthetic `onChange` / `onSelect` out of the way.
import type { DetailedHTMLProps, HTMLAttributes } from 'react';
import type { ScrewBenderElement, ScrewBenderProps } from './element-types.js';

export * from './viewer.js';
export type * from './element-types.js';

/** The props of <screw-bender> in JSX: React's own HTML props, then the element's. */
export type ScrewBenderJSXProps = DetailedHTMLProps<HTMLAttributes<ScrewBenderElement>, ScrewBenderElement> & ScrewBenderProps;

declare module 'react' {
  namespace JSX {
    interface IntrinsicElements {
      'screw-bender': ScrewBenderJSXProps;
    }
  }
}
