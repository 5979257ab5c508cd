// motorbench survey FILE [--size WxH] [--pipelines A,B,...] [--gpu ...] [-o out.json]: one file,
// loaded once, drawn by every pipeline of its space on one GL context, at rest and (animated
// files) at 1/3 and 2/3 of animation 0; one JSON document with per pipeline and frame the drawn
// pixels, the image metrics against the space's matrix baseline, the fallback counters, the
// 16-byte pipelines' position bound and seconds. The worker of scripts/corpus-check.sh: it
// judges nothing (the script applies the rules); exit 0 drawn or nothing to draw, 2 an error.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <glm/glm.hpp>

#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/options/args.h"
#include "harness/render/counter_glossary.h"
#include "harness/render/gpu_option.h"
#include "harness/render/image_metrics.h"
#include "harness/render/render_frame.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/camera_rule.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"
#include "pipelines/scene/transform.h"

namespace mb {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The pipelines whose positions are int16 in each primitive's bounding cube (pipelines/compact).
bool isCompact(const std::string& p) { return p == "matrix_c" || p == "motor_c" || p == "motor_cf"; }

// A frame draws a skinned primitive: a reachable node with a skin and a mesh primitive with joints.
bool drawsSkinned(const Scene& scene) {
  for (int n : nodesInDrawOrder(scene)) {
    const Node& node = scene.nodes[size_t(n)];
    if (node.skin < 0 || node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives)
      if (!p.joints.empty()) return true;
  }
  return false;
}

// Largest singular value of the linear part of `m`: sqrt of the largest eigenvalue of A^T A,
// closed form for a symmetric 3x3 (the trigonometric solution of its characteristic cubic).
double spectralNorm(const glm::dmat3& a) {
  const glm::dmat3 s = glm::transpose(a) * a;
  const double p1 = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
  const double q = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  if (p1 == 0.0) return std::sqrt(std::max({s[0][0], s[1][1], s[2][2]}));
  const double p2 = (s[0][0] - q) * (s[0][0] - q) + (s[1][1] - q) * (s[1][1] - q) + (s[2][2] - q) * (s[2][2] - q) + 2 * p1;
  const double p = std::sqrt(p2 / 6.0);
  const glm::dmat3 b = (1.0 / p) * (s - q * glm::dmat3(1.0));
  const double r = std::clamp(glm::determinant(b) / 2.0, -1.0, 1.0);
  return std::sqrt(std::max(0.0, q + 2.0 * p * std::cos(std::acos(r) / 3.0)));
}

// The 16-byte pipelines' position error, as a bound in world units and in pixels, for a rigid
// frame (posed by `anim`, framed by `view`, `height` pixels tall). A position is int16 SNORM in
// its primitive's bounding cube (center, half extent h = the largest half side): each axis is off
// by at most h/2/32767, the vector by at most sqrt(3)/2 h/32767 < h/32767 = eps (local units).
// World: eps times the largest singular value of the draw's world (x instance) linear part.
// Pixels: a world displacement d at camera depth z >= zmin moves the projection by at most
// |d| sqrt(1 + u^2 + v^2) / z in tangent units (u, v the on-screen tangents, at most the frustum's
// half-angle tangents; the norm of the projection's Jacobian), times H/2 / tan(yfov/2) pixels.
// zmin: the depth of the cube's world bounding sphere, never nearer than znear (nothing nearer is
// drawn). Envelope radius: a sample at a pixel centre sees the surface point that the baseline
// draws at most `pixels` away, i.e. in the pixel round(pixels) away; +1 so that the value lies
// between the baseline's neighbouring samples (the comparison takes their min..max).
struct PositionBound {
  double world = 0, pixels = 0;
  int radius = 1;
};
PositionBound positionBound(const Scene& scene, const AnimState& anim, const View& view, int width, int height) {
  PositionBound b;
  const std::vector<glm::mat4> world = worldMatrices(scene, samplePose(scene, anim));
  const glm::dmat4 toCamera = glm::inverse(glm::dmat4(trsMatrix(TRS{view.eye, view.orientation, glm::vec3(1.0f)})));
  const double tanY = std::tan(double(view.yfov) / 2), tanX = tanY * double(width) / double(height);
  const double slope = std::sqrt(1 + tanX * tanX + tanY * tanY), focal = 0.5 * height / tanY;
  for (int n : nodesInDrawOrder(scene)) {
    const Node& node = scene.nodes[size_t(n)];
    if (node.mesh < 0 || size_t(node.mesh) >= scene.meshes.size()) continue;
    std::vector<glm::dmat4> draws;
    if (node.instances.empty()) draws.push_back(glm::dmat4(world[size_t(n)]));
    for (const TRS& i : node.instances) draws.push_back(glm::dmat4(world[size_t(n)]) * glm::dmat4(trsMatrix(i)));
    for (const Primitive& p : scene.meshes[size_t(node.mesh)].primitives) {
      if (p.positions.empty()) continue;
      glm::dvec3 lo(p.positions.front()), hi = lo;
      for (const glm::vec3& v : p.positions) lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
      const glm::dvec3 half = 0.5 * (hi - lo), centre = 0.5 * (lo + hi);
      double h = std::max({half.x, half.y, half.z});
      if (!(h > 0)) h = 1;  // one point: the pipelines quantise in a unit cube
      for (const glm::dmat4& m : draws) {
        const double sigma = spectralNorm(glm::dmat3(m));
        const double eps = h / 32767.0 * sigma;
        const double depth = -(toCamera * m * glm::dvec4(centre, 1.0)).z - std::sqrt(3.0) * h * sigma;
        const double z = std::max(depth, double(view.znear));
        b.world = std::max(b.world, eps);
        b.pixels = std::max(b.pixels, eps * slope / z * focal);
      }
    }
  }
  b.radius = int(std::lround(b.pixels)) + 1;
  return b;
}

// Per pixel of `a`, how far (bytes) its farthest channel lies outside the min..max of that channel
// over the (2r+1)^2 neighbourhood of the same pixel in `b` (0 inside): what a displacement of at
// most r pixels cannot explain. `over` counts the pixels beyond `tolerance`; `worst` the largest.
struct Envelope {
  int64_t over = 0;
  int worst = 0;
};
Envelope envelope(const RgbaImage& a, const RgbaImage& b, int r, int tolerance) {
  Envelope e;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      int excess = 0;
      for (int c = 0; c < 3; ++c) {
        int lo = 255, hi = 0;
        for (int yy = std::max(0, y - r); yy <= std::min(b.height - 1, y + r); ++yy)
          for (int xx = std::max(0, x - r); xx <= std::min(b.width - 1, x + r); ++xx) {
            const int v = b.rgba[(size_t(yy) * size_t(b.width) + size_t(xx)) * 4 + size_t(c)];
            lo = std::min(lo, v), hi = std::max(hi, v);
          }
        const int v = a.rgba[(size_t(y) * size_t(a.width) + size_t(x)) * 4 + size_t(c)];
        excess = std::max({excess, lo - v, v - hi});
      }
      e.over += excess > tolerance;
      e.worst = std::max(e.worst, excess);
    }
  return e;
}

// The shading change the envelope allows, in byte steps: the 16-byte vertex also quantises the
// frame (10-bit codes) and uv (half floats), which the position bound does not cover; 4 steps is
// the diff heat map's "red" stop (image_metrics.h), fixed before any corpus run.
constexpr int kShadeTolerance = 4;

json fallbackJson(const PipelineStats& s) {
  return {{"nonUniformScaleNodes", s.nonUniformScaleNodes}, {"negativeScaleNodes", s.negativeScaleNodes},
          {"shearMatrixNodes", s.shearMatrixNodes}, {"zeroScalarFrames", s.zeroScalarFrames},
          {"biasedFrames", s.biasedFrames}, {"scaleFallbackInstances", s.scaleFallbackInstances},
          {"rotorSplitVertices", s.rotorSplitVertices}, {"rotorUnresolvedTriangles", s.rotorUnresolvedTriangles},
          {"linearFallbackDraws", s.linearFallbackDraws}, {"skinFallbackDraws", s.skinFallbackDraws},
          {"skinFallbackJoints", s.skinFallbackJoints}, {"fallbackVertices", s.fallbackVertices}};
}

// Per counter, the largest value over the frames (each counts "the last render()").
void keepMax(json& into, const json& from) {
  for (auto it = from.begin(); it != from.end(); ++it)
    if (!into.contains(it.key()) || into[it.key()].get<double>() < it.value().get<double>()) into[it.key()] = it.value();
}

struct Shot {
  int anim;
  float time;
};

int runSurvey(const std::vector<std::string>& argv) {
  auto fail = [](const std::string& message) { return commandError("survey", message); };
  Args args(argv, OptionSpec{{"size", "pipelines", "gpu", "o", "output", "images"}, {}, {}, {}});
  if (!args.error().empty()) return fail(args.error());
  if (args.positional().size() != 1) return fail("expected one SCENE (a .gltf/.glb file or a built-in name)");
  const std::string spec = args.positional()[0];
  const std::string out = args.get("o", args.get("output", ""));
  const auto [width, height] = args.size("size", 128, 128);
  if (Status ok = applyGpuOption(args); !ok) return fail(ok.error());
  if (args.has("pipelines"))
    if (Status ok = checkPipelineNames("--pipelines", splitList(args.get("pipelines", ""))); !ok) return fail(ok.error());
  if (Status ok = checkSceneSpec(spec); !ok) return fail(ok.error());

  json doc = {{"file", spec}, {"status", "error"}, {"error", nullptr}, {"size", {width, height}}};
  // Every outcome is written (stdout or -o) before the exit code says it.
  auto finish = [&](int code) {
    const std::string text = doc.dump(1) + "\n";
    if (out.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
    else if (Status w = writeTextFile(out, text); !w) return fail(w.error());
    return code;
  };
  const auto t0 = Clock::now();
  auto loaded = loadScene(spec);
  doc["loadSeconds"] = secondsSince(t0);
  if (!loaded) {
    doc["status"] = "load-failed";
    doc["error"] = loaded.error();
    commandNotes("survey", {"error: " + loaded.error()});
    return finish(2);
  }
  const Scene& scene = *loaded;
  doc["loaderFallbacks"] = loaderFallbackJson(scene);
  const FileStats fs = computeFileStats(scene);
  doc["scene"] = {{"meshes", scene.meshes.size()}, {"primitives", fs.primitives}, {"skinnedPrimitives", fs.skinnedPrimitives},
                  {"animations", scene.animations.size()}};
  if (std::string why = whyNothingDrawn(scene); !why.empty()) {
    doc["status"] = "no-data";
    doc["error"] = "nothing to draw: " + why;
    return finish(0);
  }
  std::vector<std::string> pipelines =
      args.has("pipelines") ? splitList(args.get("pipelines", "")) : pipelineNames(scene.curved.space);
  const std::string baseline = pipelineNames(scene.curved.space).front();
  if (std::find(pipelines.begin(), pipelines.end(), baseline) == pipelines.end()) pipelines.insert(pipelines.begin(), baseline);
  doc["baseline"] = baseline;
  doc["pipelineOrder"] = pipelines;

  // Rest pose, then animation 0 at 1/3 and 2/3 of its duration (its end often equals its start).
  std::vector<Shot> shots = {{-1, 0.0f}};
  if (!scene.animations.empty() && scene.animations[0].duration > 0.0f)
    for (float f : {1.0f / 3.0f, 2.0f / 3.0f}) shots.push_back({0, f * scene.animations[0].duration});
  const bool skinned = drawsSkinned(scene);
  json frames = json::array();
  std::vector<FrameSettings> settings;
  for (const Shot& s : shots) {
    FrameSettings f;
    f.width = width, f.height = height;
    f.anim.anim = s.anim, f.anim.time = s.time;
    settings.push_back(f);
    json fr = {{"animation", s.anim < 0 ? json(nullptr) : json(s.anim)}, {"time", s.time}, {"kind", skinned ? "skinned" : "rigid"}};
    if (!skinned) {  // the bound is judged on rigid frames only (skinned frames: drawn pixels)
      const View view = frameScene(scene, f.anim, float(width) / float(height));
      const PositionBound b = positionBound(scene, f.anim, view, width, height);
      fr["positionBound"] = {{"worldUnits", b.world}, {"pixels", b.pixels}, {"envelopeRadius", b.radius},
                             {"shadeTolerance", kShadeTolerance}};
      fr["view"] = toJson(view);  // the framing the pixel bound was projected with
    }
    frames.push_back(fr);
  }
  doc["frames"] = frames;

  std::vector<RgbaImage> base;  // the baseline's images, one per shot
  json results = json::object();
  bool anyError = false;
  for (const std::string& name : pipelines) {
    const auto tp = Clock::now();
    json r = {{"error", nullptr}, {"frames", json::array()}, {"fallbacks", json::object()}};
    for (size_t k = 0; k < settings.size(); ++k) {
      auto frame = renderFrame(scene, name, settings[k]);
      if (!frame) {
        r["error"] = frame.error();
        commandNotes("survey", {"error: " + frame.error()});
        anyError = true;
        break;
      }
      if (name == baseline) base.push_back(frame->image);
      if (args.has("images")) {  // for a person looking into a row: DIR/<pipeline>_<frame>.png
        const std::string png = args.get("images", ".") + "/" + name + "_" + std::to_string(k) + ".png";
        if (Status w = writeImage(png, frame->image); !w) commandNotes("survey", {"error: " + w.error()});
      }
      json f = {{"drawnPixels", drawnPixels(frame->image)}};
      if (k < base.size() && name != baseline) {
        auto m = compareImages(base[k], frame->image);
        if (m) {
          f["identical"] = m->rmse == 0.0;
          f["psnr"] = m->rmse == 0.0 ? json(nullptr) : json(m->psnr);
          f["maxError"] = m->maxError;
        }
        if (isCompact(name) && frames[k].contains("positionBound")) {
          const int radius = frames[k]["positionBound"]["envelopeRadius"].get<int>();
          // Both ways: a pixel of either image its counterpart's neighbourhood cannot explain.
          const Envelope e1 = envelope(frame->image, base[k], radius, kShadeTolerance),
                         e2 = envelope(base[k], frame->image, radius, kShadeTolerance);
          f["outsideEnvelope"] = std::max(e1.over, e2.over);
          f["envelopeExcess"] = std::max(e1.worst, e2.worst);  // bytes beyond the neighbourhood
        }
      }
      json fb = fallbackJson(frame->stats), nonzero = json::object();
      for (auto it = fb.begin(); it != fb.end(); ++it)
        if (it.value().get<double>() != 0) nonzero[it.key()] = it.value();
      f["fallbacks"] = nonzero;  // per frame the non-zero counters; the pipeline's maxima list all
      f["draws"] = frame->stats.draws;
      keepMax(r["fallbacks"], fb);
      r["frames"].push_back(f);
      if (k == 0) doc["gl"] = describeGl(frame->gl);
    }
    r["seconds"] = secondsSince(tp);
    results[name] = r;
  }
  doc["pipelines"] = results;
  doc["status"] = anyError ? "error" : "ok";
  doc["seconds"] = secondsSince(t0);
  return finish(anyError ? 2 : 0);
}

}  // namespace
}  // namespace mb

MB_COMMAND(survey, "survey",
           "SCENE [--size WxH (default 128x128)] [--pipelines A,B,...] [--gpu auto|llvmpipe|N] [--images DIR] [-o out.json]",
           "draw one file with every pipeline of its space at rest and two animation times; print one JSON "
           "document (drawn pixels, metrics against matrix, fallbacks, the 16-byte position bound, seconds): "
           "the worker of scripts/corpus-check.sh",
           mb::runSurvey);
MB_COMMAND_HELP(survey, "survey",
               "  SCENE              a .gltf/.glb file or a built-in scene name\n"
               "  --size WxH         image size (default 128x128)\n"
               "  --pipelines A,...  the pipelines (default: every one of the scene's space; its matrix baseline is always drawn)\n"
               "  -o, --output FILE  the JSON document (default: stdout)\n"
               "  --images DIR       also write every frame as DIR/<pipeline>_<frame>.png (DIR must exist)\n"
               "  Exit 0: drawn (or nothing to draw: status no-data), 2: the file did not load or a pipeline failed (reasons in the JSON).\n",
               "motorbench survey skinned_tube --size 96x96 -o out/tube.json", true);
