// One scene of a `motorbench report` run, measured in the process that calls it (a worker,
// see report_workers.h): load, the statistics of `inspect`, images of every pipeline at up to
// three animation times, diff heat maps and image metrics against the first (baseline)
// pipeline, and what each pipeline uploaded (PipelineStats). Never throws and never stops on
// an error: a failure is recorded in the returned JSON ("status", "error", per-pipeline and
// per-frame "error") and whatever could be measured is kept.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/report/report_inputs.h"
#include "pipelines/scene/scene.h"

namespace mb::report {

struct SceneJob {
  Input input;
  int index = 1, total = 1;             // for progress lines "[index/total] id: ..."
  std::string outDir;                   // report folder; images go to images/<id>/
  int width = 256, height = 192;
  std::vector<std::string> pipelines;   // first = baseline of the diffs
  std::vector<int> animations;          // --anim, resolved (report_anim_select.h); empty: the first
  int instances = 1;                    // --instances N (addGridInstances)
  std::string stepFile;                 // progress() also writes its last line here ("" none), so
                                        // the parent can say where a worker that died was
};

// Animation times the images are taken at: animation `anim` at 0, 1/3 and 2/3 of its
// duration (not the end, which equals the start for looping clips); one time (0) for a scene
// without that animation or with a zero-length one.
std::vector<float> imageTimes(const Scene& scene, int anim = 0);

// Drawn vertices by the vertex-shader variant that transforms them: "rigid" and "skinned"
// for every pipeline, and for the motor pipeline how many rigid ones sit on nodes whose own
// scale is non-uniform or mirrored ("scaledFallback"; the node's own scale only, parents'
// scales are not folded in). Used to weight ops per vertex per scene.
// "bezierPatch": tessellated patch vertices ((N+1)^2 per patch at Scene::patchLevel).
// "curvedInstance": a curved scene's vertices times its instances (the s3_/h3_ vertex shaders).
nlohmann::json vertexMix(const Scene& scene);

// Progress line on stderr: "[3/8] skinned_tube: rendering motor t=0.5" (and into job.stepFile).
void progress(const SceneJob& job, const std::string& what);
// Where a worker writing `resultPath` keeps its last progress line, and that line ("" when the
// file is missing or empty): "rendering motor_cf t=0".
std::string stepFileOf(const std::string& resultPath);
std::string lastStep(const std::string& stepFile);

// The "render" part of the scene's report.json entry (see README, section Report): images of
// every animation in job.animations (default: the first), each at imageTimes(), and one
// animated comparison per animation.
nlohmann::json measureScene(const SceneJob& job);

}  // namespace mb::report
