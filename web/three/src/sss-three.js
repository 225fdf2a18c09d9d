// sss-three: the sss library's screen-space subsurface scattering as a three.js post-processing
// pass, on three's own WebGL2 context (docs/three.md). The library (WebAssembly, wasm/sss_three.js)
// draws with Emscripten's WebGL bindings; this module registers three's context with them, lends
// three's WebGL objects the integer names the library's C API takes, writes the per-pixel
// profile texture (R8UI: profile | object << 4) from the materials' userData.sss, and splits the
// lighting of three's standard and physical materials (split-lighting.js): the library blurs the
// diffuse light alone and the pass adds the specular back.
import {
  Color, DepthFormat, DepthStencilFormat, DepthTexture, FloatType, GLSL3, HalfFloatType, NearestFilter, RedFormat,
  RedIntegerFormat, RGBAFormat, ShaderMaterial, UnsignedByteType, UnsignedInt248Type, UnsignedIntType,
  UnsignedShortType, WebGLRenderTarget
} from 'three';
import { FullScreenQuad, Pass } from 'three/examples/jsm/postprocessing/Pass.js';
import createSSSModule from './wasm/sss_three.js';
import { SplitCompose, SplitTargets, canSplit, patchMaterial } from './split-lighting.js';

export { SPLIT_PROGRAM_KEY } from './split-lighting.js';

// GL enum values of the formats the library takes (sss.h SSS_GL_*).
const GL_RGBA16F = 0x881A, GL_RGBA32F = 0x8814, GL_R8UI = 0x8232, GL_SRGB8_ALPHA8 = 0x8C43;
const GL_DEPTH_COMPONENT16 = 0x81A5, GL_DEPTH_COMPONENT24 = 0x81A6, GL_DEPTH_COMPONENT32F = 0x8CAC;
const GL_DEPTH24_STENCIL8 = 0x88F0, GL_DEPTH32F_STENCIL8 = 0x8CAD;
const SSS_FRAME_DEPTH_ZERO_TO_ONE = 0x1;

/** The measured materials of Jensen et al. 2001 by name, as sss.h's sss_profile numbers them. */
export const MEASURED_PROFILES = Object.freeze({
  apple: 1, chicken1: 2, chicken2: 3, cream: 4, ketchup: 5, marble: 6, potato: 7, skimmilk: 8, skin1: 9,
  skin2: 10, wholemilk: 11
});

/** sss_settings.path by name. */
export const PATHS = Object.freeze({ fragment: 0, compute: 1, auto: 2, masked: 3, half: 4 });

/** sss_settings.texturing (sss_texturing) by name: where the material's albedo goes (docs/three.md). */
export const TEXTURINGS = Object.freeze({ pre: 0, post: 1, 'pre-and-post': 2 });

// wasm/profile_fields.hpp's ProfileKind and the floats of one profile (kProfileFloats).
const KIND_SEPARABLE = 0, KIND_MEASURED = 1, KIND_BURLEY_MEASURED = 2, KIND_BURLEY = 3;
const PROFILE_FLOATS = 17;
// The profile nibble of pixels the library must leave alone: the profiles use 0..14 (the library
// leaves a pixel whose index has no profile as it is).
const NO_PROFILE = 15;
const MAX_PROFILES = 15;
// How far (window depth) three's depth may lie behind the profile pass's fragment and still be its
// surface: two vertex shaders' rounding (a few steps of a 24-bit depth buffer), yet finer than any
// gap between two surfaces that matters (window depth changes by about near / distance² per unit: 1e-5 is 0.1 mm at 1 m
// from a camera whose near plane is at 0.1).
const DEPTH_EPSILON = '1e-5';
const NO_SPLIT = new Float32Array(4);

/**
 * Marks a material as translucent: the pass filters the pixels it covers with the profile given.
 * `spec.profile`: 'skin' (the library's default, eq. (1) fitted to d'Eon's skin), a measured
 * material's name (MEASURED_PROFILES, through the pre-integrated kernel) or 'burley' (Burley's
 * normalized diffusion: `measured` names a material whose published parameters to take, or
 * `albedo` and `dmfpMm` give them); `object` (0-15) keeps objects of one profile from blurring into
 * each other; `scale`, `strength`, `falloff` multiply the pass's; `texturing` (TEXTURINGS: 'pre',
 * the default, 'post' or 'pre-and-post') says where the albedo goes: blurred with the light, or
 * multiplied back after the blur (a standard or physical material whose lighting the pass splits;
 * any other material, or a frame without the split, is filtered pre-scatter). Stored in
 * material.userData.sss.
 */
export function setSSSMaterial(material, spec = {}) {
  material.userData.sss = Object.assign({ profile: 'skin', object: 0 }, spec);
  return material;
}

/**
 * A render target the pass can read: half-float RGBA colour (linear light) with a DepthTexture.
 * Give it to `new EffectComposer(renderer, target)`.
 */
export function createSSSRenderTarget(width, height, options = {}) {
  return new WebGLRenderTarget(width, height, Object.assign({
    type: HalfFloatType, format: RGBAFormat, depthBuffer: true,
    depthTexture: new DepthTexture(width, height, UnsignedIntType)
  }, options));
}

// Whether a draw of `material` (userData.sss `spec`) with the pass's `settings` writes its lighting
// split, in a target with the split's attachments: a standard or physical material, opaque, with a
// strength of its own, the pass's splitLighting on. The split's albedo is this material's then.
function drawsSplit(material, spec, settings) {
  return canSplit(material) && material.transparent !== true && !!settings.splitLighting &&
    settings.strength * (spec.strength ?? 1) > 0;
}

function colorFormatOf(gl, texture) {
  if (texture.internalFormat) return gl[texture.internalFormat] || 0;
  if (texture.format !== RGBAFormat) return 0;
  return texture.type === HalfFloatType ? GL_RGBA16F : texture.type === FloatType ? GL_RGBA32F : 0;
}

// As three's WebGLTextures chooses a DepthTexture's internal format.
function depthFormatOf(texture) {
  const stencil = texture.format === DepthStencilFormat;
  if (!stencil && texture.format !== DepthFormat) return 0;
  if (texture.type === FloatType) return stencil ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
  if (texture.type === UnsignedShortType) return stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT16;
  if (texture.type === UnsignedIntType || texture.type === UnsignedInt248Type) {
    return stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
  }
  return 0;
}

// The profile pass's material: the profile texture's value where the mesh is in front, with three's
// own vertex chunks so that skinned, morphed, instanced and batched meshes land where three drew
// them. Left of `split` (a fraction of the width) every pixel is NO_PROFILE: the split view. So is
// a pixel where three's own depth lies behind this fragment: this shader and three's compute the
// position with different code, which can move a silhouette by a pixel (measured: about 400 pixels
// of the head's outline at 640x360 otherwise marked skin over the background). The second output
// is the split's mask (R8): 1 where a material that drew its lighting split is in front (left of
// the split view's line too, where that material wrote zeros to add): where the pass adds the
// unblurred light back (split-lighting.js).
const PROFILE_VERTEX = `
#include <common>
#include <batching_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
#include <batching_vertex>
#include <skinbase_vertex>
#include <begin_vertex>
#include <morphinstance_vertex>
#include <morphtarget_vertex>
#include <skinning_vertex>
#include <project_vertex>
#include <clipping_planes_vertex>
}`;
const PROFILE_FRAGMENT = `
#include <clipping_planes_pars_fragment>
uniform uint sssValue;
uniform float sssDrewSplit;
uniform float sssSplitX;
uniform highp sampler2D sssDepth;
layout(location = 0) out highp uvec4 sssProfile;
layout(location = 1) out highp vec4 sssSplitMask;
void main() {
#include <clipping_planes_fragment>
  float drawn = texelFetch(sssDepth, ivec2(gl_FragCoord.xy), 0).r;
  bool front = drawn <= gl_FragCoord.z + ${DEPTH_EPSILON};
  sssProfile = uvec4(front && gl_FragCoord.x >= sssSplitX ? sssValue : ${NO_PROFILE}u, 0u, 0u, 0u);
  sssSplitMask = vec4(front ? sssDrewSplit : 0.0, 0.0, 0.0, 0.0);
}`;

/**
 * The library on one three.js WebGLRenderer's context. Create it with `await SSS.create(renderer)`;
 * `render(target, scene, camera)` filters a render target in place (hosts without a composer),
 * `new SSSPass(sss, scene, camera)` does it inside an EffectComposer.
 */
export class SSS {
  /**
   * Loads the WebAssembly (beside this module, or `options.wasmUrl`), registers the renderer's
   * WebGL2 context with Emscripten's GL layer and creates the library's context on it.
   * Rejects with the library's message where it cannot run (no EXT_color_buffer_float, ...).
   */
  static async create(renderer, options = {}) {
    const moduleOptions = {};
    if (options.wasmUrl) moduleOptions.locateFile = (file) => (file.endsWith('.wasm') ? options.wasmUrl : file);
    const module = await createSSSModule(moduleOptions);
    return new SSS(module, renderer, options);
  }

  constructor(module, renderer, options = {}) {
    const gl = renderer.getContext();
    if (typeof WebGL2RenderingContext === 'undefined' || !(gl instanceof WebGL2RenderingContext)) {
      throw new Error('sss-three: the renderer has no WebGL2 context (the library needs OpenGL ES 3.0)');
    }
    this.module = module;
    this.renderer = renderer;
    this.gl = gl;
    const GL = module.GL;
    this._GL = GL;
    // Three enables the extensions it uses itself; Emscripten's default would enable every one the
    // browser offers on three's context behind its back. The library needs float render targets and
    // (for RGBA32F colour) float filtering, which three enables too; asking again changes nothing.
    gl.getExtension('EXT_color_buffer_float');
    gl.getExtension('OES_texture_float_linear');
    this._handle = GL.registerContext(gl, { majorVersion: 2, minorVersion: 0, enableExtensionsByDefault: false });
    this._lent = [];
    // The profiles' floats, the projection, the stats' doubles (8-byte aligned: malloc's blocks are).
    const profileBytes = Math.ceil(PROFILE_FLOATS * MAX_PROFILES * 4 / 8) * 8;
    this._scratch = module._malloc(profileBytes + 16 * 4 + 8 * 8);
    this._projection = this._scratch + profileBytes;
    this._stats = this._projection + 16 * 4;
    // sss_create restores what it binds (sss.h), by the names it reads back: three's objects need
    // theirs lent as for every other call, or the restore would unbind them.
    this.context = this._call(() => {
      this._lendBindings();
      return module._sss3_create(options.flags || 0);
    });
    if (!this.context) {
      const message = this._message();
      this._free();
      throw new Error(message);
    }
    this._profileKey = null;
    this._failedKey = null;
    this._prepared = '';
    this._albedoFormat = 0;  // the last profiles' albedo: SRGB8_ALPHA8 where a texturing needs one
    this._frame = 0;
    this._idTarget = null;
    this._idMaterials = new Map();
    this._split = { value: 0 };
    this._depth = { value: null };  // three's DepthTexture of the frame: the profile pass's uniform
    this._clear = new Color();
    this._idClear = new Color();
    this._idClear.r = NO_PROFILE;  // three clears an unsigned-integer target with the clear colour as is
    // The split (split-lighting.js): the materials patched, which pass or settings a scene's split
    // follows (scene -> { pass }, or { settings, armed } from SSS.render: read before the scene's
    // draws, when the pass has not run yet), per target what its last scene render drew split, and
    // the targets' attachments.
    this._patched = new WeakSet();
    this._sources = new WeakMap();
    this._drawn = new WeakMap();
    this._compose = null;
    this._splittable = false;  // the last frame's scene had a material that can split
    this._splitTargets = new SplitTargets(renderer);
    /** The library's message about the last refused setting or frame; '' after a successful frame. */
    this.lastError = '';
    /** sss_result of the last frame (0: SSS_OK), or -1 when no frame ran (nothing translucent). */
    this.lastResult = -1;
  }

  _message() { return this.module.UTF8ToString(this.module._sss3_last_error()); }

  // Lends `object` (a WebGL object of three's) the integer name Emscripten's GL layer will look it
  // up by, for the length of one call: the library reads bindings through glGetIntegerv, which
  // answers with `object.name`, and restores them by name. The name stays on the object, so a
  // texture keeps its name from frame to frame (the library's steady frame).
  _lend(object, table) {
    if (!object) return 0;
    if (object.name === undefined) object.name = this._GL.getNewId(table);
    if (table[object.name] !== object) {
      table[object.name] = object;
      this._lent.push(table, object.name);
    }
    return object.name;
  }

  // Everything the library reads back to restore (state_guard.cpp): the bound program, vertex
  // array, framebuffers, renderbuffer, buffers, and the textures and samplers of units 0-7.
  _lendBindings() {
    const gl = this.gl, GL = this._GL;
    this._lend(gl.getParameter(gl.CURRENT_PROGRAM), GL.programs);
    this._lend(gl.getParameter(gl.VERTEX_ARRAY_BINDING), GL.vaos);
    this._lend(gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING), GL.framebuffers);
    this._lend(gl.getParameter(gl.READ_FRAMEBUFFER_BINDING), GL.framebuffers);
    this._lend(gl.getParameter(gl.RENDERBUFFER_BINDING), GL.renderbuffers);
    for (const binding of [gl.ARRAY_BUFFER_BINDING, gl.ELEMENT_ARRAY_BUFFER_BINDING, gl.PIXEL_UNPACK_BUFFER_BINDING,
      gl.PIXEL_PACK_BUFFER_BINDING, gl.UNIFORM_BUFFER_BINDING]) {
      this._lend(gl.getParameter(binding), GL.buffers);
    }
    this._lend(gl.getIndexedParameter(gl.UNIFORM_BUFFER_BINDING, 0), GL.buffers);
    const active = gl.getParameter(gl.ACTIVE_TEXTURE);
    for (let unit = 0; unit < 8; ++unit) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      this._lend(gl.getParameter(gl.TEXTURE_BINDING_2D), GL.textures);
      this._lend(gl.getParameter(gl.SAMPLER_BINDING), GL.samplers);
    }
    gl.activeTexture(active);
  }

  // Runs `body` with three's context current in Emscripten's GL layer, then takes the lent names
  // back out of its tables (the objects stay three's; nothing of theirs is kept alive here).
  _call(body) {
    this._GL.makeContextCurrent(this._handle);
    try {
      return body();
    } finally {
      for (let i = 0; i < this._lent.length; i += 2) this._lent[i][this._lent[i + 1]] = null;
      this._lent.length = 0;
      this._GL.makeContextCurrent(0);
    }
  }

  // The profiles the visible translucent materials use, in the order they are met: [{key, spec}],
  // and for each material its profile index. `splitting`: the frame's materials draw their lighting
  // split (the target has the split's attachments), so those that do (drawsSplit) have an albedo
  // in its attachment and keep their texturing; every other material is filtered pre-scatter (where
  // it lies the albedo attachment holds 0, or another material's albedo). Each profile's texturing
  // as used (`texturings`, sss_texturing numbers; -1 for a name the pass does not know, which the
  // library refuses) is part of its key.
  _collectProfiles(scene, settings, splitting = false) {
    const profiles = [], texturings = [], byKey = new Map(), perMaterial = new Map();
    let splittable = false;
    scene.traverseVisible((object) => {
      if (!object.isMesh) return;
      const materials = Array.isArray(object.material) ? object.material : [object.material];
      for (const material of materials) {
        const spec = material && material.userData && material.userData.sss;
        if (!spec || perMaterial.has(material)) continue;
        this._patch(material);
        splittable = splittable || canSplit(material);
        const named = TEXTURINGS[spec.texturing ?? 'pre'] ?? -1;
        const texturing = named > 0 && !(splitting && drawsSplit(material, spec, settings)) ? 0 : named;
        const key = JSON.stringify([spec.profile, spec.measured, spec.albedo, spec.dmfpMm, spec.scale, spec.strength,
          spec.falloff, texturing]);
        let index = byKey.get(key);
        if (index === undefined) {
          index = profiles.length;
          byKey.set(key, index);
          profiles.push(spec);
          texturings.push(texturing);
        }
        perMaterial.set(material, index < MAX_PROFILES ? (index | ((spec.object | 0) & 15) << 4) : NO_PROFILE);
      }
    });
    const used = texturings.slice(0, MAX_PROFILES);
    return { profiles: profiles.slice(0, MAX_PROFILES), texturings: used, albedo: used.some((t) => t !== 0),
      perMaterial, splittable, key: JSON.stringify([[...byKey.keys()], settings]) };
  }

  // sss_set_profiles when the profiles or settings changed since the last call. False (the message
  // in lastError) when the library refused them: the frame is then left as three drew it.
  _setProfiles(collected, settings) {
    if (collected.key === this._profileKey) return true;
    if (collected.key === this._failedKey) return false;
    const m = this.module, f = new Float32Array(m.HEAPF32.buffer, this._scratch, PROFILE_FLOATS * MAX_PROFILES);
    const defaults = [0, 1, 2, 3, 4, 5].map((i) => m._sss3_default(i));
    collected.profiles.forEach((spec, i) => {
      const o = i * PROFILE_FLOATS;
      let kind = KIND_SEPARABLE, profile = 0;
      if (spec.profile === 'burley') {
        kind = spec.measured !== undefined ? KIND_BURLEY_MEASURED : KIND_BURLEY;
        profile = spec.measured !== undefined ? (MEASURED_PROFILES[spec.measured] ?? -1) : 0;
      } else if (spec.profile !== 'skin') {
        kind = KIND_MEASURED;
        profile = MEASURED_PROFILES[spec.profile] ?? -1;  // the library names an unknown one
      }
      const strength = settings.strength * (spec.strength ?? 1), falloff = settings.falloff * (spec.falloff ?? 1);
      f.set([kind, profile, 0.001 / settings.metresPerUnit, settings.scale * (spec.scale ?? 1),
        defaults[0] * strength, defaults[1] * strength, defaults[2] * strength,
        defaults[3] * falloff, defaults[4] * falloff, defaults[5] * falloff,
        ...(spec.albedo || [0, 0, 0]), ...(spec.dmfpMm || [0, 0, 0]), collected.texturings[i]], o);
    });
    const r = this._call(() => m._sss3_set_profiles(this.context, this._scratch, collected.profiles.length,
      settings.taps, settings.followSurface ? 1 : 0, PATHS[settings.path] ?? -1, settings.jitter));
    if (r !== 0) {
      this.lastError = this._message();
      this.lastResult = r;
      this._failedKey = collected.key;
      return false;
    }
    this._profileKey = collected.key;
    this._failedKey = null;
    this._prepared = '';
    this._albedoFormat = collected.albedo ? GL_SRGB8_ALPHA8 : 0;
    return true;
  }

  // Patches a standard or physical material for the split once (the program then compiles with it
  // in its next draw); other materials keep three's shading and are filtered as three lit them.
  _patch(material) {
    if (!canSplit(material) || this._patched.has(material)) return;
    patchMaterial(material, (renderer, scene, m, object) => this._drawsSplit(renderer, scene, m, object));
    this._patched.add(material);
  }

  // Before each draw of a patched material: whether it writes its lighting split (null: no; else the
  // window x from which it does: right of the split view's line). Only into a target whose split
  // attachments the pass has allocated (_prepareSplit), when the scene's pass is enabled with
  // splitLighting and a strength, the library has accepted the frame's profiles and settings (a
  // refusal leaves three's frame as drawn, so it must be known before the draws: sss_set_profiles
  // is called here, once per scene render, when the profiles changed; it makes no GL call), and the
  // material is opaque with a strength of its own.
  _drawsSplit(renderer, scene, material, object) {
    const target = renderer.getRenderTarget(), frame = renderer.info.render.frame;
    if (!this.context || !this._splitTargets.companion(target)) return null;
    let drawn = this._drawn.get(target);
    if (!drawn || drawn.frame !== frame) {
      drawn = { frame, settings: this._splitSettings(renderer, scene, target), materials: new Set() };
      this._drawn.set(target, drawn);
    }
    const spec = material.userData.sss, settings = drawn.settings;
    const split = !!(settings && spec && drawsSplit(material, spec, settings));
    if (!split || !this._splitTargets.open(target, object, drawn.materials.size === 0)) return null;
    drawn.materials.add(material);
    return settings.split * target.width;
  }

  // The split's attachments for `target` (a target the pass can filter, with a material of the scene
  // that can split), for its next scene render.
  _prepareSplit(target, splittable, settings) {
    const filterable = target && target.depthTexture && target.textures.length === 1 && !(target.samples > 0) &&
      colorFormatOf(this.gl, target.texture) !== 0;
    if (filterable && settings.splitLighting && splittable) this._splitTargets.prepare(target);
  }

  _splitSettings(renderer, scene, target) {
    if (!target.depthTexture || renderer.capabilities.logarithmicDepthBuffer) return null;
    const source = this._sources.get(scene);
    let settings = null;
    if (source && source.pass) {
      settings = source.pass.enabled ? source.pass.settings() : null;
    } else if (source && source.armed === target) {
      // Without a composer, a call of SSS.render arms the next scene render into its target (that
      // render must be handed to SSS.render too: a last call with splitLighting false arms none).
      settings = source.settings;
      source.armed = null;
    }
    if (!settings || !settings.splitLighting || !(settings.strength > 0)) return null;
    const collected = this._collectProfiles(scene, settings, true);  // the target has the split's attachments
    return collected.profiles.length > 0 && this._setProfiles(collected, settings) ? settings : null;
  }

  // The materials the last scene render into `target` drew split (then forgotten: one compose per
  // render), or null.
  _takeSplit(target) {
    const drawn = this._drawn.get(target);
    this._drawn.delete(target);
    return drawn && drawn.materials.size > 0 ? drawn.materials : null;
  }

  _idMaterial(value, side, drewSplit) {
    const key = (value * 2 + (drewSplit ? 1 : 0)) * 4 + side;
    let material = this._idMaterials.get(key);
    if (!material) {
      material = new ShaderMaterial({
        glslVersion: GLSL3, vertexShader: PROFILE_VERTEX, fragmentShader: PROFILE_FRAGMENT, side, clipping: true,
        uniforms: { sssValue: { value }, sssDrewSplit: { value: drewSplit ? 1 : 0 }, sssSplitX: this._split,
          sssDepth: this._depth }
      });
      this._idMaterials.set(key, material);
    }
    return material;
  }

  // Draws the profile texture: the scene with every mesh's material swapped for its profile value
  // (NO_PROFILE for materials without userData.sss), through three itself, so three's cache sees
  // every state change; and into its second texture the split's mask (the materials of `drewSplit`).
  // Transparent meshes and non-mesh objects are left out (they do not hide what lies behind them
  // from the filter).
  _renderProfiles(scene, camera, width, height, perMaterial, split, depthTexture, drewSplit) {
    const renderer = this.renderer;
    if (!this._idTarget) {
      this._idTarget = new WebGLRenderTarget(width, height, {
        format: RedIntegerFormat, type: UnsignedByteType, internalFormat: 'R8UI', count: 2,
        minFilter: NearestFilter, magFilter: NearestFilter, depthBuffer: true, generateMipmaps: false
      });
      const mask = this._idTarget.textures[1];
      mask.format = RedFormat;
      mask.internalFormat = null;  // R8
    } else if (this._idTarget.width !== width || this._idTarget.height !== height) {
      this._idTarget.setSize(width, height);
    }
    this._split.value = split * width;
    this._depth.value = depthTexture;
    const swapped = [], hidden = [];
    scene.traverse((object) => {
      if (!object.visible) return;
      if (object.isMesh) {
        const original = object.material;
        const materials = Array.isArray(original) ? original : [original];
        if (materials.every((m) => m.transparent)) {
          hidden.push(object);
          return;
        }
        const ids = materials.map((m) => this._idMaterial(perMaterial.get(m) ?? NO_PROFILE, m.side,
          drewSplit !== null && drewSplit.has(m)));
        swapped.push(object, original);
        object.material = Array.isArray(original) ? ids : ids[0];
      } else if (object.isPoints || object.isLine || object.isSprite) {
        hidden.push(object);
      }
    });
    for (const object of hidden) object.visible = false;
    const background = scene.background, override = scene.overrideMaterial;
    const autoClear = renderer.autoClear, shadowAuto = renderer.shadowMap.autoUpdate;
    const shadowNeeds = renderer.shadowMap.needsUpdate, target = renderer.getRenderTarget();
    renderer.getClearColor(this._clear);
    const clearAlpha = renderer.getClearAlpha();
    try {
      scene.background = null;
      scene.overrideMaterial = null;
      renderer.autoClear = false;
      renderer.shadowMap.autoUpdate = false;
      renderer.shadowMap.needsUpdate = false;
      renderer.setRenderTarget(this._idTarget);
      renderer.setClearColor(this._idClear, 0);
      renderer.clear(true, true, false);
      // Three clears only the first texture of an integer target (clearBufferuiv on buffer 0): the
      // mask's zero where nothing split is drawn.
      this.gl.clearBufferfv(this.gl.COLOR, 1, NO_SPLIT);
      renderer.render(scene, camera);
    } finally {
      for (let i = 0; i < swapped.length; i += 2) swapped[i].material = swapped[i + 1];
      for (const object of hidden) object.visible = true;
      scene.background = background;
      scene.overrideMaterial = override;
      renderer.autoClear = autoClear;
      renderer.shadowMap.autoUpdate = shadowAuto;
      renderer.shadowMap.needsUpdate = shadowNeeds;
      renderer.setClearColor(this._clear, clearAlpha);
      renderer.setRenderTarget(target);
      this._depth.value = null;
    }
  }

  /**
   * Filters `target` (a render target with half- or full-float RGBA colour and a DepthTexture, as
   * three rendered `scene` from `camera` into it) in place. `settings` as SSSPass's. Returns the
   * sss_result (0: filtered); on a refusal the target is left as three drew it and lastError holds
   * the library's message.
   */
  render(target, scene, camera, settings = DEFAULT_SETTINGS) {
    settings = Object.assign({}, DEFAULT_SETTINGS, settings);
    const renderer = this.renderer;
    if (!target || !target.depthTexture) {
      return this._refuse('sss-three: the render target needs a depthTexture (createSSSRenderTarget makes one)');
    }
    if (renderer.capabilities.logarithmicDepthBuffer) {
      return this._refuse('sss-three: a logarithmic depth buffer cannot be linearised from the projection');
    }
    const source = this._sources.get(scene);
    if (!source || !source.pass) this._sources.set(scene, { settings, armed: target });  // the next frame's split
    const drewSplit = this._takeSplit(target);
    const collected = this._collectProfiles(scene, settings, drewSplit !== null);
    this._splittable = collected.splittable;
    this._prepareSplit(target, collected.splittable, settings);
    if (collected.profiles.length === 0 && !drewSplit) {
      this.lastResult = -1;
      return -1;
    }
    const ready = collected.profiles.length > 0 && this._setProfiles(collected, settings);
    if (!ready && !drewSplit) return this.lastResult;
    // Where the scene drew split, colour holds the diffuse light alone: the unblurred light goes back
    // in whatever the library made of the frame (a refusal found only now leaves it unblurred).
    this._renderProfiles(scene, camera, target.width, target.height, ready ? collected.perMaterial : new Map(),
      settings.split, target.depthTexture, drewSplit);
    const r = ready ? this._apply(target, camera) : this.lastResult;
    const companion = drewSplit && this._splitTargets.companion(target);
    if (companion) {
      this._compose = this._compose || new SplitCompose();
      this._compose.render(renderer, target, companion, this._idTarget.textures[1]);
    }
    return r;
  }

  // sss_apply_frame on the target's colour and depth with the profile texture just drawn.
  _apply(target, camera) {
    const gl = this.gl, properties = this.renderer.properties, width = target.width, height = target.height;
    const colorFormat = colorFormatOf(gl, target.texture), depthFormat = depthFormatOf(target.depthTexture);
    const color = properties.get(target.texture).__webglTexture;
    const depth = properties.get(target.depthTexture).__webglTexture;
    const profile = properties.get(this._idTarget.texture).__webglTexture;
    // The split's albedo where a profile's texturing needs it (_collectProfiles gives those
    // profiles their texturing only when this frame drew split, into this target's companion).
    const companion = this._albedoFormat !== 0 ? this._splitTargets.companion(target) : null;
    const albedo = companion ? properties.get(companion.textures[1]).__webglTexture : null;
    const albedoFormat = albedo ? this._albedoFormat : 0;
    const m = this.module;
    new Float32Array(m.HEAPF32.buffer, this._projection, 16).set(camera.projectionMatrix.elements);
    const flags = camera.reversedDepth ? SSS_FRAME_DEPTH_ZERO_TO_ONE : 0;
    const prepared = [width, height, colorFormat, depthFormat, albedoFormat].join();
    if (prepared !== this._prepared) {
      // The first frame of this size and these formats that setSize did not prepare.
      const p = this.prepare(width, height, colorFormat, depthFormat, albedoFormat);
      if (p !== 0) {
        this.lastResult = p;
        return p;
      }
    }
    const r = this._call(() => {
      const GL = this._GL;
      this._lendBindings();
      return m._sss3_apply(this.context, this._lend(color, GL.textures), colorFormat, this._lend(depth, GL.textures),
        depthFormat, this._lend(profile, GL.textures), GL_R8UI, width, height, this._projection, ++this._frame, flags,
        this._lend(albedo, GL.textures), albedoFormat);
    });
    this.lastResult = r;
    this.lastError = r === 0 ? '' : this._message();
    return r;
  }

  /** The library re-prepares for this size now (called by SSSPass.setSize), not in the next frame;
   *  with an albedo texture (SRGB8_ALPHA8, the split's) where the profiles' texturing needs one. */
  prepare(width, height, colorFormat = GL_RGBA16F, depthFormat = GL_DEPTH_COMPONENT24, albedoFormat = this._albedoFormat) {
    const prepared = [width, height, colorFormat, depthFormat, albedoFormat].join();
    if (prepared === this._prepared || this._profileKey === null) return 0;
    const r = this._call(() => {
      this._lendBindings();
      return this.module._sss3_prepare(this.context, width, height, colorFormat, depthFormat, GL_R8UI, albedoFormat);
    });
    if (r === 0) this._prepared = prepared;
    else this.lastError = this._message();
    return r;
  }

  _refuse(message) {
    this.lastError = message;
    this.lastResult = 1;  // SSS_ERROR_INVALID_ARGUMENT, the library's code for a bad argument
    return 1;
  }

  /** sss_get_stats: frames, passes, lastFramePasses, lastFramePath, gpuMemoryBytes, glslVariant. */
  stats() {
    const m = this.module;
    this._call(() => m._sss3_stats(this.context, this._stats));
    const s = new Float64Array(m.HEAPF64.buffer, this._stats, 6);
    return { frames: s[0], passes: s[1], lastFramePasses: s[2], lastFramePath: s[3], gpuMemoryBytes: s[4],
      glslVariant: s[5] };
  }

  /** sss_result's name ("SSS_ERROR_INVALID_ARGUMENT"). */
  resultString(r) { return this.module.UTF8ToString(this.module._sss3_result_string(r)); }

  /** The library's defaults: strength and falloff per channel, and taps. */
  defaults() {
    const d = (i) => this.module._sss3_default(i);
    return { strength: [d(0), d(1), d(2)], falloff: [d(3), d(4), d(5)], taps: d(6) };
  }

  /** Deletes the library's GL objects (on three's context) and the profile target. */
  dispose() {
    if (this.context) {
      this._call(() => {
        this._lendBindings();
        this.module._sss3_destroy(this.context);
      });
      this.context = 0;
    }
    if (this._idTarget) this._idTarget.dispose();
    if (this._compose) this._compose.dispose();
    this._splitTargets.dispose();
    for (const material of this._idMaterials.values()) material.dispose();
    this._idMaterials.clear();
    this._free();
  }

  _free() {
    if (this._scratch) this.module._free(this._scratch);
    this._scratch = 0;
    if (this._handle) {
      delete this._GL.contexts[this._handle];
      if (this.gl.canvas) delete this.gl.canvas.GLctxObject;
      this._handle = 0;
    }
  }
}

/** What SSSPass and SSS.render take, with their defaults. */
export const DEFAULT_SETTINGS = Object.freeze({
  metresPerUnit: 1,    // the scene's unit in metres (three's convention: 1)
  scale: 1,            // multiplies every profile's scattering distance (1: physical)
  strength: 1,         // multiplies the library's calibrated per-channel strength (the skin kernel)
  falloff: 1,          // multiplies its per-channel falloff
  taps: 17,            // taps per pass, odd, 3-65
  followSurface: true, // fade taps that lie across a depth step
  path: 'auto',        // 'auto', 'fragment', 'masked', 'half' (PATHS)
  jitter: 0,           // [0, 1]: share of outer taps jittered per pixel
  split: 0,            // [0, 1]: the fraction of the width, from the left, left unfiltered
  splitLighting: true  // standard and physical materials: blur the diffuse light alone (split-lighting.js)
});

/**
 * The EffectComposer pass. Put it after a RenderPass that renders into a target with a
 * DepthTexture (createSSSRenderTarget): it filters that target in place (needsSwap false).
 * Every field of DEFAULT_SETTINGS is a property of the pass.
 */
export class SSSPass extends Pass {
  constructor(sss, scene, camera, settings = {}) {
    super();
    this.sss = sss;
    this.scene = scene;
    this.camera = camera;
    Object.assign(this, DEFAULT_SETTINGS, settings);
    this.needsSwap = false;
    this._formats = null;
    // The scene's split follows this pass, and its materials are patched now, so that their first
    // frame compiles their patched programs (the split itself starts once the pass has filtered a
    // target and allocated its attachments: from the second frame).
    this._follow();
    sss._collectProfiles(scene, this.settings());
  }

  _follow() {
    const source = this.sss._sources.get(this.scene);
    if (!source || source.pass !== this) this.sss._sources.set(this.scene, { pass: this });
  }

  get lastError() { return this.sss.lastError; }

  settings() {
    const s = {};
    for (const key of Object.keys(DEFAULT_SETTINGS)) s[key] = this[key];
    return s;
  }

  render(renderer, writeBuffer, readBuffer) {
    const target = readBuffer;
    this._follow();  // a new scene given to the pass
    const settings = this.settings();
    this.sss.render(target, this.scene, this.camera, settings);
    // The composer's other target is the next frame's (the passes that swap): its split prepared now.
    if (writeBuffer !== target) this.sss._prepareSplit(writeBuffer, this.sss._splittable, settings);
    if (target && target.depthTexture) {
      this._formats = [colorFormatOf(this.sss.gl, target.texture), depthFormatOf(target.depthTexture)];
    }
    // The last pass of a composer shows its result: the filtered target onto the screen.
    if (this.renderToScreen) {
      this._copy = this._copy || new CopyToScreen();
      this._copy.render(renderer, target);
    }
  }

  setSize(width, height) {
    if (this._formats) this.sss.prepare(width, height, this._formats[0], this._formats[1]);
  }

  dispose() { if (this._copy) this._copy.dispose(); }
}

// A composer whose last pass is SSSPass (no OutputPass after it) still shows the image: the target
// copied to the canvas as it is (linear: put three's OutputPass after the pass for tone mapping
// and sRGB).
class CopyToScreen {
  constructor() {
    this.material = new ShaderMaterial({
      uniforms: { image: { value: null } },
      vertexShader: 'varying vec2 vUv; void main() { vUv = uv; gl_Position = vec4(position.xy, 0.0, 1.0); }',
      fragmentShader: 'uniform sampler2D image; varying vec2 vUv; void main() { gl_FragColor = texture2D(image, vUv); }',
      depthTest: false, depthWrite: false
    });
    this.quad = new FullScreenQuad(this.material);
  }

  render(renderer, target) {
    this.material.uniforms.image.value = target.texture;
    renderer.setRenderTarget(null);
    this.quad.render(renderer);
  }

  dispose() {
    this.material.dispose();
    this.quad.dispose();
  }
}
