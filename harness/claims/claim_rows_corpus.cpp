// The corpus rows: the paper's two statistics over real glTF files (scale animation, non-uniform
// scale only on leaves), read from the scale figures `motorbench inspect --json` writes over the
// scene graphs of ../shared/corpus-graph (results/corpus-graph.json), and what the motor
// pipelines' exact fallback takes on real files with meshes (the report over ../shared/corpus,
// results/corpus/report.json): the scene graphs' meshes are stripped, so no draw of theirs can
// fall back.
#include "harness/claims/claim_table.h"

namespace mb::claims {
namespace {

const char* const kSection = "Scene statistics";
// Below this many real models a corpus cannot resolve the paper's 0.5 % (1 / 200); both
// statistics rows use it.
constexpr int kMinModels = 200;
const Scope kSceneGraphs{"scene data (node scales and scale animation)", "none",
                         "real corpus: the scene graphs of ../shared/corpus-graph (files scraped from GitHub, meshes "
                         "stripped), test fixtures left out, each model once"};

void animatedScaleRow(std::vector<ClaimRow>& rows) {
  rows.push_back(
      {.id = "animated_scale_corpus", .section = kSection,
       .statement = "less than 0.5 % of ~400 glTF files animate scale", .origin = "paper",
       .quote = "\"less than 0.5% of the almost 400 random glTF files tested had any animation on the scale\" (Scaling)",
       .scope = kSceneGraphs, .paper = "< 0.5 % of ~400 files", .paperValue = {{"fraction", 0.005}, {"files", 400}},
       .evidence = {{"models whose scale keys change the scale, of the real models", "graphs:scale.animated.models",
                     "graphs:scale.models"},
                    {"models with any scale channel (constant ones included), of the real models",
                     "graphs:scale.channel.models", "graphs:scale.models"}},
       .rule = {RuleKind::AtMost, 0.005, kMinModels},
       .note = "the two readings of \"any animation on the scale\": keys that change the scale (a key differs from "
               "the channel's first key by more than 1e-4 relative; the paper states no tolerance for keys), and any "
               "scale channel; models with constant scale channels only (graphs:scale.constant_channels_only.models) "
               "set a scale and animate nothing. The paper sampled almost 400 random files; this corpus "
               "(graphs:scale.files real files) is scraped from GitHub, each model counted once by content hash. "
               "Near-duplicates survive that hash: among the changing models of ../shared/corpus-graph are "
               "LittlestTokyo twice (0088, 0190), mannequiny twice (0490, 0562), three quaternius Enemy_* gun / "
               "no-gun pairs, two kaykit Med_* on one rig, and InterpolationTest, a test asset filed as a sample "
               "(counted once per family the share would be smaller; this count does not merge them). Per source kind: "
               "graphs:scale.kind.<asset|sample|test>.animated.models"});
}

void leafScaleRow(std::vector<ClaimRow>& rows) {
  rows.push_back(
      {.id = "nonuniform_scale_leaves", .section = kSection,
       .statement = "non-uniform scale is found only on leaf nodes", .origin = "paper",
       .quote = "\"we could only find non-uniform scale applied on leaf nodes\" (Handling non-uniform scaling)",
       .scope = kSceneGraphs, .paper = "all files with non-uniform scale: only on leaves",
       .paperValue = {{"fractionOnlyOnLeaves", 1.0}},
       .evidence = {{"models with non-uniform scale on leaves only, of the real models with non-uniform scale",
                     "graphs:scale.nonuniform_leaves_only.models", "graphs:scale.nonuniform.models"}},
       .rule = {RuleKind::AtLeast, 1.0, kMinModels},
       .note = "non-uniform: |s0/s1 - 1| or |s1/s2 - 1| beyond 1e-4 (the paper's loader's check), at rest or in a "
               "scale key; an inner node has children. The others have it on an inner node "
               "(graphs:scale.nonuniform_inner.models; beyond 1 %: graphs:scale.nonuniform_inner_beyond_1pct.models). "
               "What the motor pipelines' exact fallback then takes on real files with meshes: "
               "motor_fallback_real_files (these scene graphs have no meshes, so no draw of theirs can fall back)"});
}

void fallbackRow(std::vector<ClaimRow>& rows) {
  rows.push_back(
      {.id = "motor_fallback_real_files", .section = kSection,
       .statement = "the motor pipeline's exact fallback on real files with meshes: draws whose world is not a "
                    "similarity, skins whose joints are not one uniform scale",
       .origin = "baseline",
       .scope = {"frame (the most in any frame drawn, per scene)", "none",
                 "real files with meshes: the report over ../shared/corpus (a handful of small files: see the note)"},
       .paper = "-",
       .evidence = {{"scenes the motor pipeline drew with its fallback", "corpus:fallback.scenes.motor", ""},
                    {"draws", "corpus:fallback.draws.motor", ""},
                    {"joints of the skin-fallback palettes", "corpus:fallback.joints.motor", ""},
                    {"vertices", "corpus:fallback.vertices.motor", ""},
                    {"drawn primitives of these files", "corpus:kind.primitives.all", ""},
                    {"drawn vertices of these files", "corpus:kind.vertices.all", ""}},
       .rule = {RuleKind::Baseline},
       .note = "../shared/corpus is a handful of small real files (n of these figures; their drawn vertices above), "
               "so this shows that the fallback happens on real content, not how often: a skinned file whose joints "
               "carry non-uniform scale takes it on every skinned draw, at the matrix side's floats per joint. The "
               "scale statistics of nonuniform_scale_leaves come from mesh-stripped scene graphs, which cannot "
               "draw, so they say nothing about the fallback"});
}

}  // namespace

std::vector<ClaimRow> corpusRows() {
  std::vector<ClaimRow> rows;
  animatedScaleRow(rows);
  leafScaleRow(rows);
  fallbackRow(rows);
  return rows;
}

}  // namespace mb::claims
