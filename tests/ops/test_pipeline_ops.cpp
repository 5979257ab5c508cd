// Ops per vertex per registered pipeline (harness/ops/pipeline_ops.h): every pipeline has counted
// kernels, the figures equal sums derived by hand from the kernels' hand-derived counts
// (mat4 * vec4 16/12, mat4x3 * point 9/9, mat3 * vector 9/6, ...), and the README's pipeline
// table quotes exactly these figures.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "harness/ops/pipeline_ops.h"
#include "pipelines/pipeline.h"

namespace {

using namespace mb;

const opsv::VertexOps& countedOnly() {
  static const opsv::VertexOps ops = opsv::measureVertexOps(opsv::SpirvDepth::None);
  return ops;
}

std::map<std::string, opsv::PipelineOps> byName(const opsv::VertexOps& ops) {
  std::map<std::string, opsv::PipelineOps> out;
  for (const opsv::PipelineOps& r : opsv::pipelineOps(ops)) out[r.pipeline] = r;
  return out;
}

TEST(PipelineOps, EveryRegisteredPipelineHasCountedOps) {
  const auto rows = byName(countedOnly());
  const auto euclidean = pipelineNames(Space::Euclidean);
  for (const std::string& p : allPipelineNames()) {
    ASSERT_TRUE(rows.count(p)) << p;
    const opsv::PipelineOps& r = rows.at(p);
    EXPECT_EQ(r.problem, "") << p;
    EXPECT_GT(opsv::total(r.rigid.counted), 0u) << p << " rigid";
    // glTF pipelines: world to clip is a kernel of its own; a curved pipeline's instance kernel
    // is its whole counted vertex (main() adds the same projection on both sides).
    const bool gltf = std::find(euclidean.begin(), euclidean.end(), p) != euclidean.end();
    if (gltf) {
      EXPECT_GT(opsv::total(r.toClip.counted), opsv::total(r.rigid.counted)) << p << " to clip";
      EXPECT_GT(opsv::total(r.skinned.counted), opsv::total(r.rigid.counted)) << p << " skinned";
      EXPECT_TRUE(r.patch.present) << p << " bezier patch";  // every glTF pipeline draws patches
    } else {
      EXPECT_EQ(opsv::total(r.toClip.counted), opsv::total(r.rigid.counted)) << p << " to clip";
    }
  }
}

TEST(PipelineOps, EveryVariantResolvesItsKernels) {
  for (const opsv::VariantRow& v : countedOnly().variants)
    EXPECT_TRUE(v.kernelsResolved) << v.variant.pipeline << " " << v.variant.label << ": " << v.error;
}

// A pipeline whose variants are missing from the table is reported, not counted as 0 ops.
TEST(PipelineOps, APipelineWithoutVariantsIsAProblem) {
  opsv::VertexOps ops = countedOnly();
  std::erase_if(ops.variants, [](const opsv::VariantRow& v) { return v.variant.pipeline == "hybrid"; });
  const auto rows = byName(ops);
  EXPECT_NE(rows.at("hybrid").problem, "");
  EXPECT_FALSE(rows.at("hybrid").rigid.present);
}

// Totals (mul + add + div + sqrt + other) from the kernels' hand-derived counts.
TEST(PipelineOps, FiguresEqualHandDerivedSums) {
  const auto rows = byName(countedOnly());
  auto expect = [&](const char* p, uint64_t rigid, uint64_t skinned, uint64_t toClip) {
    const opsv::PipelineOps& r = rows.at(p);
    EXPECT_EQ(opsv::total(r.rigid.counted), rigid) << p;
    EXPECT_EQ(opsv::total(r.skinned.counted), skinned) << p;
    EXPECT_EQ(opsv::total(r.toClip.counted), toClip) << p;
  };
  const uint64_t matrixClip = 16 + 12;  // mat4 * vec4
  // matrix: three mat4 * vec4 + handedness 49/36; skinned: two mat4 blends 2 x (64/48), two sets
  // of three products 2 x (48/36), handedness 1.
  expect("matrix", 49 + 36, (2 * 64 + 2 * 48 + 1) + (2 * 48 + 2 * 36), 85 + matrixClip);
  // affine: mat4x3 point 9/9, mat3 normal 9/6, tangent 9/6, handedness 1/0 = 28/21; skinned:
  // blend 48/36 + cofactor 18/9 + 28/21.
  expect("affine", 28 + 21, 94 + 66, 49 + matrixClip);
  // qtangent and hybrid: + the quaternion decode 12/8 + 1 sign.
  expect("qtangent", 49 + 21, 160 + 21, 70 + matrixClip);
  expect("hybrid", 49 + 21, 160 + 21, 70 + matrixClip);
  // motor: sw_mp 21/18 + gp_rr 16/12 + extractNormalTangent 9/8 + scale 3/0 + handedness 1 div
  // 1 other = 89; skinned: + blend 44/33 + normalize_m 22/10 + 1 other; to clip: sw_mp 21/18 +
  // the per-frame projection 3/1 (both motor pipelines).
  expect("motor", 89, 89 + 66 + 43 + 1, 89 + 21 + 18 + 3 + 1);
  expect("motor_q", 89, 89 + 66 + 43 + 1, 89 + 21 + 18 + 3 + 1);
  // Bezier patch to clip: the evaluation 153/137 + the frame + world to clip.
  EXPECT_EQ(opsv::total(rows.at("matrix").patch.counted), 290 + (55 + 39) + matrixClip);
  EXPECT_EQ(opsv::total(rows.at("affine").patch.counted), 290 + (34 + 24) + matrixClip);
  EXPECT_EQ(opsv::total(rows.at("hybrid").patch.counted), 290 + (34 + 24) + matrixClip);
  EXPECT_EQ(opsv::total(rows.at("motor").patch.counted), 290 + (66 + 45) + 21 + 18 + 3 + 1);
}

// A README cell without its figure marks and the " ops" unit: "<span title=..>85 ops</span>" -> "85".
std::string withoutFigureMarks(const std::string& cellText) {
  std::string out;
  for (size_t i = 0; i < cellText.size(); ++i) {
    if (cellText[i] == '<') {
      i = cellText.find('>', i);
      if (i == std::string::npos) break;
      continue;
    }
    out += cellText[i];
  }
  for (size_t at; (at = out.find(" ops")) != std::string::npos;) out.erase(at, 4);
  return out;
}

// The README's pipeline table (written from report.json's figures by scripts/document_figures.py):
// its ops column, read without the figure marks (<span title=NAME>) and the unit, is
// readmeOpsCell() of each pipeline as measured now (counted always; the SPIR-V part when
// glslang and spirv-tools run): the committed figures are the ones the code counts.
TEST(PipelineOps, ReadmeTableQuotesTheTable) {
  std::ifstream in(std::string(MB_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(in) << "README.md";
  std::map<std::string, std::string> readme;  // pipeline -> ops cell
  std::string line;
  int opsColumn = -1;
  while (std::getline(in, line)) {
    if (line.rfind("| pipeline | bytes/vertex uploaded |", 0) == 0) {
      std::stringstream ss(line);
      std::string cellText;
      int i = -1;
      while (std::getline(ss, cellText, '|')) {
        if (cellText.find("ops rigid / skinned / to clip") != std::string::npos) opsColumn = i;
        ++i;
      }
      continue;
    }
    if (opsColumn < 0 || line.rfind("| ", 0) != 0) {
      if (opsColumn >= 0 && !readme.empty()) break;
      continue;
    }
    std::stringstream ss(line);
    std::string cellText, name;
    for (int i = -1; std::getline(ss, cellText, '|'); ++i) {
      const std::string plain = withoutFigureMarks(cellText);
      const auto b = plain.find_first_not_of(' '), e = plain.find_last_not_of(' ');
      const std::string trimmed = b == std::string::npos ? "" : plain.substr(b, e - b + 1);
      if (i == 0) name = trimmed;
      if (i == opsColumn) readme[name] = trimmed;
    }
  }
  ASSERT_GE(opsColumn, 0) << "README.md has no pipeline table with an ops column";
  const opsv::VertexOps ops = opsv::measureVertexOps(opsv::SpirvDepth::Probes);
  for (const std::string& p : pipelineNames(Space::Euclidean)) {
    ASSERT_TRUE(readme.count(p)) << "README table has no row " << p;
    std::string want;
    for (const opsv::PipelineOps& r : opsv::pipelineOps(ops))
      if (r.pipeline == p) want = opsv::readmeOpsCell(r);
    EXPECT_EQ(readme[p], want) << p;
  }
}

}  // namespace
