/*
 * The quick start of docs/integration.md, as a host writes it. Each numbered step's code lies
 * between its "quick-start N: <title>" and "quick-start N: end" lines and is, line for line, the
 * code block of the guide's step N with the same title: ctest docs.guide_quickstart_matches
 * (sss_docs quickstart) fails when one changes without the other. guide_quickstart_main.c runs the
 * steps in their order, headless (ctest docs.guide_quickstart). Strict C99; the GL header is only
 * for the format names.
 */
#include <GL/glcorearb.h>
#include <stdio.h>

#include <sss/sss.h>

#include "guide_quickstart.h"

/* Load time (steps 1-3), with the GL context current. */
sss_context *quickstart_load(sss_get_proc_address_fn load_gl, void *load_gl_user, int width, int height) {
  /* quick-start 1: Create a context with your GL loader */
  sss_context *sss = NULL;
  sss_create_desc desc = {0};
  desc.struct_size = sizeof desc;
  desc.get_proc_address = load_gl;           /* e.g. a wrapper of glfwGetProcAddress */
  desc.get_proc_address_user = load_gl_user; /* handed back to load_gl */
  if (sss_create(&desc, &sss) != SSS_OK) {
    fprintf(stderr, "sss_create: %s\n", sss_last_error(NULL));
    return NULL;
  }
  /* quick-start 1: end */
  /* quick-start 2: Start from the defaults and give the scene scale */
  sss_settings settings;
  sss_default_settings(&settings);      /* d'Eon's skin at its measured size */
  settings.world_units_per_mm = 0.001f; /* world units in a millimetre: 0.001 for metres */
  if (sss_set_settings(sss, &settings) != SSS_OK) {
    fprintf(stderr, "sss_set_settings: %s\n", sss_last_error(sss));
    sss_destroy(sss);
    return NULL;
  }
  /* quick-start 2: end */
  /* quick-start 3: Prepare for your frames' size and formats */
  sss_prepare_desc prepare = {0};
  prepare.struct_size = sizeof prepare;
  prepare.width = width;
  prepare.height = height;
  prepare.color_format = GL_RGBA16F;          /* 0x881A */
  prepare.depth_format = GL_DEPTH24_STENCIL8; /* 0x88F0 */
  if (sss_prepare(sss, &prepare) != SSS_OK) {
    fprintf(stderr, "sss_prepare: %s\n", sss_last_error(sss));
    sss_destroy(sss);
    return NULL;
  }
  /* quick-start 3: end */
  return sss;
}

/* Every frame (steps 4-6), after the diffuse lighting, before specular and tone mapping. */
int quickstart_frame(sss_context *sss, const float projection[16], uint32_t diffuse_texture, uint32_t depth_texture,
                     int width, int height) {
  /* quick-start 4: Describe the frame's textures */
  sss_frame frame = {0};
  frame.struct_size = sizeof frame;
  frame.color_texture = diffuse_texture; /* diffuse light x albedo, alpha = strength */
  frame.color_format = GL_RGBA16F;
  frame.depth_texture = depth_texture;   /* the depth the scene was drawn with */
  frame.depth_format = GL_DEPTH24_STENCIL8;
  frame.texture_width = width;
  frame.texture_height = height;
  /* quick-start 4: end */
  /* quick-start 5: Set the camera, then apply the frame */
  sss_result r = sss_set_camera(sss, projection); /* column-major, as the scene's */
  if (r == SSS_OK) r = sss_apply_frame(sss, &frame); /* blurs diffuse_texture in place */
  /* quick-start 5: end */
  /* quick-start 6: Check the result */
  if (r != SSS_OK) {
    fprintf(stderr, "%s\n", sss_last_error(sss)); /* "SSS_ERROR_...: what and why" */
    return 0; /* the texture is as it was, unless r is SSS_ERROR_GL */
  }
  /* quick-start 6: end */
  return 1;
}

/* At shutdown (step 7). */
void quickstart_unload(sss_context *sss) {
  /* quick-start 7: Destroy it in the same GL context */
  sss_destroy(sss); /* the GL context it was created in is current */
  /* quick-start 7: end */
}
