#pragma once
// Whole files written so that a crash, a kill or a power cut never leaves a part of one: the file
// is streamed to a temporary file next to it, flushed to disk, renamed over the old one and the
// folder flushed (the keyframe map file, map_file/keyframe_map_file.h; the vocabulary through
// WriteFileAtomically of binary_io.h). And FNV-1a (binary_io.h) continued over pieces, for
// checksums computed as a stream passes.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

namespace dslam {

/// FNV-1a's offset basis: the hash of no bytes, where Fnv1a64Update starts.
constexpr std::uint64_t kFnv1a64Basis = 14695981039346656037ull;

/// `hash` (of the bytes before) continued over `size` bytes at `data`: the hash of a byte string
/// fed in pieces, Fnv1a64Update(Fnv1a64Update(kFnv1a64Basis, a), b) == Fnv1a64(a + b).
std::uint64_t Fnv1a64Update(std::uint64_t hash, const char* data, std::size_t size);

/// What WriteFileAtomically does with a file already at the path.
enum class PreviousFile {
  kReplace,  ///< replaced: gone once the new file is in place
  kKeep,     ///< kept as `path` + ".prev" (replacing an older one) just before the new file
};

/// Writes the file at `path` through `write`, given a binary std::ostream on a temporary file
/// `path` + ".tmp-<pid>-<n>" (n: a process-wide counter, so that concurrent saves in one or in
/// several processes never share one), flushes it to disk (fsync), renames it to `path` and
/// flushes the folder (fsync), so that `path` is either its old file or the new one, complete,
/// whenever the process stops. With PreviousFile::kKeep a file already at `path` is first
/// hard-linked (copied and flushed where links fail) to `path` + ".prev". On failure the
/// temporary file is removed and std::runtime_error "<who>: cannot write <temporary>[: <why>]",
/// "<who>: cannot keep <path> as <path>.prev: <why>" or "<who>: cannot rename <temporary> to
/// <path>: <why>" thrown, `path` unchanged; "<who>: wrote <path> but cannot sync its folder
/// <folder>: <why>" after the rename. An exception of `write` is passed on after the temporary
/// file is removed. A killed process leaves its temporary file behind; the next successful write
/// to `path` removes those of processes that no longer exist.
void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                         const std::string& who, PreviousFile previous = PreviousFile::kReplace);

}  // namespace dslam
