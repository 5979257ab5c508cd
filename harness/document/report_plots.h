// The report's plots: scripts/plot.py (python3 + matplotlib) reads report.json and writes
// PNGs and an index (plots/index.json) into the report folder. When python or matplotlib is
// missing the report says so and goes on without plots.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::document {

// scripts/plot.py of the source tree this binary was built from (MB_PLOT_SCRIPT overrides).
std::string defaultPlotScript();

// /usr/bin/python3 when present (where Debian's python3-matplotlib, installed by
// scripts/setup.sh, lives, even when another python3 comes first on PATH), else "python3".
std::string defaultPython();

// Runs `python script reportJson outDir/plots`. Returns {"available": bool, "error": null or
// why not, "index": "plots/index.json" (where each plot's bars are listed as drawn), "files":
// [{"name", "file" (relative to outDir), "title", "caption"}...]}.
nlohmann::json makePlots(const std::string& python, const std::string& script,
                         const std::string& reportJson, const std::string& outDir);

}  // namespace mb::document
