#include "harness/accuracy/handedness.h"

#include <algorithm>
#include <cmath>

#include "harness/accuracy/accuracy_figure.h"
#include "pipelines/motor/motor_vertices.h"
#include "pipelines/scene/loader.h"

namespace mb::accuracy {
namespace {

using json = nlohmann::json;

// JavaScript's Math.sign: NaN stays NaN, +-0 stay +-0, else +-1.
double jsSign(double x) { return x > 0 ? 1.0 : x < 0 ? -1.0 : x; }

glm::dvec3 normalized(const glm::dvec3& v) { return v / std::sqrt(glm::dot(v, v)); }

// Any unit vector perpendicular to n (motor_vertices.cpp's rule for a missing tangent).
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 c = glm::cross(n, axis);
  const float len = glm::length(c);
  return len > 0.0f ? c / len : glm::vec3(1, 0, 0);
}

// The normal texture's tangent-space normal at vertex v's uv (nearest texel, repeat), scaled as
// glTF says; false without a normal texture.
bool normalTexel(const Scene& s, const Primitive& p, size_t v, glm::vec3& out) {
  if (p.material < 0 || size_t(p.material) >= s.materials.size()) return false;
  const TextureRef& ref = s.materials[size_t(p.material)].normal;
  if (ref.texture < 0 || size_t(ref.texture) >= s.textures.size()) return false;
  const int img = s.textures[size_t(ref.texture)].image;
  if (img < 0 || size_t(img) >= s.images.size()) return false;
  const Image& im = s.images[size_t(img)];
  const std::vector<glm::vec2>& uvs = ref.texCoord == 1 ? p.uv1 : p.uv0;
  if (im.width <= 0 || im.height <= 0 || im.rgba.size() < size_t(im.width) * size_t(im.height) * 4 || v >= uvs.size())
    return false;
  const float u = uvs[v].x - std::floor(uvs[v].x), w = uvs[v].y - std::floor(uvs[v].y);
  const int x = std::min(im.width - 1, int(u * float(im.width))), y = std::min(im.height - 1, int(w * float(im.height)));
  const uint8_t* t = &im.rgba[(size_t(y) * size_t(im.width) + size_t(x)) * 4];
  out = glm::vec3((2.0f * t[0] / 255.0f - 1.0f) * ref.scale, (2.0f * t[1] / 255.0f - 1.0f) * ref.scale, 2.0f * t[2] / 255.0f - 1.0f);
  return true;
}

// The angle between the fragment shader's perturbed normal with the right and with the flipped
// bitangent, for tangent-space normal `ts` at the frame (n, t, want).
double shadingNormalChangeDegrees(const glm::vec3& n, const glm::vec4& t, float want, const glm::vec3& ts) {
  const glm::vec3 nn = glm::normalize(n), tt = glm::normalize(glm::vec3(t) - nn * glm::dot(nn, glm::vec3(t)));
  const glm::vec3 b = want * glm::cross(nn, tt);
  const glm::vec3 right = glm::normalize(tt * ts.x + b * ts.y + nn * ts.z);
  const glm::vec3 wrong = glm::normalize(tt * ts.x - b * ts.y + nn * ts.z);
  return glm::degrees(std::acos(std::clamp(double(glm::dot(right, wrong)), -1.0, 1.0)));
}

void countPrimitive(const Scene& scene, const Primitive& p, HandednessCount& sc) {
  sc.zeroScalarOurs += motor::interleaveVertices(p).zeroScalarFrames;
  for (size_t v = 0; v < p.positions.size(); ++v) {
    const glm::vec3 n = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 0, 1);
    const glm::vec4 t = v < p.tangents.size() ? p.tangents[v] : glm::vec4(perpendicular(n), 1.0f);
    const float want = t.w < 0.0f ? -1.0f : 1.0f;
    const PaperFrame f = paperLoadRule(n, glm::vec4(glm::vec3(t), want));
    ++sc.frames;
    sc.zeroScalar += f.scalarZero;
    if (f.handedness == want) continue;
    ++sc.wrong;
    glm::vec3 ts;
    if (!normalTexel(scene, p, v, ts)) continue;
    ++sc.wrongNormalMapped;
    sc.worstDegrees = std::max(sc.worstDegrees, shadingNormalChangeDegrees(n, t, want, ts));
  }
}

}  // namespace

PaperFrame paperLoadRule(const glm::vec3& normalIn, const glm::vec4& tangentIn) {
  // Normalize, Orthogonalize; the bitangent; mat = [...tangent, ...bitangent, ...normal].
  const glm::dvec3 normal = normalized(glm::dvec3(normalIn));
  const glm::dvec3 t0(tangentIn);
  const glm::dvec3 tangent = normalized(t0 - normal * glm::dot(normal, t0));
  const glm::dvec3 bitangent = normalized(glm::cross(normal, tangent));
  double m00 = tangent.x, m01 = tangent.y, m02 = tangent.z, m10 = bitangent.x, m11 = bitangent.y, m12 = bitangent.z,
         m20 = normal.x, m21 = normal.y, m22 = normal.z;
  // fromMatrix3's quick scale check (rows are unit here up to rounding).
  const double s0 = std::hypot(m00, m01, m02), s1 = std::hypot(m10, m11, m12), s2 = std::hypot(m20, m21, m22);
  if (std::fabs(s0 - 1) > 0.0001 || std::fabs(s1 - 1) > 0.0001 || std::fabs(s2 - 1) > 0.0001) {
    m00 /= s0, m01 /= s0, m02 /= s0, m10 /= s1, m11 /= s1, m12 /= s1, m20 /= s2, m21 /= s2, m22 /= s2;
  }
  double r[4];
  if (m00 + m11 + m22 > 0) r[0] = m00 + m11 + m22 + 1.0, r[1] = m21 - m12, r[2] = m02 - m20, r[3] = m10 - m01;
  else if (m00 > m11 && m00 > m22) r[0] = m21 - m12, r[1] = 1.0 + m00 - m11 - m22, r[2] = m01 + m10, r[3] = m02 + m20;
  else if (m11 > m22) r[0] = m02 - m20, r[1] = m01 + m10, r[2] = 1.0 + m11 - m00 - m22, r[3] = m12 + m21;
  else r[0] = m10 - m01, r[1] = m02 + m20, r[2] = m12 + m21, r[3] = 1.0 + m22 - m00 - m11;
  const double inv = 1.0 / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (double& x : r) x *= inv;
  PaperFrame out;
  out.scalarZero = r[0] == 0.0;
  // if (Math.sign(motor[0]) != tangents[i*4+3]) motor = motor.map(x => -x);
  if (jsSign(r[0]) != double(tangentIn.w))
    for (double& x : r) x = -x;
  out.scalar = r[0];
  out.rotor = glm::vec4(float(r[0]), float(r[1]), float(r[2]), float(r[3]));
  // float handedness = sign(1/tangentRotor.x), on the float32 vertex attribute.
  const float inverse = 1.0f / out.rotor.x;
  out.handedness = inverse > 0.0f ? 1.0f : inverse < 0.0f ? -1.0f : 0.0f;
  return out;
}

std::vector<HandednessCount> measureHandedness(const std::vector<std::string>& scenes) {
  std::vector<HandednessCount> counts;
  for (const std::string& name : scenes) {
    auto scene = loadScene(name);
    if (!scene) continue;
    HandednessCount sc{name};
    for (const Mesh& mesh : scene->meshes)
      for (const Primitive& p : mesh.primitives)
        if (!p.positions.empty()) countPrimitive(*scene, p, sc);
    if (sc.frames) counts.push_back(sc);
  }
  return counts;
}

void putHandednessFigures(const std::vector<HandednessCount>& counts, json& figures, json& details) {
  HandednessCount all;
  json per = json::object();
  for (const HandednessCount& s : counts) {
    all.frames += s.frames, all.zeroScalar += s.zeroScalar, all.zeroScalarOurs += s.zeroScalarOurs;
    all.wrong += s.wrong, all.wrongNormalMapped += s.wrongNormalMapped;
    all.worstDegrees = std::max(all.worstDegrees, s.worstDegrees);
    per[s.scene] = {{"frames", s.frames}, {"zeroScalarFloat64", s.zeroScalar}, {"zeroScalarOurs", s.zeroScalarOurs},
                    {"wrong", s.wrong}, {"wrongNormalMapped", s.wrongNormalMapped}, {"worstNormalDegrees", s.worstDegrees}};
  }
  details["handedness"] = per;
  const int n = int(counts.size());
  const std::string scope = "every vertex frame (normal, tangent) of the " + std::to_string(n) +
                            " built-in scenes, as motor::interleaveVertices takes them (authored or generated tangents, "
                            "the matrix pipeline's perpendicular where none)";
  const std::string rule = "the paper's load listing (normalise, orthogonalise, bitangent, fromMatrix3, the Math.sign "
                           "rule) run in float64 as JavaScript runs it, stored as float32 and decoded with the paper's "
                           "sign(1/x)";
  const FigureText counted{"frames", "counted: sum over scenes", scope, ""};
  auto with = [&](std::string definition) {
    FigureText t = counted;
    t.definition = std::move(definition);
    return t;
  };
  putFigure(figures, "handedness.frames", all.frames, n, with("vertex frames the rule was applied to"));
  putFigure(figures, "handedness.frames_wrong", all.wrong, n,
            with("frames whose decoded handedness differs from the tangent's w under " + rule));
  putFigure(figures, "handedness.frames_zero_scalar", all.zeroScalar, n,
            with("frames whose rotor scalar part from fromMatrix3 is exactly +-0 in float64 (the rule negates it "
                 "whatever the handedness, so one of the two handednesses decodes wrong)"));
  putFigure(figures, "handedness.frames_zero_scalar_ours", all.zeroScalarOurs, n,
            with("frames whose rotor scalar part is exactly 0 in our float conversion (motor::interleaveVertices, "
                 "which encodes the handedness with signbit and |s| >= 1/32767 and decodes them right)"));
  putFigure(figures, "handedness.frames_wrong_normal_mapped", all.wrongNormalMapped, n,
            with("wrong frames on normal-mapped primitives (the only ones whose shading uses the bitangent)"));
  putFigure(figures, "handedness.worst_normal_change_deg", all.worstDegrees, all.wrongNormalMapped,
            {"deg", "measured: worst over the wrong frames of normal-mapped primitives (0: none)", scope,
             "angle between the shading normal T x + B y + N z with the right and with the flipped bitangent, "
             "(x, y, z) the normal texture's texel at the vertex uv (nearest)"});
}

}  // namespace mb::accuracy
