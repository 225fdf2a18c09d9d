// The OpenSceneGraph host's scenes (examples/osg): the head scan lit into the G-buffer the library
// reads, beside an object that is not skin; the composite that adds specular and tone-maps; and a
// second scene of OSG's standard materials (fixed-function lights, osg::Material, a texture) that
// the module never sees, drawn after it to show that OSG's state cache is still right.
#pragma once

#include <osg/Camera>
#include <osg/Group>
#include <osg/Image>
#include <osg/Texture2D>

#include <string>

namespace gltf_mesh {
struct Model;
}

namespace sss_osg_host {

// The G-buffer the lit pass writes: diffuse (RGBA16F, alpha = strength: 1 on skin, 0 elsewhere),
// specular (RGBA16F), albedo (RGBA16F: the linear albedo the diffuse light was multiplied by, what
// the library divides by in a texturing mode other than pre-scatter) and depth (DEPTH_COMPONENT32F).
struct GBuffer {
  osg::ref_ptr<osg::Texture2D> diffuse, specular, albedo, depth;
};

// The head (skin) and a box beside it (not skin), lit by a key and a fill light, with the GLSL
// program that writes the G-buffer.
osg::ref_ptr<osg::Group> make_lit_scene(const gltf_mesh::Model& head);

// A pre-render camera drawing `scene` into `g` (cleared to alpha 0, so the background is not skin)
// with a perspective projection (30° vertical field) looking at the head's face.
osg::ref_ptr<osg::Camera> make_gbuffer_camera(osg::Node* scene, const gltf_mesh::Model& head, const GBuffer& g);

// A post-render camera that draws a full-screen quad: `diffuse` (the library's output, or the
// G-buffer's diffuse without it) plus the specular, tone-mapped (Narkowicz's ACES fit) and
// sRGB-encoded into `image` (RGBA8, read back each frame). `diffuse` is swapped with
// set_composite_input. `skin_mask`: instead white where `diffuse`'s alpha is above 0 (the tests'
// mask of skin pixels). `rank`: the order among the post-render cameras.
osg::ref_ptr<osg::Camera> make_composite_camera(osg::Texture2D* diffuse, osg::Texture2D* specular, osg::Image* image,
                                               bool skin_mask = false, int rank = 0);
void set_composite_input(osg::Camera* composite, osg::Texture2D* diffuse);

// A post-render camera drawing the standard-materials scene into `image` (RGBA8), after the
// composite: fixed-function lighting, osg::Material, a checker texture, depth and blending.
osg::ref_ptr<osg::Camera> make_standard_scene_camera(osg::Image* image);

// An RGBA8 image of `width` x `height` for a camera to read back into.
osg::ref_ptr<osg::Image> make_readback_image(int width, int height);

}  // namespace sss_osg_host
