// The 3D view of report.html: the part and its toolpath (a GLB embedded in the page as base64,
// in <script type="application/octet-stream" id="part-model">) drawn with three.js into the
// element #view3d, turned with the mouse. Bundled at build time; nothing is fetched.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

function decodeBase64(text) {
  const binary = atob(text.replace(/\s+/g, ''));
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

function say(container, message) {
  const note = document.createElement('p');
  note.className = 'view3d-note';
  note.textContent = message;
  container.appendChild(note);
  container.dataset.state = 'failed';
}

function webglAvailable() {
  try {
    const canvas = document.createElement('canvas');
    return !!(canvas.getContext('webgl2') || canvas.getContext('webgl'));
  } catch (e) {
    return false;
  }
}

function show(container, gltf) {
  const width = container.clientWidth || 800;
  const height = container.clientHeight || 500;
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(width, height);
  container.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f6f9);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8a9099, 1.6));
  const key = new THREE.DirectionalLight(0xffffff, 2.0);
  key.position.set(1, 2, 3);
  scene.add(key);
  scene.add(gltf.scene);
  // Metal reads better a little rough and not mirror-like without an environment map.
  gltf.scene.traverse((node) => {
    if (node.isMesh && node.material) {
      node.material.metalness = Math.min(node.material.metalness, 0.3);
      node.material.roughness = Math.max(node.material.roughness, 0.5);
    }
  });

  // Framed on the part (the triangle meshes), not on the rapids to a far reference point, nor
  // on the machine beside it (the meshes named "machine …": the chuck's jaws, the tailstock,
  // the tool), which may reach far from the part.
  const box = new THREE.Box3();
  gltf.scene.updateMatrixWorld(true);
  gltf.scene.traverse((node) => {
    if (node.isMesh && !node.isLine && !node.isPoints && !node.name.startsWith('machine')) box.expandByObject(node);
  });
  if (box.isEmpty()) box.setFromObject(gltf.scene);
  const size = box.getSize(new THREE.Vector3());
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(size.length() / 2, 1e-6);
  const camera = new THREE.PerspectiveCamera(30, width / height, radius / 100, radius * 100);
  const distance = radius / Math.sin((camera.fov * Math.PI) / 360);
  // From the front (the spindle axis across, X up), turned a little to show the end face.
  camera.position.copy(centre).add(new THREE.Vector3(0.38, 0.18, 0.91).multiplyScalar(distance));
  camera.lookAt(centre);

  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();
  const draw = () => renderer.render(scene, camera);
  controls.addEventListener('change', draw);
  window.addEventListener('resize', () => {
    const w = container.clientWidth || width;
    const h = container.clientHeight || height;
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    renderer.setSize(w, h);
    draw();
  });
  draw();
  container.dataset.state = 'drawn';
}

function start() {
  const container = document.getElementById('view3d');
  const model = document.getElementById('part-model');
  if (!container || !model) return;
  if (!webglAvailable()) {
    say(container, 'This browser cannot draw 3D (WebGL is off); the pictures above show the part.');
    return;
  }
  new GLTFLoader().parse(
    decodeBase64(model.textContent),
    '',
    (gltf) => show(container, gltf),
    (error) => say(container, 'The 3D view could not be read: ' + (error && error.message ? error.message : error)),
  );
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
