#include "harness/isa/isa_run.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "harness/ops/spirv_count.h"

namespace mb::isa {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kChildTimeoutSeconds = 300;

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

json executablesJson(const std::vector<ExecutableStats>& exes, bool keepText) {
  json out = json::array();
  for (const ExecutableStats& e : exes) {
    json stats = json::array();
    for (const auto& [k, v] : e.statistics) stats.push_back({k, v});
    out.push_back({{"stage", e.stage}, {"name", e.name}, {"description", e.description},
                   {"subgroupSize", e.subgroupSize}, {"statistics", stats},
                   {"isa", keepText ? e.isaText : std::string()}});
  }
  return out;
}

std::vector<ExecutableStats> executablesFrom(const json& j) {
  std::vector<ExecutableStats> out;
  for (const json& e : j) {
    ExecutableStats x;
    x.stage = e.at("stage");
    x.name = e.at("name");
    x.description = e.at("description");
    x.subgroupSize = e.at("subgroupSize");
    for (const json& s : e.at("statistics")) x.statistics.push_back({s.at(0), s.at(1)});
    x.isaText = e.at("isa");
    out.push_back(std::move(x));
  }
  return out;
}

// Compiles every program on one device; {"programs": [executables...]} or {"error": ...}.
json measureDevice(const Vulkan& vk, VkPhysicalDevice physical, const std::vector<CompiledProgram>& compiled,
                   const std::vector<Program>& programs, bool keepText) {
  auto device = StatsDevice::open(vk, physical);
  if (!device) return {{"error", device.error()}};
  json list = json::array();
  for (size_t i = 0; i < compiled.size(); ++i) {
    auto r = (*device)->compile(compiled[i].vertex, compiled[i].fragment,
                                programs[i].pipeline + " " + programs[i].program);
    if (!r) return {{"error", r.error()}};
    list.push_back(executablesJson(*r, keepText));
  }
  return {{"programs", list}};
}

// The child's work. family == nullptr: --device (every hardware device with the extension).
json childWork(const Family* family, const std::vector<CompiledProgram>& compiled,
               const std::vector<Program>& programs, bool keepText) {
  Vulkan vk;
  if (Status s = openLoader(vk); !s) return {{"error", s.error()}};
  if (Status s = createInstance(vk); !s) return {{"error", s.error()}};
  const auto devices = listDevices(vk);
  if (family) {
    std::string seen;
    for (const auto& [physical, info] : devices) {
      seen += (seen.empty() ? "" : ", ") + info.deviceName;
      if (info.driverId != VK_DRIVER_ID_MESA_RADV) continue;
      if (info.deviceName.find(upper(family->name)) == std::string::npos) continue;
      if (!info.executableProperties)
        return {{"error", info.deviceName + " does not offer VK_KHR_pipeline_executable_properties"}};
      json r = measureDevice(vk, physical, compiled, programs, keepText);
      r["device"] = info.deviceName;
      r["driver"] = info.driverInfo;
      return r;
    }
    return {{"error", "RADV made no device for RADV_FORCE_FAMILY=" + family->name +
                          " (devices seen: " + (seen.empty() ? "none" : seen) + ")"}};
  }
  json measured = json::array();
  std::string seen;
  for (const auto& [physical, info] : devices) {
    const bool cpu = info.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    seen += (seen.empty() ? "" : "; ") + info.deviceName + " (" + info.driverName +
            (cpu ? ", a CPU driver" : "") +
            (info.executableProperties ? "" : ", no VK_KHR_pipeline_executable_properties") + ")";
    if (cpu || !info.executableProperties) continue;
    json r = measureDevice(vk, physical, compiled, programs, keepText);
    r["device"] = info.deviceName;
    r["driver"] = info.driverName + " " + info.driverInfo;
    measured.push_back(r);
  }
  return {{"devices", measured}, {"seen", seen.empty() ? "no Vulkan device" : seen}};
}

// Sets the child's environment: the family's RADV switches, or (device == true) none of them.
void childEnvironment(const Family* family, const std::string& manifest) {
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);  // compile, never load a cached binary
  if (!family) {
    unsetenv("RADV_FORCE_FAMILY");
    return;
  }
  setenv("VK_DRIVER_FILES", manifest.c_str(), 1);
  setenv("VK_ICD_FILENAMES", manifest.c_str(), 1);
  setenv("RADV_FORCE_FAMILY", family->name.c_str(), 1);
  if (family->nggSetting && !family->ngg) setenv("RADV_DEBUG", "nonggc", 1);
  else unsetenv("RADV_DEBUG");
}

struct Child {
  pid_t pid = -1;
  fs::path result, log;
  std::chrono::steady_clock::time_point started;
};

Child startChild(const Family* family, const std::string& manifest, const fs::path& dir,
                 const std::string& tag, const std::vector<CompiledProgram>& compiled,
                 const std::vector<Program>& programs, bool keepText) {
  Child c;
  c.result = dir / (tag + ".json");
  c.log = dir / (tag + ".log");
  std::fflush(nullptr);
  c.pid = fork();
  if (c.pid == 0) {
    // The driver's warnings (non-conformant, missing disassembler) go to the log, not the user.
    int fd = open(c.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) dup2(fd, STDERR_FILENO), dup2(fd, STDOUT_FILENO), close(fd);
    childEnvironment(family, manifest);
    const json r = childWork(family, compiled, programs, keepText);
    std::ofstream out(c.result, std::ios::binary);
    out << r.dump();
    out.close();
    _exit(out ? 0 : 3);
  }
  c.started = std::chrono::steady_clock::now();
  return c;
}

// Waits for the child; its JSON, or an error naming what it said or how it ended.
Result<json> finishChild(Child& c, const std::string& what) {
  int status = 0;
  for (;;) {
    pid_t r = waitpid(c.pid, &status, WNOHANG);
    if (r == c.pid) break;
    if (r < 0) return Result<json>::fail(what + ": lost the child process");
    if (std::chrono::steady_clock::now() - c.started > std::chrono::seconds(kChildTimeoutSeconds)) {
      kill(c.pid, SIGKILL);
      waitpid(c.pid, &status, 0);
      return Result<json>::fail(what + ": no answer in " + std::to_string(kChildTimeoutSeconds) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const std::string log = readText(c.log);
  const std::string tail = log.size() > 2000 ? log.substr(log.size() - 2000) : log;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return Result<json>::fail(what + ": the compiling process " +
                              (WIFSIGNALED(status) ? "died of signal " + std::to_string(WTERMSIG(status))
                                                   : "exited " + std::to_string(WEXITSTATUS(status))) +
                              (tail.empty() ? "" : "; driver output:\n" + tail));
  json j = json::parse(readText(c.result), nullptr, false);
  if (j.is_discarded()) return Result<json>::fail(what + ": unreadable result from the compiling process");
  if (j.contains("error")) return Result<json>::fail(what + ": " + j["error"].get<std::string>());
  return j;
}

std::vector<std::string> splitPaths(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string p; std::getline(in, p, ':');)
    if (!p.empty()) out.push_back(p);
  return out;
}

}  // namespace

long long ShaderStats::stat(const std::string& name) const {
  for (const auto& [k, v] : exe.statistics)
    if (k == name && v.is_number()) return v.get<long long>();
  return -1;
}

int ShaderStats::wavesPerSimd(const Family& f) const {
  Registers r;
  r.vgprs = int(stat("VGPRs"));
  r.sgprs = int(stat("SGPRs"));
  r.waveSize = int(exe.subgroupSize);
  r.fragment = exe.stage == "fragment";
  r.interpolants = interpolants;
  return isa::wavesPerSimd(f, r);
}

Result<std::string> radvManifest() {
  for (const char* var : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES"}) {
    const char* v = std::getenv(var);
    if (!v || !*v) continue;
    for (const std::string& p : splitPaths(v))
      if (!fs::exists(p))
        return Result<std::string>::fail(std::string(var) + " names " + p +
                                         ", which does not exist: no RADV driver to compile with");
    return std::string(v);
  }
  std::vector<std::string> dirs;
  const char* xdg = std::getenv("XDG_DATA_DIRS");
  // The loader's search folders: $XDG_DATA_DIRS (default /usr/local/share:/usr/share), /etc.
  std::vector<std::string> roots = splitPaths(xdg && *xdg ? xdg : "");
  for (const char* d : {"/usr/local/share", "/usr/share"})
    if (std::find(roots.begin(), roots.end(), d) == roots.end()) roots.push_back(d);
  for (const std::string& d : roots) dirs.push_back(d + "/vulkan/icd.d");
  dirs.push_back("/etc/vulkan/icd.d");
  for (const std::string& d : dirs) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(d, ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("radeon_icd.", 0) == 0 && e.path().extension() == ".json") return e.path().string();
    }
  }
  std::string searched;
  for (const std::string& d : dirs) searched += (searched.empty() ? "" : ", ") + d;
  return Result<std::string>::fail("RADV, Mesa's Vulkan driver for AMD, is not installed: no radeon_icd.*.json in " +
                                   searched + " (install mesa-vulkan-drivers)");
}

Result<IsaRun> runIsa(const IsaOptions& options) {
  using R = Result<IsaRun>;
  IsaRun run;
  run.programs = allPrograms();
  auto manifest = radvManifest();
  if (!manifest) return R::fail(manifest.error());

  std::vector<CompiledProgram> compiled;
  std::vector<int> interpolants;
  for (Program& p : run.programs) {
    auto c = compileProgram(p);
    if (!c) return R::fail(c.error());
    interpolants.push_back(int(c->fragment.interface.inputs.size()));
    p.varyingSlots = interpolants.back();
    for (const VertexInput& in : c->fragment.interface.inputs) p.varyingComponents += int(in.components);
    compiled.push_back(c.take());
  }
  spirv::TempDir dir("motorbench-isa");
  if (dir.path.empty()) return R::fail("cannot create a temporary folder");

  // Families (and --device last) in child processes, `jobs` at a time.
  const size_t jobs = size_t(options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency()));
  const size_t tasks = options.families.size() + (options.device ? 1 : 0);
  std::vector<Child> children(tasks);
  std::vector<Result<nlohmann::json>> results(tasks, Result<nlohmann::json>::fail("not run"));
  auto what = [&](size_t i) {
    return i < options.families.size() ? "RADV_FORCE_FAMILY=" + options.families[i].name +
                                             (options.families[i].nggSetting && !options.families[i].ngg ? " RADV_DEBUG=nonggc" : "")
                                       : std::string("--device");
  };
  size_t next = 0, done = 0;
  std::vector<size_t> running;
  while (done < tasks) {
    while (next < tasks && running.size() < jobs) {
      const Family* f = next < options.families.size() ? &options.families[next] : nullptr;
      children[next] = startChild(f, *manifest, dir.path, "task" + std::to_string(next), compiled,
                                  run.programs, options.keepIsaText);
      if (children[next].pid < 0) return R::fail("cannot start a child process (fork failed)");
      running.push_back(next++);
    }
    const size_t i = running.front();
    running.erase(running.begin());
    results[i] = finishChild(children[i], what(i));
    ++done;
  }
  for (size_t i = 0; i < tasks; ++i)
    if (!results[i]) return R::fail(results[i].error());

  for (size_t f = 0; f < options.families.size(); ++f) {
    const nlohmann::json& j = *results[f];
    run.families.push_back({options.families[f], j.at("device")});
    if (run.driver.empty()) run.driver = j.at("driver");
    const nlohmann::json& progs = j.at("programs");
    for (size_t p = 0; p < progs.size(); ++p)
      for (ExecutableStats& e : executablesFrom(progs[p])) {
        const int inputs = e.stage == "fragment" ? interpolants[p] : 0;
        run.shaders.push_back({p, f, std::move(e), inputs});
      }
  }
  auto order = [](const ShaderStats& a, const ShaderStats& b) {
    const int sa = a.exe.stage == "vertex" ? 0 : 1, sb = b.exe.stage == "vertex" ? 0 : 1;
    return std::tie(a.program, sa, a.family) < std::tie(b.program, sb, b.family);
  };
  std::stable_sort(run.shaders.begin(), run.shaders.end(), order);

  if (options.device) {
    run.deviceAsked = true;
    const nlohmann::json& j = *results.back();
    run.deviceNote = j.at("seen");
    const nlohmann::json& devs = j.at("devices");
    for (size_t d = 0; d < devs.size(); ++d) {
      DeviceRun dr{devs[d].at("device"), devs[d].at("driver"), {}};
      if (devs[d].contains("error")) return R::fail("--device " + dr.device + ": " + devs[d]["error"].get<std::string>());
      const nlohmann::json& progs = devs[d].at("programs");
      for (size_t p = 0; p < progs.size(); ++p)
        for (ExecutableStats& e : executablesFrom(progs[p])) dr.shaders.push_back({p, d, std::move(e), 0});
      std::stable_sort(dr.shaders.begin(), dr.shaders.end(), order);
      run.devices.push_back(std::move(dr));
    }
  }
  return run;
}

}  // namespace mb::isa
