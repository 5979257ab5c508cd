#include "harness/cli/survey_probe.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>

#include <glm/glm.hpp>

#include "harness/render/render_frame.h"
#include "harness/render/rounding_magnitude.h"
#include "pipelines/compact/compact_encoding.h"
#include "pipelines/gl/context.h"
#include "pipelines/gl/framebuffer.h"
#include "pipelines/pipeline.h"
#include "pipelines/scene/drawable.h"
#include "pipelines/scene/transform.h"

namespace mb::survey {

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
        const double sigma = largestSingularValue(glm::dmat3(m));
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
// `ties` (a tie mask, or null): `overNotTies` and `worstNotTies` the same over the non-tie pixels.
Envelope envelope(const RgbaImage& a, const RgbaImage& b, int r, int tolerance, const std::vector<uint8_t>* ties) {
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
      if (!ties || !(*ties)[size_t(y) * size_t(a.width) + size_t(x)]) {
        e.overNotTies += excess > tolerance;
        e.worstNotTies = std::max(e.worstNotTies, excess);
      }
    }
  return e;
}

namespace {

// Tie pixels: the pixels of a frame that the transform does not determine. Coplanar surfaces
// (z-fighting: a court's painted lines on its floor) and pixel centres on a shared edge are
// resolved by the rasteriser from the last bits of the transformed positions, so any other
// correct rounding of the same transform (motor vs matrix) flips some of them. The probe: the
// baseline draws each frame again from the scene with every vertex position moved by a
// pseudo-random amount of at most kTieJitter times its primitive's rounding magnitude (per vertex
// and axis, fixed per file), in antithetic pairs (+j, -j: a tie the jitter reaches flips in one of
// the two), probe.pairs pair(s); a pixel whose RGB differs from the baseline's image in any of
// them is a tie pixel. The camera is the baseline's (framed on the unjittered scene). Why the
// vertices and not the view: moving the eye or nudging the projection moves coplanar surfaces
// together and leaves z-fights as they were (court.glb: 48 eye shifts of 1e-6 of the radius in 24
// directions left 3 of motor's line pixels out, 1e-5 still one), while a pipeline's rounding
// differs per vertex. Why the rounding magnitude (harness/render/rounding_magnitude.h: the largest
// of the primitive's own, world and view-space coordinates, in its units) and not the primitive's
// own coordinates: the pipelines round the world and view coordinates too, so they differ by ulps
// of those, a multiple of the primitive's own for a small mesh away from the origin or the camera
// (hello-fragments.glb: cells 0.1 across seen from 2.5 away; scaled by the primitive's own
// coordinates the jitter moves its vertices 9 times less than motor and matrix differ and leaves
// out 4 pixels motor flips, on a silhouette edge and on coincident primitives: 44.4 dB). Why
// 2^-20: it is 8 to 16 float32 ulps of that magnitude, more than the rounding of the chained
// multiply-adds by which two correct float pipelines differ (rounding_magnitude.h: matrix and
// motor vertices up to 6.4 units of roundoff of it apart; court.glb: 62 tie pixels, motor 65.6 dB
// outside them); for a primitive around its origin it is 30 times below the 16-byte pipelines'
// int16 step (h / 32767), and it moves a vertex by at most 2^-20 sqrt(3) (m / z) (H / 2) /
// tan(yfov / 2) (1 + tx^2 + ty^2)^(1/2) pixels (m the magnitude in world units, z the depth),
// 3e-4 at 128 px where the view coordinates are the largest: orders of magnitude below any
// transform error the rules are there to catch (a wrong sign, a dropped scale, a rotor off by
// 1e-4 all move pixels by 0.01 px and more). normal_torus, with no coplanar surfaces, gets 17 tie
// pixels (README: Corpus check).
// kFloatTies, one pair: two more matrix draws (and prepares) per frame. Missing a tie only makes the rules
// stricter; a second pair would find more at twice the cost (court.glb, jittered at its
// primitives' own scale: motor 54 dB outside the ties with one pair, 66 dB with two).
constexpr double kTieJitter = kFloatTieJitter;

// A uniform value in [-1, 1] from (pair, primitive, vertex, axis): splitmix64, fixed for a file.
double jitterValue(uint64_t pair, uint64_t prim, uint64_t vertex, uint64_t axis) {
  uint64_t z = (pair * 0x9E3779B97F4A7C15ull) ^ (prim * 0xC2B2AE3D27D4EB4Full) ^ (vertex * 4 + axis);
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return double(z >> 11) / double(1ull << 52) - 1.0;
}

}  // namespace

// 1 per pixel that differs (any RGB channel) between `a` and `b`, same size.
std::vector<uint8_t> differingMask(const RgbaImage& a, const RgbaImage& b) {
  std::vector<uint8_t> m(size_t(a.width) * size_t(a.height), 0);
  for (size_t i = 0; i < m.size(); ++i)
    for (size_t c = 0; c < 3; ++c) m[i] |= a.rgba[i * 4 + c] != b.rgba[i * 4 + c];
  return m;
}

namespace {

// The largest move of a coordinate of the primitive whose positions are `from` (TieJitter);
// `rounding`: its rounding magnitude (roundingMagnitudes).
double jitterAmplitude(const std::vector<glm::vec3>& from, double rounding, TieJitter jitter) {
  if (from.empty()) return 0;
  if (jitter == TieJitter::FloatRounding) return kTieJitter * rounding;
  glm::dvec3 lo(from.front()), hi = lo;  // the bounding cube the 16-byte pipelines quantise in
  for (const glm::vec3& v : from) lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
  double h = 0.5 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(h > 0)) h = 1;
  return 0.5 * h / 32767.0;
}

}  // namespace

int tieRenders(TieProbe probe) { return 2 * probe.pairs + (probe.jitter == TieJitter::Int16Cell ? 1 : 0); }

// The tie masks of every shot: the baseline pipeline drawn from the scene with probe.pairs x 2
// jitters of its positions (each prepared once, posed and drawn per shot) against `base`, its
// images of the scene. The positions are jittered in place (a copy would copy every texture)
// and restored before it returns, whatever happens.
Result<std::vector<std::vector<uint8_t>>> tieMasks(Scene& scene, const std::string& baseline,
                                                   const std::vector<FrameSettings>& settings,
                                                   const std::vector<RgbaImage>& base, TieProbe probe) {
  using R = Result<std::vector<std::vector<uint8_t>>>;
  const std::string where = scene.source + " [" + baseline + ", tie probe]: ";
  std::vector<std::vector<uint8_t>> masks;
  for (const FrameSettings& f : settings) masks.emplace_back(size_t(f.width) * size_t(f.height), 0);
  try {
    auto ctx = gl::sharedContext();
    if (!ctx) return R::fail(where + ctx.error());
    const std::vector<View> views = framings(scene, settings);  // the unjittered scene's: the baseline's camera
    std::vector<std::vector<glm::vec3>> original;
    for (const Mesh& mesh : scene.meshes)
      for (const Primitive& prim : mesh.primitives) original.push_back(prim.positions);
    struct Restore {
      Scene& scene;
      std::vector<std::vector<glm::vec3>>& original;
      ~Restore() {
        size_t n = 0;
        for (Mesh& mesh : scene.meshes)
          for (Primitive& prim : mesh.primitives) prim.positions = std::move(original[n++]);
      }
    } restore{scene, original};
    std::vector<AnimState> poses;  // the rounding magnitudes of the unjittered scene, every frame
    for (const FrameSettings& f : settings) poses.push_back(f.anim);
    const std::vector<double> rounding = probe.jitter == TieJitter::FloatRounding
                                             ? roundingMagnitudes(scene, poses, views)
                                             : std::vector<double>(original.size(), 0.0);
    for (int render = 0; render < tieRenders(probe); ++render) {
      const double sign = render % 2 ? -1.0 : 1.0;  // antithetic: +j, then -j
      const bool rounded = render == 2 * probe.pairs;  // Int16Cell's last render: the int16 grid itself
      size_t n = 0;
      for (size_t m = 0; m < scene.meshes.size(); ++m)
        for (size_t q = 0; q < scene.meshes[m].primitives.size(); ++q) {
          const std::vector<glm::vec3>& from = original[n++];
          std::vector<glm::vec3>& to = scene.meshes[m].primitives[q].positions;
          if (rounded) {
            const compact::PositionCube cube = compact::positionCube(from);
            for (size_t i = 0; i < from.size(); ++i) {
              int16_t code[4];
              compact::quantizePosition(from[i], cube, code);
              to[i] = compact::dequantizePosition(code, cube);
            }
            continue;
          }
          const double amplitude = jitterAmplitude(from, rounding[n - 1], probe.jitter);
          const uint64_t prim = uint64_t(m) << 20 | uint64_t(q);
          for (size_t i = 0; i < from.size(); ++i)
            for (int c = 0; c < 3; ++c) {
              double u = jitterValue(uint64_t(render / 2), prim, i, uint64_t(c));
              if (probe.jitter == TieJitter::Int16Cell) u = u < 0 ? -1.0 : 1.0;  // a corner of the cell
              to[i][c] = float(double(from[i][c]) + sign * amplitude * u);
            }
        }
      auto images = drawFromViews(scene, baseline, settings, views);
      if (!images) return R::fail(where + images.error());
      for (size_t k = 0; k < settings.size(); ++k) {
        const std::vector<uint8_t> d = differingMask(base[k], (*images)[k]);
        for (size_t i = 0; i < d.size(); ++i) masks[k][i] |= d[i];
      }
    }
    return masks;
  } catch (const std::exception& e) {
    return R::fail(where + "internal error (exception): " + e.what());
  }
}


}  // namespace mb::survey
