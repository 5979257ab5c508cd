// TRS <-> matrix helpers used by the loader and by anything that poses nodes.
#pragma once
#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb {

// T * R * S as a column-major matrix (the glTF node transform).
glm::mat4 trsMatrix(const TRS& trs);

// Decomposes an affine matrix into TRS. A negative determinant is expressed as a negative
// scale.x. Returns true when the matrix is exactly representable as TRS up to a small
// tolerance; false when it has shear, a projective row or a zero-length axis (the TRS is then
// the best orthogonal approximation: rotation from a Gram-Schmidt of the columns).
bool decomposeMatrix(const glm::mat4& m, TRS* out);

}  // namespace mb
