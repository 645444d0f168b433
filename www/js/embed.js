// embed.html: one figure alone, for an <iframe> in a course page or an LMS (the Share & embed
// dialog writes the snippet). The figure is mount() of the <screw-bender> element (element/) in
// the page's <main>: the share payload comes from the hash (#s=…, as in a share link), the
// element's options from the query (?levels=4&show=strobe+grid&controls=full&autoplay), and
// ?backend=webgl2 forces the fallback. A new hash loads the new motion in place.
//
// The page never touches storage (the element's `persist` is refused here), so it works in
// `sandbox="allow-scripts"` (an opaque origin, where storage throws), and it listens only to its
// own elements. An unknown or refused option is named in a line below the figure; a bad value
// of a known one shows inside the figure, as the element does.
import { ATTRIBUTES, FLAGS, OPTIONS } from './element/features.js';
import { mount } from './element/screw-bender.js';

/** The element's options that the query may set: all but the source of a share payload and storage. */
const QUERY_OPTIONS = ATTRIBUTES.filter((a) => a !== 'share' && a !== 'persist');
/** Options for mount() only (`backend`). */
const EXTRA = OPTIONS.filter((o) => o.attribute === false).map((o) => o.name);

/** The options of `search` (a query string) and the messages of the names it cannot take. */
export function queryOptions(search) {
  const options = {};
  const problems = [];
  for (const [k, v] of new URLSearchParams(search)) {
    if (k === 'persist') problems.push('persist is not available in an embedded figure (it never touches storage)');
    else if (k === 'share') problems.push('share goes in the hash: embed.html#s=…');
    else if (QUERY_OPTIONS.includes(k) || EXTRA.includes(k)) options[k] = FLAGS.includes(k) && v === '' ? true : v;
    else problems.push(`unknown option "${k}" (known: ${[...QUERY_OPTIONS, ...EXTRA].join(', ')})`);
  }
  return { options, problems };
}

/** The share payload of `hash` ('#s=…'), or null. */
const payloadOf = (hash) => hash.match(/^#s=(.+)$/)?.[1] ?? null;

const host = document.getElementById('figure');
const msg = document.getElementById('embed-msg');
const { options, problems } = queryOptions(location.search);
if (problems.length) {
  msg.textContent = `embed.html: ${problems.join('; ')}.`;
  msg.hidden = false;
}
const share = payloadOf(location.hash);
const handle = mount(host, share ? { ...options, share } : options);
window.screwbenderEmbed = handle;

/** The frame's title names the motion (screen readers announce it with the frame). */
function retitle() {
  const name = handle.document?.name;
  document.title = name ? `${name} · ScrewBender figure` : 'ScrewBender figure';
}
handle.ready.then(retitle);

window.addEventListener('hashchange', () => {
  const next = payloadOf(location.hash);
  if (next) {
    handle.options = { share: next };
    handle.ready.then(retitle);
  }
});
