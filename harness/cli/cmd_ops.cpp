// `motorbench ops [--json FILE]`: counts the arithmetic of every kernel of shaders/pga.glsl and
// of the matrix equivalents by executing them on the op-counting scalar (mb::Counted), and
// prints them next to the paper's claims.
#include <cstdio>
#include <string>
#include <vector>

#include "harness/options/args.h"
#include "harness/cli/command.h"
#include "harness/cli/output_paths.h"
#include "harness/process/progress.h"
#include "harness/ops/op_count.h"
#include "harness/ops/op_kernels.h"
#include "harness/ops/ops_figures.h"
#include "harness/isa/isa_ops.h"
#include "harness/ops/ops_vertex.h"
#include "harness/ops/pipeline_ops.h"

namespace {

int runOps(const std::vector<std::string>& argv) {
  const mb::options::Args args(argv, {{"json"}, {}, {}});
  if (!args.error().empty()) {
    std::fprintf(stderr, "motorbench ops: %s\n", args.error().c_str());
    return 2;
  }
  if (!args.positional().empty()) {
    std::fprintf(stderr, "motorbench ops: unexpected argument '%s'\n", args.positional()[0].c_str());
    return 2;
  }
  if (const auto path = args.get("json"))  // checked (folder made) before anything is counted
    if (mb::Status ok = mb::prepareOutputFile("--json", *path); !ok) {
      std::fprintf(stderr, "motorbench ops: %s\n", ok.error().c_str());
      return 2;
    }
  // Four steps, about a minute in all (the SPIR-V and ISA compiles): a line on stderr after each,
  // so a silent terminal never looks hung.
  mb::process::Progress progress("ops", "steps done", 4, false);
  const std::vector<mb::ops::Row> rows = mb::ops::measureAll(mb::ops::allKernels());
  progress.done("kernels counted (" + std::to_string(rows.size()) + ")");

  std::printf("Arithmetic per kernel, counted by executing shaders/pga.glsl and the GLSL matrix\n"
              "operators on an op-counting scalar (subtraction = add, negation free).\n"
              "claimed: the paper's mul/add ('paper(x)': stated for the x axis; 'ref-src': a\n"
              "comment in the reference implementation); agree: measured mul and add equal it.\n\n");
  std::fputs(mb::ops::formatTable(rows).c_str(), stdout);
  int disagree = 0;
  for (const auto& r : rows) disagree += r.agree() == "NO";
  std::printf("\n%d kernel(s) disagree with their claim.\n\n", disagree);
  std::fputs(mb::ops::formatListings(rows).c_str(), stdout);

  // Per-vertex transforms of each pipeline, counted and from SPIR-V (harness/ops/ops_vertex.h).
  const mb::opsv::VertexOps perVertex = mb::opsv::measureVertexOps();
  progress.done("per-vertex transforms counted and compiled to SPIR-V");
  std::printf("\n");
  std::fputs(mb::opsv::formatVertexOps(perVertex).c_str(), stdout);
  const std::vector<mb::opsv::PipelineOps> perPipeline = mb::opsv::pipelineOps(perVertex);
  progress.done("per-pipeline ops");
  std::printf("\n");
  std::fputs(mb::opsv::formatPipelineOps(perPipeline).c_str(), stdout);

  // The same variants as AMD's compiler builds them (harness/isa), when RADV is installed.
  std::fflush(stdout);
  const auto isa = mb::isa::runIsa({});
  progress.done(isa ? "AMD ISA compiled (RADV)" : "no AMD ISA (" + isa.error() + ")");
  if (isa) std::fputs(mb::isa::formatIsaBesideOps(perVertex, *isa).c_str(), stdout);
  else std::printf("\nNo ISA columns: %s\n", isa.error().c_str());

  if (const auto path = args.get("json")) {
    nlohmann::json j = {
        {"tool", "motorbench ops"},
        {"counting", "mb::Counted: mul, add (incl. subtraction), div, sqrt, other built-in calls; "
                     "negation and comparisons free"},
        {"source", "shaders/pga.glsl"},
        {"kernels", mb::ops::toJson(rows)},
        {"per_vertex", mb::opsv::toJson(perVertex)},
        {"per_pipeline", mb::opsv::toJson(perPipeline)},
        {"isa", isa ? mb::isa::isaBesideOpsJson(perVertex, *isa) : nlohmann::json{{"error", isa.error()}}},
        // Every count above (and the listings and pieces claims quote) as named figures.
        {"figures", mb::ops::opsFigures(rows, perVertex)},
    };
    if (mb::Status ok = mb::writeTextFile(*path, j.dump(2) + "\n"); !ok) {
      std::fprintf(stderr, "motorbench ops: %s\n", ok.error().c_str());
      return 2;
    }
  }
  return 0;
}

}  // namespace

MB_COMMAND(ops, "ops", "[--json FILE]",
           "count mul/add/div/sqrt per PGA kernel and matrix op, next to the paper's claims; ops per "
           "vertex of each pipeline, counted and from SPIR-V", runOps);
MB_COMMAND_HELP(ops, "ops",
               "  --json FILE        every count as JSON (and as named figures: \"figures\")\n",
                "motorbench ops --json out/ops.json", false);
