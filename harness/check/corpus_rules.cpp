#include "harness/check/corpus_rules.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "harness/check/corpus_junit.h"
#include "harness/check/corpus_tables.h"
#include "harness/options/args.h"
#include "harness/process/interrupt.h"
#include "harness/process/progress.h"
#include "harness/process/report_workers.h"
#include "harness/render/frame_options.h"
#include "harness/render/scene_inputs.h"

namespace mb::check {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> paths;
  std::string size = "128x128";
  int jobs = 1;
  double timeoutS = 300;
  std::string out = "out/corpus-check";
  std::string junit;
  std::string exe = "/proc/self/exe";  // this very binary, even if a rebuild replaces its file
  bool quiet = false;
  RuleSet set;
};

// The path as os.path.abspath makes it: absolute, normalised, no trailing separator.
std::string absolutePath(const std::string& p) {
  std::string s = fs::absolute(p).lexically_normal().string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

// {absolute path: features} from the MANIFEST.tsv (columns path, features) of each folder given.
std::map<std::string, std::string> manifestFeatures(const std::vector<std::string>& paths) {
  std::map<std::string, std::string> features;
  for (const std::string& p : paths) {
    std::ifstream in(fs::path(p) / "MANIFEST.tsv");
    if (!fs::is_directory(p) || !in) continue;
    auto cells = [](const std::string& line) {
      std::vector<std::string> out;
      std::stringstream s(line);
      for (std::string c; std::getline(s, c, '\t');) out.push_back(c);
      return out;
    };
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> head = cells(line);
    const auto column = [&](const char* name) { return size_t(std::find(head.begin(), head.end(), name) - head.begin()); };
    const size_t path = column("path"), feat = column("features");
    while (std::getline(in, line)) {
      const std::vector<std::string> row = cells(line);
      if (path < row.size()) features[absolutePath((fs::path(p) / row[path]).string())] = feat < row.size() ? row[feat] : "";
    }
  }
  return features;
}

// The folder the rows' file names are relative to: the common folder of several inputs, the
// folder given, or a single file's folder.
std::string commonRoot(const std::vector<std::string>& paths) {
  std::vector<fs::path> roots;
  for (const std::string& p : paths) roots.push_back(absolutePath(p));
  if (roots.size() == 1) return fs::is_directory(roots[0]) ? roots[0].string() : roots[0].parent_path().string();
  fs::path common;
  for (auto a = roots[0].begin(); a != roots[0].end(); ++a) {
    fs::path next = common / *a;
    const bool everyOne = std::all_of(roots.begin(), roots.end(), [&](const fs::path& r) {
      auto it = r.begin();
      for (auto c = next.begin(); c != next.end(); ++c, ++it)
        if (it == r.end() || *it != *c) return false;
      return true;
    });
    if (!everyOne) break;
    common = next;
  }
  return common.string();
}

std::string tail(const std::string& path, size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.size() > bytes ? text.substr(text.size() - bytes) : text;
}

// How runProgram said the worker ended ("" / "exit status 2" / "killed by signal 11 (...)" /
// "timed out after 300 s" / "could not be started" / "interrupted (SIGINT)"), as the record.
void readEnd(const std::string& how, WorkerRecord& rec) {
  int n = 0;
  if (how.empty()) rec.exit = 0;
  else if (std::sscanf(how.c_str(), "exit status %d", &n) == 1) rec.exit = n;
  else if (std::sscanf(how.c_str(), "killed by signal %d", &n) == 1) {
    const char* abbrev = sigabbrev_np(n);
    rec.signal = abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(n);
  } else if (how.rfind("timed out", 0) == 0) rec.timeout = true, rec.signal = "SIGKILL";
  else if (how.rfind("interrupted", 0) == 0) rec.signal = process::interruptName();
  else rec.stderrTail = how;
}

// One survey worker over `file` (`pipelines` empty: every one of its space).
WorkerRecord runSurvey(const Options& o, const std::string& file, const std::vector<std::string>& pipelines,
                              const std::string& scratch) {
  const std::string out = scratch + ".json", log = scratch + ".log";
  std::vector<std::string> args = {"survey", file, "--size", o.size, "-o", out};
  std::string list;
  for (const std::string& p : pipelines) list += (list.empty() ? "" : ",") + p;
  if (!pipelines.empty()) args.insert(args.end(), {"--pipelines", list});
  std::remove(out.c_str());
  const auto t0 = Clock::now();
  WorkerRecord rec;
  const std::string how = process::runProgram(o.exe, args, log, true, o.timeoutS);
  rec.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  readEnd(how, rec);
  rec.stderrTail = tail(log, 2000) + (rec.stderrTail.empty() ? "" : "\n" + rec.stderrTail);
  std::error_code ec;
  if (rec.signal.is_null() && !rec.timeout && fs::exists(out) && fs::file_size(out, ec) > 0) {
    std::ifstream in(out);
    ojson doc = ojson::parse(in, nullptr, false);
    if (doc.is_discarded()) rec.stderrTail += "\n" + out + ": not a JSON document";
    else rec.doc = std::move(doc);
  }
  std::remove(out.c_str());
  std::remove(log.c_str());
  return rec;
}

// A file's result; a crashed worker's pipelines retried one process each (with the matrix
// baseline each is compared against), so the crash is pinned on a pipeline.
ojson surveyFile(const Options& o, const std::string& file, const std::string& rel, const std::string& features,
                 const std::string& scratch) {
  ojson res = fileResult(rel, runSurvey(o, file, o.set.pipelines, scratch), features, o.set);
  if (res["status"] != "crashed") return res;
  std::vector<std::string> alone = {"matrix"}, crashed;
  alone.insert(alone.end(), o.set.fullPrecision.begin(), o.set.fullPrecision.end());
  alone.insert(alone.end(), o.set.compact.begin(), o.set.compact.end());
  for (const std::string& name : alone) {
    const WorkerRecord one = runSurvey(o, file, {name}, scratch + "-" + name);
    const ojson sub = fileResult(rel, one, features, o.set);
    if (sub["status"] == "crashed") {
      crashed.push_back(name);
      res["rows"].push_back(crashedRow(rel, name, one, sub["error"]));
      continue;
    }
    for (const ojson& r : sub["rows"])
      if (r["pipeline"] == name) res["rows"].push_back(r);
    for (const char* k : {"kind", "boundPixels", "boundWorld", "envelopeRadius", "frames", "loaderFallbacks", "scene"})
      if (!res.contains(k)) res[k] = member(sub, k);
  }
  res["crashedPipelines"] = crashed;
  res["error"] = res["error"].get<std::string>() + " (alone: " + (crashed.empty() ? "none" : joinNames(crashed)) + " crashed)";
  return res;
}

// "check --rules: [12/158] a/b.glb: ok 1.2 s, 14 s elapsed, about 5 min left".
std::string progressLine(size_t done, size_t total, const ojson& res, double elapsed) {
  std::string status = res["status"].get<std::string>();
  if (status != "ok") status += " (" + valueText(res["error"]) + ")";
  std::string line = "check --rules: [" + std::to_string(done) + "/" + std::to_string(total) + "] " +
                     res["file"].get<std::string>() + ": " + status + printed(" %.1f s", res["seconds"].get<double>()) +
                     ", " + process::durationText(elapsed) + " elapsed";
  if (done < total) line += ", about " + process::durationText(elapsed / double(done) * double(total - done)) + " left";
  return line;
}

std::vector<ojson> surveyAll(const Options& o, const std::vector<std::string>& files) {
  const std::map<std::string, std::string> features = manifestFeatures(o.paths);
  const std::string common = commonRoot(o.paths);
  char pattern[] = "/tmp/check-rules-XXXXXX";
  const std::string scratch = mkdtemp(pattern) ? pattern : "/tmp";
  std::vector<ojson> results(files.size());
  std::atomic<size_t> next{0};
  std::mutex lock;
  size_t done = 0;
  const auto t0 = Clock::now();
  auto work = [&] {
    for (size_t i = next++; i < files.size(); i = next++) {
      const std::string abs = absolutePath(files[i]);
      const std::string rel = fs::path(abs).lexically_relative(common).string();
      const auto f = features.find(abs);
      ojson res = surveyFile(o, files[i], rel, f == features.end() ? "" : f->second, scratch + "/" + std::to_string(i));
      std::lock_guard<std::mutex> g(lock);
      ++done;
      if (!o.quiet) {
        std::fprintf(stderr, "%s\n",
                     progressLine(done, files.size(), res, std::chrono::duration<double>(Clock::now() - t0).count()).c_str());
        std::fflush(stderr);
      }
      results[i] = std::move(res);
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::max(1, std::min<int>(o.jobs, int(files.size()))); ++j) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  std::error_code ec;
  fs::remove_all(scratch, ec);
  return results;
}

// The folder `path` is created when missing and must take a file.
std::string prepareFolder(const std::string& option, const std::string& path) {
  std::error_code ec;
  if (fs::exists(path) && !fs::is_directory(path)) return option + " " + path + ": a file, not a folder";
  fs::create_directories(path, ec);
  if (ec) return option + " " + path + ": cannot create folder (" + ec.message() + ")";
  if (access(path.c_str(), W_OK) != 0) return option + " " + path + ": folder not writable";
  return "";
}

std::string prepareFile(const std::string& option, const std::string& path) {
  if (fs::is_directory(path)) return option + " " + path + ": a folder, not a file";
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) {
    std::string why = prepareFolder(option, parent.string());
    if (!why.empty()) return why;
  }
  return "";
}

// The options, or the error ("" when they parsed) in `error`.
Options parseOptions(const std::vector<std::string>& argv, std::string& error) {
  Options o;
  options::Args args(argv, options::OptionSpec{{"pipelines", "size", "jobs", "timeout", "min-psnr", "max-drawn-diff", "out", "o", "junit",
                              "worker-exe"},
                             {"rules", "quiet"},
                             {},
                             {}});
  if (!args.error().empty()) return error = args.error(), o;
  o.paths = args.positional();
  if (o.paths.empty()) return error = "--rules: expected FILE|DIR... (folders are searched for .gltf/.glb files)", o;
  for (const std::string& p : o.paths)
    if (!fs::exists(p)) return error = p + ": no such file or folder", o;
  const auto [w, h] = args.size("size", 128, 128);
  o.size = std::to_string(w) + "x" + std::to_string(h);
  o.jobs = int(args.integer("jobs", std::max(1u, std::thread::hardware_concurrency()), 1, 256));
  o.timeoutS = args.real("timeout", 300, 1, 86400, "seconds per worker");
  const std::vector<std::string> only = splitList(args.get("pipelines", ""));
  if (args.has("pipelines") && only.empty()) return error = "--pipelines: expected pipeline names, e.g. matrix,motor", o;
  if (Status ok = checkPipelineNames("--pipelines", only); !ok) return error = ok.error(), o;
  o.set = defaultRuleSet(only);
  o.set.minPsnr = args.real("min-psnr", 50, 0, 1000, "a PSNR in dB");
  o.set.maxDrawnDiff = args.real("max-drawn-diff", 0.01, 0, 0.5, "a fraction of the drawn pixels (0.01 is 1 %)");
  o.out = args.get("out", args.get("o", o.out));
  o.junit = args.get("junit", "");
  o.quiet = args.has("quiet");
  o.exe = args.get("worker-exe", o.exe);
  if (args.has("worker-exe") && access(o.exe.c_str(), X_OK) != 0) return error = "--worker-exe " + o.exe + ": not an executable", o;
  if (std::string why = prepareFolder("--out", o.out); !why.empty()) return error = why, o;
  if (!o.junit.empty())
    if (std::string why = prepareFile("--junit", o.junit); !why.empty()) return error = why, o;
  return o;
}

// "a, b" for one or two inputs, else "N paths under COMMON".
std::string folderText(const std::vector<std::string>& paths) {
  if (paths.size() <= 2) return joinNames(paths);
  return std::to_string(paths.size()) + " paths under " + commonRoot(paths);
}

// --quiet: the failing rules with their lines, and one summary line.
void printQuiet(const Verdicts& v, const ojson& summary) {
  int failed = 0;
  for (const Rule& r : v.rules) {
    if (r.pass()) continue;
    ++failed;
    std::printf("FAIL: %s (%zu)\n", r.name.c_str(), r.failures.size());
    for (const std::string& line : r.failures) std::printf("  - %s\n", line.c_str());
  }
  std::printf("check --rules: %s: %d of %zu rules failed; %s files, %s rows, %s ok, %s no data, %s load failed, %s crashed\n",
              failed ? "FAIL" : "PASS", failed, v.rules.size(), summary["files"].dump().c_str(),
              summary["rows"].dump().c_str(), summary["ok"].dump().c_str(), summary["noData"].dump().c_str(),
              summary["loadFailed"].dump().c_str(), summary["crashed"].dump().c_str());
}

bool writeText(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  return bool(f.flush());
}

}  // namespace

int runCheckRules(const std::vector<std::string>& argv) {
  std::string error;
  Options o;
  try {
    o = parseOptions(argv, error);
  } catch (const options::OptionError& e) {
    error = e.what();
  }
  if (!error.empty()) return commandError("check", error);
  const std::vector<std::string> files = expandSceneInputs(o.paths);  // folders as their .gltf/.glb files
  if (files.empty()) return commandError("check", "no .gltf/.glb files under " + joinNames(o.paths));
  if (o.jobs > 1 && !std::getenv("LP_NUM_THREADS")) {
    // llvmpipe: a share of the CPUs per worker, so that --jobs workers do not contend.
    const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
    setenv("LP_NUM_THREADS", std::to_string(std::max(1u, cpus / unsigned(o.jobs))).c_str(), 1);
  }
  const auto t0 = Clock::now();
  const std::vector<ojson> results = surveyAll(o, files);
  const Verdicts v = evaluate(results, o.set);
  const ojson per = totals(results, pipelinesOfRows(results), o.set);
  const RunFacts facts{folderText(o.paths), o.size, o.jobs,
                              std::chrono::duration<double>(Clock::now() - t0).count()};
  const ojson summary = summaryOf(facts, results, per, o.set);
  const std::string md = markdown(summary, results, per, v, o.set);
  const std::string jsonPath = (fs::path(o.out) / "corpus-check.json").string(),
                    mdPath = (fs::path(o.out) / "corpus-check.md").string();
  if (!writeText(jsonPath, checkDocument(summary, per, v, results).dump(1) + "\n"))
    return commandError("check", jsonPath + ": cannot write");
  if (!writeText(mdPath, md)) return commandError("check", mdPath + ": cannot write");
  if (!o.junit.empty())
    if (Status ok = writeRulesJunit(o.junit, results, o.set); !ok) return commandError("check", ok.error());
  if (o.quiet) printQuiet(v, summary);
  else std::printf("%s\n", md.substr(0, md.find("\n## Files")).c_str());
  std::fflush(stdout);
  std::fprintf(stderr, "motorbench check: wrote %s and corpus-check.json%s\n", mdPath.c_str(),
               o.junit.empty() ? "" : (" and " + o.junit).c_str());
  return v.pass() ? 0 : 1;
}

}  // namespace mb::check
