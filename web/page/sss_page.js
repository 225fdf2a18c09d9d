// The demo page's script: the controls, the frame time, the library's messages, and window.sssDemo,
// which the browser test (web/test/browser_test.py) drives. The WebAssembly side: web/src/web_page.cpp.
'use strict';

var WIDTH = 640, HEIGHT = 360;

function $(id) { return document.getElementById(id); }

// The renderer behind WebGL (ANGLE's SwiftShader in headless Chromium), as the page reports it.
function rendererString() {
  var gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return 'no WebGL2';
  var info = gl.getExtension('WEBGL_debug_renderer_info');
  var name = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  var exts = ['EXT_color_buffer_float', 'OES_texture_float_linear', 'EXT_disjoint_timer_query_webgl2'].map(
      function (e) { return e + (gl.getSupportedExtensions().indexOf(e) >= 0 ? ' yes' : ' no'); });
  return 'WebGL2: ' + name + ' (' + gl.getParameter(gl.VERSION) + '); ' + exts.join(', ');
}

var sssDemo = {
  ready: false,
  failed: null,
  lastResult: 0,
  // The page's knobs, read from the controls as typed: nothing is clamped or checked here.
  knobs: function () {
    return {
      enabled: $('enabled').checked, scale: parseFloat($('scale').value),
      strength: parseFloat($('strength').value), falloff: parseFloat($('falloff').value),
      taps: parseInt($('taps').value, 10), follow: $('follow').checked,
      split: $('split-on').checked ? parseFloat($('split').value) : 0.0,
      material: $('material').selectedIndex
    };
  },
  // sss_set_settings with the knobs; the library's message on the page when it refuses.
  apply: function (k) {
    var r = Module.ccall('web_set_knobs', 'number',
        ['number', 'number', 'number', 'number', 'number', 'number', 'number'],
        [k.enabled ? 1 : 0, k.scale, k.strength, k.falloff, isNaN(k.taps) ? -1 : k.taps, k.follow ? 1 : 0,
         k.material || 0]);
    $('error').textContent = r === 0 ? '' : Module.ccall('web_message', 'string', [], []);
    return r;
  },
  // One frame, waited for and timed (median of `frames`), onto the canvas.
  render: function (split, frames) {
    var ms = Module.ccall('web_time_frames', 'number', ['number', 'number'], [frames || 1, split || 0.0]);
    var r = Module.ccall('web_render', 'number', ['number'], [split || 0.0]);
    if (r !== 0) $('error').textContent = Module.ccall('web_message', 'string', [], []);
    sssDemo.lastResult = r;
    $('readout').textContent = 'frame ' + ms.toFixed(1) + ' ms (' + WIDTH + 'x' + HEIGHT +
        ', lighting + sss_apply_frame + composite, waited for with a one-pixel read)';
    return ms;
  },
  // The last frame, RGBA8 top row first, base64.
  pixels: function () {
    var n = WIDTH * HEIGHT * 4, ptr = Module._malloc(n);
    Module.ccall('web_read_pixels', null, ['number'], [ptr]);
    var bytes = Module.HEAPU8.subarray(ptr, ptr + n), text = '';
    for (var i = 0; i < n; i += 0x8000) text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    Module._free(ptr);
    return btoa(text);
  },
  update: function () {
    var k = sssDemo.knobs();
    $('strength-value').textContent = '× ' + k.strength.toFixed(2);
    $('falloff-value').textContent = '× ' + k.falloff.toFixed(2);
    sssDemo.apply(k);
    sssDemo.render(k.split, 1);
  }
};
window.sssDemo = sssDemo;

var Module = {
  canvas: $('canvas'),
  printErr: function (text) { console.warn(text); },
  onRuntimeInitialized: function () {
    $('renderer').textContent = rendererString();
    if (Module.ccall('web_init', 'number', ['number', 'number'], [WIDTH, HEIGHT]) !== 0) {
      sssDemo.failed = Module.ccall('web_message', 'string', [], []);
      $('error').textContent = sssDemo.failed;
      $('readout').textContent = 'not running';
      return;
    }
    // The strength and falloff sliders stop where a channel would leave the library's [0, 1].
    var maxStrength = 0, maxFalloff = 0;
    for (var c = 0; c < 3; ++c) {
      maxStrength = Math.max(maxStrength, Module.ccall('web_default', 'number', ['number'], [c]));
      maxFalloff = Math.max(maxFalloff, Module.ccall('web_default', 'number', ['number'], [c + 3]));
    }
    $('strength').max = (1 / maxStrength).toFixed(2);
    $('falloff').max = (1 / maxFalloff).toFixed(2);
    for (var m = 0; m < Module.ccall('web_material_count', 'number', [], []); ++m) {
      var option = document.createElement('option');
      option.textContent = Module.ccall('web_material_label', 'string', ['number'], [m]);
      $('material').appendChild(option);
    }
    $('scale-range').addEventListener('input', function () { $('scale').value = $('scale-range').value; sssDemo.update(); });
    ['enabled', 'scale', 'strength', 'falloff', 'taps', 'follow', 'split-on', 'split', 'material'].forEach(function (id) {
      $(id).addEventListener(id === 'scale' || id === 'taps' ? 'change' : 'input', sssDemo.update);
    });
    $('controls').disabled = false;
    sssDemo.update();
    sssDemo.ready = true;
  }
};
