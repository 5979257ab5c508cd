// Scene-graph statistics of a corpus of glTF files (`motorbench inspect` over a folder, `merge`
// of its shards): per file the scale fields of pipelines/scene/scene_stats.h, grouped by the
// source kind a MANIFEST.tsv beside the files gives (columns `output_file` and `kind`: asset,
// sample, test; ../shared/corpus-graph has one), each model counted once (corpus_models.h), and
// the figures the corpus claims read (scaleFigures).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb::report {

// output_file -> kind from `dir`/MANIFEST.tsv; empty when there is none (or it lacks the columns).
std::map<std::string, std::string> readManifestKinds(const std::string& dir);

// The kind of each of `files` (inspect's per-file JSON, "input" or "file" a path): its own "kind"
// when it has one, else from the MANIFEST.tsv of its folder; "" where neither gives one.
std::vector<std::string> fileKinds(const nlohmann::json& files);

// {kind: aggregateFileJson of that kind's files} for `files`; files a manifest does not list are
// "unlisted". Null when no file's folder has a manifest.
nlohmann::json aggregateByKind(const nlohmann::json& files);

// Adds to inspect's `aggregate` of `files` "byKind" (aggregateByKind, when a manifest lists the
// files) and "models" (corpus_models.h); and to each listed file its "kind", so that the JSON
// alone gives the kinds where the corpus folder is absent (a clone reading
// results/corpus-graph.json). inspect and merge both call it, so that merged shards equal one run.
void addCorpusAggregates(nlohmann::json& files, nlohmann::json& aggregate);

// The scale figures of `files` (inspect's per-file JSON, each with its "contentHash"), counted
// over distinct models: "scale.*" for the real models (test fixtures, manifest kind test, and
// built-in scenes left out: what the corpus claims judge), "scale.all.*" for every model and
// "scale.kind.<kind>.*" per source kind. Each group has files, models (loaded), channel.models,
// animated.models, animated_nonuniform.models, constant_channels_only.models, nonuniform.models,
// nonuniform_leaves_only.models, nonuniform_inner.models, nonuniform_inner_beyond_1pct.models;
// the real group also failed.files. harness/report/README.md defines each.
nlohmann::json scaleFigures(const nlohmann::json& files);

}  // namespace mb::report
