// shaders/shim/glsl_end.h: closes the C++ shader class opened by glsl_begin.h.
#ifndef MB_GLSL_CPP
#error "glsl_end.h without glsl_begin.h"
#endif
#undef float
};
#undef MB_GLSL_CPP
#undef MB_GLSL_CLASS
// Include guards of the shared .glsl modules act per C++ class (a second class in the same
// translation unit must see the module again). Add the guard of every new shared module.
#undef MB_PGA_GLSL
#undef MB_MOTOR_TRANSFORM_GLSL
#undef MB_MATRIX_TRANSFORM_GLSL
#undef MB_AFFINE_TRANSFORM_GLSL
#undef MB_COMPACT_FRAME_GLSL
#undef MB_FRAME_SHADING_GLSL
#undef MB_SKINNING_GLSL
#undef MB_GGX_GLSL
#undef MB_PGA_KAPPA_GLSL
#undef MB_CURVED_TRANSFORM_GLSL
#undef MB_PAPER_LISTINGS_GLSL
#undef MB_BEZIER_PATCH_GLSL
#undef MB_PATCH_TRANSFORM_GLSL
