#include "harness/claims/figure_set.h"

#include <fstream>
#include <iterator>

namespace mb::claims {

using nlohmann::json;

std::map<std::string, std::string> resultsLayout(const std::string& dir) {
  const std::string d = dir.empty() || dir.back() == '/' ? dir : dir + "/";
  return {{"report", d + "report.json"},         {"ops", d + "ops.json"},
          {"morph", d + "morph.json"},           {"accuracy", d + "accuracy.json"},
          {"graphs", d + "corpus-graph.json"},   {"corpus", d + "corpus/report.json"},
          {"corpus_accuracy", d + "corpus/accuracy.json"}};
}

FigureSet loadFigureSet(const std::map<std::string, std::string>& layout) {
  FigureSet set;
  for (const auto& [source, path] : layout) {
    set.files[source] = path;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      set.missing[source] = path + ": not found";
      continue;
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
      set.missing[source] = path + ": not JSON";
    } else if (!j.contains("figures") || !j["figures"].is_object()) {
      set.missing[source] = path + ": no \"figures\" (written by an older motorbench?)";
    } else {
      set.figures[source] = j["figures"];
    }
    if (source == "report" && j.is_object()) set.report = j;
  }
  return set;
}

std::optional<figures::Figure> lookUp(const FigureSet& set, const std::string& reference) {
  const auto colon = reference.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const auto it = set.figures.find(reference.substr(0, colon));
  if (it == set.figures.end()) return std::nullopt;
  return figures::figureNamed(it->second, reference.substr(colon + 1));
}

}  // namespace mb::claims
