/*
 * The README's integration example, compiled as strict C99 and run by ctest (docs.readme_example,
 * through readme_example_main.c); docs.readme_example_matches fails when the README's copy (the
 * block after "<!-- example: tools/docs/readme_example.c") differs from the lines between the markers.
 */
/* readme-example: begin */
#include <sss/sss.h>

/* Once per GL context (OpenGL 3.3+, current; ES: docs/integration.md): the loader, the scene scale. */
sss_context *engine_sss_create(sss_get_proc_address_fn get_proc_address, void *loader_user) {
  sss_create_desc desc = {0};
  sss_settings settings;
  sss_context *sss = NULL;
  desc.struct_size = sizeof desc;
  desc.get_proc_address = get_proc_address; /* e.g. a wrapper of glfwGetProcAddress */
  desc.get_proc_address_user = loader_user;
  if (sss_create(&desc, &sss) != SSS_OK) return NULL; /* sss_last_error(NULL) says why */
  sss_default_settings(&settings);                    /* d'Eon's skin at its measured size */
  settings.world_units_per_mm = 0.001f;               /* one world unit is a metre */
  settings.scale = 1.0f;                              /* 1 = physical; the artist's multiplier */
  sss_set_settings(sss, &settings);                   /* the defaults and these are valid */
  return sss;
}

/* Every frame, after the lighting pass and before specular is added and the image tone mapped. */
int engine_sss_frame(sss_context *sss, const float projection[16], uint32_t diffuse, uint32_t depth) {
  sss_frame frame = {0};
  frame.struct_size = sizeof frame;
  frame.color_texture = diffuse; /* RGBA16F: linear diffuse light x albedo, alpha = SSS strength */
  frame.depth_texture = depth;   /* the depth (or depth-stencil) texture the scene was drawn with */
  if (sss_set_camera(sss, projection) != SSS_OK) return 0; /* column-major, as glUniformMatrix4fv */
  return sss_apply_frame(sss, &frame) == SSS_OK;           /* blurred in place */
}
/* At shutdown, with the same GL context current: sss_destroy(sss). */
/* readme-example: end */
