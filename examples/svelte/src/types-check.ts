// Typed usage of <screw-bender> in Svelte 5's svelte/elements, for svelte-check --strict (not part
// of the app): what must compile, and with @ts-expect-error what the typings must refuse.
import type { SvelteHTMLElements } from 'svelte/elements';
import type { CameraChangeDetail } from 'screwbender/svelte';
import 'screwbender/svelte';

type Props = SvelteHTMLElements['screw-bender'];

export const typed: Props = {
  scene: 'l_cycle_rotated',
  levels: 4,
  strobe: '12',
  scheme: 'fourpoint',
  autoplay: true,
  loop: false,
  controls: 'full',
  theme: 'dark',
  camera: 'iso',
  alt: 'A rigid motion',
  loading: 'eager',
  document: { closed: true, poses: [] },
  currentTime: 1.5,
  playbackRate: -1,
  ontime: (e) => e.detail.t,
  onchange: (e) => e.detail.poses.length,
  onselect: (e) => e.detail.index + 1,
  onerror: (e) => e.detail.message.toUpperCase(),
  onratechange: (e: Event) => e.type,
  'oncamera-change': (e: CustomEvent<CameraChangeDetail>) => e.detail.source === 'user',
  class: 'figure',
};
// @ts-expect-error: no such control style
export const badControls: Props = { controls: 'maximal' };
// @ts-expect-error: levels is a number
export const badLevels: Props = { levels: { n: 4 } };
// @ts-expect-error: the time event's detail has no field `other`
export const badTime: Props = { ontime: (e) => e.detail.other };
