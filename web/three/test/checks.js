// The web.three test's side in the page (web/three/test/three_test.py loads it into the example
// page, window.sssExample): frames, GL state snapshots, a probe of three's state cache, and the
// compile counter. It returns measurements; the Python driver judges them.
import * as THREE from 'three';
import { SPLIT_PROGRAM_KEY, createSSSRenderTarget } from 'sss-three';

const ex = window.sssExample;
const PROFILE_FLOATS = 17;  // the floats of one profile the pass hands sss3_set_profiles (sss-three.js)
const gl = ex.renderer.getContext();

// ---- A second scene of three's standard materials (no userData.sss): textures, lights, shadows,
// a transparent object, points and lines, so that a frame of it exercises much of three's state.
function standardScene() {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x223344);
  const camera = new THREE.PerspectiveCamera(45, gl.drawingBufferWidth / gl.drawingBufferHeight, 0.1, 50);
  camera.position.set(0, 1.5, 5);
  camera.lookAt(0, 0, 0);
  const data = new Uint8Array(8 * 8 * 4).map((_, i) => ((i >> 2) % 3 === 0 ? 255 : (i * 37) & 255));
  const texture = new THREE.DataTexture(data, 8, 8);
  texture.needsUpdate = true;
  const light = new THREE.SpotLight(0xffffff, 40);
  light.position.set(2, 4, 3);
  light.castShadow = true;
  scene.add(light, new THREE.AmbientLight(0x404040));
  const box = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshStandardMaterial({ map: texture, roughness: 0.4 }));
  box.position.x = -1.5;
  box.castShadow = true;
  const knot = new THREE.Mesh(new THREE.TorusKnotGeometry(0.5, 0.15, 96, 12), new THREE.MeshPhongMaterial({ color: 0x44aa88 }));
  knot.castShadow = true;
  const glass = new THREE.Mesh(new THREE.SphereGeometry(0.6, 32, 16),
    new THREE.MeshPhysicalMaterial({ color: 0xff8844, transparent: true, opacity: 0.5 }));
  glass.position.x = 1.5;
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(8, 8), new THREE.MeshLambertMaterial({ color: 0x888888 }));
  floor.rotation.x = -Math.PI / 2;
  floor.position.y = -1;
  floor.receiveShadow = true;
  const points = new THREE.Points(new THREE.BufferGeometry().setAttribute('position',
    new THREE.Float32BufferAttribute([-2, 1.5, 0, 0, 1.8, 0, 2, 1.5, 0], 3)), new THREE.PointsMaterial({ size: 8, sizeAttenuation: false }));
  const line = new THREE.Line(new THREE.BufferGeometry().setAttribute('position',
    new THREE.Float32BufferAttribute([-3, -0.5, 1, 3, -0.5, 1], 3)), new THREE.LineBasicMaterial({ color: 0xffff00 }));
  scene.add(box, knot, glass, floor, points, line);
  return { scene, camera };
}
const standard = standardScene();

// The example's background is near black, which dark skin at the silhouette can equal after tone
// mapping; the test's frames show a colour no lit surface has, so that "background" is exact.
const exampleBackground = ex.scene.background;
ex.scene.background = new THREE.Color(1, 0, 1);

// ---- GL state: everything getParameter can read that a draw depends on, with WebGL objects as
// stable labels (the same object, the same label).
const labels = new WeakMap();
let nextLabel = 1;
function label(object) {
  if (object === null || object === undefined) return null;
  if (typeof object !== 'object' || ArrayBuffer.isView(object) || Array.isArray(object)) {
    return ArrayBuffer.isView(object) ? Array.from(object) : object;
  }
  if (!labels.has(object)) labels.set(object, object.constructor.name + '#' + nextLabel++);
  return labels.get(object);
}

const PARAMETERS = ['ACTIVE_TEXTURE', 'ARRAY_BUFFER_BINDING', 'ELEMENT_ARRAY_BUFFER_BINDING', 'CURRENT_PROGRAM',
  'VERTEX_ARRAY_BINDING', 'DRAW_FRAMEBUFFER_BINDING', 'READ_FRAMEBUFFER_BINDING', 'RENDERBUFFER_BINDING',
  'PIXEL_PACK_BUFFER_BINDING', 'PIXEL_UNPACK_BUFFER_BINDING', 'UNIFORM_BUFFER_BINDING', 'COPY_READ_BUFFER_BINDING',
  'COPY_WRITE_BUFFER_BINDING', 'TRANSFORM_FEEDBACK_BINDING', 'TRANSFORM_FEEDBACK_BUFFER_BINDING',
  'BLEND', 'CULL_FACE', 'DEPTH_TEST', 'DITHER', 'POLYGON_OFFSET_FILL', 'RASTERIZER_DISCARD',
  'SAMPLE_ALPHA_TO_COVERAGE', 'SAMPLE_COVERAGE', 'SCISSOR_TEST', 'STENCIL_TEST',
  'BLEND_COLOR', 'BLEND_DST_ALPHA', 'BLEND_DST_RGB', 'BLEND_EQUATION_ALPHA', 'BLEND_EQUATION_RGB', 'BLEND_SRC_ALPHA',
  'BLEND_SRC_RGB', 'COLOR_CLEAR_VALUE', 'COLOR_WRITEMASK', 'CULL_FACE_MODE', 'DEPTH_CLEAR_VALUE', 'DEPTH_FUNC',
  'DEPTH_RANGE', 'DEPTH_WRITEMASK', 'FRONT_FACE', 'LINE_WIDTH', 'POLYGON_OFFSET_FACTOR', 'POLYGON_OFFSET_UNITS',
  'SAMPLE_COVERAGE_INVERT', 'SAMPLE_COVERAGE_VALUE', 'SCISSOR_BOX', 'VIEWPORT',
  'STENCIL_BACK_FAIL', 'STENCIL_BACK_FUNC', 'STENCIL_BACK_PASS_DEPTH_FAIL', 'STENCIL_BACK_PASS_DEPTH_PASS',
  'STENCIL_BACK_REF', 'STENCIL_BACK_VALUE_MASK', 'STENCIL_BACK_WRITEMASK', 'STENCIL_CLEAR_VALUE', 'STENCIL_FAIL',
  'STENCIL_FUNC', 'STENCIL_PASS_DEPTH_FAIL', 'STENCIL_PASS_DEPTH_PASS', 'STENCIL_REF', 'STENCIL_VALUE_MASK',
  'STENCIL_WRITEMASK', 'PACK_ALIGNMENT', 'UNPACK_ALIGNMENT', 'PACK_ROW_LENGTH', 'PACK_SKIP_PIXELS', 'PACK_SKIP_ROWS',
  'UNPACK_ROW_LENGTH', 'UNPACK_SKIP_PIXELS', 'UNPACK_SKIP_ROWS', 'UNPACK_IMAGE_HEIGHT', 'UNPACK_SKIP_IMAGES',
  'UNPACK_FLIP_Y_WEBGL', 'UNPACK_PREMULTIPLY_ALPHA_WEBGL', 'UNPACK_COLORSPACE_CONVERSION_WEBGL',
  'GENERATE_MIPMAP_HINT', 'FRAGMENT_SHADER_DERIVATIVE_HINT', 'READ_BUFFER'];
const TEXTURE_PARAMETERS = ['TEXTURE_MIN_FILTER', 'TEXTURE_MAG_FILTER', 'TEXTURE_WRAP_S', 'TEXTURE_WRAP_T',
  'TEXTURE_WRAP_R', 'TEXTURE_COMPARE_MODE', 'TEXTURE_COMPARE_FUNC', 'TEXTURE_BASE_LEVEL', 'TEXTURE_MAX_LEVEL',
  'TEXTURE_MIN_LOD', 'TEXTURE_MAX_LOD'];

// The textures whose parameters the snapshot reads: the composer's colour and depth, the pass's
// profile target (three's WebGLTexture objects).
function passTextures() {
  const props = ex.renderer.properties, out = {};
  const add = (name, texture) => { if (texture && props.get(texture).__webglTexture) out[name] = props.get(texture).__webglTexture; };
  add('colour1', ex.composer.renderTarget1.texture);
  add('depth1', ex.composer.renderTarget1.depthTexture);
  add('colour2', ex.composer.renderTarget2.texture);
  add('depth2', ex.composer.renderTarget2.depthTexture);
  if (ex.sss && ex.sss._idTarget) add('profile', ex.sss._idTarget.texture);
  return out;
}

export function snapshot() {
  const s = {};
  for (const name of PARAMETERS) s[name] = label(gl.getParameter(gl[name]));
  const units = gl.getParameter(gl.MAX_COMBINED_TEXTURE_IMAGE_UNITS);
  const active = gl.getParameter(gl.ACTIVE_TEXTURE);
  for (let unit = 0; unit < Math.min(units, 32); ++unit) {
    gl.activeTexture(gl.TEXTURE0 + unit);
    for (const b of ['TEXTURE_BINDING_2D', 'TEXTURE_BINDING_CUBE_MAP', 'TEXTURE_BINDING_3D', 'TEXTURE_BINDING_2D_ARRAY',
      'SAMPLER_BINDING']) s[b + '[' + unit + ']'] = label(gl.getParameter(gl[b]));
  }
  gl.activeTexture(active);
  for (let i = 0; i < gl.getParameter(gl.MAX_UNIFORM_BUFFER_BINDINGS); ++i) {
    s['UNIFORM_BUFFER_BINDING[' + i + ']'] = label(gl.getIndexedParameter(gl.UNIFORM_BUFFER_BINDING, i));
  }
  const drawFramebuffer = gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING);
  for (let i = 0; i < (drawFramebuffer ? 4 : 1); ++i) s['DRAW_BUFFER' + i] = gl.getParameter(gl.DRAW_BUFFER0 + i);
  const attribs = gl.getParameter(gl.MAX_VERTEX_ATTRIBS);
  for (let i = 0; i < attribs; ++i) {
    s['VERTEX_ATTRIB_ARRAY_ENABLED[' + i + ']'] = gl.getVertexAttrib(i, gl.VERTEX_ATTRIB_ARRAY_ENABLED);
    s['VERTEX_ATTRIB_ARRAY_BUFFER_BINDING[' + i + ']'] = label(gl.getVertexAttrib(i, gl.VERTEX_ATTRIB_ARRAY_BUFFER_BINDING));
  }
  // Texture parameters: bound on the active unit for the read, then the unit's binding put back.
  const bound = gl.getParameter(gl.TEXTURE_BINDING_2D);
  for (const [name, texture] of Object.entries(passTextures())) {
    gl.bindTexture(gl.TEXTURE_2D, texture);
    for (const p of TEXTURE_PARAMETERS) s[name + '.' + p] = gl.getTexParameter(gl.TEXTURE_2D, gl[p]);
  }
  gl.bindTexture(gl.TEXTURE_2D, bound);
  return s;
}

export function differences(a, b) {
  const out = [];
  for (const key of new Set([...Object.keys(a), ...Object.keys(b)])) {
    if (JSON.stringify(a[key]) !== JSON.stringify(b[key])) out.push(key + ': ' + JSON.stringify(a[key]) + ' -> ' + JSON.stringify(b[key]));
  }
  return out;
}

// ---- Three's cache against the GL: set each piece of state three caches to what the GL holds,
// through three's own WebGLState, and count the GL calls three makes. Three skips a call where its
// cache already holds the value, so 0 calls means its cache agrees with the GL on all of them. A
// value three has not cached yet (a capability it never touched, the read framebuffer) costs a
// call the first time: a probe first brings the cache up to the GL, a second one then measures.
const COUNTED = ['enable', 'disable', 'useProgram', 'bindFramebuffer', 'activeTexture', 'bindTexture', 'viewport',
  'scissor', 'colorMask', 'depthMask', 'depthFunc', 'stencilMask', 'stencilFunc', 'stencilOp', 'cullFace',
  'frontFace', 'blendEquationSeparate', 'blendFuncSeparate', 'blendEquation', 'blendFunc', 'lineWidth',
  'polygonOffset', 'clearColor', 'clearDepth', 'clearStencil', 'bindBufferBase', 'bindSampler'];
export function cacheProbe() {
  const state = ex.renderer.state, calls = [];
  const saved = {};
  for (const name of COUNTED) {
    saved[name] = Object.prototype.hasOwnProperty.call(gl, name) ? gl[name] : undefined;
    const original = gl[name];
    gl[name] = function (...args) { calls.push(name); return original.apply(gl, args); };
  }
  try {
    for (const cap of ['BLEND', 'CULL_FACE', 'DEPTH_TEST', 'POLYGON_OFFSET_FILL', 'SAMPLE_ALPHA_TO_COVERAGE',
      'SCISSOR_TEST', 'STENCIL_TEST']) {
      if (gl.isEnabled(gl[cap])) state.enable(gl[cap]); else state.disable(gl[cap]);
    }
    state.useProgram(gl.getParameter(gl.CURRENT_PROGRAM));
    state.bindFramebuffer(gl.DRAW_FRAMEBUFFER, gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING));
    state.bindFramebuffer(gl.READ_FRAMEBUFFER, gl.getParameter(gl.READ_FRAMEBUFFER_BINDING));
    const active = gl.getParameter(gl.ACTIVE_TEXTURE);
    state.activeTexture(active);
    state.bindTexture(gl.TEXTURE_2D, gl.getParameter(gl.TEXTURE_BINDING_2D));
    const v = gl.getParameter(gl.VIEWPORT), sc = gl.getParameter(gl.SCISSOR_BOX);
    state.viewport(new THREE.Vector4(v[0], v[1], v[2], v[3]));
    state.scissor(new THREE.Vector4(sc[0], sc[1], sc[2], sc[3]));
    const b = state.buffers;
    b.color.setMask(gl.getParameter(gl.COLOR_WRITEMASK)[0]);
    b.depth.setMask(gl.getParameter(gl.DEPTH_WRITEMASK));
    const depthFuncs = { [gl.NEVER]: THREE.NeverDepth, [gl.ALWAYS]: THREE.AlwaysDepth, [gl.LESS]: THREE.LessDepth,
      [gl.LEQUAL]: THREE.LessEqualDepth, [gl.EQUAL]: THREE.EqualDepth, [gl.GEQUAL]: THREE.GreaterEqualDepth,
      [gl.GREATER]: THREE.GreaterDepth, [gl.NOTEQUAL]: THREE.NotEqualDepth };
    b.depth.setFunc(depthFuncs[gl.getParameter(gl.DEPTH_FUNC)]);
    b.stencil.setMask(gl.getParameter(gl.STENCIL_WRITEMASK));
    b.stencil.setFunc(gl.getParameter(gl.STENCIL_FUNC), gl.getParameter(gl.STENCIL_REF), gl.getParameter(gl.STENCIL_VALUE_MASK));
    b.stencil.setOp(gl.getParameter(gl.STENCIL_FAIL), gl.getParameter(gl.STENCIL_PASS_DEPTH_FAIL), gl.getParameter(gl.STENCIL_PASS_DEPTH_PASS));
    state.setFlipSided(gl.getParameter(gl.FRONT_FACE) === gl.CW);
    state.setLineWidth(gl.getParameter(gl.LINE_WIDTH));
  } finally {
    for (const name of COUNTED) {
      if (saved[name] === undefined) delete gl[name]; else gl[name] = saved[name];
    }
  }
  return calls;
}

// ---- Frames.
function frame() {
  ex.frame();
  return ex.pixels();
}

function glErrors() {
  const errors = [];
  for (let e = gl.getError(); e !== gl.NO_ERROR && errors.length < 16; e = gl.getError()) errors.push(e);
  return errors;
}

function standardFrame() {
  ex.renderer.setRenderTarget(null);
  ex.renderer.render(standard.scene, standard.camera);
  return ex.pixels();
}

// Before the library exists (?hold): three's own frames of both scenes.
export function before() {
  return { composer: frame(), standard: standardFrame(), errors: glErrors() };
}

// Screen positions (pixels, top-left origin) of the head's centre and the two spheres.
export function positions() {
  const out = {};
  const at = (name, v) => {
    const p = v.clone().project(ex.camera);
    out[name] = [Math.round((p.x + 1) / 2 * gl.drawingBufferWidth), Math.round((1 - p.y) / 2 * gl.drawingBufferHeight)];
  };
  at('head', new THREE.Vector3(0, 0.03, 0.08));
  at('marble', ex.marble.position);
  at('milk', ex.milk.position);
  at('glossy', ex.glossy.position);
  return out;
}

// Frames with the library: on, off (the pass disabled), the standard scene after it; the state
// and three's cache around every library call of one frame, and with three's standard frame.
export function withLibrary() {
  const out = {};
  ex.pass.enabled = true;
  ex.pass.split = 0;
  out.on = frame();
  out.onResult = ex.sss.lastResult;
  out.onError = ex.sss.lastError;
  out.errorsOn = glErrors();
  // Around the library's own call (the wasm export that runs sss_apply_frame): the GL state and three's
  // cache, with names lent as the package lends them.
  const m = ex.sss.module, apply = m._sss3_apply, around = [];
  m._sss3_apply = function (...args) {
    // The first probe fills what three's cache does not know yet (it issues those calls) so that
    // the cache then holds the GL's every value; after the library's call it must issue none.
    const syncCalls = cacheProbe();
    const s0 = snapshot();
    const r = apply.apply(this, args);
    const s1 = snapshot();
    around.push({ result: r, differences: differences(s0, s1), syncCalls, cacheCalls: cacheProbe(), errors: glErrors() });
    return r;
  };
  try {
    frame();
  } finally {
    m._sss3_apply = apply;
  }
  out.around = around;
  // The probe can see a stale cache: the GL changed behind three's back must cost three calls.
  cacheProbe();
  const depthTest = gl.isEnabled(gl.DEPTH_TEST);
  if (depthTest) gl.disable(gl.DEPTH_TEST); else gl.enable(gl.DEPTH_TEST);
  out.staleProbeCalls = cacheProbe();
  out.afterStaleState = snapshot();
  if (depthTest) gl.enable(gl.DEPTH_TEST); else gl.disable(gl.DEPTH_TEST);
  ex.renderer.state.reset();  // three forgets what it thought; the next frame sets everything again
  frame();
  out.stats = ex.sss.stats();
  ex.pass.enabled = false;
  out.off = frame();
  out.standard = standardFrame();
  out.errorsAfter = glErrors();
  ex.pass.enabled = true;
  return out;
}

// What the library restores wrongly where three's bound objects have no names in Emscripten's tables
// (the package's lending turned off for the bindings): the state differences around its call.
export function withoutLending() {
  const sss = ex.sss, lendBindings = sss._lendBindings, m = sss.module, apply = m._sss3_apply;
  let diffs = null;
  sss._lendBindings = () => {};
  m._sss3_apply = function (...args) {
    const s0 = snapshot();
    const r = apply.apply(this, args);
    diffs = differences(s0, snapshot());
    return r;
  };
  try {
    frame();
  } finally {
    sss._lendBindings = lendBindings;
    m._sss3_apply = apply;
  }
  ex.renderer.resetState();  // three rebinds everything: the next frames are as before
  glErrors();
  return diffs;
}

// The example's frame with the pass and splitLighting off (the whole lit colour blurred), then on
// again.
export function unsplitFrame() {
  ex.pass.splitLighting = false;
  const image = frame();
  ex.pass.splitLighting = true;
  frame();
  return image;
}

// A setting the library refuses: its message, the frame (three's, untouched), then valid again.
export function badSetting(name, value) {
  const pass = ex.pass, valid = pass[name];
  pass[name] = value;
  const image = frame();
  const out = { result: ex.sss.lastResult, message: ex.sss.lastError, shown: document.getElementById('error').textContent,
    image, errors: glErrors() };
  pass[name] = valid;
  out.validAgain = frame();
  out.validResult = ex.sss.lastResult;
  out.validMessage = ex.sss.lastError;
  return out;
}

// A new canvas size: the composer's and the pass's setSize (the library prepares there), then the
// first frame at that size with gl.compileShader counted; then back.
export function resize(width, height) {
  const r = ex.renderer, w0 = gl.drawingBufferWidth, h0 = gl.drawingBufferHeight;
  const compile = gl.compileShader;
  let compiles = 0;
  const setSize = (w, h) => {
    r.setSize(w, h);
    ex.composer.setSize(w, h);
    ex.camera.aspect = w / h;
    ex.camera.updateProjectionMatrix();
  };
  setSize(width, height);
  const framesBefore = ex.sss.stats().frames;
  gl.compileShader = function (...args) { ++compiles; return compile.apply(gl, args); };
  try {
    ex.frame();
  } finally {
    delete gl.compileShader;
  }
  const out = { compiles, result: ex.sss.lastResult, message: ex.sss.lastError,
    frames: ex.sss.stats().frames - framesBefore, size: [gl.drawingBufferWidth, gl.drawingBufferHeight], errors: glErrors() };
  setSize(w0, h0);
  ex.frame();
  out.backResult = ex.sss.lastResult;
  return out;
}

// Split view for the screenshot: the left half unfiltered.
export function split(value) {
  ex.scene.background = exampleBackground;
  ex.pass.split = value;
  ex.gui.controllersRecursive().forEach((c) => c.updateDisplay());  // the panel shows the split too
  return frame();
}

// What the library's calls that draw nothing leave changed (sss_create, sss_prepare, sss_destroy on
// a second context of the library on three's context): the state differences around each, before
// the package tells three to forget its cache (docs/three.md).
export function setupCalls() {
  const m = ex.sss.module, out = {};
  const wrap = (name) => {
    const original = m[name];
    m[name] = function (...args) {
      const s0 = snapshot();
      const r = original.apply(this, args);
      out[name.replace('_sss3_', 'sss_')] = differences(s0, snapshot());
      return r;
    };
    return () => { m[name] = original; };
  };
  const undo = ['_sss3_create', '_sss3_prepare', '_sss3_destroy'].map(wrap);
  try {
    const second = new ex.sss.constructor(m, ex.renderer);
    second._profileKey = 'defaults';  // sss_prepare with the library's default settings
    second.prepare(320, 180, 0x881A, 0x81A6);
    second.dispose();
  } finally {
    undo.forEach((u) => u());
  }
  out.errors = glErrors();
  return out;
}

// ---- Against the native frame (docs/three.md): exactly what the pass gives the library in one frame
// of a single profile (the head's skin; the spheres made not translucent for it) and what the library
// made of it, for web/three/test/native_apply.cpp to filter again natively. Three's scene cannot be
// rebuilt natively, so the same inputs stand in for the same scene.
function base64(bytes) {
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

// A texture's level 0 through a framebuffer of our own on the read binding only, which is put back:
// the draw state the library's call sees is not touched. Rows bottom first, as GL reads them.
function readTexture(texture, width, height, integer) {
  const previous = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.READ_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  let data;
  if (integer) {  // R8UI: RGBA_INTEGER/UNSIGNED_INT is the read every implementation has
    const wide = new Uint32Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA_INTEGER, gl.UNSIGNED_INT, wide);
    data = new Uint8Array(width * height).map((_, i) => wide[i * 4]);
  } else {  // RGBA16F as FLOAT (EXT_color_buffer_float): every half float exactly
    data = new Float32Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, data);
  }
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, previous);
  gl.deleteFramebuffer(fbo);
  return data;
}

// An 8-bit texture (the albedo, SRGB8_ALPHA8) as its bytes: the stored sRGB encoding (readPixels
// does not convert). Through a framebuffer of our own on the read binding, put back.
function readBytes(texture, width, height) {
  const previous = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING), fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.READ_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  const data = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, data);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, previous);
  gl.deleteFramebuffer(fbo);
  return data;
}

// A DepthTexture cannot be read: drawn by three into an RGBA32F target (red: the window depth as a
// shader samples it, which is what the library samples) and that read.
function readDepth(depthTexture, width, height) {
  const target = new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType, format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, depthBuffer: false, generateMipmaps: false });
  const material = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3, depthTest: false, depthWrite: false, uniforms: { depthTexture: { value: depthTexture } },
    vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
    fragmentShader: 'uniform highp sampler2D depthTexture; layout(location = 0) out highp vec4 depthOut;\n' +
      'void main() { depthOut = vec4(texelFetch(depthTexture, ivec2(gl_FragCoord.xy), 0).r, 0.0, 0.0, 1.0); }'
  });
  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), material);
  quad.frustumCulled = false;
  const scene = new THREE.Scene(), camera = new THREE.OrthographicCamera();
  scene.add(quad);
  const previous = ex.renderer.getRenderTarget();
  const rgba = new Float32Array(width * height * 4);
  try {
    ex.renderer.setRenderTarget(target);
    ex.renderer.render(scene, camera);
    ex.renderer.readRenderTargetPixels(target, 0, 0, width, height, rgba);
  } finally {
    ex.renderer.setRenderTarget(previous);
    target.dispose();
    material.dispose();
    quad.geometry.dispose();
  }
  return new Float32Array(width * height).map((_, i) => rgba[i * 4]);
}

// One frame (split off) with what the pass gives sss3_set_profiles and sss3_apply and the textures
// before and after: of the head's skin alone (single, the spheres made not translucent), or of the
// example's own three profiles (three_test.py, "against the native frame").
export function nativeInputs(single = true) {
  const sss = ex.sss, m = sss.module, pass = ex.pass;
  const spheres = single ? [ex.marble.material, ex.milk.material].map((material) => [material, material.userData.sss]) : [];
  for (const [material] of spheres) delete material.userData.sss;
  // The example's own three profiles: the pass calls sss_set_profiles only when they changed, so
  // forget the last ones (the same key again: the same call as the example's first frame).
  if (!single) sss._profileKey = null;
  const setProfiles = m._sss3_set_profiles, apply = m._sss3_apply, render = sss.render;
  const out = { settings: pass.settings() };
  let target = null, colour = null, profile = null, web = null, albedo = null;
  sss.render = function (t, ...rest) { target = t; return render.call(this, t, ...rest); };
  m._sss3_set_profiles = function (context, fields, count, taps, followSurface, path, jitter) {
    out.profiles = { fields: Array.from(new Float32Array(m.HEAPF32.buffer, fields, PROFILE_FLOATS * count)), count, taps,
      followSurface, path, jitter };
    return setProfiles.apply(this, arguments);
  };
  m._sss3_apply = function (context, color, colorFormat, depth, depthFormat, profileName, profileFormat, width, height,
    projection, noiseIndex, flags, albedoName, albedoFormat) {
    out.frame = { colorFormat, depthFormat, profileFormat, width, height, noiseIndex, flags, albedoFormat,
      projection: Array.from(new Float32Array(m.HEAPF32.buffer, projection, 16)) };
    const textures = sss._GL.textures;  // the names the package lent for this call
    colour = readTexture(textures[color], width, height, false);
    profile = readTexture(textures[profileName], width, height, true);
    // The split's albedo (SRGB8_ALPHA8) as its stored bytes, where a profile's texturing reads it.
    if (albedoName) albedo = readBytes(textures[albedoName], width, height);
    const r = apply.apply(this, arguments);
    web = readTexture(textures[color], width, height, false);
    return r;
  };
  const enabled = pass.enabled, split = pass.split;
  try {
    pass.enabled = true;
    pass.split = 0;
    ex.frame();
  } finally {
    sss.render = render;
    m._sss3_set_profiles = setProfiles;
    m._sss3_apply = apply;
    pass.enabled = enabled;
    pass.split = split;
  }
  out.result = sss.lastResult;
  out.message = sss.lastError;
  if (out.frame) {
    // Three's depth after the frame is the depth of the frame: the passes after SSSPass draw to the screen.
    const depth = readDepth(target.depthTexture, out.frame.width, out.frame.height);
    out.colour = base64(new Uint8Array(colour.buffer));
    out.depth = base64(new Uint8Array(depth.buffer));
    out.profile = base64(profile);
    out.web = base64(new Uint8Array(web.buffer));
    if (albedo) out.albedo = base64(albedo);
  }
  for (const [material, spec] of spheres) material.userData.sss = spec;
  out.errors = glErrors();
  if (single) ex.frame();  // the three profiles again
  return out;
}

// ---- Split lighting (docs/three.md "Split lighting"): a glossy skin sphere (MeshPhysicalMaterial,
// low roughness, userData.sss skin) beside the same material without userData.sss, under a point
// light, filtered without a composer (SSS.render). Read back as floats: three's own frame before
// the pass saw the materials; per frame with the pass, the colour the library is handed and what
// it made of it (around sss3_apply), the unblurred light and the albedo the split wrote, the
// profile texture and the composed colour; three's specular alone (the skin material with a black
// diffuse colour: with metalness 0 three's specular does not depend on it); the shader compiles.
const SPLIT_W = 320, SPLIT_H = 180;
export const SKIN_COLOUR = [0.8, 0.5, 0.38];  // linear
// The split scenes' stage: a black background, a camera 0.6 m away, a point light up and right of
// it and a little ambient light.
function splitStage() {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0, 0, 0);
  const camera = new THREE.PerspectiveCamera(30, SPLIT_W / SPLIT_H, 0.05, 10);
  camera.position.set(0, 0, 0.6);
  const light = new THREE.PointLight(0xffffff, 0.6, 0, 2);
  light.position.set(0.25, 0.3, 0.4);
  scene.add(light, new THREE.AmbientLight(0xffffff, 0.15));
  return { scene, camera };
}

function splitScene() {
  const { scene, camera } = splitStage();
  const glossy = (colour) => new THREE.MeshPhysicalMaterial({ color: new THREE.Color(...colour), roughness: 0.25,
    metalness: 0, specularIntensity: 1 });
  const geometry = new THREE.SphereGeometry(0.06, 96, 48);
  const skin = new THREE.Mesh(geometry, glossy(SKIN_COLOUR));
  skin.material.userData.sss = { profile: 'skin', object: 0 };
  skin.position.x = -0.07;
  const plain = new THREE.Mesh(geometry, glossy(SKIN_COLOUR));  // no userData.sss
  plain.position.x = 0.07;
  scene.add(skin, plain);
  const black = glossy([0, 0, 0]);
  return { scene, camera, skin, plain, black };
}

function textureOf(texture) { return ex.renderer.properties.get(texture).__webglTexture; }

function drawInto(target, scene, camera) {
  ex.renderer.setRenderTarget(target);
  ex.renderer.render(scene, camera);
  ex.renderer.setRenderTarget(null);
}

const floats = (texture) => base64(new Uint8Array(readTexture(textureOf(texture), SPLIT_W, SPLIT_H, false).buffer));

const bytes = (texture) => base64(readBytes(textureOf(texture), SPLIT_W, SPLIT_H));

// gl.compileShader and gl.linkProgram counted around `body`.
function counting(body) {
  const compile = gl.compileShader, link = gl.linkProgram, counts = { compiles: 0, links: 0 };
  gl.compileShader = function (...args) { ++counts.compiles; return compile.apply(gl, args); };
  gl.linkProgram = function (...args) { ++counts.links; return link.apply(gl, args); };
  try {
    body();
  } finally {
    delete gl.compileShader;
    delete gl.linkProgram;
  }
  return counts;
}

// One frame with the pass and `settings` on `scene` into `target` (SPLIT_W x SPLIT_H): a call of
// SSS.render first (it arms the next scene render's split with these settings), then the frame
// measured: what the library is handed and what it made of it, the composed colour, the split's
// unblurred light and albedo, the profile texture.
function passFrame(target, scene, camera, settings) {
  const sss = ex.sss, m = sss.module, frame = {};
  drawInto(target, scene, camera);
  sss.render(target, scene, camera, settings);
  drawInto(target, scene, camera);
  const apply = m._sss3_apply;
  m._sss3_apply = function (context, color) {
    frame.albedoFormat = arguments[13];  // sss3_apply's last: 0 without an albedo, SRGB8_ALPHA8 with the split's
    frame.handed = base64(new Uint8Array(readTexture(sss._GL.textures[color], SPLIT_W, SPLIT_H, false).buffer));
    const r = apply.apply(this, arguments);
    frame.blurred = base64(new Uint8Array(readTexture(sss._GL.textures[color], SPLIT_W, SPLIT_H, false).buffer));
    return r;
  };
  try {
    frame.result = sss.render(target, scene, camera, settings);
  } finally {
    m._sss3_apply = apply;
  }
  frame.message = sss.lastError;
  frame.composed = floats(target.texture);
  const companion = sss._splitTargets.companion(target);
  frame.unblurred = companion ? floats(companion.textures[0]) : null;
  frame.albedo = companion ? bytes(companion.textures[1]) : null;
  frame.profile = base64(readTexture(textureOf(sss._idTarget.texture), SPLIT_W, SPLIT_H, true));
  return frame;
}

export function splitLighting() {
  const s = splitScene(), target = createSSSRenderTarget(SPLIT_W, SPLIT_H);
  const skinMaterial = s.skin.material, out = { width: SPLIT_W, height: SPLIT_H, skinColour: SKIN_COLOUR };
  // Three's own frames, before the pass has seen (and patched) the materials.
  drawInto(target, s.scene, s.camera);
  out.three = floats(target.texture);
  s.skin.material = s.black;
  drawInto(target, s.scene, s.camera);
  out.specular = floats(target.texture);
  s.skin.material = skinMaterial;
  const passFrameOf = (settings) => passFrame(target, s.scene, s.camera, settings);
  // The first frames: the materials patched (their programs compiled with the split), the profile
  // pass's materials and the compose.
  // The sphere higher up in them, so that the frames after would find its old pixels in the split's
  // attachments if they were not cleared each frame.
  s.skin.position.y = 0.08;
  out.firstFrames = counting(() => { out.first = passFrameOf({}); });
  s.skin.position.y = 0;
  out.steadyFrames = counting(() => {
    out.on = passFrameOf({});
    out.noSplit = passFrameOf({ splitLighting: false });  // the check's own test: the specular blurred
    // After a call with splitLighting false no scene render is armed: the frame without the pass.
    drawInto(target, s.scene, s.camera);
    out.off = floats(target.texture);
    out.zero = passFrameOf({ strength: 0 });
    out.onAgain = passFrameOf({});
  });
  // The target's framebuffer after the split frames, bound by three: as three made it and caches it
  // (one draw buffer, nothing at attachments 1 and 2).
  ex.renderer.setRenderTarget(target);
  out.framebuffer = { drawBuffers: [0, 1, 2].map((i) => gl.getParameter(gl.DRAW_BUFFER0 + i)),
    attachments: [1, 2].map((i) => gl.getFramebufferAttachmentParameter(gl.DRAW_FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i,
      gl.FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE)) };
  ex.renderer.setRenderTarget(null);
  const program = (material) => ex.renderer.properties.get(material).currentProgram;
  out.programs = { skin: program(skinMaterial).cacheKey, plain: program(s.plain.material).cacheKey,
    shared: program(skinMaterial) === program(s.plain.material), splitKey: SPLIT_PROGRAM_KEY };
  out.errors = glErrors();
  target.dispose();
  return out;
}

// The split with what three adds to outgoingLight after the diffuse sum, each on a skin sphere of
// its own: clearcoat, sheen, transmission (opaque), emissive with a colour map, and fog over all.
// Three's frame before the pass saw them, and one frame with the pass (three_test.py: composed -
// blurred = three's colour - the diffuse handed, within half-float rounding).
export function splitFeatures() {
  const { scene, camera } = splitStage();
  scene.fog = new THREE.Fog(0x203040, 0.4, 1.2);
  const map = new THREE.DataTexture(new Uint8Array(16 * 16 * 4).map((_, i) => (i % 4 === 3 ? 255 : 128 + ((i * 53) & 127))),
    16, 16);
  map.colorSpace = THREE.SRGBColorSpace;
  map.needsUpdate = true;
  const colour = new THREE.Color(...SKIN_COLOUR), geometry = new THREE.SphereGeometry(0.04, 64, 32);
  const features = [
    { clearcoat: 1, clearcoatRoughness: 0.1 },
    { sheen: 1, sheenColor: new THREE.Color(0.9, 0.6, 0.5), sheenRoughness: 0.4 },
    { transmission: 0.5, thickness: 0.02 },
    { emissive: new THREE.Color(0.2, 0.05, 0.02), map }
  ];
  features.forEach((extra, i) => {
    const material = new THREE.MeshPhysicalMaterial(Object.assign({ color: colour, roughness: 0.3 }, extra));
    material.userData.sss = { profile: 'skin', object: i };
    const mesh = new THREE.Mesh(geometry, material);
    mesh.position.set(-0.15 + 0.1 * i, 0, 0);
    scene.add(mesh);
  });
  const target = createSSSRenderTarget(SPLIT_W, SPLIT_H), out = { width: SPLIT_W, height: SPLIT_H };
  drawInto(target, scene, camera);
  out.three = floats(target.texture);
  passFrame(target, scene, camera, {});  // the materials patched and compiled
  out.on = passFrame(target, scene, camera, {});
  out.errors = glErrors();
  target.dispose();
  map.dispose();
  return out;
}

// ---- Texturing (docs/three.md "Texturing"): a plane of skin filling the view, its albedo a noise
// map of texels about 3 pixels wide (nearest, no mipmaps), under an ambient light alone: the same
// irradiance at every pixel, so that the blur of the light alone is the light itself and a
// post-scatter frame is three's own (three_test.py: within the sRGB-8 and half-float roundings),
// where pre-scatter blurs the noise. Three's frame before the pass saw the material; frames with
// each texturing, explicitly 'pre' and none; 'post' with splitLighting off and on a Lambert
// material (neither splits: pre-scatter, as 'pre' frames of the same, bit for bit).
export function texturing() {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0, 0, 0);
  const camera = new THREE.PerspectiveCamera(30, SPLIT_W / SPLIT_H, 0.05, 10);
  camera.position.set(0, 0, 0.3);  // 0.9 mm a pixel at the plane
  scene.add(new THREE.AmbientLight(0xffffff, 1));
  const N = 160, encode = (x) => Math.round(255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055));
  const data = new Uint8Array(N * N * 4);
  for (let t = 0; t < N * N; ++t) {
    const f = 0.35 + 0.65 * (((t * 2654435761) >>> 0) % 1000) / 999;  // a texel's albedo: 0.35-1 of the skin's
    for (let c = 0; c < 3; ++c) data[t * 4 + c] = encode(SKIN_COLOUR[c] * f);
    data[t * 4 + 3] = 255;
  }
  const map = new THREE.DataTexture(data, N, N);
  Object.assign(map, { colorSpace: THREE.SRGBColorSpace, magFilter: THREE.NearestFilter, minFilter: THREE.NearestFilter,
    generateMipmaps: false, needsUpdate: true });
  const standardSkin = new THREE.MeshStandardMaterial({ map, roughness: 0.8, metalness: 0 });
  const lambertSkin = new THREE.MeshLambertMaterial({ map });
  const plane = new THREE.Mesh(new THREE.PlaneGeometry(0.4, 0.4), standardSkin);  // 2.5 mm a texel
  scene.add(plane);
  const target = createSSSRenderTarget(SPLIT_W, SPLIT_H), out = { width: SPLIT_W, height: SPLIT_H };
  drawInto(target, scene, camera);
  out.three = floats(target.texture);
  const frameWith = (material, texturing, settings = {}) => {
    plane.material = material;
    material.userData.sss = texturing === undefined ? { profile: 'skin', object: 0 } : { profile: 'skin', object: 0, texturing };
    return passFrame(target, scene, camera, settings);
  };
  frameWith(standardSkin, 'post');  // the material patched and compiled
  out.post = frameWith(standardSkin, 'post');
  out.pre = frameWith(standardSkin, undefined);
  out.preNamed = frameWith(standardSkin, 'pre');
  out.prePost = frameWith(standardSkin, 'pre-and-post');
  out.postAgain = frameWith(standardSkin, 'post');
  out.preUnsplit = frameWith(standardSkin, 'pre', { splitLighting: false });
  out.postUnsplit = frameWith(standardSkin, 'post', { splitLighting: false });
  out.lambertPre = frameWith(lambertSkin, 'pre');
  out.lambertPost = frameWith(lambertSkin, 'post');
  out.unknown = frameWith(standardSkin, 'after');
  out.errors = glErrors();
  for (const k of ['pre', 'preNamed', 'prePost', 'postAgain', 'preUnsplit', 'postUnsplit', 'lambertPre', 'lambertPost',
    'unknown']) {
    delete out[k].handed;  // what three_test.py reads of them: composed, profile, albedo, the result
    delete out[k].blurred;
    delete out[k].unblurred;
  }
  target.dispose();
  map.dispose();
  standardSkin.dispose();
  lambertSkin.dispose();
  return out;
}
