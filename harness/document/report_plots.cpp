#include "harness/document/report_plots.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/process/report_workers.h"

namespace mb::document {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The last lines of the plot log: python's traceback ends with the reason.
std::string tail(const std::string& path, size_t lines) {
  std::ifstream in(path);
  std::vector<std::string> all;
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) all.push_back(l);
  std::string out;
  for (size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i)
    out += (out.empty() ? "" : " | ") + all[i];
  return out;
}

}  // namespace

std::string defaultPlotScript() {
  if (const char* env = std::getenv("MB_PLOT_SCRIPT")) return env;
  // MB_SOURCE_DIR is the source tree (harness/document/CMakeLists.txt).
  return (fs::path(MB_SOURCE_DIR) / "scripts" / "plot.py").string();
}

std::string defaultPython() {
  std::error_code ec;
  return fs::exists("/usr/bin/python3", ec) ? "/usr/bin/python3" : "python3";
}

json makePlots(const std::string& pythonArg, const std::string& script, const std::string& reportJson,
               const std::string& outDir) {
  json r = {{"available", false}, {"error", nullptr}, {"files", json::array()}};
  const std::string python = pythonArg.empty() ? defaultPython() : pythonArg;
  const std::string s = script.empty() ? defaultPlotScript() : script;
  std::error_code ec;
  if (!fs::is_regular_file(s, ec)) {
    r["error"] = "plot script " + s + " not found";
    return r;
  }
  const fs::path plots = fs::path(outDir) / "plots";
  fs::create_directories(plots, ec);
  const std::string log = (plots / "plot.log").string();
  const std::string how = process::runProgram(python, {s, reportJson, plots.string()}, log, true, 600);
  if (!how.empty()) {
    const std::string why = tail(log, 2);
    r["error"] = python + " " + s + ": " + how + (why.empty() ? "" : ": " + why);
    if (how == "could not be started") r["error"] = python + " not found: no plots (install python3 and python3-matplotlib)";
    return r;
  }
  std::ifstream in(plots / "index.json");
  json index = json::parse(in, nullptr, false);
  if (index.is_discarded() || !index.is_object()) {
    r["error"] = (plots / "index.json").string() + ": missing or not JSON";
    return r;
  }
  if (index.contains("error") && !index["error"].is_null()) r["error"] = index["error"];
  r["index"] = "plots/index.json";  // each plot's bars as drawn ("bars"), kept there only
  for (json f : index.value("files", json::array())) {
    f["file"] = "plots/" + f.value("file", "");
    f.erase("bars");
    r["files"].push_back(f);
  }
  r["available"] = !r["files"].empty();
  fs::remove(log, ec);
  return r;
}

}  // namespace mb::document
