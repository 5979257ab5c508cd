// The built-in curved-space scenes:
//   s3_tiling: non-euclidean-rendering.txt's spherical example: one triangle, 14,400
//     instances x -> q1 x q2 for the 120 x 120 pairs of the binary icosahedral group, the
//     reference's three lights; a camera path flies forward and turns.
//   h3_tiling: the hyperbolic analogue: the cells of the regular honeycomb {4,3,5} (cubes,
//     five around each edge) reached by words in the six face-to-face translations, breadth
//     first to the first depth with >= 10,000 cells, one triangle near each cell's +x, +y and
//     +z faces.
#include <cmath>
#include <map>
#include <tuple>

#include "pipelines/scene/curved_space.h"

namespace mb {
namespace {

using Quat = glm::dvec4;  // (real, i, j, k), the reference's order

Quat qmul(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// The 120 unit quaternions of the binary icosahedral group, in the reference's order: the
// 24 Hurwitz units' 12 representatives (up to the order-10 element q), each times q^0..q^9.
// q = (cos 36deg, 1/(2 phi), 1/2, 0) exactly (the reference rounds it to 0.809, 0.309).
std::vector<Quat> binaryIcosahedralGroup() {
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  const Quat q(0.5 * phi, 0.5 / phi, 0.5, 0.0);
  const Quat seeds[12] = {{1, 0, 0, 0},          {0, 1, 0, 0},          {0, 0, 1, 0},
                          {0, 0, 0, 1},          {.5, .5, .5, .5},      {.5, .5, .5, -.5},
                          {.5, .5, -.5, .5},     {.5, .5, -.5, -.5},    {.5, -.5, .5, .5},
                          {.5, -.5, .5, -.5},    {.5, -.5, -.5, .5},    {.5, -.5, -.5, -.5}};
  std::vector<Quat> g;
  for (Quat t : seeds)
    for (int i = 0; i < 10; ++i, t = qmul(q, t)) g.push_back(t);
  return g;
}

// The vector orthogonal (in the space's form) to three points: the normal of the plane
// through them. Cofactors of the 3x4 matrix [a; b; c], then the form's sign on w.
glm::dvec4 planeNormal(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, int kappa) {
  auto det3 = [](double a1, double a2, double a3, double b1, double b2, double b3, double c1,
                 double c2, double c3) {
    return a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1);
  };
  glm::dvec4 n(det3(a.y, a.z, a.w, b.y, b.z, b.w, c.y, c.z, c.w),
               -det3(a.x, a.z, a.w, b.x, b.z, b.w, c.x, c.z, c.w),
               det3(a.x, a.y, a.w, b.x, b.y, b.w, c.x, c.y, c.w),
               -det3(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z));
  n.w *= double(kappa);  // Euclidean-orthogonal to eta p  <=>  form-orthogonal to p
  const double len = n.x * n.x + n.y * n.y + n.z * n.z + kappa * n.w * n.w;
  return n / std::sqrt(len);
}

void addTriangle(CurvedScene& c, const glm::dvec4 (&p)[3], const glm::dvec4& n) {
  for (const glm::dvec4& v : p) {
    c.positions.push_back(glm::vec4(v));
    c.normals.push_back(glm::vec4(n));
  }
}

Animation cameraAnimation(float duration) {
  Animation a;
  a.name = "camera_path";
  a.duration = duration;
  return a;
}

Scene s3Tiling() {
  Scene s;
  s.source = "s3_tiling";
  CurvedScene& c = s.curved;
  c.space = Space::Spherical;
  // The reference's triangle, projected onto the unit sphere (its vertices are not unit) and
  // given the exact normal of its great 2-sphere, oriented like the reference's normal.
  glm::dvec4 p[3] = {{0.176, 0.9, 0.8382, 0.8}, {0.176, 0.8, 0.9, 0.8382}, {-0.176, 0.8, 0.9, 0.8382}};
  for (glm::dvec4& v : p) v = glm::normalize(v);
  glm::dvec4 n = planeNormal(p[0], p[1], p[2], 1);
  if (glm::dot(n, glm::dvec4(0.0, 0.236, 1.382, -1.618)) < 0) n = -n;
  addTriangle(c, p, n);
  const std::vector<Quat> g = binaryIcosahedralGroup();
  c.instances.reserve(g.size() * g.size());
  for (const Quat& q1 : g)
    for (const Quat& q2 : g) {
      glm::dmat4 m;
      for (int i = 0; i < 4; ++i) {
        Quat e(0.0);
        e[i] = 1.0;
        m[i] = qmul(q1, qmul(e, q2));  // column i: the image of basis vector i
      }
      c.instances.push_back(m);
    }
  c.lights = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  c.lightStrength = 0.3f;
  // Fly forward (the origin towards -z) and turn slowly to the right.
  c.camera = {{0, 2, 0.0, -0.15}, {2, 3, 0.0, -0.35}};
  s.animations.push_back(cameraAnimation(8.0f));
  return s;
}

Scene h3Tiling() {
  Scene s;
  s.source = "h3_tiling";
  CurvedScene& c = s.curved;
  c.space = Space::Hyperbolic;
  // Cube with dihedral angle 2 pi / 5: face planes at distance a with sinh^2 a = cos 72deg.
  const double a = std::asinh(std::sqrt(std::cos(2.0 * M_PI / 5.0)));
  const glm::dvec4 o(0, 0, 0, 1);
  // Triangles a little inside the cell (0.85 a from the centre, parallel to the face): two
  // cells that share a face, reached with different orientations, never draw coplanar
  // triangles (their depth order would be a rounding race between the pipelines).
  const glm::dmat4 toFace = elementaryMatrix(-1, 2, 3, 0.85 * a);
  glm::dvec4 p[3];
  for (int k = 0; k < 3; ++k) {
    const double t = M_PI / 2 + k * 2.0 * M_PI / 3.0, r = 0.45;
    p[k] = toFace * glm::dvec4(std::sinh(r) * std::cos(t), std::sinh(r) * std::sin(t), 0.0, std::cosh(r));
  }
  glm::dvec4 n = planeNormal(p[0], p[1], p[2], -1);
  if (n.z < 0) n = -n;  // outwards (+z)
  // The same triangle near the +x and +y faces (turned about the origin).
  for (int axis : {0, 1}) {
    const glm::dmat4 turn = elementaryMatrix(-1, 2, axis, M_PI / 2);  // e_z -> e_axis
    const glm::dvec4 q[3] = {turn * p[0], turn * p[1], turn * p[2]};
    addTriangle(c, q, turn * n);
  }
  addTriangle(c, p, n);
  // Breadth first over words in the six face translations; a cell is new when its centre is.
  std::vector<glm::dmat4> gens;
  for (int i = 0; i < 3; ++i)
    for (double sgn : {1.0, -1.0}) gens.push_back(elementaryMatrix(-1, i, 3, sgn * 2.0 * a));
  using Key = std::tuple<long long, long long, long long>;
  std::map<Key, int> seen;
  auto keyOf = [](const glm::dvec4& v) {
    return Key{std::llround(v.x * 64.0), std::llround(v.y * 64.0), std::llround(v.z * 64.0)};
  };
  auto known = [&](const glm::dvec4& v) {  // neighbouring keys too: rounding at a boundary
    const Key k = keyOf(v);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz)
          if (seen.count({std::get<0>(k) + dx, std::get<1>(k) + dy, std::get<2>(k) + dz})) return true;
    return false;
  };
  std::vector<glm::dmat4> frontier = {glm::dmat4(1.0)};
  c.instances.push_back(glm::dmat4(1.0));
  seen[keyOf(o)] = 0;
  while (c.instances.size() < 10000 && !frontier.empty()) {
    std::vector<glm::dmat4> next;
    for (const glm::dmat4& m : frontier)
      for (const glm::dmat4& g : gens) {
        const glm::dmat4 w = m * g;
        const glm::dvec4 centre = w * o;
        if (known(centre)) continue;
        seen[keyOf(centre)] = int(c.instances.size());
        c.instances.push_back(w);
        next.push_back(w);
      }
    frontier = std::move(next);
  }
  c.lights = {elementaryMatrix(-1, 0, 3, 0.35) * o, elementaryMatrix(-1, 1, 3, 0.35) * o,
              elementaryMatrix(-1, 2, 3, -0.6) * o};
  c.lightStrength = 0.6f;
  c.camera = {{0, 2, 0.0, 0.2}, {2, 3, 0.0, -0.12}};
  s.animations.push_back(cameraAnimation(8.0f));
  return s;
}

}  // namespace

const std::vector<std::string>& curvedSceneNames() {
  static const std::vector<std::string> names = {"s3_tiling", "h3_tiling"};
  return names;
}

bool isCurvedScene(const std::string& name) { return name == "s3_tiling" || name == "h3_tiling"; }

Space curvedSceneSpace(const std::string& name) {
  if (name == "s3_tiling") return Space::Spherical;
  if (name == "h3_tiling") return Space::Hyperbolic;
  return Space::Euclidean;
}

Result<Scene> buildCurvedScene(const std::string& name) {
  if (name == "s3_tiling") return s3Tiling();
  if (name == "h3_tiling") return h3Tiling();
  return Result<Scene>::fail(name + ": not a built-in curved-space scene (s3_tiling, h3_tiling)");
}

}  // namespace mb
