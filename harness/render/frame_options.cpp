#include "harness/render/frame_options.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "harness/render/gpu_option.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/curved_space.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/instancing.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

namespace mb {
namespace {

// Index of `value` among `count` items named by `nameOf`, accepting a number or a name.
template <class NameOf>
Result<int> resolveIndex(const std::string& option, const std::string& value, size_t count,
                         NameOf nameOf, const std::string& source) {
  char* end = nullptr;
  long i = std::strtol(value.c_str(), &end, 10);
  if (!value.empty() && *end == '\0') {
    if (i >= 0 && size_t(i) < count) return int(i);
    if (count == 0) return Result<int>::fail("--" + option + " " + value + ": " + source + " has none");
    return Result<int>::fail("--" + option + " " + value + ": " + source + " has " +
                             std::to_string(count) + " (indices 0.." +
                             std::to_string(long(count) - 1) + ")");
  }
  std::string names;
  for (size_t k = 0; k < count; ++k) {
    if (nameOf(k) == value) return int(k);
    names += (names.empty() ? "'" : ", '") + nameOf(k) + "'";
  }
  return Result<int>::fail("--" + option + " " + value + ": no such name in " + source +
                           (names.empty() ? " (it has none)" : " (names: " + names + ")"));
}

std::string seconds(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%g s", t);
  return b;
}

std::string animText(const Scene& scene, int index) {
  const Animation& a = scene.animations[size_t(index)];
  return "animation " + std::to_string(index) + (a.name.empty() ? " (unnamed)" : " '" + a.name + "'") + " (" + std::to_string(index + 1) + " of " +
         std::to_string(scene.animations.size()) + ", duration " + seconds(a.duration) + ")";
}

// Reads --<timeKey> for animation `anim` (>= 0): >= 0 seconds, clamped to the duration (noted).
Result<float> timeFor(const options::Args& args, const std::string& timeKey, double fallback, const Scene& scene,
                      int anim, std::vector<std::string>& notes) {
  const double t = args.real(timeKey, fallback, 0.0, 1e9, "a time in seconds");
  const double duration = scene.animations[size_t(anim)].duration;
  if (t > duration) {
    notes.push_back("--" + timeKey + " " + args.get(timeKey, "") + " is past the end of " + animText(scene, anim) +
                    ": drawing its last pose, t = " + seconds(duration) +
                    " (times are clamped to the animation, not looped)");
    return float(duration);
  }
  return float(t);
}

// Every name loadScene builds: the glTF built-ins, those only check draws by default
// (morph_torus), then the curved-space ones (s3_tiling, h3_tiling).
std::vector<std::string> everyBuiltinName() {
  std::vector<std::string> names = builtinSceneNames();
  names.insert(names.end(), goldenOnlySceneNames().begin(), goldenOnlySceneNames().end());
  names.insert(names.end(), curvedSceneNames().begin(), curvedSceneNames().end());
  return names;
}

}  // namespace

options::OptionSpec sceneCommandOptions(std::set<std::string> values, std::set<std::string> flags) {
  options::OptionSpec spec;
  spec.values = std::move(values);
  spec.values.insert({"o", "output", "anim", "time", "anim2", "time2", "blend", "camera", "size", "instances", "gpu"});
  spec.flags = std::move(flags);
  const std::string once =
      "a run draws one frame per pipeline: run the command once per time (report draws three times per scene)";
  spec.repeatHints["time"] = once;
  spec.repeatHints["anim"] = once;
  return spec;
}

Status checkSceneSpec(const std::string& spec) {
  namespace fs = std::filesystem;
  if (isBuiltinScene(spec)) return Status();
  std::error_code ec;
  if (fs::is_directory(spec, ec))
    return Status::fail(spec + ": is a folder; this command takes one glTF file or a built-in scene "
                               "(inspect, report and time take folders)");
  if (!fs::exists(spec, ec))
    return Status::fail(spec + ": no such file, and not a built-in scene (built-in: " +
                        joinNames(everyBuiltinName()) + ")");
  return Status();
}

Status checkPipelineNames(const std::string& option, const std::vector<std::string>& names) {
  const std::vector<std::string> known = allPipelineNames();
  for (const std::string& n : names)
    if (std::find(known.begin(), known.end(), n) == known.end())
      return Status::fail(option + " " + n + ": unknown pipeline (registered: " + joinNames(known) + ")");
  return Status();
}

Result<ChosenAnimation> chooseAnimation(const options::Args& args, const Scene& scene) {
  ChosenAnimation c;
  if (auto a = args.get("anim")) {
    auto i = resolveIndex("anim", *a, scene.animations.size(), [&](size_t k) { return scene.animations[k].name; },
                          scene.source + " (animations)");
    if (!i) return Result<ChosenAnimation>::fail(i.error());
    c.index = *i;
  } else if (!scene.animations.empty()) {
    c.index = 0;
  }
  c.text = c.index < 0 ? "the rest pose (no animations)" : animText(scene, c.index);
  if (!args.has("anim") && scene.animations.size() > 1) c.text += "; --anim picks another";
  return c;
}

Result<FrameSettings> frameSettingsFromArgs(const options::Args& args, const Scene& scene, std::vector<std::string>* notesOut) {
  using R = Result<FrameSettings>;
  std::vector<std::string> notes;
  FrameSettings s;
  auto animName = [&](size_t k) { return scene.animations[k].name; };
  const std::string& src = scene.source;
  if (auto a = args.get("anim")) {
    auto i = resolveIndex("anim", *a, scene.animations.size(), animName, src + " (animations)");
    if (!i) return R::fail(i.error());
    s.anim.anim = *i;
  } else if (args.has("time")) {
    if (scene.animations.empty())
      return R::fail("--time " + args.get("time", "") + ": " + src + " has no animations (only its rest pose)");
    s.anim.anim = 0;
    notes.push_back("--time without --anim: using " + animText(scene, 0));
  }
  if (auto a = args.get("anim2")) {
    auto i = resolveIndex("anim2", *a, scene.animations.size(), animName, src + " (animations)");
    if (!i) return R::fail(i.error());
    s.anim.anim2 = *i;
  }
  if (args.has("time2") && s.anim.anim2 < 0) return R::fail("--time2 needs --anim2 (the animation it poses)");
  if (args.has("blend") && s.anim.anim2 < 0) return R::fail("--blend needs --anim2 (the animation to blend towards)");
  if (auto c = args.get("camera")) {
    auto camName = [&](size_t k) { return scene.cameras[k].name; };
    auto i = resolveIndex("camera", *c, scene.cameras.size(), camName, src + " (cameras)");
    if (!i) return R::fail(i.error());
    s.camera = *i;
  }
  if (s.anim.anim >= 0) {
    auto t = timeFor(args, "time", 0.0, scene, s.anim.anim, notes);
    if (!t) return R::fail(t.error());
    s.anim.time = *t;
  }
  if (s.anim.anim2 >= 0) {
    auto t = timeFor(args, "time2", args.real("time", 0.0, 0.0, 1e9, "a time in seconds"), scene, s.anim.anim2, notes);
    if (!t) return R::fail(t.error());
    s.anim.time2 = *t;
    s.anim.blend = float(args.real("blend", 0.5, 0.0, 1.0, "a weight"));
  }
  std::tie(s.width, s.height) = args.size("size", s.width, s.height);
  if (notesOut) notesOut->insert(notesOut->end(), notes.begin(), notes.end());
  return s;
}

Result<int> applyInstancesOption(const options::Args& args, Scene& scene, std::vector<std::string>* notes) {
  if (!args.has("instances")) return 1;
  const long n = args.integer("instances", 1, 1, kMaxInstances);
  if (scene.curved.space != Space::Euclidean)
    return Result<int>::fail("--instances " + std::to_string(n) + ": " + scene.source +
                             " is a curved-space scene (already drawn as instances of one triangle list)");
  const FileStats was = computeFileStats(scene);
  const long long total = (long long)std::max(1, was.instances + was.meshNodes - was.instancedNodes) * n;
  if (total > kMaxInstances * 16)
    return Result<int>::fail("--instances " + std::to_string(n) + ": " + scene.source + " would draw " +
                             std::to_string(total) + " instances; the limit is " + std::to_string(kMaxInstances * 16));
  const int before = was.instances;
  const int drawnOnce = addGridInstances(scene, int(n));
  if (notes && n > 1) {
    const FileStats f = computeFileStats(scene);
    notes->push_back("--instances " + std::to_string(n) + ": " + std::to_string(f.instancedNodes) +
                     " mesh node(s) drawn as " + std::to_string(f.instances) + " instances (" +
                     std::to_string(before) + " before), " + std::to_string(f.drawnVertices) + " vertices per frame" +
                     (drawnOnce ? "; " + std::to_string(drawnOnce) + " node(s) drawn once (skinned or Bezier patches)" : ""));
  }
  return int(n);
}

Result<SceneCommand> parseSceneCommand(const options::Args& args, const std::string& outputWhat) {
  using R = Result<SceneCommand>;
  if (!args.error().empty()) return R::fail(args.error());
  if (args.positional().size() != 1)
    return R::fail("expected one SCENE (a glTF file or a built-in scene name), got " +
                   std::to_string(args.positional().size()) +
                   (args.positional().empty() ? "" : ": " + joinNames(args.positional())));
  SceneCommand c;
  c.output = args.get("o", args.get("output", ""));
  if (c.output.empty()) return R::fail("missing -o " + outputWhat);
  if (Status gpu = applyGpuOption(args); !gpu) return R::fail(gpu.error());
  if (Status ok = checkSceneSpec(args.positional()[0]); !ok) return R::fail(ok.error());
  auto scene = loadScene(args.positional()[0]);
  if (!scene) return R::fail(scene.error());
  c.scene = scene.take();
  if (std::string why = whyNothingDrawn(c.scene); !why.empty())
    return R::fail(c.scene.source + ": nothing to draw: " + why);
  auto settings = frameSettingsFromArgs(args, c.scene, &c.notes);
  if (!settings) return R::fail(settings.error());
  c.settings = *settings;
  auto instances = applyInstancesOption(args, c.scene, &c.notes);
  if (!instances) return R::fail(instances.error());
  c.settings.instances = *instances;
  return c;
}

std::vector<std::string> describeFrame(const Scene& scene, const FrameSettings& s) {
  std::vector<std::string> lines;
  const size_t n = scene.animations.size();
  if (s.anim.anim >= 0) {
    lines.push_back(animText(scene, s.anim.anim) + " at t = " + seconds(s.anim.time));
  } else {
    lines.push_back(n == 0 ? "rest pose (the scene has no animations)"
                           : "rest pose (no --anim/--time; the scene has " + std::to_string(n) + " animation" +
                                 (n == 1 ? "" : "s") + ")");
  }
  if (s.anim.anim2 >= 0) {
    char w[32];
    std::snprintf(w, sizeof w, "%g", double(s.anim.blend));
    lines.push_back("blended towards " + animText(scene, s.anim.anim2) + " at t = " + seconds(s.anim.time2) +
                    ", weight " + w);
  }
  bool carried = false;
  for (const Node& node : scene.nodes) carried = carried || (s.camera >= 0 && node.camera == s.camera);
  if (s.camera < 0) {
    lines.push_back("camera: automatic framing of the posed scene (" + std::to_string(scene.cameras.size()) +
                    " glTF camera(s) in the file; --camera picks one)");
  } else {
    const Camera& c = scene.cameras[size_t(s.camera)];
    std::string line = "camera: glTF camera " + std::to_string(s.camera) + " '" + c.name + "' (" +
                       (c.perspective ? "perspective" : "orthographic, drawn as perspective") + ")";
    if (!carried) line += " is on no node: automatic framing instead";
    lines.push_back(line);
  }
  lines.push_back("size: " + std::to_string(s.width) + "x" + std::to_string(s.height));
  return lines;
}

int commandError(const char* command, const std::string& message) {
  std::fprintf(stderr, "motorbench %s: error: %s\n", command, message.c_str());
  return 2;
}

void commandNotes(const char* command, const std::vector<std::string>& lines) {
  for (const std::string& l : lines) std::fprintf(stderr, "motorbench %s: %s\n", command, l.c_str());
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace mb
