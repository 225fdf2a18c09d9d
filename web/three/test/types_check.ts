// Compiled (not run) by the web.three test with TypeScript against @types/three: the package's
// declarations (sss-three.d.ts) describe what a host writes, and reject what it must not.
import * as THREE from 'three';
import { EffectComposer } from 'three/examples/jsm/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/examples/jsm/postprocessing/RenderPass.js';
import {
  SSS, SSSPass, createSSSRenderTarget, setSSSMaterial, MEASURED_PROFILES, SPLIT_PROGRAM_KEY, TEXTURINGS, type SSSStats
} from 'sss-three';

export async function host(renderer: THREE.WebGLRenderer, scene: THREE.Scene, camera: THREE.PerspectiveCamera): Promise<SSSStats> {
  const skin = setSSSMaterial(new THREE.MeshStandardMaterial(), { profile: 'skin', object: 1, texturing: 'post' });
  setSSSMaterial(new THREE.MeshPhysicalMaterial(), { texturing: 'pre-and-post' });
  const post: number = TEXTURINGS.post;
  skin.roughness = 0.5;  // the helper returns the material's own type
  setSSSMaterial(new THREE.MeshPhysicalMaterial(), { profile: 'burley', measured: 'wholemilk' });
  setSSSMaterial(new THREE.MeshStandardMaterial(), { profile: 'burley', albedo: [0.8, 0.5, 0.4], dmfpMm: [3, 1.4, 0.7] });
  const marble: number = MEASURED_PROFILES.marble;
  const sss = await SSS.create(renderer, { wasmUrl: '/sss_three.wasm' });
  const composer = new EffectComposer(renderer, createSSSRenderTarget(640, 360));
  composer.addPass(new RenderPass(scene, camera));
  const pass = new SSSPass(sss, scene, camera, { metresPerUnit: 1, taps: 25, path: 'masked' });
  pass.split = 0.5 + marble * 0 + post * 0;
  pass.splitLighting = false;  // the whole lit colour blurred
  const patched: boolean = skin.customProgramCacheKey().includes(SPLIT_PROGRAM_KEY);
  composer.addPass(pass);
  composer.render();
  const r: number = sss.render(createSSSRenderTarget(64, 64), scene, camera, { scale: 2, splitLighting: patched });
  if (r !== 0) console.log(sss.lastError, sss.resultString(r));
  // @ts-expect-error: not a profile the library has
  setSSSMaterial(new THREE.MeshStandardMaterial(), { profile: 'jade' });
  // @ts-expect-error: texturing is one of TEXTURINGS' names
  setSSSMaterial(new THREE.MeshStandardMaterial(), { texturing: 'after' });
  // @ts-expect-error: path is one of PATHS' names
  pass.path = 'fastest';
  // @ts-expect-error: splitLighting is a boolean
  pass.splitLighting = 'specular';
  return sss.stats();
}
