#include "core/process_cpu.h"

#include <sys/resource.h>

namespace pond::core {

double process_cpu_ms() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;  // RUSAGE_SELF with a valid pointer cannot fail
  auto ms = [](const timeval& t) { return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_usec) * 1e-3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

}  // namespace pond::core
