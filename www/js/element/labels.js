// Labels on control poses: a child of the figure with slot="pose-3" (or slot="pose" and
// data-pose="3") is shown at pose 3 on screen, following it as the camera turns or the pose is
// dragged, and hidden while the pose is behind the camera or missing. Every other child is the
// caption. The shadow root assigns slots by hand (slotAssignment 'manual'), so both spellings
// reach a label; a MutationObserver on the figure's own children keeps the assignment current.
//
// A label is a box (part "label", also "label-<k>") whose bottom centre sits
// --screw-bender-label-offset (default 10px) above the pose (placed in percent of the view's
// box); the page styles it with ::part or
// the variables of css/screw-bender.css.

/** @type {import('./options.js').Feature} */
export const labelsFeature = {
  name: 'labels',
  doc: 'The caption and the labels on poses.',
  slots: [
    { name: '', doc: 'The caption, shown under the figure. An inline `<script type="application/json">` child is read as the motion document.' },
    { name: 'pose-<i>', doc: 'A label placed at control pose i on screen (or slot="pose" with data-pose="i"), following it through orbit, drag and playback.' },
  ],
  parts: [{ name: 'label', doc: 'A label\'s box (also `label-<i>` for pose i).' }],
};

/** The pose a child labels, or null (a caption node). */
function poseOfChild(n) {
  if (n.nodeType !== 1) return null;
  const slot = n.getAttribute('slot');
  const m = /^pose-(\d+)$/.exec(slot ?? '');
  if (m) return Number(m[1]);
  if (slot === 'pose' && /^\d+$/.test(n.dataset.pose ?? '')) return Number(n.dataset.pose);
  return null;
}

export class Labels {
  /** Labels of figure `fig` (its host's children; fig.el.labels the layer, fig.el.caption the caption slot). */
  constructor(fig) {
    this.fig = fig;
    this.boxes = new Map(); // pose → {box, slot}
    this.observer = new MutationObserver(() => this.assign());
    this.observer.observe(fig.host, { childList: true, subtree: true, attributes: true, attributeFilter: ['slot', 'data-pose'] });
    this.assign();
  }

  /** Sends each child to the caption or to its pose's label box. */
  assign() {
    const { host, el } = this.fig;
    if (typeof el.caption.assign !== 'function' || host.shadowRoot.slotAssignment !== 'manual') return;
    const caption = [];
    const byPose = new Map();
    for (const n of host.childNodes) {
      const k = poseOfChild(n);
      if (k === null) caption.push(n);
      else byPose.set(k, [...(byPose.get(k) ?? []), n]);
    }
    el.caption.assign(...caption);
    for (const [k, b] of this.boxes) {
      if (!byPose.has(k)) {
        b.box.remove();
        this.boxes.delete(k);
      }
    }
    for (const [k, nodes] of byPose) {
      let b = this.boxes.get(k);
      if (!b) {
        const box = document.createElement('div');
        box.className = 'label';
        box.setAttribute('part', `label label-${k}`);
        box.hidden = true;
        const slot = document.createElement('slot');
        box.append(slot);
        el.labels.append(box);
        b = { box, slot };
        this.boxes.set(k, b);
      }
      b.slot.assign(...nodes);
    }
    this.place();
  }

  /** Moves each box to its pose as last drawn (after every frame). */
  place() {
    const { viewer, model } = this.fig;
    const n = model.motion ? model.motion.poseCount : 0;
    const { cssW, cssH } = viewer?.renderer ? viewer.pixelSize() : {};
    for (const [k, { box }] of this.boxes) {
      const p = viewer?.renderer && k < n ? viewer.toCanvas(model.motion.pose(k).origin) : null;
      box.hidden = !p;
      // In percent of the view's box, so a printed still (stretched to the box) keeps them on it.
      if (p) {
        box.style.left = `${((100 * p.x) / cssW).toFixed(3)}%`;
        box.style.top = `${((100 * p.y) / cssH).toFixed(3)}%`;
      }
    }
  }

  dispose() {
    this.observer.disconnect();
  }
}
