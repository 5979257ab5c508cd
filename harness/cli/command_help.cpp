// `motorbench CMD --help` / `motorbench help CMD`: the command's usage, what it does, its
// options one per line, the pipeline names it accepts and one example.
#include <cstdio>
#include <cstring>

#include "harness/cli/command.h"
#include "harness/render/frame_options.h"
#include "pipelines/pipeline.h"

namespace mb {

std::vector<CommandHelp>& commandHelps() {
  static std::vector<CommandHelp> list;
  return list;
}

void printCommandHelp(const Command& c) {
  std::printf("usage: motorbench %s %s\n  %s\n", c.name, c.usage, c.summary);
  for (const CommandHelp& h : commandHelps()) {
    if (std::strcmp(h.name, c.name) != 0) continue;
    std::printf("\noptions:\n%s", h.options);
    if (h.pipelines)
      std::printf("\npipelines: %s (glTF scenes); %s (s3_tiling); %s (h3_tiling)\n",
                  joinNames(pipelineNames(Space::Euclidean)).c_str(), joinNames(pipelineNames(Space::Spherical)).c_str(),
                  joinNames(pipelineNames(Space::Hyperbolic)).c_str());
    std::printf("\nexample:\n  %s\n", h.example);
  }
}

}  // namespace mb
