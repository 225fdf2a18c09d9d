// Types of sss-three (sss-three.js; docs/three.md). Checked by the web.three test with TypeScript
// against @types/three (test/types_check.ts).
import type { Camera, Material, Scene, WebGLRenderer, WebGLRenderTarget, RenderTargetOptions } from 'three';
import { Pass } from 'three/examples/jsm/postprocessing/Pass.js';

/** Jensen et al. 2001's measured materials, numbered as sss.h's sss_profile. */
export declare const MEASURED_PROFILES: Readonly<{
  apple: 1; chicken1: 2; chicken2: 3; cream: 4; ketchup: 5; marble: 6; potato: 7; skimmilk: 8; skin1: 9;
  skin2: 10; wholemilk: 11;
}>;
export type MeasuredProfile = keyof typeof MEASURED_PROFILES;

/** sss_settings.path by name. */
export declare const PATHS: Readonly<{ fragment: 0; compute: 1; auto: 2; masked: 3; half: 4 }>;
export type SSSPath = keyof typeof PATHS;

/** sss_settings.texturing by name: where a material's albedo goes (docs/three.md "Texturing"). */
export declare const TEXTURINGS: Readonly<{ pre: 0; post: 1; 'pre-and-post': 2 }>;
export type SSSTexturing = keyof typeof TEXTURINGS;

/** In customProgramCacheKey() of a material the pass has patched to split its lighting
 *  (MeshStandardMaterial and MeshPhysicalMaterial with userData.sss, once the pass has seen them). */
export declare const SPLIT_PROGRAM_KEY: string;

/** A translucent material's profile (material.userData.sss). */
export interface SSSMaterialSpec {
  /** 'skin': eq. (1) fitted to d'Eon's skin (the library's default); a measured material; 'burley'. */
  profile?: 'skin' | 'burley' | MeasuredProfile;
  /** 'burley' with a measured material's published albedo and mean free path. */
  measured?: MeasuredProfile;
  /** 'burley': surface albedo per channel, (0, 1]. */
  albedo?: [number, number, number];
  /** 'burley': diffuse mean free path per channel, millimetres. */
  dmfpMm?: [number, number, number];
  /** 0-15: objects of one profile do not blur into each other. Default 0. */
  object?: number;
  /** Multiply the pass's scale, strength and falloff. Default 1. */
  scale?: number;
  strength?: number;
  falloff?: number;
  /** Where the albedo goes: 'pre' (default: blurred with the light), 'post' (the light alone
   *  blurred, the albedo multiplied back: a scanned or textured albedo stays sharp), 'pre-and-post'
   *  (half of it blurred). Only where the pass splits the material's lighting (a standard or physical
   *  material, splitLighting on); elsewhere the material is filtered pre-scatter. */
  texturing?: SSSTexturing;
}

/** The pass's settings (SSSPass properties, SSS.render's last argument). */
export interface SSSSettings {
  /** The scene's unit in metres. Default 1. */
  metresPerUnit: number;
  /** Multiplies every profile's scattering distance; 1 is physical. */
  scale: number;
  /** Multiply the library's calibrated per-channel strength and falloff (the skin kernel). */
  strength: number;
  falloff: number;
  /** Taps per pass, odd, 3-65. Default 17. */
  taps: number;
  /** Fade taps across depth steps. Default true. */
  followSurface: boolean;
  /** Default 'auto'. */
  path: SSSPath;
  /** [0, 1]: share of outer taps jittered per pixel. Default 0. */
  jitter: number;
  /** [0, 1]: the fraction of the width, from the left, left unfiltered (split view). Default 0. */
  split: number;
  /** Standard and physical materials draw their diffuse light apart from their specular and
   *  emissive light, and only the diffuse is blurred (docs/three.md "Split lighting"). Default true. */
  splitLighting: boolean;
}
export declare const DEFAULT_SETTINGS: Readonly<SSSSettings>;

/** sss_get_stats. */
export interface SSSStats {
  frames: number;
  passes: number;
  lastFramePasses: number;
  lastFramePath: number;
  gpuMemoryBytes: number;
  glslVariant: number;
}

export interface SSSCreateOptions {
  /** Where the WebAssembly is; default: wasm/sss_three.wasm beside sss-three.js. */
  wasmUrl?: string;
  /** sss_create_desc.flags (sss.h sss_create_flag). */
  flags?: number;
}

/** The library on one WebGLRenderer's WebGL2 context. */
export declare class SSS {
  static create(renderer: WebGLRenderer, options?: SSSCreateOptions): Promise<SSS>;
  readonly renderer: WebGLRenderer;
  readonly gl: WebGL2RenderingContext;
  /** The library's message about the last refused setting or frame; '' after a successful frame. */
  readonly lastError: string;
  /** sss_result of the last frame (0: SSS_OK), -1 when nothing translucent was visible. */
  readonly lastResult: number;
  /** Filters the target in place; returns the sss_result (0: filtered, else the target is untouched). */
  render(target: WebGLRenderTarget, scene: Scene, camera: Camera, settings?: Partial<SSSSettings>): number;
  /** Re-prepares for a new size now instead of in the next frame. */
  prepare(width: number, height: number, colorFormat?: number, depthFormat?: number): number;
  stats(): SSSStats;
  resultString(result: number): string;
  defaults(): { strength: [number, number, number]; falloff: [number, number, number]; taps: number };
  dispose(): void;
}

/** The EffectComposer pass: filters the read buffer in place (needsSwap false). Its settings are
 *  its properties: every field of SSSSettings (the interface below merges them into the class). */
export declare class SSSPass extends Pass {
  constructor(sss: SSS, scene: Scene, camera: Camera, settings?: Partial<SSSSettings>);
  sss: SSS;
  scene: Scene;
  camera: Camera;
  readonly lastError: string;
  settings(): SSSSettings;
}
export interface SSSPass extends SSSSettings {}

/** Sets material.userData.sss; returns the material. */
export declare function setSSSMaterial<M extends Material>(material: M, spec?: SSSMaterialSpec): M;

/** Half-float RGBA colour with a DepthTexture: the target SSSPass reads. */
export declare function createSSSRenderTarget(width: number, height: number, options?: RenderTargetOptions): WebGLRenderTarget;
