#include "harness/report/corpus_stats.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "harness/figures/figure.h"
#include "harness/report/corpus_models.h"
#include "pipelines/scene/builtin_scenes.h"
#include "pipelines/scene/scene_stats.h"
#include "pipelines/scene/similarity_tolerance.h"

namespace mb::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::vector<std::string> splitTabs(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, '\t')) out.push_back(cell);
  return out;
}

std::string pathOf(const json& f) { return f.value("input", f.value("file", std::string())); }

bool isBuiltin(const json& f) {
  for (const std::string& b : builtinSceneNames())
    if (b == pathOf(f) || b == f.value("file", std::string())) return true;
  return false;
}

// Where the files come from: their folders (up to three named), built-in scenes apart.
std::string sourceText(const json& files) {
  std::set<std::string> folders;
  int builtins = 0;
  for (const json& f : files) {
    if (isBuiltin(f)) ++builtins;
    else folders.insert(fs::path(pathOf(f)).parent_path().generic_string());
  }
  std::string text;
  if (folders.size() <= 3)
    for (const std::string& d : folders) text += (text.empty() ? "" : ", ") + (d.empty() ? std::string(".") : d);
  else
    text = std::to_string(folders.size()) + " folders";
  if (builtins) text += (text.empty() ? "" : " and ") + std::to_string(builtins) + " built-in scenes";
  return std::to_string(files.size()) + " files of " + text;
}

std::string toleranceText() {
  char b[48];
  std::snprintf(b, sizeof b, "%g relative", kSimilarityTolerance);
  return b;
}

// One counted statistic of a group: its figure-name suffix, aggregateFileJson key, definition.
struct Statistic {
  const char* suffix;
  const char* key;
  const char* definition;
};
const Statistic kStatistics[] = {
    {"channel.models", "filesWithAnimatedScale", "models with a scale animation channel, constant channels included"},
    {"animated.models", "filesWithChangingScale",
     "models with a scale channel whose keys change the scale: a key differs from the channel's first key by more "
     "than the tolerance in some component (our tolerance for keys: the paper states none)"},
    {"animated_nonuniform.models", "filesWithNonUniformChangingScale",
     "models with a scale channel whose keys change the scale and hold a non-uniform key"},
    {"constant_channels_only.models", "filesWithOnlyConstantScaleChannels",
     "models whose scale channels all hold constant keys: they set a scale and animate nothing"},
    {"nonuniform.models", "filesWithNonUniformScale",
     "models with a non-uniform scale (|s0/s1 - 1| or |s1/s2 - 1| beyond the tolerance) on some node, at rest or "
     "in a scale key (an authored matrix with shear counts)"},
    {"nonuniform_leaves_only.models", "filesWithNonUniformOnlyOnLeaves",
     "models with a non-uniform scale on leaf nodes (nodes without children) only"},
    {"nonuniform_inner.models", "filesWithInnerNonUniformScale",
     "models with a non-uniform scale on an inner node (a node with children)"},
    {"nonuniform_inner_beyond_1pct.models", "filesWithInnerNonUniformScaleBeyond1Percent",
     "models with a non-uniform scale on an inner node by more than 1 %"},
};

// The figures of one group: `files` how many files it has (duplicates included), `models` the
// first file of each of its content groups.
void putGroup(json& out, const std::string& prefix, size_t files, const json& models, const std::string& who,
              const std::string& scope) {
  const json a = aggregateFileJson(models);
  const int n = a.value("loaded", 0);
  const std::string statistic = "counted: distinct models (the first file of each content-hash group, loaded) " + who;
  auto put = [&](const std::string& name, double value, const std::string& unit, const std::string& definition,
                 const std::string& stat, int over) {
    figures::Figure f;
    f.kind = "measured";
    f.name = prefix + name;
    f.value = value;
    f.unit = unit;
    f.n = over;
    f.statistic = stat;
    f.scope = scope;
    f.device = "scene graphs as loaded (pipelines/scene/scale_analysis.h)";
    f.tolerance = toleranceText();
    f.definition = definition;
    figures::put(out, f);
  };
  put("files", double(files), "files", "files read, before the same model's files are counted once",
      "counted: files " + who, int(files));
  put("models", n, "models", "distinct models that loaded (" + std::string(kSameModelDefinition) + ")", statistic, n);
  for (const Statistic& s : kStatistics) put(s.suffix, a.value(s.key, 0), "models", s.definition, statistic, n);
}

}  // namespace

std::map<std::string, std::string> readManifestKinds(const std::string& dir) {
  std::map<std::string, std::string> kinds;
  std::ifstream in(fs::path(dir) / "MANIFEST.tsv");
  std::string line;
  if (!in || !std::getline(in, line)) return kinds;
  const std::vector<std::string> header = splitTabs(line);
  size_t fileCol = header.size(), kindCol = header.size();
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "output_file") fileCol = i;
    if (header[i] == "kind") kindCol = i;
  }
  if (fileCol == header.size() || kindCol == header.size()) return kinds;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = splitTabs(line);
    if (cells.size() > std::max(fileCol, kindCol)) kinds[cells[fileCol]] = cells[kindCol];
  }
  return kinds;
}

std::vector<std::string> fileKinds(const json& files) {
  std::map<std::string, std::map<std::string, std::string>> manifests;  // folder -> kinds
  std::vector<std::string> out;
  for (const json& f : files) {
    if (f.value("kind", json()).is_string()) {  // written beside the file's figures (addCorpusAggregates)
      out.push_back(f["kind"].get<std::string>());
      continue;
    }
    const fs::path p(pathOf(f));
    const std::string dir = p.parent_path().empty() ? "." : p.parent_path().string();
    if (!manifests.count(dir)) manifests[dir] = readManifestKinds(dir);
    const auto& kinds = manifests[dir];
    const auto k = kinds.find(p.filename().string());
    out.push_back(k == kinds.end() ? "" : k->second);
  }
  return out;
}

json aggregateByKind(const json& files) {
  const std::vector<std::string> kinds = fileKinds(files);
  std::map<std::string, json> groups;
  bool anyListed = false;
  for (size_t i = 0; i < kinds.size(); ++i) {
    anyListed |= !kinds[i].empty();
    json& group = groups[kinds[i].empty() ? "unlisted" : kinds[i]];
    if (group.is_null()) group = json::array();
    group.push_back(files[i]);
  }
  if (!anyListed) return nullptr;
  json out = json::object();
  for (const auto& [kind, list] : groups) out[kind] = aggregateFileJson(list);
  return out;
}

void addCorpusAggregates(json& files, json& aggregate) {
  const std::vector<std::string> kinds = fileKinds(files);
  for (size_t i = 0; i < kinds.size(); ++i)
    if (!kinds[i].empty()) files[i]["kind"] = kinds[i];
  if (const json byKind = aggregateByKind(files); !byKind.is_null()) aggregate["byKind"] = byKind;
  aggregate["models"] = toJson(distinctModels(files));
}

json scaleFigures(const json& files) {
  const DistinctModels m = distinctModels(files);
  std::vector<bool> representative(files.size(), false);
  for (size_t i : m.representatives) representative[i] = true;
  const std::vector<std::string> kinds = fileKinds(files);
  std::vector<bool> real(files.size());
  for (size_t i = 0; i < files.size(); ++i) real[i] = kinds[i] != "test" && !isBuiltin(files[i]);
  // The models of the files `in` selects, and how many files it selects.
  auto group = [&](const std::function<bool(size_t)>& in, size_t& count) {
    json out = json::array();
    count = 0;
    for (size_t i = 0; i < files.size(); ++i) {
      if (!in(i)) continue;
      ++count;
      if (representative[i]) out.push_back(files[i]);
    }
    return out;
  };
  const std::string scope = "scene graphs of " + sourceText(files) + "; a scale is non-uniform when |s0/s1 - 1| or "
                            "|s1/s2 - 1| exceeds " + toleranceText() + " (the paper's loader's check)";
  json out = json::object();
  size_t count = 0;
  json models = group([&](size_t i) { return bool(real[i]); }, count);
  putGroup(out, "scale.", count, models, "without the test fixtures (manifest kind test) and built-in scenes", scope);
  int failed = 0;
  for (size_t i = 0; i < files.size(); ++i) failed += real[i] && !files[i].value("loaded", false);
  figures::Figure f;
  f.kind = "measured";
  f.name = "scale.failed.files";
  f.value = failed;
  f.unit = "files";
  f.n = int(count);
  f.statistic = "counted: files without the test fixtures and built-in scenes";
  f.scope = scope;
  f.device = "scene graphs as loaded";
  f.definition = "files that failed to load (left out of every model count)";
  figures::put(out, f);
  models = group([](size_t) { return true; }, count);
  putGroup(out, "scale.all.", count, models, "of every file", scope);
  for (const std::string& k : std::set<std::string>(kinds.begin(), kinds.end())) {
    if (k.empty()) continue;
    models = group([&](size_t i) { return kinds[i] == k; }, count);
    putGroup(out, "scale.kind." + k + ".", count, models, "of manifest kind " + k, scope);
  }
  return out;
}

}  // namespace mb::report
