// Pointer gestures on the viewer's canvas: orbit (drag), pan (right / middle / Shift-drag, two
// fingers), zoom (wheel, pinch). The camera gestures live here, with the viewer, so an embedded
// view can be turned without the editor; the editor claims presses on poses and gizmo parts
// through `tool`:
//   press(pt, e)  a primary-button press (no Alt): 'drag' when the tool starts a drag (it then
//                 gets drag / release), any other truthy value when it used the press up,
//                 falsy to leave it to the camera
//   drag(pt, e)   pointer moves during the tool's drag;   release()  its end
//   hover(pt)     pointer moves with no button down;     cancel()   a second finger arrived
//   click()       a press and release on empty space without moving (not a drag of the view)
// All hooks are optional. A touch gives the canvas the focus only once it acts on the figure (a
// tap, an orbit that moved, a second finger): a swipe the browser takes to scroll the page
// (touch-action pan-y, then pointercancel) leaves the focus where it was.
import { local } from './picking.js';

export function bindPointer(viewer, tool = {}) {
  const c = viewer.canvas;
  const pointers = new Map();
  let gesture = null; // {kind: 'orbit'|'pan'|'tool'|'pinch', ...}
  c.addEventListener('contextmenu', (e) => e.preventDefault());
  c.addEventListener('pointerdown', (e) => {
    if (e.pointerType !== 'touch') c.focus();
    const pt = local(viewer, e);
    pointers.set(e.pointerId, pt);
    if (pointers.size === 2) {
      // Second finger: cancel any drag, start pinch/pan.
      c.focus();
      tool.cancel?.();
      const [a, b] = [...pointers.values()];
      gesture = { kind: 'pinch', dist: Math.hypot(a[0] - b[0], a[1] - b[1]), mid: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] };
      return;
    }
    if (pointers.size > 2) return;
    const button = e.button;
    if (button === 0 && !e.altKey) {
      const took = tool.press?.(pt, e);
      if (took) c.focus();
      if (took === 'drag') {
        gesture = { kind: 'tool' };
        return;
      }
      if (took) return;
    }
    const pan = button === 1 || button === 2 || e.shiftKey;
    // A touch where the page may pan (the canvas's touch-action, read as the browser applies it)
    // waits until the finger shows its direction: along the page's axis it is the page's scroll.
    const pans = e.pointerType === 'touch' ? getComputedStyle(c).touchAction : 'none';
    const yields = pans === 'pan-y' ? 'y' : pans === 'pan-x' ? 'x' : null;
    gesture = { kind: pan ? 'pan' : 'orbit', last: pt, start: pt, moved: false, yields };
    c.setPointerCapture?.(e.pointerId);
  });
  c.addEventListener('pointermove', (e) => {
    const pt = local(viewer, e);
    if (pointers.has(e.pointerId)) pointers.set(e.pointerId, pt);
    if (!gesture) {
      tool.hover?.(pt);
      return;
    }
    const { camera } = viewer;
    if (gesture.kind === 'tool') {
      tool.drag?.(pt, e);
    } else if (gesture.kind === 'pinch' && pointers.size >= 2) {
      const [a, b] = [...pointers.values()];
      const dist = Math.hypot(a[0] - b[0], a[1] - b[1]);
      const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      if (dist > 0 && gesture.dist > 0) camera.zoom(gesture.dist / dist);
      camera.pan(mid[0] - gesture.mid[0], mid[1] - gesture.mid[1], viewer.pixelSize().cssH);
      gesture.dist = dist;
      gesture.mid = mid;
      viewer.cameraMoved('user');
    } else if (gesture.kind === 'orbit' || gesture.kind === 'pan') {
      if (gesture.yields && !gesture.moved) {
        const ax = Math.abs(pt[0] - gesture.start[0]);
        const ay = Math.abs(pt[1] - gesture.start[1]);
        if (Math.max(ax, ay) < 8) return;
        if (gesture.yields === 'y' ? ay >= ax : ax >= ay) {
          gesture = null;
          return;
        }
        gesture.last = pt;
      }
      const dx = pt[0] - gesture.last[0];
      const dy = pt[1] - gesture.last[1];
      gesture.last = pt;
      if (!gesture.moved && Math.hypot(pt[0] - gesture.start[0], pt[1] - gesture.start[1]) > 3) {
        gesture.moved = true;
        c.focus();
      }
      if (gesture.kind === 'orbit') camera.orbit(dx, dy);
      else camera.pan(dx, dy, viewer.pixelSize().cssH);
      c.style.cursor = 'grabbing';
      viewer.cameraMoved('user');
    }
  });
  const up = (e) => {
    pointers.delete(e.pointerId);
    if (!gesture) return;
    if (gesture.kind === 'tool') tool.release?.();
    else if (gesture.kind === 'orbit' && !gesture.moved && e.type === 'pointerup') {
      c.focus();
      tool.click?.();
    }
    c.style.cursor = 'grab';
    gesture = pointers.size === 0 ? null : gesture.kind === 'pinch' ? null : gesture;
  };
  c.addEventListener('pointerup', up);
  c.addEventListener('pointercancel', up);
  c.addEventListener(
    'wheel',
    (e) => {
      // An embedded figure lets the page scroll until it has the focus (a click gives it).
      if (viewer.wheelNeedsFocus && c.getRootNode().activeElement !== c) return;
      e.preventDefault();
      const k = e.deltaMode === 1 ? 0.05 : 0.0015;
      viewer.camera.zoom(Math.exp(e.deltaY * k));
      viewer.cameraMoved('user');
    },
    { passive: false },
  );
}
