// Duplicate models in a corpus: the same model copied into two repositories,
// or re-exported under another name, is one sample of real content, not two. Each file gets a
// content hash; files with equal hashes are one model, and a corpus statistic counts the first
// file (sorted by path) of each group once, the file count printed beside it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/scene/scene.h"

namespace mb::report {

// The definition, printed beside every count of distinct models (claims text and JSON, inspect).
extern const char* const kSameModelDefinition;

// 16 hex digits: FNV-1a 64 of the loaded scene's content as kSameModelDefinition states it; ""
// for a file without meshes, skins and animations (no content that identifies a model).
std::string contentHash(const Scene& scene);

// The files of a corpus (inspect's per-file JSON, "contentHash" per file) grouped by content.
struct DistinctModels {
  std::vector<size_t> representatives;  // index into the files of each model's first file, in input order
  std::vector<std::vector<std::string>> duplicateGroups;  // groups of 2+ files (names), largest first
  int files = 0;
  int withoutHash = 0;  // no hash or "" (see contentHash): each counted as its own model
};
DistinctModels distinctModels(const nlohmann::json& files);

// {"files", "distinctModels", "filesWithoutContentHash", "duplicateGroups" (count), "filesInDuplicateGroups",
//  "largestDuplicateGroups" (up to `listed` groups of file names), "definition"}.
nlohmann::json toJson(const DistinctModels& m, size_t listed = 10);

// The files of `files` that represent a model (first of each group), in input order.
nlohmann::json representativeFiles(const nlohmann::json& files, const DistinctModels& m);

// "962 files, 896 distinct models"
std::string filesAndModels(const DistinctModels& m);

}  // namespace mb::report
