// The automatic camera on files (Framing::Fit, pipelines/scene/camera_rule.h) and orthographic
// glTF cameras, rendered: drawn pixels against the area of the model's outline projected by
// GLM (glm::perspective / glm::ortho of the View, independent of the pipelines' own
// projections), and against pixel extents derived by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "harness/render/render_frame.h"
#include "pipelines/scene/loader.h"
#include "tests/support/scene_test_gltf.h"

using namespace mb;

namespace {

constexpr int kFloat = 5126, kUint16 = 5123;

// A glTF document with one mesh (`positions`, `indices`) on node 0 and its flat normals; the
// default material (single-sided).
mbtest::TestGltf meshDocument(const std::vector<glm::vec3>& positions, const std::vector<uint16_t>& indices) {
  mbtest::TestGltf g;
  std::vector<float> xyz, normals;
  std::vector<glm::vec3> n(positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3 a = positions[indices[t]], b = positions[indices[t + 1]], c = positions[indices[t + 2]];
    for (size_t k = 0; k < 3; ++k) n[indices[t + k]] = glm::normalize(glm::cross(b - a, c - a));
  }
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (size_t i = 0; i < positions.size(); ++i) {
    xyz.insert(xyz.end(), {positions[i].x, positions[i].y, positions[i].z});
    normals.insert(normals.end(), {n[i].x, n[i].y, n[i].z});
    lo = glm::min(lo, positions[i]), hi = glm::max(hi, positions[i]);
  }
  const int pos = g.accessor(g.viewOf(xyz), kFloat, positions.size(), "VEC3");
  g.doc["accessors"][size_t(pos)]["min"] = {lo.x, lo.y, lo.z};
  g.doc["accessors"][size_t(pos)]["max"] = {hi.x, hi.y, hi.z};
  const int nrm = g.accessor(g.viewOf(normals), kFloat, positions.size(), "VEC3");
  const int idx = g.accessor(g.viewOf(indices), kUint16, indices.size(), "SCALAR");
  g.meshPrimitive({{"POSITION", pos}, {"NORMAL", nrm}}, idx);
  return g;
}

Scene load(const mbtest::TestGltf& g, const std::string& name) {
  auto s = loadGltfMemory(g.glb(), name);
  EXPECT_TRUE(s) << s.error();
  return s ? s.take() : Scene{};
}

// The unit square centred on the origin in the plane across `axis` (0 x, 1 y, 2 z), wound so
// that its front faces +axis (facing > 0) or -axis.
std::vector<glm::vec3> squareCorners(int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // (u, v, axis) right-handed
  std::vector<glm::vec3> out;
  for (glm::vec2 c : {glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)}) {
    glm::vec3 p(0.0f);
    p[u] = c.x, p[v] = c.y;
    out.push_back(p);
  }
  return out;  // counter-clockwise seen from +axis
}

Scene squareScene(int axis, int facing) {
  const std::vector<uint16_t> indices = facing > 0 ? std::vector<uint16_t>{0, 1, 2, 0, 2, 3}
                                                   : std::vector<uint16_t>{0, 2, 1, 0, 3, 2};
  return load(meshDocument(squareCorners(axis), indices), "square.glb");
}

// A closed unit cube, outward faces.
Scene cubeScene() {
  std::vector<glm::vec3> positions;
  std::vector<uint16_t> indices;
  for (int axis = 0; axis < 3; ++axis)
    for (int facing : {1, -1}) {
      const uint16_t base = uint16_t(positions.size());
      for (glm::vec3 p : squareCorners(axis)) {
        p[axis] = 0.5f * float(facing);
        positions.push_back(p);
      }
      const std::vector<uint16_t> face = facing > 0 ? std::vector<uint16_t>{0, 1, 2, 0, 2, 3}
                                                    : std::vector<uint16_t>{0, 2, 1, 0, 3, 2};
      for (uint16_t i : face) indices.push_back(uint16_t(base + i));
    }
  return load(meshDocument(positions, indices), "cube.glb");
}

Frame render(const Scene& scene, const std::string& pipeline, int width, int height, int camera = -1) {
  FrameSettings settings;
  settings.width = width, settings.height = height, settings.camera = camera;
  auto f = renderFrame(scene, pipeline, settings);
  EXPECT_TRUE(f) << f.error();
  return f ? *f : Frame{};
}

// `points` in pixels (x right, y up) through the View, by GLM.
std::vector<glm::dvec2> toPixels(const View& v, const std::vector<glm::vec3>& points, int width, int height) {
  const glm::mat4 view = glm::inverse(glm::translate(glm::mat4(1.0f), v.eye) * glm::mat4_cast(v.orientation));
  const float halfWidth = v.ymag * v.aspect;
  const glm::mat4 proj = v.orthographic ? glm::ortho(-halfWidth, halfWidth, -v.ymag, v.ymag, v.znear, v.zfar)
                                        : glm::perspective(v.yfov, v.aspect, v.znear, v.zfar);
  std::vector<glm::dvec2> out;
  for (glm::vec3 p : points) {
    const glm::vec4 c = proj * view * glm::vec4(p, 1.0f);
    out.push_back({(c.x / c.w + 1.0) * 0.5 * width, (c.y / c.w + 1.0) * 0.5 * height});
  }
  return out;
}

// Convex hull (monotone chain), counter-clockwise.
std::vector<glm::dvec2> hull(std::vector<glm::dvec2> p) {
  std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::dvec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); h[k++] = p[i++])
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0; h[k++] = p[i])
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
  h.resize(k - 1);
  return h;
}

struct Outline {
  double area = 0, perimeter = 0;
};

Outline outline(const std::vector<glm::dvec2>& polygon) {
  Outline o;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    o.area += 0.5 * (a.x * b.y - b.x * a.y);
    o.perimeter += glm::length(b - a);
  }
  o.area = std::abs(o.area);
  return o;
}

// Drawn pixels match the outline's area to within half a pixel along its perimeter (the pixels
// the edges cut).
void expectCovers(const Frame& f, const Outline& o) {
  EXPECT_NEAR(double(drawnPixels(f.image)), o.area, 0.5 * o.perimeter + 4.0);
}

}  // namespace

// A flat square in each axis plane, facing either way (single-sided): seen from its front as the
// fixed direction sees a square facing +Z, so all six draw the same outline, most of a square
// frame (61 %: GLM's projection of the corners); the fixed direction alone (Framing::BoundingSphere)
// sees the back of the one facing -Z and draws nothing.
TEST(CameraFraming, SquareInEachAxisPlaneFillsMostOfTheFrameFromItsFront) {
  constexpr int kSize = 96;
  std::vector<double> fractions;
  for (int axis = 0; axis < 3; ++axis)
    for (int facing : {1, -1}) {
      SCOPED_TRACE("axis " + std::to_string(axis) + " facing " + std::to_string(facing));
      const Scene scene = squareScene(axis, facing);
      ASSERT_EQ(scene.framing, Framing::Fit) << "a file gets the fitted framing";
      for (const char* pipeline : {"matrix", "motor"}) {
        SCOPED_TRACE(pipeline);
        const Frame f = render(scene, pipeline, kSize, kSize);
        const Outline o = outline(toPixels(f.view, squareCorners(axis), kSize, kSize));
        expectCovers(f, o);
        fractions.push_back(double(drawnPixels(f.image)) / (kSize * kSize));
        EXPECT_GT(fractions.back(), 0.5);
      }
    }
  const auto [lo, hi] = std::minmax_element(fractions.begin(), fractions.end());
  EXPECT_LT(*hi - *lo, 0.01) << "the six squares are seen alike";
  Scene behind = squareScene(2, -1);
  behind.framing = Framing::BoundingSphere;
  EXPECT_EQ(drawnPixels(render(behind, "matrix", kSize, kSize).image), 0);
}

// A closed cube: its silhouette (the hull of its projected corners) fills 66 % of a square
// frame fitted, 48 % framed by its bounding sphere.
TEST(CameraFraming, CubeFillsMostOfTheFrame) {
  constexpr int kSize = 96;
  std::vector<glm::vec3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back({i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f});
  Scene scene = cubeScene();
  for (Framing framing : {Framing::Fit, Framing::BoundingSphere}) {
    scene.framing = framing;
    const Frame f = render(scene, "matrix", kSize, kSize);
    const Outline o = outline(hull(toPixels(f.view, corners, kSize, kSize)));
    expectCovers(f, o);
    const double fraction = double(drawnPixels(f.image)) / (kSize * kSize);
    if (framing == Framing::Fit) {
      EXPECT_GT(fraction, 0.6);
    } else {
      EXPECT_LT(fraction, 0.5);
    }
  }
}

// An orthographic glTF camera (xmag = ymag = 1) on the +Z axis looking at the origin and the
// unit square facing it: x_ndc = x / (ymag * aspect), y_ndc = y / ymag, so the square spans
// ndc -0.5..0.5 vertically and -0.5 / aspect..0.5 / aspect horizontally, whatever the
// distance: at 128x64 (aspect 2) 32 of 128 columns and 32 of 64 rows, pixel edges on pixel
// boundaries, 1024 pixels. One pipeline per render() that builds a projection (matrix; affine,
// whose render the qtangent, hybrid and matrix_c pipelines share; motor, shared by motor_q,
// motor_c and motor_cf through motor.vs's MB_ORTHOGRAPHIC). A perspective camera (yfov 0.8) at distance 5
// would span 0.5 / (5 tan 0.4) = 0.236 of the half-height: 15 rows.
TEST(CameraFraming, OrthographicCameraDrawsTheHandDerivedExtent) {
  mbtest::TestGltf g = meshDocument(squareCorners(2), {0, 1, 2, 0, 2, 3});
  g.doc["cameras"] = {{{"type", "orthographic"},
                       {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.5}, {"zfar", 10.0}}}}};
  g.doc["nodes"].push_back({{"camera", 0}, {"translation", {0.0, 0.0, 5.0}}});
  g.doc["scenes"][0]["nodes"] = {0, 1};
  const Scene scene = load(g, "orthographic.glb");
  ASSERT_EQ(scene.cameras.size(), 1u);
  ASSERT_FALSE(scene.cameras[0].perspective);
  for (const char* pipeline : {"matrix", "affine", "motor"}) {
    SCOPED_TRACE(pipeline);
    const Frame f = render(scene, pipeline, 128, 64, 0);
    EXPECT_TRUE(f.view.orthographic);
    EXPECT_EQ(drawnPixels(f.image), 32 * 32);
    // The drawn pixels are the block of columns 48..79, rows 16..47.
    int outside = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 128; ++x) {
        const uint8_t* p = &f.image.rgba[size_t(4 * (y * 128 + x))];
        const bool drawn = p[0] != 51 || p[1] != 51 || p[2] != 56;
        outside += drawn != (x >= 48 && x < 80 && y >= 16 && y < 48);
      }
    EXPECT_EQ(outside, 0);
  }
}
