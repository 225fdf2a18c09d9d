/*
 * The guide's quick start (guide_quickstart.c) as three calls a host makes: at load time, every
 * frame, at shutdown. guide_quickstart_main.c runs them headless.
 */
#ifndef SSS_GUIDE_QUICKSTART_H
#define SSS_GUIDE_QUICKSTART_H

#include <sss/sss.h>

/* Steps 1-3: NULL on failure (the reason is on stderr). */
sss_context *quickstart_load(sss_get_proc_address_fn load_gl, void *load_gl_user, int width, int height);
/* Steps 4-6: 1 when the frame was blurred, 0 on failure (the reason is on stderr). */
int quickstart_frame(sss_context *sss, const float projection[16], uint32_t diffuse_texture, uint32_t depth_texture,
                     int width, int height);
/* Step 7. */
void quickstart_unload(sss_context *sss);

#endif /* SSS_GUIDE_QUICKSTART_H */
