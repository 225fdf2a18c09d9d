// Split lighting for sss-three (docs/three.md "Split lighting"): three's MeshStandardMaterial and
// MeshPhysicalMaterial write one lit colour, so a screen-space blur of it blurs the specular
// highlights with the diffuse light. Patched here, a material writes, in the one render of the
// scene, to three attachments of the render target's framebuffer:
//
//   0  the target's colour: the diffuse light, what the library blurs (reflectedLight.directDiffuse
//      + indirectDiffuse as three sums them: irradiance × diffuse colour, the library's pre-scatter
//      texturing), scaled by what three scales it by afterwards (transmission, clearcoat, fog,
//      premultiplied alpha), with three's own alpha;
//   1  everything else of three's colour (specular, emissive, sheen, clearcoat, transmitted light,
//      dithering): three's final colour minus attachment 0, added back after the blur unblurred;
//   2  the diffuse albedo three multiplied the irradiance by (material.diffuseContribution:
//      diffuseColor.rgb × (1 − metalness), linear; stored sRGB-encoded, SRGB8_ALPHA8, as G-buffers
//      hold albedo), for the library's albedo texturing modes.
//
// Attachments 1 and 2 are the textures of a companion render target of the pass's (SplitTargets),
// attached to three's framebuffer for the patched draws only: WebGL refuses a draw whose program
// has no output for an active draw buffer, so every other material (three's, the host's, the
// background) must see the target as three made it, one draw buffer. Whether a draw splits is a
// uniform (sssSplitLighting; and left of sssSplitFromX, the pass's split view, the pixels are not
// split either): off, the material writes three's own colour to attachment 0 and zeros to the
// others, so one program serves both and toggling the pass compiles nothing.
import {
  AddEquation, CustomBlending, GLSL3, HalfFloatType, NearestFilter, OneFactor, RGBAFormat, SRGBColorSpace,
  ShaderLib, ShaderMaterial, UnsignedByteType, WebGLRenderTarget, ZeroFactor
} from 'three';
import { FullScreenQuad } from 'three/examples/jsm/postprocessing/Pass.js';

/** The part of customProgramCacheKey that keeps patched programs apart from three's own. */
export const SPLIT_PROGRAM_KEY = 'sss-three:split-lighting:1';

// The declarations go first in the material's fragment source (after three's prefix, which
// declares location 0 as pc_fragColor).
const DECLARATIONS = `layout(location = 1) out highp vec4 sssUnblurred;
layout(location = 2) out highp vec4 sssAlbedo;
uniform bool sssSplitLighting;
uniform float sssSplitFromX;
`;
// Before three mixes the transmitted light into totalDiffuse: the diffuse light alone, and its
// share left after the mix (the transmitted light is a view through the surface, not light to
// blur).
const TRANSMISSION = '#include <transmission_fragment>';
const BEFORE_TRANSMISSION = `vec3 sssDiffuse = totalDiffuse;
#include <transmission_fragment>
#ifdef USE_TRANSMISSION
	sssDiffuse *= 1.0 - material.transmission;
#endif`;
// After three's last chunk, gl_FragColor is the colour three writes. The diffuse is scaled by
// what three scaled outgoingLight by since (the clearcoat's Fresnel, fog, premultiplied alpha;
// tone mapping and the colour-space conversion are off for a linear render target, the only kind
// the pass splits), and the rest of three's colour is what is left: their sum is three's colour
// up to float32 rounding.
const LAST = '#include <dithering_fragment>';
const AFTER_LAST = `#include <dithering_fragment>
#ifdef USE_CLEARCOAT
	sssDiffuse *= 1.0 - material.clearcoat * Fcc;
#endif
#ifdef USE_FOG
	sssDiffuse *= 1.0 - fogFactor;
#endif
#ifdef PREMULTIPLIED_ALPHA
	sssDiffuse *= gl_FragColor.a;
#endif
	if ( sssSplitLighting && gl_FragCoord.x >= sssSplitFromX ) {
		sssUnblurred = vec4( gl_FragColor.rgb - sssDiffuse, 0.0 );
		sssAlbedo = vec4( material.diffuseContribution, 1.0 );
		gl_FragColor.rgb = sssDiffuse;
	} else {
		sssUnblurred = vec4( 0.0 );
		sssAlbedo = vec4( 0.0 );
	}`;

/** The fragment source of three's meshphysical shader (standard and physical) with the split. */
export function splitFragmentShader(source) {
  if (!source.includes(TRANSMISSION) || !source.includes(LAST)) {
    // The material's own onBeforeCompile took the chunks out: its outputs could not be declared.
    throw new Error('sss-three: the fragment shader lacks ' + TRANSMISSION + ' or ' + LAST + ' (split lighting)');
  }
  return DECLARATIONS + source.replace(TRANSMISSION, BEFORE_TRANSMISSION).replace(LAST, AFTER_LAST);
}

// A three whose meshphysical shader has not these chunks (another release than the one tested,
// 0.187) gets no split: its materials are filtered as three lit them, as before the split.
const THREE_HAS_CHUNKS = ShaderLib.physical.fragmentShader.includes(TRANSMISSION) &&
  ShaderLib.physical.fragmentShader.includes(LAST);

/** Whether the pass can split a material's lighting: three's standard and physical materials. */
export function canSplit(material) {
  return THREE_HAS_CHUNKS && !!(material && material.isMeshStandardMaterial && !material.isNodeMaterial);
}

/**
 * Patches `material` once (onBeforeCompile, customProgramCacheKey, onBeforeRender, each chained to
 * what the material had): `decide(renderer, scene, material, object)` says, before each of its
 * draws, whether that draw splits: null for no, else the window x from which its pixels split.
 * Marks it for recompiling.
 */
export function patchMaterial(material, decide) {
  const split = { value: false }, fromX = { value: 0 };
  const onBeforeCompile = material.onBeforeCompile, cacheKey = material.customProgramCacheKey;
  const onBeforeRender = material.onBeforeRender;
  material.onBeforeCompile = function (shader, renderer) {
    onBeforeCompile.call(this, shader, renderer);
    shader.uniforms.sssSplitLighting = split;
    shader.uniforms.sssSplitFromX = fromX;
    shader.fragmentShader = splitFragmentShader(shader.fragmentShader);
  };
  material.customProgramCacheKey = function () { return cacheKey.call(this) + '|' + SPLIT_PROGRAM_KEY; };
  material.onBeforeRender = function (renderer, scene, camera, geometry, object, group) {
    onBeforeRender.call(this, renderer, scene, camera, geometry, object, group);
    const x = decide(renderer, scene, this, object);
    split.value = x !== null;
    fromX.value = x ?? 0;
  };
  material.needsUpdate = true;
}

/**
 * The split's attachments of each render target the pass filters: a companion WebGLRenderTarget
 * (two textures: the unblurred light, RGBA16F, and the albedo, SRGB8_ALPHA8) whose textures are
 * attached to the target's framebuffer at COLOR_ATTACHMENT1 and 2 around each patched draw.
 */
export class SplitTargets {
  constructor(renderer) {
    this.renderer = renderer;
    this.gl = renderer.getContext();
    this._companions = new WeakMap();  // target -> companion
    this._all = new Set();             // the companions, for dispose
    this._wrapped = new WeakSet();     // objects whose onAfterRender puts the draw buffers back
    this._open = false;                // a patched draw has all three draw buffers
  }

  /** Allocates (or resizes) `target`'s companion, outside a scene render (three binds its framebuffer
   *  for it, and the current target is bound again after). */
  prepare(target) {
    let companion = this._companions.get(target);
    if (!companion) {
      companion = new WebGLRenderTarget(target.width, target.height, {
        type: HalfFloatType, format: RGBAFormat, count: 2, depthBuffer: false, minFilter: NearestFilter,
        magFilter: NearestFilter, generateMipmaps: false
      });
      const albedo = companion.textures[1];
      albedo.type = UnsignedByteType;
      albedo.colorSpace = SRGBColorSpace;
      this._companions.set(target, companion);
      this._all.add(companion);
    } else if (companion.width !== target.width || companion.height !== target.height) {
      companion.setSize(target.width, target.height);
    }
    const renderer = this.renderer;
    if (renderer.properties.get(companion).__webglFramebuffer === undefined) {
      const current = renderer.getRenderTarget();
      const face = renderer.getActiveCubeFace(), level = renderer.getActiveMipmapLevel();
      renderer.initRenderTarget(companion);
      renderer.setRenderTarget(current, face, level);
    }
    return companion;
  }

  /** `target`'s companion when it is allocated at the target's size, else null. */
  companion(target) {
    const companion = target && this._companions.get(target);
    const ready = companion && companion.width === target.width && companion.height === target.height &&
      this.renderer.properties.get(companion).__webglFramebuffer !== undefined;
    return ready ? companion : null;
  }

  /**
   * In a patched material's draw into `target` (its framebuffer bound by three): the companion's
   * textures attached and all three draw buffers on until `object`'s draw ends (its
   * onAfterRender, wrapped here once); with `clear` (the frame's first split draw) both cleared to
   * zero first, so that they hold 0 wherever no split draw lands. False when the target has no
   * companion yet.
   */
  open(target, object, clear) {
    const companion = this.companion(target);
    if (!companion) return false;
    const gl = this.gl, properties = this.renderer.properties;
    gl.framebufferTexture2D(gl.DRAW_FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D,
      properties.get(companion.textures[0]).__webglTexture, 0);
    gl.framebufferTexture2D(gl.DRAW_FRAMEBUFFER, gl.COLOR_ATTACHMENT2, gl.TEXTURE_2D,
      properties.get(companion.textures[1]).__webglTexture, 0);
    gl.drawBuffers(ALL_BUFFERS);
    if (clear) {
      // A colour mask left off by the last draw would mask the clear; through three's state, which
      // the draw then sets to the material's own.
      this.renderer.state.buffers.color.setMask(true);
      gl.clearBufferfv(gl.COLOR, 1, ZERO);
      gl.clearBufferfv(gl.COLOR, 2, ZERO);
    }
    this._open = true;
    if (!this._wrapped.has(object)) {
      const onAfterRender = object.onAfterRender, targets = this;
      object.onAfterRender = function (...args) {
        targets.close();
        onAfterRender.apply(this, args);
      };
      this._wrapped.add(object);
    }
    return true;
  }

  // After the draw: the framebuffer as three made it (one draw buffer, nothing at attachments 1
  // and 2), which is what three's cache holds.
  close() {
    if (!this._open) return;
    const gl = this.gl;
    gl.drawBuffers(ONE_BUFFER);
    gl.framebufferTexture2D(gl.DRAW_FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, null, 0);
    gl.framebufferTexture2D(gl.DRAW_FRAMEBUFFER, gl.COLOR_ATTACHMENT2, gl.TEXTURE_2D, null, 0);
    this._open = false;
  }

  dispose() {
    for (const companion of this._all) companion.dispose();
    this._all.clear();
    this._companions = new WeakMap();
  }
}
const ALL_BUFFERS = [0x8CE0, 0x8CE1, 0x8CE2];  // COLOR_ATTACHMENT0-2
const ONE_BUFFER = [0x8CE0];
const ZERO = new Float32Array(4);

// The compose: the unblurred light (the companion's first texture) added to the target's colour
// (which the library filtered in place) where the profile pass found a split material in front, by blending (one + one on the colour; the alpha,
// which the library reads as the strength, kept: zero + one). Elsewhere the fragment is
// discarded: pixels of other materials and the background keep three's colour bit for bit
// (the companion holds whatever a split draw last left there, which is not theirs).
const COMPOSE_VERTEX = 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }';
const COMPOSE_FRAGMENT = `uniform highp sampler2D sssUnblurred;
uniform highp sampler2D sssSplitMask;
layout(location = 0) out highp vec4 composed;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(sssSplitMask, pixel, 0).r < 0.5) discard;
  composed = vec4(texelFetch(sssUnblurred, pixel, 0).rgb, 0.0);
}`;

/** Adds `companion`'s unblurred light back into `target`'s colour, where `mask` (R8) is 1. */
export class SplitCompose {
  constructor() {
    this.material = new ShaderMaterial({
      glslVersion: GLSL3, vertexShader: COMPOSE_VERTEX, fragmentShader: COMPOSE_FRAGMENT,
      uniforms: { sssUnblurred: { value: null }, sssSplitMask: { value: null } },
      depthTest: false, depthWrite: false, blending: CustomBlending, blendEquation: AddEquation,
      blendSrc: OneFactor, blendDst: OneFactor, blendEquationAlpha: AddEquation, blendSrcAlpha: ZeroFactor,
      blendDstAlpha: OneFactor
    });
    this.quad = new FullScreenQuad(this.material);
  }

  render(renderer, target, companion, mask) {
    this.material.uniforms.sssUnblurred.value = companion.textures[0];
    this.material.uniforms.sssSplitMask.value = mask;
    const previous = renderer.getRenderTarget(), autoClear = renderer.autoClear;
    renderer.autoClear = false;  // added to the colour, which a clear would take
    renderer.setRenderTarget(target);
    try {
      this.quad.render(renderer);
    } finally {
      renderer.autoClear = autoClear;
      renderer.setRenderTarget(previous);
    }
    this.material.uniforms.sssUnblurred.value = null;
    this.material.uniforms.sssSplitMask.value = null;
  }

  dispose() {
    this.material.dispose();
    this.quad.dispose();
  }
}
