// What the fuzzer does with one input, shared by the libFuzzer target (tests/fuzz/fuzz_loader.cpp,
// which aborts on a non-empty result) and the regression replay
// (tests/scene/test_scene_fuzz_regressions.cpp, which fails the test with it).
//
// The input is loaded from memory with no base directory (external URIs are refused, so nothing
// touches the filesystem): as .glb when it starts with the GLB magic, as .gltf JSON otherwise,
// and a JSON input is also wrapped as the JSON chunk of a GLB. For every load:
//   - a failure must name the input and be reportable by `inspect --json` (serialisable);
//   - a Scene must pass tests/hostile/scene_checks.h (indices, stream lengths, hierarchy,
//     joints, keyframes...), be posable (rest pose, each animation at several times, blends),
//     framed by the camera rule, give world matrices, and be summarised by computeFileStats.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "tests/hostile/gltf_builder.h"
#include "tests/hostile/scene_checks.h"

namespace mb::fuzz {

inline std::string checkView(const Scene& scene, const View& v, const char* what) {
  if (!hostile::poseInputsTame(scene)) return "";
  bool finite = hostile::finite(v.eye) && hostile::finite(v.orientation) && std::isfinite(v.yfov) &&
                std::isfinite(v.znear) && std::isfinite(v.zfar) && std::isfinite(v.ymag);
  return finite ? "" : std::string(what) + ": frameScene produced a non-finite view";
}

// Loads `bytes` as `name` and runs everything pipelines run on a scene. "" when all is well,
// else what went wrong. C++ exceptions escaping the loader are reported too.
inline std::string exerciseOne(const std::vector<uint8_t>& bytes, const std::string& name) {
  try {
    Result<Scene> r = loadGltfMemory(bytes, name);
    if (!r.ok()) {
      if (r.error().find(name) == std::string::npos) return "error does not name the file: " + r.error();
      (void)toJson(failedFileStats(name, r.error())).dump();  // what `inspect --json` writes
      return "";
    }
    const Scene& scene = *r;
    if (std::string e = hostile::checkSceneInvariants(scene); !e.empty()) return "scene invariant: " + e;
    if (std::string e = hostile::exercisePoses(scene); !e.empty()) return "pose: " + e;
    if (std::string e = checkView(scene, frameScene(scene, AnimState{}, 1.5f), "rest view"); !e.empty()) return e;
    if (!scene.animations.empty()) {
      AnimState st;
      st.anim = 0;
      st.time = 0.5f * scene.animations[0].duration;
      if (std::string e = checkView(scene, frameScene(scene, st, 1.0f), "animated view"); !e.empty()) return e;
      if (worldMatrices(scene, samplePose(scene, st)).size() != scene.nodes.size()) return "worldMatrices: wrong count";
    }
    for (int c = 0; c < int(scene.cameras.size()) && c < 2; ++c) (void)frameScene(scene, AnimState{}, 1.0f, c);
    (void)toJson(computeFileStats(scene)).dump();
    return "";
  } catch (const std::exception& e) {
    return std::string("exception: ") + e.what();
  }
}

inline std::string exercise(const uint8_t* data, size_t size) {
  std::vector<uint8_t> bytes(data, data + size);
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  std::string e = exerciseOne(bytes, glb ? "fuzz.glb" : "fuzz.gltf");
  if (e.empty() && !glb && size < (size_t(1) << 20))
    e = exerciseOne(hostile::glbContainer(std::string(reinterpret_cast<const char*>(data), size), {}), "fuzz-wrapped.glb");
  return e;
}

}  // namespace mb::fuzz
