#pragma once
// Little-endian byte helpers and the write-then-rename of the binary files dslam writes (the
// vocabulary, place_recognition/vocabulary.h; the keyframe map, map_file/keyframe_map_file.h):
// integers and doubles appended to and read from a byte string, the 64-bit FNV-1a hash both use
// as identity or checksum, and its hex form.

#include <cstddef>
#include <cstdint>
#include <string>

namespace dslam {

/// Appends `v` as 4 bytes, least significant first.
void PutU32(std::uint32_t v, std::string* out);
/// Appends `v` as 8 bytes, least significant first.
void PutU64(std::uint64_t v, std::string* out);
/// Appends the IEEE-754 bit pattern of `v` as PutU64 does (NaN payloads and -0 kept).
void PutF64(double v, std::string* out);

/// The `size` (1..8) bytes of `bytes` from `offset` as a little-endian unsigned integer. The
/// caller checks that offset + size <= bytes.size().
std::uint64_t GetLittleEndian(const std::string& bytes, std::size_t offset, int size);
/// The double whose bit pattern GetLittleEndian(bytes, offset, 8) is.
double GetF64(const std::string& bytes, std::size_t offset);

/// 64-bit FNV-1a hash of `size` bytes at `data` (offset basis 14695981039346656037, prime
/// 1099511628211).
std::uint64_t Fnv1a64(const char* data, std::size_t size);

/// A 64-bit identity or hash as 16 lower-case hex digits (how tools print a vocabulary's
/// identity and docs state it).
std::string FormatIdentity(std::uint64_t identity);

/// Writes `bytes` as WriteFileAtomically of core/atomic_file.h does (a temporary file, fsync,
/// rename, fsync of the folder), so that `path` is either its old file or the new one. On failure
/// removes the temporary file and throws std::runtime_error "<who>: cannot write <temporary>" or
/// "<who>: cannot rename <temporary> to <path>: <reason>" (atomic_file.h).
void WriteFileAtomically(const std::string& path, const std::string& bytes, const std::string& who);

/// The whole file at `path`. Throws std::runtime_error "<who>: <path>: cannot open the file" or
/// "...: read error".
std::string ReadWholeFile(const std::string& path, const std::string& who);

}  // namespace dslam
