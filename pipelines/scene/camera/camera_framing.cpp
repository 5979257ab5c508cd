#include "pipelines/scene/camera/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <compare>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mb {
namespace {

constexpr float kAutoYfov = 0.8f;
constexpr float kAutoYaw = glm::radians(30.0f);    // towards +X
constexpr float kAutoPitch = glm::radians(20.0f);  // camera above, looking down
constexpr float kSkinPadding = 1.05f;              // other skinning methods may bulge out
constexpr float kFlatRatio = 0.1f;                 // smallest / largest extent of a flat scene
constexpr double kFrontShare = 0.1;                // net front area that picks a side (of the total)
constexpr double kFitMargin = 0.95;                // extreme points at 95% of the half-frame

glm::quat fixedDirection() {
  return glm::angleAxis(kAutoYaw, glm::vec3(0, 1, 0)) * glm::angleAxis(-kAutoPitch, glm::vec3(1, 0, 0));
}

// The turn taking +Z to `axis` (0 x, 1 y, 2 z), or to its negative: about +Y for a vertical
// plane's normal (world up kept), about +X for a horizontal one (+Y up becomes -Z from above,
// +Z from below).
glm::quat faceTurn(int axis, bool negative) {
  const float quarter = glm::radians(90.0f);
  if (axis == 2) return negative ? glm::angleAxis(2.0f * quarter, glm::vec3(0, 1, 0)) : glm::quat(1, 0, 0, 0);
  if (axis == 0) return glm::angleAxis(negative ? -quarter : quarter, glm::vec3(0, 1, 0));
  return glm::angleAxis(negative ? quarter : -quarter, glm::vec3(1, 0, 0));
}

// The fixed direction, or for a flat scene the fixed direction turned to face its front.
glm::quat fitOrientation(const PosedPoints& p) {
  const glm::vec3 extent = p.hi - p.lo;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (extent[k] < extent[axis]) axis = k;
  const float largest = std::max({extent.x, extent.y, extent.z});
  if (!(extent[axis] <= kFlatRatio * largest)) return fixedDirection();
  const bool backwards = p.frontArea[axis] < -kFrontShare * p.absoluteArea[axis];
  return faceTurn(axis, backwards) * fixedDirection();
}

// The points in camera axes (x right, y up, camera looking down -z) relative to their box's
// centre, grown by `grow` about it.
struct CameraAxes {
  glm::dmat3 toCamera;
  glm::dvec3 centre;
  double grow;
  glm::dvec3 operator()(glm::vec3 p) const { return toCamera * ((glm::dvec3(p) - centre) * grow); }
};

// A point's offset in the image with what breaks its ties (its coordinate, signed towards the
// side measured, then its depth), so that the extreme found is the same in any point order.
struct Extreme {
  double offset, c, depth;
  auto operator<=>(const Extreme&) const = default;
};

// The eye's offset along frame axis `axis` (0 x, 1 y) that centres the points in it, the eye's
// depth `eyeDepth` given: their largest offsets to either side in the image, max (c - e) / depth
// and max (e - c) / depth, made equal. Their difference falls strictly as e grows, so the root
// is bracketed by the points' extent and found by Newton steps on the two extreme points
// (exact once they are the right ones: both sides are piecewise linear), bisection when a step
// leaves the bracket.
double centredOffset(const PosedPoints& points, const CameraAxes& axes, int axis, double eyeDepth, double lo,
                     double hi) {
  double e = 0.5 * (lo + hi);
  for (int step = 0; step < 32; ++step) {
    const double none = -std::numeric_limits<double>::max();
    Extreme right{none, 0, 1}, left{none, 0, 1};
    for (const glm::vec3& p : points.points) {
      const glm::dvec3 q = axes(p);
      const double c = q[axis], depth = std::max(eyeDepth - q.z, 1e-12);
      right = std::max(right, Extreme{(c - e) / depth, c, depth});
      left = std::max(left, Extreme{(e - c) / depth, -c, depth});
    }
    if (right.offset == left.offset) break;
    (right.offset > left.offset ? lo : hi) = e;
    const double newton = (right.c * left.depth - left.c * right.depth) / (right.depth + left.depth);
    const double next = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    if (next == e) break;
    e = next;
  }
  return e;
}

}  // namespace

View sphereFraming(const PosedPoints& points, float aspect) {
  View view;
  view.aspect = aspect;
  glm::vec3 center = 0.5f * (points.lo + points.hi);
  float radius = 0.5f * glm::length(points.hi - points.lo) * (points.skinned ? kSkinPadding : 1.0f);
  if (!(radius > 1e-6f)) radius = 1.0f;
  view.yfov = kAutoYfov;
  float halfX = std::atan(std::tan(0.5f * kAutoYfov) * view.aspect);
  float half = std::min(0.5f * kAutoYfov, halfX);
  float distance = radius / std::sin(half);
  view.orientation = fixedDirection();
  view.eye = center + view.orientation * glm::vec3(0.0f, 0.0f, distance);
  view.znear = std::max(0.9f * (distance - radius), 1e-4f * distance);
  view.zfar = 1.1f * (distance + radius);
  return view;
}

// For each point (x, y, z) and an eye at (ex, ey, ez), inside the frame means
// |x - ex| <= tX (ez - z) and |y - ey| <= tY (ez - z), i.e. x + tX z <= ex + tX ez and
// tX z - x <= tX ez - ex. With A = max(x + tX z) and B = max(tX z - x), the nearest eye that
// holds them has ez = (A + B) / (2 tX) and ex = (A - B) / 2, both x constraints then met with
// equality (points on both edges); the same for y, and ez the larger of the two. The other
// axis is then centred (centredOffset).
View fitFraming(const PosedPoints& points, float aspect) {
  const glm::vec3 extent = points.hi - points.lo;
  if (!(std::max({extent.x, extent.y, extent.z}) > 1e-6f)) return sphereFraming(points, aspect);
  View view;
  view.aspect = aspect;
  view.yfov = kAutoYfov;
  view.orientation = fitOrientation(points);
  const CameraAxes axes{glm::transpose(glm::dmat3(glm::mat3_cast(view.orientation))),
                        0.5 * (glm::dvec3(points.lo) + glm::dvec3(points.hi)), points.skinned ? kSkinPadding : 1.0};
  const double tY = std::tan(0.5 * double(kAutoYfov)) * kFitMargin, tX = tY * double(aspect);
  const double lowest = -std::numeric_limits<double>::max();
  double a = lowest, b = lowest, c = lowest, d = lowest;
  for (const glm::vec3& p : points.points) {
    const glm::dvec3 q = axes(p);
    a = std::max(a, q.x + tX * q.z), b = std::max(b, tX * q.z - q.x);
    c = std::max(c, q.y + tY * q.z), d = std::max(d, tY * q.z - q.y);
  }
  const double depthX = (a + b) / (2.0 * tX), depthY = (c + d) / (2.0 * tY);
  glm::dvec3 eye(0.5 * (a - b), 0.5 * (c - d), std::max(depthX, depthY));
  const int loose = depthX < depthY ? 0 : 1;
  if (depthX != depthY) {
    // No point is farther from the box's centre than the grown box's diagonal: a bracket.
    const double reach = axes.grow * glm::length(glm::dvec3(points.hi) - glm::dvec3(points.lo));
    eye[loose] = centredOffset(points, axes, loose, eye.z, -reach, reach);
  }
  double nearest = std::numeric_limits<double>::max(), farthest = 0.0;
  for (const glm::vec3& p : points.points) {
    const double depth = eye.z - axes(p).z;
    nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
  }
  if (!(farthest > 0.0) || !std::isfinite(farthest)) return sphereFraming(points, aspect);
  view.eye = glm::vec3(axes.centre + glm::transpose(axes.toCamera) * eye);
  view.znear = float(std::max(0.9 * nearest, 1e-4 * farthest));
  view.zfar = float(1.1 * farthest);
  return view;
}

}  // namespace mb
