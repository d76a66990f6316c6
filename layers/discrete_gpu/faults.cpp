// Faults on demand (layer.h, Faults): POND_DISCRETE_GPU_FAULT names them, comma-separated:
//   device-lost@submit:N            the Nth vkQueueSubmit(2) returns VK_ERROR_DEVICE_LOST, and that
//                                   device stays lost: every later call on it that may return
//                                   VK_ERROR_DEVICE_LOST does
//   out-of-device-memory@allocate:N the Nth vkAllocateMemory returns VK_ERROR_OUT_OF_DEVICE_MEMORY
//   out-of-host-memory@allocate:N   ... VK_ERROR_OUT_OF_HOST_MEMORY
// N counts from 1 over the whole process (every instance and device: the library is never
// unloaded), so a device created after the fault works: an application that recreates its device
// after a loss goes on.
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "layer.h"

namespace pond::layer {
namespace {

struct Fault {
  FaultKind kind;
  bool at_submit;     // else at vkAllocateMemory
  std::uint64_t nth;  // 1-based
};

// The faults of POND_DISCRETE_GPU_FAULT, parsed once; `error` says what is wrong with it.
struct FaultPlan {
  std::vector<Fault> faults;
  std::string error;
};

FaultPlan parse_plan() {
  FaultPlan plan;
  const char* text = std::getenv("POND_DISCRETE_GPU_FAULT");
  if (!text || !*text) return plan;
  const std::string all = text;
  std::size_t start = 0;
  while (start <= all.size()) {
    const std::size_t comma = all.find(',', start);
    const std::string item = all.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    start = comma == std::string::npos ? all.size() + 1 : comma + 1;
    const std::size_t at = item.find('@'), colon = item.find(':');
    if (at == std::string::npos || colon == std::string::npos || colon < at) {
      plan.error = "'" + item + "' is not KIND@POINT:N";
      return plan;
    }
    const std::string kind = item.substr(0, at), point = item.substr(at + 1, colon - at - 1), n = item.substr(colon + 1);
    Fault f{};
    if (kind == "device-lost" && point == "submit") {
      f = {FaultKind::device_lost, true, 0};
    } else if (kind == "out-of-device-memory" && point == "allocate") {
      f = {FaultKind::out_of_device_memory, false, 0};
    } else if (kind == "out-of-host-memory" && point == "allocate") {
      f = {FaultKind::out_of_host_memory, false, 0};
    } else {
      plan.error = "'" + item + "': the faults are device-lost@submit:N, out-of-device-memory@allocate:N and "
                   "out-of-host-memory@allocate:N";
      return plan;
    }
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(n.c_str(), &end, 10);
    if (n.empty() || n[0] == '-' || *end != '\0' || errno == ERANGE || v == 0) {
      plan.error = "'" + item + "': N must be a whole number from 1";
      return plan;
    }
    f.nth = v;
    plan.faults.push_back(f);
  }
  return plan;
}

const FaultPlan& plan() {
  static const FaultPlan p = parse_plan();
  return p;
}

std::atomic<std::uint64_t> g_submits{0}, g_allocations{0};

// The fault planned for the `nth` call at a submit (or an allocation), if any.
const Fault* planned(bool at_submit, std::uint64_t nth) {
  for (const Fault& f : plan().faults)
    if (f.at_submit == at_submit && f.nth == nth) return &f;
  return nullptr;
}

}  // namespace

bool fault_plan_ok() {
  if (plan().error.empty()) return true;
  report("POND_DISCRETE_GPU_FAULT: %s; no device created", plan().error.c_str());
  return false;
}

bool submit_fault(DeviceState& d) {
  if (d.lost) return true;
  const std::uint64_t nth = ++g_submits;
  const Fault* f = planned(true, nth);
  if (!f) return false;
  // What the driver already runs finishes first: the application frees what those submissions use
  // once it knows the device is gone, as it may on a real lost device.
  d.next.device_wait_idle(d.handle);
  d.lost = true;
  report("fault injected: the device is lost at submit %llu", static_cast<unsigned long long>(nth));
  return true;
}

VkResult allocation_fault() {
  const std::uint64_t nth = ++g_allocations;
  const Fault* f = planned(false, nth);
  if (!f) return VK_SUCCESS;
  const bool device = f->kind == FaultKind::out_of_device_memory;
  report("fault injected: vkAllocateMemory %llu is out of %s memory", static_cast<unsigned long long>(nth),
         device ? "device" : "host");
  return device ? VK_ERROR_OUT_OF_DEVICE_MEMORY : VK_ERROR_OUT_OF_HOST_MEMORY;
}

}  // namespace pond::layer
