// pond bench in a build without Vulkan: the GPU's figures are skipped, and the report says so.
#include "app/bench/gpu_figures.h"

namespace pond::bench {

void measure_gpu_groups(const Plan& plan, Progress&, Report& report) {
  if (plan.runs("gpu") || plan.runs("frame") || plan.runs("bodies"))
    report.notes.push_back("the GPU's figures skipped: this build has no Vulkan");
}

}  // namespace pond::bench
