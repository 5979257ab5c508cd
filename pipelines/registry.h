// What each pipeline declares beside its factory (README.md: what reads each): the harness reads
// these instead of naming pipelines.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pipelines/pipeline.h"
#include "pipelines/skin_method.h"

namespace mb {

// One program a pipeline links: its vertex stage (file and #defines, as its prepare() links
// them), what it draws, and the GLSL functions its main() calls that harness/ops counts
// (harness/ops/vertex_kernels*.cpp). What each label means: harness/ops/shader_variants.h.
struct ShaderVariant {
  std::string stage;  // the vertex shader, relative to the shader folder
  std::vector<std::pair<std::string, std::string>> defines = {};  // name, value ("" = none)
  std::string draws;                                               // "rigid", "skinned", ...
  std::vector<std::string> kernels;
  std::string note = "";                // what main() does besides those kernels
  std::string fragment = "forward.fs";  // the fragment stage it is linked with
};

// #defines as a compiler's -D options name them: "NAME NAME=VALUE ..." (a name alone: value "").
std::vector<std::pair<std::string, std::string>> defines(const std::string& names);

// A family's programs: `rows` with `stage` where a row names none, and `clip` (the transform to
// clip space every program of the family ends with) after each row's kernels.
std::vector<ShaderVariant> programs(const std::string& stage, const std::string& clip,
                                    std::vector<ShaderVariant> rows);

// Which side of the paper's comparison a pipeline is on: what it transforms with on the CPU
// (hybrid poses with motors and hands matrices to the GPU: Motor).
enum class PipelineFamily { Matrix, Motor };

// How a vertex stores its tangent frame and where it is unpacked.
struct FrameEncoding {
  std::string decodeKernel = "";  // the counted GLSL function that unpacks it ("": none runs)
  std::string fetched = "";       // without one: what the vertex fetch reads ("float frame")
  bool perFragment = false;       // the world tangent rotor is the varying, unpacked in forward.fs
};

struct PipelineEntry {
  std::string name;
  std::unique_ptr<Pipeline> (*make)();
  Space space = Space::Euclidean;  // the scenes it draws
  SkinMethod skin;                 // how its vertex shader blends joints (skin_method.h)
  PipelineFamily family;
  int vertexBytes = 0;  // shading attributes of a normal-mapped vertex (0: no glTF vertex)
  FrameEncoding frame = {};
  std::vector<ShaderVariant> variants = {};
};

// Every registered pipeline, in registry order (the matrix baseline first).
const std::vector<PipelineEntry>& registeredPipelines();
// nullptr when `name` is not registered.
const PipelineEntry* findPipeline(const std::string& name);
// Whether `name` is registered with the 16-byte vertex (int16 position, 4-byte frame, half uv).
inline bool hasSixteenByteVertex(const std::string& name) {
  const PipelineEntry* e = findPipeline(name);
  return e && e->vertexBytes == 16;
}

// A registration that lasts as long as the object: a test adds a pipeline (a copy of one under
// another name) with one entry and finds it in every command's lists. A name already taken is
// not added (added() is false).
class ScopedRegistration {
public:
  explicit ScopedRegistration(PipelineEntry entry);
  ~ScopedRegistration();
  ScopedRegistration(const ScopedRegistration&) = delete;
  ScopedRegistration& operator=(const ScopedRegistration&) = delete;
  bool added() const { return added_; }

private:
  std::string name_;
  bool added_ = false;
};

}  // namespace mb

namespace mb::variant_notes {

// What several pipelines' variants say alike (constants, not strings built at start-up: the
// registry may be read during static initialisation).
inline constexpr const char* kTexels = "the 16 control points are texelFetch (no arithmetic)";
// Instanced draws (EXT_mesh_gpu_instancing): the rigid transform with its per-draw data read
// from per-instance attributes; the same arithmetic as the non-instanced variant.
inline constexpr const char* kInstanced = "the per-draw transform read from per-instance attributes (divisor 1)";
inline constexpr const char* kMorphSums =
    "morph.glsl's delta sums, per target with a non-zero weight 1 mul + 1 add per float of the target "
    "(storage-buffer reads by the vertex index), before the transform";
// A morphing rigid vertex beside the rigid one (shaders/morph.glsl), two targets as morph_torus.
inline constexpr const char* kMorph = "MB_MORPH MB_MORPH_TARGETS=2";

}  // namespace mb::variant_notes
