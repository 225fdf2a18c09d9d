var Module = {
  canvas: document.getElementById('canvas'),
  onRuntimeInitialized: function () {
    var r = Module.ccall('web_init', 'number', ['number', 'number'], [640, 360]);
    var s = document.getElementById('status');
    if (r !== 0) { s.textContent = 'error: ' + Module.ccall('web_message', 'string', [], []); return; }
    var f = Module.ccall('web_render', 'number', ['number'], [0.0]);
    s.textContent = 'frame ' + f + ' ' + Module.ccall('web_gl_renderer', 'string', [], []);
  }
};
