#include "harness/ops/patch_memory.h"

#include <cstdio>

#include "pipelines/gl/context.h"
#include "shaders/shim/patch.h"

namespace mb::opsv {

Primitive tessellatePatches(const Primitive& src, int n) {
  using P = PatchShaders<float>;
  P shader;
  Primitive out;
  out.material = src.material;
  const size_t patches = src.patchPoints.size() / 16;
  const uint32_t row = uint32_t(n) + 1;
  for (size_t p = 0; p < patches; ++p) {
    P::mat4x3 r[4];
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 4; ++c) {
        const glm::vec3& q = src.patchPoints[16 * p + size_t(4 * i + c)];
        r[i][c] = P::vec3(q.x, q.y, q.z);
      }
    const uint32_t base = uint32_t(out.positions.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        glm::vec2 uv(float(i) / float(n), float(j) / float(n));
        P::mat3 s = shader.bezierPatch(r[0], r[1], r[2], r[3], P::vec2(uv.x, uv.y));
        glm::vec3 pos(s[0].x, s[0].y, s[0].z), du(s[1].x, s[1].y, s[1].z), dv(s[2].x, s[2].y, s[2].z);
        glm::vec3 nrm = glm::cross(du, dv);
        out.positions.push_back(pos);
        out.normals.push_back(glm::length(nrm) > 0.0f ? glm::normalize(nrm) : glm::vec3(0, 0, 1));
        out.tangents.push_back(glm::vec4(glm::length(du) > 0.0f ? glm::normalize(du) : glm::vec3(1, 0, 0), 1.0f));
        out.uv0.push_back(uv);
      }
    for (uint32_t j = 0; j < uint32_t(n); ++j)
      for (uint32_t i = 0; i < uint32_t(n); ++i) {
        uint32_t a = base + i + row * j, b = a + 1, c = a + row + 1, d = a + row;
        out.indices.insert(out.indices.end(), {a, b, c, a, c, d});
      }
  }
  return out;
}

Result<std::vector<PatchMemoryRow>> measurePatchMemory(const Scene& scene, const std::vector<int>& levels) {
  using R = Result<std::vector<PatchMemoryRow>>;
  auto ctx = gl::sharedContext();
  if (!ctx) return R::fail(ctx.error());
  std::vector<PatchMemoryRow> rows;
  for (int level : levels) {
    Scene patched = scene;
    patched.patchLevel = level;
    Scene flat = scene;
    for (Mesh& m : flat.meshes)
      for (Primitive& p : m.primitives)
        if (!p.patchPoints.empty()) p = tessellatePatches(p, level);
    for (const std::string& name : pipelineNames()) {
      PatchMemoryRow row;
      row.pipeline = name, row.level = level;
      auto a = createPipeline(name), b = createPipeline(name);
      if (!a || !b) continue;  // placeholder pipeline
      if (Status s = a->prepare(patched); !s) return R::fail(name + ": " + s.error());
      const PipelineStats sa = a->stats();
      a.reset();
      if (Status s = b->prepare(flat); !s) return R::fail(name + ": " + s.error());
      const PipelineStats sb = b->stats();
      b.reset();
      row.controlPointBytes = sa.patchBytes;
      row.instancedBytes = sa.patchBytes + sa.patchPatternBytes + sa.vertexBytes + sa.indexBytes;
      row.pretessellatedBytes = sb.vertexBytes + sb.indexBytes;
      row.pretessellatedVertices = sb.vertices;
      rows.push_back(row);
    }
  }
  return rows;
}

std::string formatPatchMemory(const std::vector<PatchMemoryRow>& rows) {
  std::string out = "Bezier patches: bytes uploaded, instanced tessellation (control points + one refinement "
                    "pattern) vs the same surface pre-tessellated into the pipeline's own vertex buffer + indices\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-8s %5s %14s %14s %16s %12s %8s\n", "pipeline", "level", "control pts B",
                "instanced B", "pre-tessellated B", "vertices", "ratio");
  out += line;
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%-8s %5d %14llu %14llu %16llu %12llu %8.1f\n", r.pipeline.c_str(), r.level,
                  (unsigned long long)r.controlPointBytes, (unsigned long long)r.instancedBytes,
                  (unsigned long long)r.pretessellatedBytes, (unsigned long long)r.pretessellatedVertices,
                  r.instancedBytes ? double(r.pretessellatedBytes) / double(r.instancedBytes) : 0.0);
    out += line;
  }
  return out;
}

nlohmann::json toJson(const std::vector<PatchMemoryRow>& rows) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : rows)
    j.push_back({{"pipeline", r.pipeline}, {"level", r.level}, {"controlPointBytes", r.controlPointBytes},
                 {"instancedBytes", r.instancedBytes}, {"pretessellatedBytes", r.pretessellatedBytes},
                 {"pretessellatedVertices", r.pretessellatedVertices}});
  return j;
}

}  // namespace mb::opsv
