// Appended inside the module factory (--post-js): Emscripten's GL layer, which the package needs to
// register three's WebGL2 context (GL.registerContext, GL.makeContextCurrent) and to lend three's
// WebGL objects integer names in its tables (GL.textures, GL.framebuffers, ...). Referencing it here
// also keeps it when the optimiser drops what nothing uses.
Module['GL'] = GL;
