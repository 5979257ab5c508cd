// The figures a claims run reads: the "figures" object of each run JSON, by source name. A
// reference "<source>:<name>" is looked up exactly; nothing is computed here.
//   report           report.json                 built-in scenes: bytes, images, frame times, ops, ISA, CPU kernels
//   ops              ops.json                    counted arithmetic of every kernel and listing
//   morph            morph.json                  morph targets' bytes and images
//   accuracy         accuracy.json               handedness, blending, skin volume, drift, conversion
//   graphs           corpus-graph.json           scale statistics over real scene graphs
//   corpus           corpus/report.json          real files with meshes: bytes per kind, fallbacks
//   corpus_accuracy  corpus/accuracy.json        skin volume on real skinned files
#pragma once
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/figures/figure.h"

namespace mb::claims {

struct FigureSet {
  std::map<std::string, nlohmann::json> figures;  // source -> its {name: figure}
  nlohmann::json report;                          // report.json whole (the answer block and ladder read it)
  std::map<std::string, std::string> files;       // source -> the file it was read from
  // source -> why it is absent (not given, unreadable, no "figures")
  std::map<std::string, std::string> missing;
};

// The source files under a results folder laid out as scripts/reproduce.sh writes it.
std::map<std::string, std::string> resultsLayout(const std::string& dir);

// Reads every file of `layout` (source -> path); an absent or unreadable one is noted in
// `missing`, never an error: the rows that read it are "not measurable here".
FigureSet loadFigureSet(const std::map<std::string, std::string>& layout);

// The figure `reference` names, or nullopt (unknown source or name).
std::optional<figures::Figure> lookUp(const FigureSet& set, const std::string& reference);

}  // namespace mb::claims
