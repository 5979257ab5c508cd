#include "harness/claims/corpus_stats.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "harness/claims/corpus_models.h"
#include "harness/report/report_inputs.h"
#include "pipelines/scene/loader.h"
#include "pipelines/scene/scene_stats.h"

namespace mb::claims {
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
    const fs::path p(f.value("input", f.value("file", "")));  // inspect: "input" is the path given
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

Result<json> corpusFiles(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    json files = json::array();
    for (const report::Input& in : report::expandInputs({path})) {
      auto scene = loadScene(in.spec);
      FileStats stats = scene ? computeFileStats(*scene) : failedFileStats(in.spec, scene.error());
      stats.file = in.spec;  // the path, so that the folder's MANIFEST.tsv is found
      files.push_back(toJson(stats));
      if (scene) files.back()["contentHash"] = contentHash(*scene);  // duplicates: corpus_models.h
    }
    if (files.empty()) return Result<json>::fail(path + ": no .gltf/.glb files in this folder");
    return files;
  }
  std::ifstream f(path);
  if (!f) return Result<json>::fail(path + ": cannot read (neither a folder nor a readable file)");
  const json j = json::parse(f, nullptr, false);
  if (j.is_discarded()) return Result<json>::fail(path + ": not JSON (expected `motorbench inspect --json` output)");
  if (!j.is_object() || !j.value("files", json()).is_array())
    return Result<json>::fail(path + ": no \"files\" array (expected `motorbench inspect --json` output)");
  return j["files"];
}

}  // namespace mb::claims
