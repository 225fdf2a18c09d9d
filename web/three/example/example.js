// The sss-three example (docs/three.md): the head scan through GLTFLoader, OrbitControls, every
// setting of the pass in a lil-gui panel, a split view and the frame time. window.sssExample is
// what the web.three test drives (web/three/test/three_test.py).
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { EffectComposer } from 'three/examples/jsm/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/examples/jsm/postprocessing/RenderPass.js';
import { OutputPass } from 'three/examples/jsm/postprocessing/OutputPass.js';
import GUI from 'lil-gui';
import { SSS, SSSPass, PATHS, MEASURED_PROFILES, TEXTURINGS, createSSSRenderTarget, setSSSMaterial } from 'sss-three';

const params = new URLSearchParams(location.search);
const WIDTH = Number(params.get('width') || 640), HEIGHT = Number(params.get('height') || 360);
const $ = (id) => document.getElementById(id);

const example = { ready: false, failed: null };
window.sssExample = example;

// The renderer behind WebGL, as the page reports it (SwiftShader through ANGLE in headless Chromium).
function rendererString(gl) {
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return 'WebGL2: ' + (info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)) +
    ' (' + gl.getParameter(gl.VERSION) + ')';
}

// The canvas as RGBA8, top row first, base64 (what the test compares and saves).
function pixels(gl) {
  const width = gl.drawingBufferWidth, height = gl.drawingBufferHeight;
  const data = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  const rows = new Uint8Array(data.length);
  for (let y = 0; y < height; ++y) rows.set(data.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
  let text = '';
  for (let i = 0; i < rows.length; i += 0x8000) text += String.fromCharCode.apply(null, rows.subarray(i, i + 0x8000));
  return btoa(text);
}

async function main() {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(WIDTH, HEIGHT);
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  renderer.shadowMap.enabled = true;
  $('view').appendChild(renderer.domElement);
  const gl = renderer.getContext();
  $('renderer').textContent = rendererString(gl);

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x0b0c10);
  // Metres, as the scan: the head 0.36 m tall, centred on the origin, facing +Z.
  const camera = new THREE.PerspectiveCamera(30, WIDTH / HEIGHT, 0.05, 10);
  camera.position.set(0.12, 0.05, 0.62);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.set(0.0, 0.02, 0.0);
  controls.update();

  const key = new THREE.DirectionalLight(0xffffff, 3.0);
  key.position.set(0.6, 0.5, 0.8);
  key.castShadow = true;
  key.shadow.mapSize.set(1024, 1024);
  Object.assign(key.shadow.camera, { left: -0.3, right: 0.3, top: 0.3, bottom: -0.3, near: 0.1, far: 3 });
  scene.add(key, new THREE.HemisphereLight(0xbcd0ff, 0x302418, 0.6));

  const gltf = await new GLTFLoader().loadAsync(params.get('model') || '/head.glb');
  const head = gltf.scene;
  // The head's albedo map is a scan: it already holds the skin's own scattering, so only the light
  // is blurred and the map multiplied back sharp (post-scatter texturing, docs/three.md).
  head.traverse((o) => {
    if (o.isMesh) {
      o.castShadow = o.receiveShadow = true;
      setSSSMaterial(o.material, { profile: 'skin', object: 0, texturing: 'post' });
    }
  });
  scene.add(head);
  const sphere = new THREE.SphereGeometry(0.045, 64, 32);
  const marble = new THREE.Mesh(sphere, setSSSMaterial(new THREE.MeshStandardMaterial({ color: 0xf2efe8, roughness: 0.35 }),
    { profile: 'marble', object: 1 }));
  marble.position.set(-0.19, -0.09, 0.08);
  const milk = new THREE.Mesh(sphere, setSSSMaterial(new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.3 }),
    { profile: 'burley', measured: 'wholemilk', object: 2 }));
  milk.position.set(0.19, -0.09, 0.08);
  // Glossy skin (a physical material, low roughness, clearcoat off): its highlight stays sharp while
  // the diffuse light under it scatters (the pass's split lighting).
  // Post-scatter like the head: one skin profile for both.
  const glossy = new THREE.Mesh(sphere, setSSSMaterial(new THREE.MeshPhysicalMaterial({ color: 0xd9a08a, roughness: 0.2,
    specularIntensity: 1 }), { profile: 'skin', object: 3, texturing: 'post' }));
  glossy.position.set(-0.2, 0.075, 0.05);
  for (const m of [marble, milk, glossy]) m.castShadow = m.receiveShadow = true;
  scene.add(marble, milk, glossy);

  const composer = new EffectComposer(renderer, createSSSRenderTarget(WIDTH, HEIGHT));
  composer.addPass(new RenderPass(scene, camera));
  composer.addPass(new OutputPass());

  // One frame, waited for with a one-pixel read (a full round trip through the GPU): its time in ms.
  const pixel = new Uint8Array(4);
  let pass = null;
  function frame() {
    const start = performance.now();
    composer.render();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    const ms = performance.now() - start;
    $('error').textContent = pass && pass.enabled ? pass.lastError : '';
    $('readout').textContent = `frame ${ms.toFixed(1)} ms (${WIDTH}x${HEIGHT}, three's render + SSSPass + OutputPass, ` +
      'waited for with a one-pixel read)';
    return ms;
  }
  Object.assign(example, { THREE, renderer, scene, camera, composer, frame, pixels: () => pixels(gl) });
  // ?hold: the test renders three's own frames before the library exists, then calls proceed().
  if (params.has('hold')) {
    example.holding = true;
    await new Promise((resolve) => { example.proceed = resolve; });
  }

  let sss;
  try {
    sss = await SSS.create(renderer);
  } catch (e) {
    example.failed = String(e.message || e);
    $('error').textContent = example.failed;
    return;
  }
  pass = new SSSPass(sss, scene, camera, { metresPerUnit: 1 });
  composer.insertPass(pass, 1);  // after the RenderPass, before tone mapping and sRGB

  // Every setting of the pass; the materials' profiles too.
  const gui = new GUI({ title: 'SSSPass' });
  const redraw = () => frame();
  gui.add(pass, 'enabled').onChange(redraw);
  gui.add(pass, 'metresPerUnit', 0.01, 10).onChange(redraw);
  gui.add(pass, 'scale', 0, 4, 0.05).onChange(redraw);
  const d = sss.defaults();
  gui.add(pass, 'strength', 0, 1 / Math.max(...d.strength), 0.01).onChange(redraw);
  gui.add(pass, 'falloff', 0, 1 / Math.max(...d.falloff), 0.01).onChange(redraw);
  gui.add(pass, 'taps', 3, 65, 2).onChange(redraw);
  gui.add(pass, 'followSurface').onChange(redraw);
  gui.add(pass, 'path', Object.keys(PATHS)).onChange(redraw);
  gui.add(pass, 'jitter', 0, 1, 0.05).onChange(redraw);
  gui.add(pass, 'split', 0, 1, 0.01).onChange(redraw);
  gui.add(pass, 'splitLighting').onChange(redraw);
  const profiles = ['skin', 'burley', ...Object.keys(MEASURED_PROFILES)];
  const materials = gui.addFolder('materials');
  for (const [label, mesh] of [['head', null], ['left sphere', marble], ['right sphere', milk], ['glossy sphere', glossy]]) {
    const material = mesh ? mesh.material : head.getObjectByProperty('isMesh', true).material;
    materials.add(material.userData.sss, 'profile', profiles).name(label).onChange(redraw);
  }
  const headSpec = head.getObjectByProperty('isMesh', true).material.userData.sss;
  materials.add(headSpec, 'texturing', Object.keys(TEXTURINGS)).name('head texturing').onChange(redraw);
  controls.addEventListener('change', redraw);

  Object.assign(example, {
    pass, sss, gui, marble, milk, glossy, head,
    // Median ms of `count` frames with the pass on, with it on and splitLighting off (the whole lit
    // colour blurred), and with it off (three's frame alone).
    time(count) {
      const median = (a) => a.sort((x, y) => x - y)[a.length >> 1];
      const enabled = pass.enabled, splitLighting = pass.splitLighting, on = [], unsplit = [], off = [];
      for (let i = 0; i < count; ++i) {
        pass.enabled = true;
        on.push(frame());
        pass.splitLighting = false;
        unsplit.push(frame());
        pass.splitLighting = splitLighting;
        pass.enabled = false;
        off.push(frame());
      }
      pass.enabled = enabled;
      frame();
      return { on: median(on), unsplit: median(unsplit), off: median(off) };
    }
  });
  frame();
  example.ready = true;
}

main().catch((e) => {
  example.failed = String((e && e.stack) || e);
  $('error').textContent = example.failed;
});
