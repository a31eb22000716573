#include "dslam/ros/heap_report.h"

#include <dlfcn.h>
#include <malloc.h>

#include <cstdint>
#include <cstdio>

namespace dslam {
namespace ros_layer {
namespace {

using Mallctl = int (*)(const char*, void*, size_t*, void*, size_t);

Mallctl FindMallctl() { return reinterpret_cast<Mallctl>(dlsym(RTLD_DEFAULT, "mallctl")); }

constexpr double kMb = 1.0 / (1 << 20);

/// jemalloc's statistic `name` [bytes], or a negative value when it is not available.
double JemallocStat(Mallctl mallctl, const char* name) {
  size_t value = 0;
  size_t size = sizeof(value);
  if (mallctl(name, &value, &size, nullptr, 0) != 0) return -1.0;
  return static_cast<double>(value);
}

std::string JemallocReport(Mallctl mallctl) {
  // The statistics are a snapshot taken when the epoch advances.
  uint64_t epoch = 1;
  size_t size = sizeof(epoch);
  mallctl("epoch", &epoch, &size, &epoch, size);
  const double allocated = JemallocStat(mallctl, "stats.allocated");
  const double active = JemallocStat(mallctl, "stats.active");
  const double resident = JemallocStat(mallctl, "stats.resident");
  if (allocated < 0.0 || active < 0.0 || resident < 0.0) {
    return "heap (jemalloc): statistics not available";
  }
  bool background_thread = false;  // purges freed pages on time (malloc_conf, MALLOC_CONF)
  size = sizeof(background_thread);
  const bool known = mallctl("background_thread", &background_thread, &size, nullptr, 0) == 0;
  char text[200];
  std::snprintf(text, sizeof(text),
                "heap (jemalloc): %.1f MB allocated, %.1f MB in active pages, %.1f MB resident, "
                "background thread %s",
                allocated * kMb, active * kMb, resident * kMb,
                known ? (background_thread ? "on" : "off") : "unknown");
  return text;
}

std::string GlibcReport() {
  const struct mallinfo2 heap = mallinfo2();
  char text[160];
  std::snprintf(text, sizeof(text),
                "heap (glibc): %.1f MB in use, %.1f MB free in malloc's heaps, %.1f MB mapped",
                (heap.uordblks + heap.hblkhd) * kMb, heap.fordblks * kMb, heap.hblkhd * kMb);
  return text;
}

}  // namespace

Allocator CurrentAllocator() {
  return FindMallctl() != nullptr ? Allocator::kJemalloc : Allocator::kGlibc;
}

std::string HeapReport() {
  const Mallctl mallctl = FindMallctl();
  return mallctl != nullptr ? JemallocReport(mallctl) : GlibcReport();
}

void ReleaseFreeHeapMemory() {
  if (CurrentAllocator() == Allocator::kGlibc) malloc_trim(0);
}

}  // namespace ros_layer
}  // namespace dslam
