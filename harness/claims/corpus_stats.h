// Scene-graph statistics of a corpus of glTF files for the two scale claims:
// per file the scale fields of `motorbench inspect` (pipelines/scene/scene_stats.h), grouped by
// the source kind a MANIFEST.tsv beside the files gives (columns `output_file` and `kind`:
// asset, sample, test; ../shared/corpus-graph has one).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipelines/result.h"

namespace mb::claims {

// output_file -> kind from `dir`/MANIFEST.tsv; empty when there is none (or it lacks the columns).
std::map<std::string, std::string> readManifestKinds(const std::string& dir);

// The kind of each of `files` (inspect's per-file JSON, "file" a path): its own "kind" when it
// has one, else from the MANIFEST.tsv of its folder; "" where neither gives one.
std::vector<std::string> fileKinds(const nlohmann::json& files);

// {kind: aggregateFileJson of that kind's files} for `files` (inspect's per-file JSON, "file" a
// path), the kind looked up in the MANIFEST.tsv of each file's folder; files not listed there
// are "unlisted". Null when no file's folder has a manifest.
nlohmann::json aggregateByKind(const nlohmann::json& files);

// Adds to inspect's `aggregate` of `files` what the corpus claims read beside it: "byKind"
// (aggregateByKind, when a manifest lists the files) and "models" (corpus_models.h); and to each
// listed file its "kind", so that the JSON alone gives the kinds where the corpus folder is
// absent (a clone reading results/corpus-graph.json). inspect and merge both call it, so that
// merged shards equal one run.
void addCorpusAggregates(nlohmann::json& files, nlohmann::json& aggregate);

// The per-file JSON of a corpus: `path` is an inspect JSON (its "files") or a folder whose
// .gltf/.glb files are loaded and analysed now (each with its "contentHash", corpus_models.h). An error names the path and the reason.
Result<nlohmann::json> corpusFiles(const std::string& path);

}  // namespace mb::claims
