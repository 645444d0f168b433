// Pose numbers beside the control poses' handles: small labels over the 3-D view, placed after
// each drawn frame (editor/responsive.js calls `place` while frames are drawn), hidden with the
// control poses or by the panel's Display › Pose numbers.

/** Offset of a label from its handle's centre, CSS pixels. */
const OFFSET = [9, -22];

/** @type {import('../app.js').Part} */
export default {
  id: 'labels',
  create(app) {
    const layer = document.createElement('div');
    layer.id = 'pose-labels';
    layer.setAttribute('aria-hidden', 'true');
    const labels = [];
    let key = '';

    return {
      bind() {
        // Right after the canvas: over the 3-D view, under every control.
        app.viewer.canvas.closest('main').after(layer);
        this.place();
      },

      /** Puts one label at each control pose's handle (or hides them). */
      place() {
        const v = app.view;
        const show = !!app.motion && v.showControl && v.showPoseNumbers !== false;
        layer.hidden = !show;
        if (!show) return;
        const n = app.motion.poseCount;
        const r = app.viewer.canvas.getBoundingClientRect();
        const parts = [];
        for (let k = 0; k < n; k++) {
          const p = app.viewer.screenOfPose(k);
          parts.push(p && p.x >= r.left && p.x <= r.right && p.y >= r.top && p.y <= r.bottom ? p : null);
        }
        const now = `${n}:${app.selected}:${parts.map((p) => (p ? `${Math.round(p.x)},${Math.round(p.y)}` : '-')).join(';')}`;
        if (now === key) return;
        key = now;
        while (labels.length < n) {
          const e = document.createElement('span');
          e.className = 'pose-label';
          e.textContent = String(labels.length);
          layer.append(e);
          labels.push(e);
        }
        labels.forEach((e, k) => {
          const p = parts[k];
          e.hidden = k >= n || !p;
          if (e.hidden) return;
          e.classList.toggle('on', k === app.selected);
          e.style.transform = `translate(${Math.round(p.x + OFFSET[0])}px, ${Math.round(p.y + OFFSET[1])}px)`;
        });
      },
    };
  },
};
