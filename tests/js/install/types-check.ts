// Type-checked (tsc --strict --noEmit) against the installed package's .d.ts by
// scripts/test.d/npm-package.sh: the types are real, and wrong uses fail to compile.
import init, {
  Motion,
  limits,
  posesToMatrices,
  scenes,
  screw,
  screwInfo,
  screwPoses,
  type Kinematics,
  type MotionDocument,
  type Pose,
  type PoseInput,
  type SceneInfo,
  type SchemeName,
  type ScrewInfo,
  type SubdivisionOptions,
} from 'screwbender';
import { mount, type ScrewBenderElement, type ViewerHandle, type ViewerOptions } from 'screwbender/viewer';

await init();

const m: Motion = Motion.fromScene('circle4');
const p: Pose = m.poseAt(0.5);
const x: number = p.origin[0];
const w: number = p.rotation[0];
const options: SubdivisionOptions = m.options();
const scheme: SchemeName = options.scheme;
const doc: MotionDocument = m.toDocument();
const again = new Motion(doc, { scheme: 'jarek', levels: 3 });
const basisPose: PoseInput = { origin: [0, 0, 0], basis: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] };
again.setPose(0, basisPose);
again.setScheme('bspline');
again.setRules('split');
const refined: Float64Array = again.subdivide();
const matrices: Float32Array = again.refinedMatrices();
const k: Kinematics = again.kinematicsAt(0.25, [1, 0, 0]);
const speed: number = Math.hypot(...k.velocity);
const info: ScrewInfo = screwInfo(p, again.poseAt(1));
const pitch: number = info.kind === 'general' ? info.pitch : 0;
const list: SceneInfo[] = scenes();
const firstShape: string = list[0].shape.kind;
const ts = new Float64Array([0, 0.5, 1]);
const batch: Float64Array = screwPoses(p, screw(p, 0.5, again.poseAt(2)), ts);
const mats: Float32Array = posesToMatrices(batch);
const stride: 7 = limits().poseStride;
const [start, end]: [number, number] = again.domain();
const closed: boolean = again.closed;

// @ts-expect-error: not a scheme name
m.setScheme('cubic');
// @ts-expect-error: not a rule set
m.setRules('v3');
// @ts-expect-error: a quaternion has four components
m.setPose(0, { origin: [0, 0, 0], rotation: [1, 0, 0] });
// @ts-expect-error: the index is a number
m.removePose('1');
// @ts-expect-error: unknown scene id
Motion.fromScene('nope');
// @ts-expect-error: levels is a number
m.setOptions({ levels: '3' });

// The viewer entry: options, the handle, the element's typed events.
const viewerOptions: ViewerOptions = { scene: 'circle4', levels: 4, editable: true, controls: 'full', theme: 'dark' };
const fig: ViewerHandle = mount(document.createElement('div'), {
  ...viewerOptions,
  document: { closed: false, poses: [{ origin: [0, 0, 0], rotation: [1, 0, 0, 0] }, { origin: [1, 0, 0], rotation: [1, 0, 0, 0] }] },
});
fig.seek(0.5);
const figEl: ScrewBenderElement = document.createElement('screw-bender');
figEl.addEventListener('change', (e) => console.log(e.detail.poses.length, e.detail.index));
figEl.addEventListener('error', (e) => console.log(e.detail.attribute, e.detail.message));
// @ts-expect-error: not a controls value
mount(document.createElement('div'), { controls: 'most' });
// The media-element API, the camera, pictures, and their events.
figEl.currentTime = 1.5;
figEl.playbackRate = -1;
figEl.loop = false;
figEl.play({ repetitions: 2 });
const paused: boolean = figEl.paused;
const duration: number = fig.duration;
figEl.addEventListener('camera-change', (e) => console.log(e.detail.source === 'user', e.detail.camera.yaw));
figEl.addEventListener('timeupdate', (e) => console.log(e.detail.t));
figEl.addEventListener('ended', () => console.log(figEl.currentTime));
if (figEl.camera) figEl.camera = { ...figEl.camera, projection: 'orthographic' };
const picture: Promise<Blob> = fig.toBlob({ type: 'image/png', scale: 2, transparent: true });
const still: string = figEl.toDataURL({ type: 'image/jpeg', quality: 0.9 });
mount(document.createElement('div'), { loading: 'eager', poster: 'poster.png', alt: 'A screw motion', touchAction: 'pan-y' });
// @ts-expect-error: not a projection
figEl.camera = { yaw: 0, pitch: 0, distance: 5, target: [0, 0, 0], projection: 'fisheye' };
// @ts-expect-error: not a loading value
mount(document.createElement('div'), { loading: 'later' });
console.log(paused, duration, picture, still);

console.log(x, w, scheme, refined.length, matrices.length, speed, pitch, firstShape, mats.length, stride, start, end, closed);
