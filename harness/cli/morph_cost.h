// The image and byte cost of each morph method, measured for `motorbench morph`:
// matrix (glTF's position, normal and tangent deltas added, then transformed) beside the motor
// pipeline with its two rotor methods, (a) frame (PipelineOptions MorphMethod::Frame, the
// default) and (b) rotor deltas (MorphMethod::Rotor), on every frame of each scene: the rest
// pose and every animation at 1/4, 1/2 and 3/4 of its duration. Unskinned scenes compare each
// motor method with matrix; skinned ones with harness/render/skin_reference.h's CPU reference
// (motor blending differs from matrix's linear blend by design), matrix beside it. Bytes per
// vertex and per vertex of one target are read from the uploads (PipelineStats vertexBytes /
// vertices, morphBytes / morphTargetVertices). Figures (harness/figures) are computed once here.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::morph {

// The three rows of the table, in order: {"id", "pipeline", "method", "program"} where
// "program" is the `motorbench isa` / shaderVariants() label of its morphing rigid vertex shader.
struct Method {
  std::string id, pipeline, method, label;
  bool rotorDeltas = false;  // MorphMethod::Rotor
};
const std::vector<Method>& methods();

// The scenes (built-in names or glTF paths) measured at `size` x `size` pixels.
// JSON "motorbench-morph/1": {"gl", "size", "methods", "scenes": [{"scene", "skinned",
// "reference" (skinned: available/why), "targets", "weightChannels", "frames": [{"anim", "time",
// "morphDraws", "methods": {id: {"psnr" (null: identical), "maxError", "morphDraws"}}}],
// "bytes": {id: {...}}}], "figures": {...}}. A scene that fails to load or draw is recorded with
// its "error" and left out of the figures; `errors` counts them.
nlohmann::json measureMorphCost(const std::vector<std::string>& scenes, int size, int* errors);

// From the "scenes" of such a JSON: the figures (morph.worst_psnr.rigid.<id>, ...), also used by
// the tests on a hand-made document.
nlohmann::json morphFigures(const nlohmann::json& doc);

// The files of `folder` whose MANIFEST.tsv features column (the 9th) lists "morph-targets".
std::vector<std::string> manifestMorphFiles(const std::string& folder);

}  // namespace mb::morph
