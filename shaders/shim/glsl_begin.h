// shaders/shim/glsl_begin.h: opens a C++ shader class; see the usage in shaders/shim/glsl.h.
// No include guard: included once per instantiated class, paired with glsl_end.h.
#ifndef MB_GLSL_SHIM_H
#error "include shaders/shim/glsl.h at file scope before glsl_begin.h"
#endif
#ifndef MB_GLSL_CLASS
#error "#define MB_GLSL_CLASS <class template name> before including glsl_begin.h"
#endif
#ifdef MB_GLSL_CPP
#error "glsl_begin.h: the previous shader class was not closed with glsl_end.h"
#endif
#define MB_GLSL_CPP 1

template <class Scalar>
struct MB_GLSL_CLASS {
  using scalar_type = Scalar;
#include "shaders/shim/glsl_prelude.inl"
#define float Scalar
