// The MB_bezier_patches primitive extension (this project's): a POINTS primitive whose
// POSITION accessor holds the control points of bicubic Bezier patches, 16 per patch, row by
// row (Primitive::patchPoints' order). A viewer without the extension shows the control
// points; motorbench tessellates the patches. Extension object: {"degree": [3, 3]} (optional;
// any other degree is refused).
#include <tiny_gltf.h>

#include <cmath>

#include "pipelines/scene/gltf/accessors.h"
#include "pipelines/scene/gltf/gltf_convert.h"

namespace mb {

Result<Primitive> convertPatchPrimitive(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                                        int materialCount) {
  using R = Result<Primitive>;
  const tinygltf::Value& ext = prim.extensions.at(kBezierPatchesExtension);
  if (prim.mode != TINYGLTF_MODE_POINTS) return R::fail(std::string(kBezierPatchesExtension) + " needs mode 0 (POINTS)");
  if (ext.IsObject() && ext.Has("degree")) {
    const tinygltf::Value& d = ext.Get("degree");
    bool bicubic = d.IsArray() && d.ArrayLen() == 2 && d.Get(0).IsNumber() && d.Get(1).IsNumber() &&
                   d.Get(0).GetNumberAsDouble() == 3.0 && d.Get(1).GetNumberAsDouble() == 3.0;
    if (!bicubic) return R::fail(std::string(kBezierPatchesExtension) + ": only degree [3, 3] is supported");
  }
  auto it = prim.attributes.find("POSITION");
  if (it == prim.attributes.end()) return R::fail(std::string(kBezierPatchesExtension) + " without POSITION");
  if (prim.material >= materialCount || prim.material < -1)
    return R::fail("material " + std::to_string(prim.material) + " does not exist");
  auto pos = readAccessorFloat(m, it->second, "POSITION");
  if (!pos) return R::fail(pos.error());
  if (pos->components != 3) return R::fail("accessor " + std::to_string(it->second) + " (POSITION) is not VEC3");
  if (pos->count == 0 || pos->count % 16)
    return R::fail(std::to_string(pos->count) + " control points is not a whole number of bicubic patches (16 each)");
  for (float v : pos->values)
    if (!std::isfinite(v)) return R::fail("patch control point with a non-finite coordinate");
  Primitive p;
  p.material = prim.material;
  p.patchPoints.resize(pos->count);
  for (size_t i = 0; i < pos->count; ++i)
    p.patchPoints[i] = glm::vec3(pos->values[3 * i], pos->values[3 * i + 1], pos->values[3 * i + 2]);
  return p;
}

}  // namespace mb
