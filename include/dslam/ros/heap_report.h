#pragma once

#include <string>

namespace dslam {
namespace ros_layer {

/// Which malloc serves the process: jemalloc when it is linked in or preloaded (it exports
/// `mallctl`), else glibc's.
enum class Allocator { kGlibc, kJemalloc };

/// The allocator in use (looked up once per call with dlsym).
Allocator CurrentAllocator();

/// What the allocator holds, in MB, as one line for the log: jemalloc's allocated, active and
/// resident bytes (after refreshing its statistics), or glibc's in use, free in its heaps and
/// mapped (mallinfo2, summed over its arenas).
std::string HeapReport();

/// Hands freed memory back to the kernel where the allocator does not do it by itself: glibc's
/// malloc_trim(0) over every arena. jemalloc returns unused pages on its own (its decay), so
/// nothing is done there.
void ReleaseFreeHeapMemory();

}  // namespace ros_layer
}  // namespace dslam
