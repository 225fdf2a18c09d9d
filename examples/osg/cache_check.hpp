// What OpenSceneGraph's state cache (osg::State) believes is bound, against what the GL says,
// read right after the library's call on the draw thread. OSG skips a call it thinks redundant, so
// any state the library left different from the cache would break the engine's next draw, silently.
#pragma once

#include <osg/RenderInfo>

#include <string>
#include <vector>

namespace sss_osg_host {

// The framebuffers bound when the engine called the library (OSG keeps no cache of them: it
// believes what it bound is still bound).
struct FramebufferBindings {
  int draw = 0, read = 0;
};
FramebufferBindings read_framebuffer_bindings();

// One line per state where the cache and the GL disagree ("GL_CURRENT_PROGRAM: OSG believes 3, the GL
// has 7"), and one per pending GL error; empty when they agree. What is compared: the program, the
// active unit, every unit's 2D texture where OSG applied one and its sampler (OSG binds none), the
// modes the library touches, the viewport, the vertex array object and array buffer, the pixel
// unpack buffer, the colour mask, the depth function, mask and range, the blend function, and the
// framebuffers against `bound`. Restores what it changes to look (the active unit).
std::vector<std::string> compare_cache_with_gl(osg::RenderInfo& info, const FramebufferBindings& bound);

// One line per texture unit (0-7) with a sampler object bound ("GL_SAMPLER_BINDING of unit 6: 12"):
// OSG binds none, so after a library without its restore the callback must have unbound every one
// it used (units 0-5, and 6 in a frame with an albedo). Restores the active unit.
std::vector<std::string> samplers_left_bound(osg::RenderInfo& info);

}  // namespace sss_osg_host
