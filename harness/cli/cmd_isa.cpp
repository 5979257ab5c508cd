// `motorbench isa [--family F,...] [--json FILE] [--isa-text DIR] [--device]`: AMD ISA
// statistics of every pipeline's shaders from Mesa RADV's null device (harness/isa).
#include <cstdio>
#include <string>
#include <vector>

#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/isa/isa_output.h"
#include "harness/isa/isa_run.h"
#include "harness/options/args.h"

namespace {

int runIsaCommand(const std::vector<std::string>& argv) {
  const mb::options::Args args(argv, {{"family", "json", "isa-text", "jobs"}, {"device"}, {}, {"family"}});
  if (!args.error().empty()) {
    std::fprintf(stderr, "motorbench isa: %s\n", args.error().c_str());
    return 2;
  }
  if (!args.positional().empty()) {
    std::fprintf(stderr, "motorbench isa: unexpected argument '%s'\n", args.positional()[0].c_str());
    return 2;
  }
  mb::isa::IsaOptions options;
  options.device = args.has("device");
  options.keepIsaText = args.has("isa-text");
  options.jobs = int(args.integer("jobs", 0, 1, 64));
  if (const auto list = args.get("family")) {
    options.families.clear();
    std::string known;
    for (const auto& f : mb::isa::allFamilies()) known += (known.empty() ? "" : ", ") + f.id();
    size_t start = 0;
    while (start <= list->size()) {
      const size_t comma = std::min(list->find(',', start), list->size());
      const std::string name = list->substr(start, comma - start);
      start = comma + 1;
      bool found = false;
      // "navi21" selects both NGG settings; "navi21-ngg" / "navi21-nonggc" one.
      for (const auto& f : mb::isa::allFamilies())
        if (f.name == name || f.id() == name) options.families.push_back(f), found = true;
      if (!found) {
        std::fprintf(stderr, "motorbench isa: --family: unknown family '%s' (known: %s)\n", name.c_str(), known.c_str());
        return 2;
      }
    }
  }
  // Output paths are checked (and their folders made) before anything is compiled.
  if (const auto path = args.get("json"))
    if (mb::Status ok = mb::prepareOutputFile("--json", *path); !ok) {
      std::fprintf(stderr, "motorbench isa: %s\n", ok.error().c_str());
      return 2;
    }
  auto run = mb::isa::runIsa(options);
  if (!run) {
    std::fprintf(stderr, "motorbench isa: %s\n", run.error().c_str());
    return 2;
  }
  std::fputs(mb::isa::formatTable(*run).c_str(), stdout);
  if (const auto path = args.get("json")) {
    if (mb::Status ok = mb::writeTextFile(*path, mb::isa::toJson(*run).dump(1) + "\n"); !ok) {
      std::fprintf(stderr, "motorbench isa: %s\n", ok.error().c_str());
      return 2;
    }
  }
  if (const auto dir = args.get("isa-text"))
    if (mb::Status s = mb::isa::writeIsaText(*run, *dir); !s) {
      std::fprintf(stderr, "motorbench isa: %s\n", s.error().c_str());
      return 2;
    }
  return 0;
}

}  // namespace

MB_COMMAND(isa, "isa", "[--family F,...] [--json FILE] [--isa-text DIR] [--device] [--jobs N]",
           "AMD ISA statistics (instructions, registers, occupancy) of every pipeline's shaders "
           "from Mesa RADV's null device, GCN 1 to RDNA 3", runIsaCommand);
MB_COMMAND_HELP(isa, "isa",
               "  --family F,...     GPU families (a name selects both NGG settings, e.g. navi21; an id one,\n"
               "                     e.g. navi21-ngg); default: every family, GCN 1 to RDNA 3\n"
               "  --json FILE        every statistic as JSON (missing folders are created; checked first)\n"
               "  --isa-text DIR     the disassembly of every shader, one file each\n"
               "  --device           also every real Vulkan device that reports its statistics (pipeline executable properties)\n"
               "  --jobs N           compiles in parallel (1..64; default: the cores)\n",
                "motorbench isa --family navi21,gfx1100 --json out/isa.json", false);
