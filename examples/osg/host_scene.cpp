#include "host_scene.hpp"

#include <gltf_mesh.hpp>

#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LightSource>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/Program>
#include <osg/Shape>
#include <osg/ShapeDrawable>
#include <osg/Texture2D>

#include <algorithm>
#include <cmath>

namespace sss_osg_host {

namespace {

// GLSL 3.30 compatibility: OSG feeds gl_Vertex, gl_Normal and the built-in matrices.
const char* const kLitVertex = R"(#version 330 compatibility
out vec3 v_normal;    // eye space
out vec3 v_position;  // eye space
void main() {
  v_normal = gl_NormalMatrix * gl_Normal;
  v_position = (gl_ModelViewMatrix * gl_Vertex).xyz;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
)";

// The G-buffer: Lambert diffuse from a key and a fill light (fixed to the camera) times the albedo,
// alpha the strength the library reads (1 skin, 0 not); a Blinn-Phong specular apart, which the
// library must not blur.
const char* const kLitFragment = R"(#version 330 compatibility
in vec3 v_normal;
in vec3 v_position;
uniform vec3 u_albedo;     // linear
uniform float u_strength;  // the library's strength: 1 on skin, 0 elsewhere
layout(location = 0) out vec4 o_diffuse;
layout(location = 1) out vec4 o_specular;
layout(location = 2) out vec4 o_albedo;  // the albedo the light is multiplied by (sss_frame.albedo_texture)
void main() {
  vec3 n = normalize(v_normal);
  vec3 key = normalize(vec3(-0.8, 0.45, 0.4));  // from the upper left: the terminator crosses the face
  vec3 fill = normalize(vec3(0.8, -0.1, 0.4));
  float light = 1.3 * max(dot(n, key), 0.0) + 0.12 * max(dot(n, fill), 0.0) + 0.015;
  o_diffuse = vec4(u_albedo * light, u_strength);
  vec3 h = normalize(key + normalize(-v_position));
  o_specular = vec4(vec3(0.18 * pow(max(dot(n, h), 0.0), 48.0)), 1.0);
  o_albedo = vec4(u_albedo, 1.0);
}
)";

const char* const kQuadVertex = R"(#version 330 compatibility
void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
)";

// u_mode 0: (diffuse + specular), Narkowicz's ACES fit, sRGB encode; 1: the skin mask (white where
// the diffuse's alpha is above 0), for the host's tests.
const char* const kCompositeFragment = R"(#version 330 compatibility
uniform sampler2D u_diffuse;
uniform sampler2D u_specular;
uniform int u_mode;
out vec4 o_color;
vec3 filmic(vec3 x) {
  x *= 0.6;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 srgb(vec3 c) { return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c)); }
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 d = texelFetch(u_diffuse, p, 0);
  if (u_mode == 1) {
    o_color = vec4(vec3(d.a > 0.0 ? 1.0 : 0.0), 1.0);
    return;
  }
  o_color = vec4(srgb(filmic(max(d.rgb + texelFetch(u_specular, p, 0).rgb, vec3(0.0)))), 1.0);
}
)";

osg::ref_ptr<osg::Program> program(const char* vertex, const char* fragment) {
  osg::ref_ptr<osg::Program> p = new osg::Program;
  p->addShader(new osg::Shader(osg::Shader::VERTEX, vertex));
  p->addShader(new osg::Shader(osg::Shader::FRAGMENT, fragment));
  return p;
}

osg::ref_ptr<osg::Geometry> head_geometry(const gltf_mesh::Model& head) {
  osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
  osg::ref_ptr<osg::Vec3Array> normals = new osg::Vec3Array;
  const std::size_t stride = gltf_mesh::Model::kFloatsPerVertex;
  for (std::size_t v = 0; v < head.vertex_count(); ++v) {
    const float* p = &head.vertices[v * stride];
    positions->push_back(osg::Vec3(p[0], p[1], p[2]));
    normals->push_back(osg::Vec3(p[3], p[4], p[5]));
  }
  osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
  g->setUseDisplayList(false);
  g->setUseVertexBufferObjects(true);
  g->setVertexArray(positions.get());
  g->setNormalArray(normals.get(), osg::Array::BIND_PER_VERTEX);
  g->addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES, head.indices.begin(), head.indices.end()));
  return g;
}

// Centre and height of the head's bounds.
osg::Vec3 centre_of(const gltf_mesh::Model& m) {
  return osg::Vec3(0.5f * (m.bounds_min[0] + m.bounds_max[0]), 0.5f * (m.bounds_min[1] + m.bounds_max[1]),
                   0.5f * (m.bounds_min[2] + m.bounds_max[2]));
}
float height_of(const gltf_mesh::Model& m) { return std::max(m.bounds_max[1] - m.bounds_min[1], 1e-6f); }

osg::ref_ptr<osg::Camera> render_to_texture_camera(int width, int height, osg::Camera::RenderOrder order, int rank) {
  osg::ref_ptr<osg::Camera> c = new osg::Camera;
  c->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
  c->setRenderOrder(order, rank);
  c->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
  c->setViewport(0, 0, width, height);
  c->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  return c;
}

osg::ref_ptr<osg::Image> checker_image() {
  osg::ref_ptr<osg::Image> image = new osg::Image;
  image->allocateImage(64, 64, 1, GL_RGBA, GL_UNSIGNED_BYTE);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      unsigned char* p = image->data(x, y);
      const bool light = ((x / 8) + (y / 8)) % 2 == 0;
      p[0] = light ? 230 : 40;
      p[1] = light ? 200 : 60;
      p[2] = light ? 120 : 90;
      p[3] = 255;
    }
  }
  return image;
}

}  // namespace

osg::ref_ptr<osg::Group> make_lit_scene(const gltf_mesh::Model& head) {
  osg::ref_ptr<osg::Group> scene = new osg::Group;
  osg::ref_ptr<osg::Program> lit = program(kLitVertex, kLitFragment);
  scene->getOrCreateStateSet()->setAttributeAndModes(lit.get());

  osg::ref_ptr<osg::Geode> skin = new osg::Geode;
  skin->addDrawable(head_geometry(head).get());
  osg::StateSet* skin_state = skin->getOrCreateStateSet();
  skin_state->addUniform(new osg::Uniform("u_albedo", osg::Vec3(0.80f, 0.52f, 0.42f)));
  skin_state->addUniform(new osg::Uniform("u_strength", 1.0f));
  scene->addChild(skin.get());

  // A box beside the head, not skin (strength 0): the library must leave every pixel of it alone.
  const float h = height_of(head);
  const osg::Vec3 c = centre_of(head);
  osg::ref_ptr<osg::Geode> other = new osg::Geode;
  osg::ref_ptr<osg::ShapeDrawable> box =
      new osg::ShapeDrawable(new osg::Box(c + osg::Vec3(0.62f * h, -0.15f * h, -0.1f * h), 0.35f * h, 0.6f * h, 0.3f * h));
  box->setUseDisplayList(false);
  box->setUseVertexBufferObjects(true);
  other->addDrawable(box.get());
  osg::StateSet* other_state = other->getOrCreateStateSet();
  other_state->addUniform(new osg::Uniform("u_albedo", osg::Vec3(0.35f, 0.45f, 0.55f)));
  other_state->addUniform(new osg::Uniform("u_strength", 0.0f));
  scene->addChild(other.get());
  return scene;
}

osg::ref_ptr<osg::Camera> make_gbuffer_camera(osg::Node* scene, const gltf_mesh::Model& head, const GBuffer& g) {
  const int width = g.diffuse->getTextureWidth(), height = g.diffuse->getTextureHeight();
  osg::ref_ptr<osg::Camera> c = render_to_texture_camera(width, height, osg::Camera::PRE_RENDER, 0);
  c->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));  // alpha 0: the background is not skin
  c->attach(osg::Camera::COLOR_BUFFER0, g.diffuse.get());
  c->attach(osg::Camera::COLOR_BUFFER1, g.specular.get());
  c->attach(osg::Camera::COLOR_BUFFER2, g.albedo.get());
  c->attach(osg::Camera::DEPTH_BUFFER, g.depth.get());
  // The demo's close-up, a little wider: the face, the box beside it and background around them.
  const float h = height_of(head), fovy = 30.0f;
  const osg::Vec3 target = centre_of(head) + osg::Vec3(0.12f * h, 0.15f * h, 0.2f * h);
  const float distance = 0.95f * h / (2.0f * std::tan(osg::DegreesToRadians(0.5f * fovy)));
  const float yaw = osg::DegreesToRadians(20.0f), pitch = osg::DegreesToRadians(5.0f);
  const osg::Vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  c->setViewMatrixAsLookAt(target + offset * distance, target, osg::Vec3(0.0f, 1.0f, 0.0f));
  // OSG computes near and far from the bounds each frame (its default): the library takes the
  // projection OSG applied, not this one (sss_osg_pass.cpp).
  c->setProjectionMatrixAsPerspective(fovy, static_cast<double>(width) / height, 0.01, 10.0);
  c->addChild(scene);
  return c;
}

osg::ref_ptr<osg::Camera> make_composite_camera(osg::Texture2D* diffuse, osg::Texture2D* specular, osg::Image* image,
                                               bool skin_mask, int rank) {
  osg::ref_ptr<osg::Camera> c = render_to_texture_camera(image->s(), image->t(), osg::Camera::POST_RENDER, rank);
  c->setClearMask(0);  // the quad covers every pixel
  c->attach(osg::Camera::COLOR_BUFFER, image);
  c->setProjectionMatrixAsOrtho2D(0.0, 1.0, 0.0, 1.0);
  c->setViewMatrix(osg::Matrix::identity());
  osg::ref_ptr<osg::Geode> quad = new osg::Geode;
  osg::ref_ptr<osg::Geometry> geometry =
      osg::createTexturedQuadGeometry(osg::Vec3(0, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(0, 1, 0));
  geometry->setUseDisplayList(false);
  geometry->setUseVertexBufferObjects(true);
  quad->addDrawable(geometry.get());
  osg::StateSet* s = quad->getOrCreateStateSet();
  s->setAttributeAndModes(program(kQuadVertex, kCompositeFragment).get());
  s->setTextureAttribute(0, diffuse);
  s->setTextureAttribute(1, specular);
  s->addUniform(new osg::Uniform("u_diffuse", 0));
  s->addUniform(new osg::Uniform("u_specular", 1));
  s->addUniform(new osg::Uniform("u_mode", skin_mask ? 1 : 0));
  s->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
  s->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
  c->addChild(quad.get());
  return c;
}

void set_composite_input(osg::Camera* composite, osg::Texture2D* diffuse) {
  composite->getChild(0)->getOrCreateStateSet()->setTextureAttribute(0, diffuse);
}

osg::ref_ptr<osg::Camera> make_standard_scene_camera(osg::Image* image) {
  osg::ref_ptr<osg::Camera> c = render_to_texture_camera(image->s(), image->t(), osg::Camera::POST_RENDER, 1);
  c->setClearColor(osg::Vec4(0.18f, 0.2f, 0.24f, 1.0f));
  c->attach(osg::Camera::COLOR_BUFFER, image);
  c->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
  c->setProjectionMatrixAsPerspective(40.0, static_cast<double>(image->s()) / image->t(), 0.1, 50.0);
  c->setViewMatrixAsLookAt(osg::Vec3(0.0f, -6.0f, 2.5f), osg::Vec3(0.0f, 0.0f, 0.0f), osg::Vec3(0.0f, 0.0f, 1.0f));

  osg::ref_ptr<osg::Group> scene = new osg::Group;
  osg::ref_ptr<osg::LightSource> key = new osg::LightSource;
  key->getLight()->setLightNum(0);
  key->getLight()->setPosition(osg::Vec4(-3.0f, -4.0f, 6.0f, 1.0f));
  key->getLight()->setDiffuse(osg::Vec4(0.9f, 0.9f, 0.85f, 1.0f));
  key->getLight()->setSpecular(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
  osg::ref_ptr<osg::LightSource> fill = new osg::LightSource;
  fill->getLight()->setLightNum(1);
  fill->getLight()->setPosition(osg::Vec4(1.0f, -0.5f, 0.3f, 0.0f));
  fill->getLight()->setDiffuse(osg::Vec4(0.25f, 0.3f, 0.4f, 1.0f));
  scene->addChild(key.get());
  scene->addChild(fill.get());
  osg::StateSet* lights = scene->getOrCreateStateSet();
  lights->setMode(GL_LIGHTING, osg::StateAttribute::ON);
  lights->setMode(GL_LIGHT0, osg::StateAttribute::ON);
  lights->setMode(GL_LIGHT1, osg::StateAttribute::ON);
  lights->setMode(GL_DEPTH_TEST, osg::StateAttribute::ON);
  lights->setMode(GL_CULL_FACE, osg::StateAttribute::ON);

  const auto add = [&scene](osg::Shape* shape, const osg::Vec4& colour) {
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::ShapeDrawable> drawable = new osg::ShapeDrawable(shape);
    geode->addDrawable(drawable.get());
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setDiffuse(osg::Material::FRONT_AND_BACK, colour);
    material->setAmbient(osg::Material::FRONT_AND_BACK, colour * 0.3f);
    material->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.6f, 0.6f, 0.6f, 1.0f));
    material->setShininess(osg::Material::FRONT_AND_BACK, 40.0f);
    geode->getOrCreateStateSet()->setAttributeAndModes(material.get());
    scene->addChild(geode.get());
    return geode;
  };
  add(new osg::Sphere(osg::Vec3(-1.4f, 0.0f, 0.0f), 1.0f), osg::Vec4(0.8f, 0.25f, 0.2f, 1.0f));
  // A textured box: the cache's units matter here (the library binds textures on units 0-5).
  osg::ref_ptr<osg::Geode> box = add(new osg::Box(osg::Vec3(1.3f, 0.3f, -0.2f), 1.5f), osg::Vec4(1, 1, 1, 1));
  osg::ref_ptr<osg::Texture2D> checker = new osg::Texture2D(checker_image().get());
  checker->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR_MIPMAP_LINEAR);
  box->getOrCreateStateSet()->setTextureAttributeAndModes(0, checker.get());
  // A blended cone in front: blending and a read-only depth (state the library also sets).
  osg::ref_ptr<osg::Geode> cone = add(new osg::Cone(osg::Vec3(0.0f, -1.6f, -0.6f), 0.6f, 1.6f),
                                      osg::Vec4(0.3f, 0.7f, 0.9f, 0.5f));
  osg::StateSet* glass = cone->getOrCreateStateSet();
  glass->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
  glass->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
  glass->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
  c->addChild(scene.get());
  return c;
}

osg::ref_ptr<osg::Image> make_readback_image(int width, int height) {
  osg::ref_ptr<osg::Image> image = new osg::Image;
  image->allocateImage(width, height, 1, GL_RGBA, GL_UNSIGNED_BYTE);
  return image;
}

}  // namespace sss_osg_host
