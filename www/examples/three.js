// The three.js example (three.html): a ScrewBender motion as three.js keyframe tracks, played by
// an AnimationMixer. ScrewBender runs once, to sample the motion (Motion.keyframeTracks); every
// frame after that is three.js alone. `?t=<seconds>` shows one moment, paused (for screenshots).
import * as THREE from 'three';
import init, { Motion } from 'screwbender'; // the playground's analysis module (www/pkg-full/: has keyframeTracks)

const view = document.getElementById('view');
const status = document.getElementById('status');

/** The figure: renderer, z-up camera, lights and a grid, sized to the #view box. */
function stage() {
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  view.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  const camera = new THREE.PerspectiveCamera(40, 4 / 3, 0.1, 200);
  camera.up.set(0, 0, 1); // the project's scenes are z-up
  scene.add(new THREE.AmbientLight(0xffffff, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2);
  sun.position.set(4, -6, 10);
  scene.add(sun);
  const grid = new THREE.GridHelper(12, 12, 0xcccccc, 0xe6e6e6);
  grid.rotation.x = Math.PI / 2; // into the z = 0 plane
  scene.add(grid);
  const resize = () => {
    const { width, height } = view.getBoundingClientRect();
    renderer.setSize(width, height, false);
    camera.aspect = width / Math.max(height, 1);
    camera.updateProjectionMatrix();
  };
  new ResizeObserver(resize).observe(view);
  resize();
  return { renderer, scene, camera };
}

/** A polyline through `positions` (x, y, z each). */
function path(positions, color) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  return new THREE.Line(geometry, new THREE.LineBasicMaterial({ color }));
}

async function main() {
  await init();
  const motion = Motion.fromScene('l_cycle_rotated');
  motion.setOptions({ scheme: 'fourpoint', levels: 5 });

  const { renderer, scene, camera } = stage();
  const geometry = new THREE.TorusKnotGeometry(0.6, 0.18, 128, 16);
  const knot = new THREE.Mesh(
    geometry,
    new THREE.MeshStandardMaterial({ color: 0x2f6fd6, roughness: 0.45, metalness: 0.1 }),
  );
  knot.add(new THREE.AxesHelper(0.9));
  scene.add(knot);

  // The keyframes: within 1e-3 scene units of the motion at every vertex of the knot.
  const tracks = motion.keyframeTracks({ tolerance: 1e-3, points: geometry.attributes.position.array });
  const clip = new THREE.AnimationClip(motion.name ?? 'motion', tracks.duration, [
    new THREE.VectorKeyframeTrack('.position', tracks.times, tracks.positions),
    // x, y, z, w: three.js's quaternion order (ScrewBender's Pose.rotation is w, x, y, z).
    new THREE.QuaternionKeyframeTrack('.quaternion', tracks.times, tracks.quaternions),
  ]);
  const mixer = new THREE.AnimationMixer(knot);
  mixer.clipAction(clip).setLoop(THREE.LoopRepeat, Infinity).play();

  scene.add(path(tracks.positions, 0x888888));
  for (let i = 0; i < motion.poseCount; i++) {
    const pose = motion.pose(i);
    const axes = new THREE.AxesHelper(0.7);
    axes.position.set(...pose.origin);
    const [w, x, y, z] = pose.rotation;
    axes.quaternion.set(x, y, z, w);
    scene.add(axes);
  }

  // Frame the path: look at its centre from the front-left, above.
  const box = new THREE.Box3().setFromArray(tracks.positions);
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3()).length() + 2 * tracks.radius;
  camera.position.copy(centre).add(new THREE.Vector3(-0.75, -1.1, 0.8).multiplyScalar(0.75 * size));
  camera.lookAt(centre);

  const fixed = Number.parseFloat(new URLSearchParams(location.search).get('t'));
  status.textContent = `${tracks.times.length} keyframes over ${tracks.duration.toFixed(2)} s, within ${tracks.tolerance} at the knot's ${geometry.attributes.position.count} vertices.`;
  // `?t=` holds that moment (a resize still redraws it); otherwise the mixer advances per frame.
  if (Number.isFinite(fixed)) mixer.setTime(fixed);
  const timer = new THREE.Timer();
  renderer.setAnimationLoop((time) => {
    timer.update(time);
    if (!Number.isFinite(fixed)) mixer.update(timer.getDelta());
    renderer.render(scene, camera);
  });
  document.body.dataset.keys = String(tracks.times.length);
  motion.free();
}

main().catch((e) => {
  status.textContent = `The example could not start: ${e instanceof Error ? e.message : e}`;
  document.body.dataset.error = 'true';
});
