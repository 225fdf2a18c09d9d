// The vertex stage for a GltfMesh's attributes (gltf_mesh.hpp: locations 0-3 hold position, normal,
// texture coordinate and tangent), passing them on in object space with the clip position: the
// demo's lighting pass and the web demo's lit pass share it, each putting its own #version line
// (330 core; 300 es) in front.
#pragma once

#include <string>

namespace gltf_mesh {

inline const char* const kMeshVertexBody = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;
layout(location = 3) in vec4 a_tangent;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_texcoord;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_tangent = a_tangent;
  v_texcoord = a_texcoord;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

// The source with `version_line` ("#version 330 core") in front.
inline std::string mesh_vertex_shader(const char* version_line) { return std::string(version_line) + kMeshVertexBody; }

}  // namespace gltf_mesh
